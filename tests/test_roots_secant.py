"""jkrcyl.numerics.roots.secant_or_none (the correctors of jkrcyl.numerics.cohesive_crossing): converges where
the secant does, accepts a root within ``noise`` where f's rounding stops it, and says None (never a wrong root)
where f is not finite or the iterates do not settle."""
import math

from jkrcyl.numerics import roots


def test_converges_to_the_root():
    # reference: sqrt(2) (math.sqrt, correctly rounded)
    got = roots.secant_or_none(lambda x: x * x - 2.0, 1.0, 1.1, 1e-13, 1e-9, 30)
    assert abs(got - math.sqrt(2.0)) < 1e-13


def test_a_rounding_plateau_is_a_root_within_noise_only():
    # f constant (0 to rounding) on [1 - 1e-10, 1 + 1e-10], linear outside: the secant stops on the plateau
    f = lambda x: 0.0 if abs(x - 1.0) < 1e-10 else x - 1.0
    got = roots.secant_or_none(f, 1.0 + 5e-11, 1.0 - 5e-11, 1e-16, 1e-9, 30)
    assert got is not None and abs(got - 1.0) < 1e-10
    assert roots.secant_or_none(f, 1.0 + 5e-11, 1.0 - 5e-11, 1e-16, 1e-12, 30) is None     # plateau wider than noise


def test_not_finite_or_no_root_is_none():
    assert roots.secant_or_none(lambda x: math.nan, 0.0, 1.0, 1e-13, 1e-9, 30) is None
    assert roots.secant_or_none(lambda x: x * x + 1.0, 0.5, 0.6, 1e-13, 1e-9, 30) is None       # no real root
