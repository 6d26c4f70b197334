"""continuation.project's stopping rule (issue 18, speed item 2): Newton ends at the noise floor of f, and
its success flag says whether the returned point is on the curve.  References: the exact zero sets of the
test functions (a line, a circle), with deterministic noise of known size added."""
import math
import zlib

import numpy as np

from jkrcyl.numerics import continuation as cont


def _noisy(f, size):
    """f plus a deterministic pseudo-random term of magnitude ``size`` (rounding noise of a long computation)."""
    def g(x):
        h = zlib.crc32(np.asarray(x, dtype=float).tobytes()) / 2 ** 32      # changes with the last bit of x
        return f(x) + size * (2 * h - 1)
    return g


def _counted(f):
    calls = [0]

    def g(x):
        calls[0] += 1
        return f(x)
    return g, calls


def test_stops_at_the_noise_floor():
    """Circle x^2 + y^2 = 2 with noise 6e-11 (steps of ~1e-11 > tol 1e-12 for ever): on it to the noise's
    reach, in far fewer than the 30 iterations the step criterion alone would take."""
    f, calls = _counted(_noisy(lambda x: x[0] ** 2 + x[1] ** 2 - 2.0, 6e-11))
    x, ok = cont.project(f, [1.3, 1.1], direction=np.array([1.0, 0.0]))
    assert ok
    assert abs(math.hypot(*x) - math.sqrt(2)) < 1e-10
    assert calls[0] < 5 * 12          # each iteration: f and a central gradient; before: 151 (all 30)


def test_noise_above_the_floor_is_not_reported_as_converged_below_it():
    """Noise 1e-6 > ACCEPT_F: Newton never gets |f| down to ACCEPT_F reliably; ok must match |f| at the point."""
    f = _noisy(lambda x: x[0] - 0.5, 1e-6)
    x, ok = cont.project(f, [0.9, 0.2], direction=np.array([1.0, 0.0]))
    assert ok == (abs(f(x)) <= cont.ACCEPT_F)


def test_no_root_is_a_failure():
    """f = 1 + x^2 + y^2 > 0 has no zero: ok is False whatever the iteration does."""
    x, ok = cont.project(lambda x: 1.0 + x[0] ** 2 + x[1] ** 2, [0.3, 0.4])
    assert not ok


def test_clean_function_still_converges_to_tol():
    """Without noise the step criterion ends it (quadratic convergence), to the root of the line."""
    x, ok = cont.project(lambda x: 2 * x[0] - 3 * x[1] + 1, [0.0, 0.0])
    assert ok and abs(2 * x[0] - 3 * x[1] + 1) < 1e-14
