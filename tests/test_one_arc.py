"""The numba one-arc kernel (the even half-system, numerics.one_arc_kernels) against the full bordered system
assembled and solved in Python (numerics.one_arc.OneArc): the same states to rounding, for alpha* = 0 and != 0,
tiny to nearly closed contacts; and the Bessel coefficients of its enrichment against scipy."""
import math

import numpy as np
import pytest
from scipy.special import jv

from jkrcyl.numerics import arcs_enrich, one_arc
from jkrcyl.numerics import one_arc_kernels as ok


@pytest.mark.parametrize("theta, gb, ar", [(1.0, 0.5, 0.0), (0.67, 0.3, 0.117), (1.3, 0.3, -0.3), (math.inf, 0.9, -0.1)])
def test_even_kernel_equals_the_full_system(theta, gb, ar):
    worst = 0.0
    for a in np.geomspace(1e-3, 50, 25):
        even = one_arc.arc_state(a, 0.1, theta, gb, ar)
        full = one_arc.arc_state(a, 0.1, theta, gb, ar, even=False)
        worst = max(worst, max(abs(x - y) / max(abs(y), 1e-12) for x, y in zip(even, full)))
    assert worst < 1e-10                  # measured 1e-12 (alpha* = 0) to 2e-11: the condition of the system


@pytest.mark.parametrize("e", [1e-8, 0.3, 1.5, math.pi])
def test_trig_coefficients_against_scipy_bessel(e):
    gc, gs = np.zeros(arcs_enrich.K_TRIG), np.zeros(arcs_enrich.K_TRIG)
    ok.trig_coefficients(e, gc, gs)
    rc, rs = arcs_enrich.trig_coefficients(e)            # scipy.special.jv (Jacobi-Anger)
    assert np.max(np.abs(gc - rc)) < 1e-15 and np.max(np.abs(gs - rs)) < 1e-15     # a few ulp of 2 J_k <= 2
    assert ok.bessel_j(3, e) == pytest.approx(float(jv(3, e)), rel=1e-14, abs=1e-300)
