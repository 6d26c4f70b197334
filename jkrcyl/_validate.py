"""Input checks: every bad value gets a ValueError that names the parameter and the allowed range.

Documented domain: every real input is 0 or has magnitude in [TINY, HUGE] = [1e-100, 1e100]
(inf only where a parameter allows it, e.g. a rigid body); the contact parameter a = tan(eps/2) lies in
[A_MIN, A_MAX] = [1e-100, 1e20] (beyond, the closed forms under- or overflow), a <= PRESSURE_A_MAX = 1e4 for
the pressure; vartheta <= 1e100 or inf;
counts n <= N_MAX = 1e6.  Booleans, strings, complex numbers and None are not numbers here.
"""
import math
import numbers

import numpy as np

TINY, HUGE = 1e-100, 1e100
A_MIN, A_MAX = 1e-100, 1e20
PRESSURE_A_MAX = 1e4       # Contact.pressure: beyond (eps > pi - 2e-4) atanh near 1 in (5.4) loses the bounded part
THETA_MAX = 1e100
N_MAX = 1_000_000


def real(name, value):
    """float(value) for a real number (int, float, numpy real scalar or size-1 real array), else ValueError."""
    if isinstance(value, (bool, np.bool_)) or value is None or isinstance(value, (str, bytes)):
        raise ValueError(f"{name} must be a real number, got {value!r}")
    if isinstance(value, np.ndarray):
        if value.size != 1 or value.dtype.kind not in "iuf":
            raise ValueError(f"{name} must be a real number, got {value!r}")
        return float(value.reshape(()))
    if not isinstance(value, numbers.Real):
        raise ValueError(f"{name} must be a real number, got {value!r}")
    try:
        return float(value)
    except (TypeError, ValueError, OverflowError):
        raise ValueError(f"{name} must be a real number, got {value!r}") from None


def finite_scalar(name, value, low=None, high=None, low_open=False, allow_inf=False, tiny=TINY, huge=HUGE):
    """A real number in [low, high] (or (low, high] with low_open); inf only with allow_inf.

    Finite values must also be 0 or of magnitude in [tiny, huge] (the documented domain)."""
    v = real(name, value)
    if math.isnan(v) or (math.isinf(v) and not allow_inf):
        raise ValueError(f"{name} must be finite, got {v}")
    lo_ok = low is None or (v > low if low_open else v >= low)
    if not lo_ok or (high is not None and v > high):
        lo_txt = "-inf" if low is None else f"{low:g}"
        hi_txt = "inf" if high is None else f"{high:g}"
        bracket = "(" if low_open or low is None else "["
        raise ValueError(f"{name} must be in {bracket}{lo_txt}, {hi_txt}], got {v!r}")
    if math.isfinite(v) and v != 0 and not tiny <= abs(v) <= huge:
        zero_ok = low is None or low < 0 or (low == 0 and not low_open)
        raise ValueError(f"{name} must be {'0 or ' if zero_ok else ''}of magnitude in [{tiny:g}, {huge:g}] "
                         f"(the supported domain), got {v!r}")
    return v


def count(name, value, low, high=N_MAX):
    """An integer in [low, high] (floats with integral values accepted)."""
    v = finite_scalar(name, value, low=low, high=high)
    if v != int(v):
        raise ValueError(f"{name} must be an integer, got {v!r}")
    return int(v)


def real_array(name, value):
    """A non-empty float array of real numbers (no bools, strings, complex, None)."""
    if value is None or isinstance(value, (str, bytes, bool, np.bool_)):
        raise ValueError(f"{name} must be a real number or an array of them, got {value!r}")
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a real number or an array of them, got {value!r}") from None
    if arr.dtype.kind not in "iuf":
        raise ValueError(f"{name} must be a real number or an array of them, got {value!r}")
    if arr.size == 0:
        raise ValueError(f"{name} must not be empty")
    return arr.astype(float)


def angle(phi):
    """phi [rad]: finite real numbers of magnitude <= HUGE (wrapped by the caller)."""
    arr = real_array("phi", phi)
    bad = ~np.isfinite(arr) | (np.abs(arr) > HUGE)
    if bad.any():
        raise ValueError(f"phi must be finite, of magnitude <= {HUGE:g} [rad], got {float(arr[bad].flat[0])!r}")
    return arr


def contact_parameter(a):
    """a = tan(eps/2): float array, every entry in [A_MIN, A_MAX]."""
    if isinstance(a, float) and A_MIN <= a <= A_MAX:  # the common scalar (numpy float64 too), no array round trip
        return np.array(a)
    arr = real_array("a", a)
    bad = ~np.isfinite(arr) | (arr <= 0)
    if bad.any():
        raise ValueError(f"a must be in (0, inf) (a = tan(eps/2), 0 < eps < pi), got {float(arr[bad].flat[0])!r}")
    out = (arr < A_MIN) | (arr > A_MAX)
    if out.any():
        raise ValueError(f"a must be in [{A_MIN:g}, {A_MAX:g}] (the supported domain of a = tan(eps/2)), "
                         f"got {float(arr[out].flat[0])!r}")
    return arr


def theta(value):
    """vartheta = 1/2 + G (kappa_I + 1)/(2 G_I (1 + kappa)) in [1/2, THETA_MAX]; inf is the rigid cradle."""
    v = finite_scalar("theta", value, low=0.5, allow_inf=True, huge=math.inf)
    if math.isfinite(v) and v > THETA_MAX:
        raise ValueError(f"theta must be in [0.5, {THETA_MAX:g}] or inf (the supported domain), got {v!r}")
    return v


#: the three controls: what is held (the load P, the paper's approach delta, the work-conjugate delta_work)
CONTROLS = ("load", "grip", "grip-work")


def control(value):
    """One of :data:`CONTROLS` (ValueError naming control, with the value given)."""
    if not isinstance(value, str) or value not in CONTROLS:
        raise ValueError(f"control must be one of {', '.join(repr(c) for c in CONTROLS)}, got {value!r}")
    return value
