"""One fused kernel for the whole equilibrium state: no new physics.

The outputs of load_state (derive/load.py), approach (derive/approach.py) and gap_pi
(derive/gap.py) -- the very expressions those modules emit and prove -- in one kernel, so that
common subexpressions (sqrt(a), log1p(a^2), sqrt(1 + a^2), the denominator of (4.4)) are computed
once per point instead of once per kernel.
"""
from . import approach, gap, load
from .kernel import Kernel
from .symbols import Delta, zeta


def _kernels():
    sol = load.solution()
    delta = Delta * approach.d_Delta() + zeta * approach.d_zeta()
    h_pi, _ = gap.stable_gap_forms()
    outputs = tuple((n, sol[n]) for n in ("P", "B", "C", "c0", "c1", "r0")) + (("delta", delta), ("h_pi", h_pi))
    return [Kernel("full_state", outputs,
                   "Equilibrium state at contact parameter a = tan(eps/2), fused: P, B, C, c0, c1, r0 as\n"
                   "load_state, delta as approach, h_pi as gap_pi (same expressions, shared subexpressions).\n"
                   "Delta [m], R [m], beta = beta* [1/Pa], inv_G_I = 1/G_I [1/Pa], inv_theta = 1/vartheta,\n"
                   "zeta = sqrt(2wR/A) [N/m^(1/2)].")]


def derive(report):
    """Nothing to prove or report: every output is proved where it is derived."""
    del report
    return _kernels()
