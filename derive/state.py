"""One fused kernel for the whole equilibrium state: no new physics.

The outputs of load_state (derive/load.py), the stress intensity (3.4)-(3.5) of those constants,
approach (derive/approach.py) and gap_pi (derive/gap.py) -- the very expressions those modules emit
and prove -- in one kernel, so that common subexpressions (sqrt(a), log1p(a^2), sqrt(1 + a^2), the
denominator of (4.4)) are computed once per point instead of once per kernel.
"""
from . import approach, gap, load
from .kernel import Kernel
from .symbols import Delta, zeta


def _kernels():
    sol = load.solution()
    K, G_release = load.stress_intensity_forms(sol["C"], sol["c0"], sol["c1"])
    delta = Delta * approach.d_Delta() + zeta * approach.d_zeta()
    h_pi, _ = gap.stable_gap_forms()
    outputs = tuple((n, sol[n]) for n in ("P", "B", "C", "c0", "c1", "r0"))
    outputs += (("K", K), ("G_release", G_release), ("delta", delta), ("h_pi", h_pi))
    return [Kernel("full_state", outputs,
                   "Equilibrium state at contact parameter a = tan(eps/2), fused: P, B, C, c0, c1, r0 as\n"
                   "load_state, K, G_release as stress_intensity, delta as approach, h_pi as gap_pi (same\n"
                   "expressions, shared subexpressions).  Delta [m], R [m], beta = beta* [1/Pa],\n"
                   "inv_G_I = 1/G_I [1/Pa], inv_theta = 1/vartheta, zeta = sqrt(2wR/A) [N/m^(1/2)].",
                   forms=("into", "parallel"))]


def derive(report):
    """Nothing to prove or report: every output is proved where it is derived."""
    del report
    return _kernels()
