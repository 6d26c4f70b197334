"""jkrcyl.numerics.roots.damped_newton, the one damped Newton of the small cohesive systems (cohesive_two.newton,
cohesive_two_branch.solve_at), on systems whose roots are known in closed form."""
import math

import numpy as np

from jkrcyl.numerics import roots


def circle_line(x):
    """x^2 + y^2 = 4, y = x: the root (sqrt 2, sqrt 2) from the first quadrant."""
    return np.array([x[0] ** 2 + x[1] ** 2 - 4.0, x[1] - x[0]])


def exact_jacobian(x, r):
    return np.array([[2 * x[0], 2 * x[1]], [-1.0, 1.0]])


def test_converges_to_the_closed_form_root():
    x, r = roots.damped_newton(circle_line, np.array([3.0, 0.5]), exact_jacobian, np.ones(2), 1e-14,
                               np.array([1.0, 1.0]), 40, 12)
    assert np.max(np.abs(x - math.sqrt(2))) < 1e-14 and np.max(np.abs(r)) < 1e-14


def test_steps_are_capped_and_the_domain_respected():
    """A domain x > 0 (f None outside) and a far start: the capped, halved steps stay inside and converge; a
    start whose every step leaves the domain returns None."""
    f = lambda x: circle_line(x) if np.all(x > 0) else None
    seen = []
    got = roots.damped_newton(f, np.array([50.0, 0.1]), exact_jacobian, np.ones(2), 1e-13, np.array([2.0, 2.0]),
                              60, 12, after_step=lambda x, dx, r, rt, J: seen.append(np.max(np.abs(dx))))
    assert got is not None and np.max(np.abs(got[0] - math.sqrt(2))) < 1e-13
    assert max(seen) <= 2.0
    assert roots.damped_newton(lambda x: None, np.array([1.0, 1.0]), exact_jacobian, np.ones(2), 1e-13,
                               np.ones(2), 10, 4) is None


def test_the_rounding_floor():
    """f with noise 5e-10 .. 2.5e-9 (a jitter drawn per point, never 0): tol 1e-14 is out of reach -- None without a floor, the best
    point (within the noise of the root) with the floor 1e-8."""
    def noisy(x):
        jitter = np.random.default_rng(abs(hash(x.tobytes()))).uniform(0.5, 2.5, 2)      # per point, as rounding
        return circle_line(x) + 1e-9 * jitter * np.array([1.0, -1.0])

    args = (np.array([3.0, 0.5]), exact_jacobian, np.ones(2), 1e-14, np.ones(2), 30, 6)
    assert roots.damped_newton(noisy, *args) is None
    x, r = roots.damped_newton(noisy, *args, floor=np.full(2, 1e-8))
    assert np.max(np.abs(r)) < 1e-8 and np.max(np.abs(x - math.sqrt(2))) < 1e-8


def test_singular_jacobian_is_none():
    assert roots.damped_newton(circle_line, np.array([3.0, 0.5]), lambda x, r: None, np.ones(2), 1e-14,
                               np.ones(2), 10, 4) is None
