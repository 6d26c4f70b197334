"""Full contact: the pin bonded all round (eps + eps_top = pi): no edge, no Griffith condition, always stable.

n = N0 + N1 cos(phi) all round (the Fourier modes 0 and 1 of the kernel K of numerics.arcs, a convolution on the
circle), N0 = -1/(pi (1 - 2 vartheta alpha*/beta*)) (-1/pi at alpha* = 0: the interface is in tension wherever
|P*| < 1/(1 - 2 vartheta alpha*/beta*)).

Any edge law: with no gap there is no edge and no zone, so the state is the same for every law with the same w
(the elastic field fixes n, the interface energy is -w over the whole circle).  A law of finite strength (the
Maugis-Dugdale traction s0, Edge.bond_strength) holds the bond only where the tension -vartheta n <= s0: an
opening h > 0 anywhere costs s0 h of interface energy and releases -vartheta n h of elastic energy to first
order, so the bonded pin is a strict minimum (stable under any control) where the tension is below s0
everywhere, and no equilibrium where it exceeds it (:func:`holds`).
"""
from __future__ import annotations

import math

from .._validate import finite_scalar
from ..numerics import arcs as _arcs
from ..results import FullContact
from .problem import Problem

BOND_RTOL = 1e-6          # the bond's limit as reached by a branch's end: the cohesive round-zone tail's closing
#                           state lies 2.5e-7 (relative, in P*) past it (lambda 3.875, M 0.6475, vartheta 1, gb 1/2.8)


def law(pb: Problem):
    """(N0, c) with n = N0 + N1 cos(phi) and delta/Delta = -1 + c P* in full contact.

    The modes 1 and cos(phi) of the right-hand side (delta/Delta) cos(phi) - (1 - cos(phi)) are answered mode by
    mode (nu = vartheta n): int K dt = 2 pi (k0 - 1 + ar) (= -pi/vartheta + 2 pi ar) and
    int K cos(t) dt = pi (k1 - 1/2 + ar/2), so N0 = 1/(vartheta int K dt) and
    delta/Delta + 1 = -vartheta (k1 - 1/2 + ar/2) P* (k0, k1: the engine's derived constants, so the law follows
    its definition of delta; at alpha* = 0, k1 = gb: c = 0 is the degeneracy gb = 1/2).  tests/test_twopatch.py
    checks both integrals by quadrature and the law as the limit of closing gaps.  A rigid cradle: vartheta -> scale
    1 (n = nu, P* = p), int K dt = 2 pi ar, so N0 = 1/(2 pi ar), finite for a compressible pin (ar < 0) -- the limit
    of a stiff cradle (tests/test_rigid_confined.py)."""
    kn = _arcs.Kernel(pb.theta, pb.gb, pb.alpha_ratio)
    mode0 = 2 * math.pi * (kn.k0 - 1.0 + kn.ar)
    mode1 = math.pi * (kn.k1 - 0.5 + 0.5 * kn.ar)
    if not mode0 < 0:        # a rigid cradle (scale 1, k0 = 1): 2 pi ar, the pin's compressibility fills the gap
        raise ValueError(f"alpha_ratio: no full contact in a rigid cradle at alpha*/beta* = {pb.alpha_ratio!r} >= 0 "
                         "(an incompressible pin cannot fill the clearance: the tension would be unbounded)")
    return 1.0 / (pb.scale * mode0), -pb.scale * mode1 / math.pi


def state(pb: Problem, P_star=None, delta_over_Delta=None) -> FullContact:
    """Full contact at a given load P* or approach delta/Delta (exactly one of them)."""
    if (P_star is None) == (delta_over_Delta is None):
        raise ValueError("P_star: give exactly one of P_star and delta_over_Delta")
    N0, c = law(pb.require_material_pair())
    if P_star is not None:
        P = finite_scalar("P_star", P_star)
        d = -1.0 + c * P
    else:
        d = finite_scalar("delta_over_Delta", delta_over_Delta)
        if c == 0:
            if d != -1.0:
                raise ValueError("delta_over_Delta: full contact needs delta/Delta = -1 when gb = 1/2")
            raise ValueError("P_star: undetermined by delta/Delta when gb = 1/2 (give P_star)")
        P = (d + 1.0) / c
    return FullContact(theta=pb.theta, gb=pb.gb, P_star=P, delta_over_Delta=d, N0=N0, N1=P / math.pi,
                       alpha_ratio=pb.alpha_ratio)


def at_work(pb: Problem, delta_work_over_Delta) -> FullContact:
    """Full contact at a given delta_work/Delta = delta/Delta + c' P* (affine in P*: c' = work_shift vartheta)."""
    N0, c = law(pb)
    slope = c + pb.work_shift * pb.scale
    if slope == 0:
        raise ValueError("delta_work: full contact fixes no load at this delta_work (zero compliance)")
    return state(pb, P_star=(finite_scalar("delta_work", delta_work_over_Delta) + 1.0) / slope)


def holds(pb: Problem, fc: FullContact) -> bool:
    """Whether the bond holds under the edge law: the largest tension vartheta (|N1| - N0) (kernel scale, at phi = 0
    or pi) is at most the law's bond strength (module docstring; always for JKR), to BOND_RTOL: the cohesive
    round-zone tail closes into the bonded pin at its limit, so the state the branch continues as holds there."""
    return pb.scale * (abs(fc.N1) - fc.N0) <= pb.edge.bond_strength() * (1 + BOND_RTOL)


def bond_limit(pb: Problem, sign: float) -> float:
    """P* (of the sign of ``sign``) where the bond stops holding, vartheta (|N1| - N0) = bond strength with
    N1 = P*/pi: pi (strength/vartheta + N0) in magnitude (inf for JKR); nan where it never holds."""
    N0, _ = law(pb)
    size = math.pi * (pb.edge.bond_strength() / pb.scale + N0)
    return math.copysign(size, sign) if size >= 0 else math.nan
