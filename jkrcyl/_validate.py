"""Input checks: every bad value gets a ValueError that names the parameter and the allowed range."""
import math

import numpy as np


def finite_scalar(name, value, low=None, high=None, low_open=False, allow_inf=False):
    """A real number in [low, high] (or (low, high] with low_open); inf only with allow_inf."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a real number, got {value!r}") from None
    if math.isnan(v) or (math.isinf(v) and not allow_inf):
        raise ValueError(f"{name} must be finite, got {v}")
    lo_ok = low is None or (v > low if low_open else v >= low)
    if not lo_ok or (high is not None and v > high):
        lo_txt = "-inf" if low is None else f"{low:g}"
        hi_txt = "inf" if high is None else f"{high:g}"
        bracket = "(" if low_open or low is None else "["
        raise ValueError(f"{name} must be in {bracket}{lo_txt}, {hi_txt}], got {v:g}")
    return v


def contact_parameter(a):
    """a = tan(eps/2): float array, every entry finite and > 0."""
    arr = np.asarray(a, dtype=float)
    if arr.size == 0:
        raise ValueError("a must not be empty")
    bad = ~np.isfinite(arr) | (arr <= 0)
    if bad.any():
        raise ValueError(f"a must be in (0, inf) (a = tan(eps/2), 0 < eps < pi), got {arr[bad].flat[0]:g}")
    return arr


def theta(value):
    """vartheta = 1/2 + G (kappa_I + 1)/(2 G_I (1 + kappa)) >= 1/2; inf is the rigid cradle."""
    v = finite_scalar("theta", value, low=0.5, allow_inf=True)
    return v
