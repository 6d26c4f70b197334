"""Two contact arcs: the pin after the gap closes at phi = pi (paper sections 5, 6, 8.2).

Bottom arc |phi| < eps (a = tan(eps/2)), top arc |phi - pi| < eps_top (a_top = tan(eps_top/2)).  On both arcs the
pin and the hole touch, so the relative radial displacement is the rigid one (5.1),
``v_r - u_r = delta cos(phi) - Delta (1 - cos(phi))`` -- the same formula on both arcs, with one approach delta.
Normalised as in section 6 (n = N R beta*/(4 pi Delta vartheta), so P* = int n cos(phi) dphi, B* = int n dphi),
everything is linear in delta for fixed arcs: numerics.two_arcs gives, for each arc end, the edge coefficient k of
n ~ -k/sqrt(distance to the end in rad), as k = k0 + (delta/Delta) k1.

Griffith (3.5)-(3.6) at an end reads G/w = (pi k/M)^2 = 1, i.e. k = M/pi at both ends (checked against the
closed form (4.4)).  Eliminating delta leaves ONE scalar equation in the half-angles,

    F(eps, eps_top) = sign(det A) [(k0_bot - M/pi) k1_top - (k0_top - M/pi) k1_bot] / |k1| = 0,

whose zero set -- curves in the (eps, eps_top) plane, traced by jkrcyl.analysis.tracing -- is the set of two-patch
equilibria (A: the fixed-arc collocation matrix, singular on curves such as eps = 2 atan(a_crit); the sign factor
keeps F smooth there).

Energy (per unit length, in units 4 pi Delta^2 vartheta/beta*; vartheta here is pb.scale, 1 for a rigid cradle):
U* = [(1 + delta/Delta) P* - B*]/2, half the work of the pressure on the rigid overlap (5.1).  Then
dU*/d(delta/Delta) = P* (load and approach conjugate) and dU*/d eps = 2 vartheta pi^2 k_bot^2 = 2 vartheta M^2 G/w
(energy release at fixed grip), which the tests check by finite differences.  Stability: the total potential
Pi* = U* - 2 vartheta M^2 (eps + eps_top) (minus P* delta/Delta
under load control) must be a minimum (:func:`hessian`, jkrcyl.model.stability.two_patch_flags).

Mirror: turning the picture upside down (phi -> phi + pi) swaps the arcs and maps P* -> -P*,
delta/Delta -> -2 - delta/Delta (the operator only depends on phi - psi).  Any alpha*: the kernel of
numerics.arcs is still even and 2 pi-periodic in phi - psi, so the mirror, the energy U* (Clapeyron: a symmetric
operator, frictionless arcs) and dU*/d delta = P* hold unchanged; the alpha* part is bounded, so the edges stay
square-root and Griffith is still k = M/pi (tests: finite differences of U* give G = w to 1e-6).
"""
from __future__ import annotations

import math

import numpy as np

from .._validate import finite_scalar
from ..numerics import roots as _roots
from ..numerics import two_arcs as _two
from ..results import TwoPatchState
from . import stability as _stability
from .problem import Problem

N_NODES = _two.N_NODES
GAP_SAMPLES = 128       # exterior angles per state for the gap check h >= 0 (Chebyshev points of the open gap,
                        # clustered at the arc ends where h ~ distance^(3/2) is smallest)
F_NOISE = 1e-11         # F's rounding near full contact (~5e-13 at a gap of 0.06; 1e-8 is an equilibrium)
GAP_FULL = 0.02         # eps + eps_top >= pi - GAP_FULL: full contact (traced branches end there, solve() stays short)


def require_two_patch(pb: Problem):
    """pb, validated for two-patch states (M > 0, a material pair); a rigid cradle (vartheta = inf) in the
    kernel scale (M_R*, P_R* = p: numerics.arcs.Linear normalises by pb.scale = 1)."""
    if pb.M <= 0:
        raise ValueError(f"M must be in (0, inf) for two-patch states (Griffith at both ends), got {pb.M!r}")
    return pb.require_material_pair()


def linear(pb: Problem, eps, eps_top, n=N_NODES, exact=False):
    """Affine pieces at fixed arcs: q0, q1 = [P*, B*, k_bot, k_top] for (Delta-case, unit delta/Delta); at least
    n nodes per arc (the node policy of numerics.two_arcs.nodes), or exactly n."""
    return _two.linear(eps, eps_top, pb.theta, pb.gb, pb.alpha_ratio, n, exact)


def residual_pieces(pb: Problem, eps, eps_top, n=N_NODES, exact=False):
    """(F, Linear) at the half-angles: F of the module docstring, distance-like (units of k)."""
    lin = linear(pb, eps, eps_top, n, exact)
    q0, q1 = lin.q0, lin.q1
    m = pb.M / math.pi
    D = (q0[2] - m) * q1[3] - (q0[3] - m) * q1[2]
    # k0, k1 ~ 1/det(A): D/|k1| ~ sign(det) x smooth; det's sign relative to two tiny arcs at the same node count
    sign = lin.sign_det * _two.reference_sign(lin.sys.n, pb.theta, pb.gb, pb.alpha_ratio)
    return sign * D / math.hypot(q1[2], q1[3]), lin


def residual(pb: Problem, eps, eps_top, n=N_NODES):
    """F(eps, eps_top): zero exactly at the two-patch equilibria."""
    return residual_pieces(pb, eps, eps_top, n)[0]


def griffith_delta(lin, M):
    """delta/Delta from the Griffith condition at the better-conditioned end."""
    q0, q1 = lin.q0, lin.q1
    i = 2 if abs(q1[2]) >= abs(q1[3]) else 3
    return (M / math.pi - q0[i]) / q1[i]


def exterior_angles(eps, eps_top, k=GAP_SAMPLES):
    """k angles in the open gap eps < phi < pi - eps_top, clustered at both ends (Chebyshev points)."""
    lo, hi = eps, math.pi - eps_top
    s = np.cos(np.pi * (np.arange(k) + 0.5) / k)
    return 0.5 * (lo + hi) + 0.5 * (hi - lo) * s


def fixed_arcs(pb: Problem, eps, eps_top, delta_over_Delta, n=N_NODES, lin=None) -> TwoPatchState:
    """The state with given arcs and approach (Griffith not imposed): for energy and stability checks."""
    lin = linear(pb, eps, eps_top, n) if lin is None else lin
    d = float(delta_over_Delta)
    q = lin.q0 + d * lin.q1
    gap_min = float(np.min(lin.gap(exterior_angles(eps, eps_top), d)))
    scale = (math.pi / pb.M) ** 2 if pb.M > 0 else math.inf
    return TwoPatchState(M=pb.M, theta=pb.theta, gb=pb.gb, eps=eps, eps_top=eps_top, P_star=float(q[0]),
                         B_star=float(q[1]), delta_over_Delta=d, G_bot=float(q[2] ** 2 * scale),
                         G_top=float(q[3] ** 2 * scale), energy=0.5 * ((1 + d) * q[0] - q[1]),
                         gap_min=gap_min, alpha_ratio=pb.alpha_ratio, _lin=lin)


def equilibrium_state(pb: Problem, eps, eps_top, n=N_NODES) -> TwoPatchState:
    """State at a point of the zero set of F (delta from Griffith)."""
    lin = linear(pb, eps, eps_top, n)
    return fixed_arcs(pb, eps, eps_top, griffith_delta(lin, pb.M), n, lin=lin)


def mirror(pb: Problem, s: TwoPatchState) -> TwoPatchState:
    """The upside-down state: arcs swapped, P* -> -P*, delta/Delta -> -2 - delta/Delta."""
    return fixed_arcs(pb, s.eps_top, s.eps, -2.0 - s.delta_over_Delta)


def solve(pb: Problem, eps_top=None, eps=None, guess=None, n=N_NODES, tol=1e-13) -> TwoPatchState:
    """A two-patch equilibrium with ONE half-angle given (eps_top or eps): the other by the secant on F.

    guess: starting value of the unknown half-angle.  ValueError if it does not converge (no equilibrium near
    the guess)."""
    require_two_patch(pb)
    if (eps_top is None) == (eps is None):
        raise ValueError("eps_top: give exactly one of eps_top and eps")
    name, given = ("eps_top", eps_top) if eps is None else ("eps", eps)
    given = finite_scalar(name, given, low=0.0, low_open=True)
    if given >= math.pi:
        raise ValueError(f"{name} must be in (0, pi), got {given!r}")
    pair = (lambda x: (x, given)) if eps is None else (lambda x: (given, x))
    x = float(guess) if guess is not None else 0.5 * (math.pi - given)
    policy = lambda x: _two.nodes(*pair(x), n, pb.alpha_ratio)       # nodes per arc at half-angles pair(x)
    for _ in range(3):      # F's sign (det's) holds at one node count: the policy's at the start, then at the root
        count = policy(x)
        x, fx, lin = _secant(pb, pair, x, count, math.pi - given - GAP_FULL, tol)
        if policy(x) == count:
            break
    if not abs(fx) < 1e-8:
        raise ValueError(f"guess: no two-patch equilibrium found near {x!r}")
    return fixed_arcs(pb, *pair(x), griffith_delta(lin, pb.M), n, lin=lin)


def _secant(pb, pair, x0, count, hi, tol):
    """(x, F, Linear) of the secant on F(pair(x)) = 0 in (0, hi) from x0, count nodes per arc exactly (F with
    the policy's count per point jumps in sign where the count steps: session 37's hypothesis test of a rigid
    cradle, M_R* 0.219 -- 22 of 26 states at a load missed)."""
    last = {}

    def f(x):                                           # keeps each solve for the final state
        r, last[x] = residual_pieces(pb, *pair(x), count, exact=True)
        return r
    try:
        x, fx = _roots.secant(f, x0, x0 * (1 + 1e-4), 0.0, hi, tol=tol, noise=F_NOISE)
    except ValueError:
        raise ValueError(f"guess: no two-patch equilibrium found near {x0!r}") from None
    return x, fx, last[x]


def hessian(pb: Problem, eps, eps_top, delta_over_Delta, n=N_NODES, h=1e-6, lin=None):
    """3x3 Hessian of Pi* in (eps, eps_top, delta/Delta) at fixed load (the last row/column drops at fixed grip),
    and the gradient of P* in the same variables.

    d Pi*/d eps_i = 2 vartheta (pi^2 k_i^2 - M^2), d Pi*/d delta = P* - P*_applied, so the entries are
    4 vartheta pi^2 k_i dk_i/d eps_j (central differences at fixed delta), 4 vartheta pi^2 k_i k1_i and
    dP*/d delta = q1[P].  The eps block is symmetrised (Maxwell; the asymmetry is a check in the tests).
    Returns (H, He, gP): He the unsymmetrised eps block, gP = (dP*/d eps, dP*/d eps_top, dP*/d(delta/Delta)).
    """
    d = delta_over_Delta
    pick = [2, 3, 0]                                          # k_bot, k_top, P* of the fixed-arc pieces
    kP = lambda e, et: (lambda L: L.q0[pick] + d * L.q1[pick])(linear(pb, e, et, n))
    lin = linear(pb, eps, eps_top, n) if lin is None else lin
    kk = lin.q0[2:4] + d * lin.q1[2:4]
    dkP = np.zeros((3, 2))
    h0, h1 = min(h, 0.1 * eps), min(h, 0.1 * eps_top)        # relative steps near an axis
    dkP[:, 0] = (kP(eps + h0, eps_top) - kP(eps - h0, eps_top)) / (2 * h0)
    if eps_top > 0:          # eps_top = 0: the single arc; the top row/column is decoupled (the identity)
        dkP[:, 1] = (kP(eps, eps_top + h1) - kP(eps, eps_top - h1)) / (2 * h1)
    c = 4 * pb.scale * math.pi ** 2
    H = np.empty((3, 3))
    He = c * kk[:, None] * dkP[:2]
    H[:2, :2] = 0.5 * (He + He.T)
    H[:2, 2] = H[2, :2] = c * kk * lin.q1[2:4]
    H[2, 2] = lin.q1[0]
    if eps_top == 0:
        H[1, :] = H[:, 1] = 0.0
        H[1, 1] = 1.0
    return H, He, np.array([dkP[2, 0], dkP[2, 1], lin.q1[0]])


def stability(pb: Problem, eps, eps_top, delta_over_Delta, n=N_NODES, lin=None):
    """(stable_load, stable_grip, stable_grip_work) from the second variation (model.stability.two_patch_flags;
    the Hessian is in P* = p/vartheta, so the pin's n = 1 term carries c = work_shift vartheta)."""
    H, _, g = hessian(pb, eps, eps_top, delta_over_Delta, n, lin=lin)
    return _stability.two_patch_flags(H, g, pb.work_shift * pb.scale)



DESCENT_TINY = 1e-9     # a half-angle below this has vanished (descend)
DESCENT_START = 1e-7    # the nascent top arc of descend
DESCENT_STEP = 0.02     # longest descent step [rad]
DESCENT_POLE = 1e6      # G/w where the descent's steps vanish: a pole of the fixed arcs, not a stationary point
                        # (measured 4e21 at the pole; a stationary point's G/w - 1 ~ the last step, 1e-10)


def _held_delta(pb, lin, control, value):
    """delta/Delta of the fixed arcs with the held quantity at value (P*, delta/Delta or delta_work/Delta)."""
    if control == "load":
        return (value - lin.q0[0]) / lin.q1[0]
    if control == "grip":
        return value
    c = pb.work_shift * pb.scale                       # delta_work/Delta = delta/Delta + c P*
    return (value - c * lin.q0[0]) / (1 + c * lin.q1[0])


def descend(pb: Problem, value: float, eps: float, eps_top: float = DESCENT_START, control: str = "load",
            max_steps: int = 4000):
    """Where slow relaxation with the held quantity at value (P*, delta/Delta or delta_work/Delta) leads from the
    arcs (eps, eps_top): the edges move down the total potential, d eps_i/dt ~ -(G_i - w) (equal edge
    mobilities; dPi*/d eps_i = 2 vartheta (pi^2 k_i |k_i| - M^2) at the approach the control fixes, a
    compressive edge k < 0 counting as G > w... growing).  Returns (outcome, (eps, eps_top)): 'full' (the arcs
    meet), 'transfer' (the bottom arc vanishes), 'single' (the top arc vanishes), 'two-patch' (a stationary
    point: a two-patch state stable under the control) or 'pole' (grip only: the edges run into arcs where the
    fixed-arc load at the held paper's delta is unbounded, G/w > DESCENT_POLE -- the potential of a held delta,
    E = E_work - c p^2/2, is unbounded below there: no state to relax to)."""
    x = np.array([eps, eps_top], dtype=float)
    h, g_old = DESCENT_STEP, None
    for _ in range(max_steps):
        lin = linear(pb, x[0], x[1])
        k = lin.q0[2:4] + _held_delta(pb, lin, control, value) * lin.q1[2:4]
        g = -(math.pi ** 2 * k * np.abs(k) - pb.M ** 2)      # the descent direction of the potential
        turned = g_old is not None and g @ g_old < 0
        if turned:
            h /= 2                                           # overshot a stationary point (or straddles a pole)
        if h < 1e-10 or np.linalg.norm(g) < 1e-12 * pb.M ** 2:
            return ("pole" if np.max(np.abs(g)) > DESCENT_POLE * pb.M ** 2 else "two-patch"), tuple(x)
        x, g_old = x + min(h, 0.5 * min(x)) * g / np.linalg.norm(g), g
        if x.sum() >= math.pi - 0.02:
            return "full", tuple(x)
        if x[0] < DESCENT_TINY:
            return "transfer", tuple(x)
        if x[1] < DESCENT_TINY:
            return "single", tuple(x)
        if not turned:
            h = min(2 * h, DESCENT_STEP)
    return "two-patch", tuple(x)


ESCAPE_STEP = 1e-3      # the escape from a fold starts this far past it along its unstable direction [rad]
ESCAPE_NUDGE = 1e-8     # and the held value this far past the fold's (relative, at least absolute)


def reduced_hessian(pb: Problem, eps, eps_top, delta_over_Delta, control: str, lin=None):
    """The 2x2 Hessian of the total potential in (eps, eps_top) under the control, the held quantity fixed and
    the approach relaxed (as model.stability.two_patch_flags reads H: grip the eps block, load the Schur complement
    of H + c g g^T, grip-work its restriction to d delta = -c dp)."""
    H, _, g = hessian(pb, eps, eps_top, delta_over_Delta, lin=lin)
    if control == "grip":
        return H[:2, :2]
    c = pb.work_shift * pb.scale
    Ht = H + c * np.outer(g, g)
    if control == "load":
        return Ht[:2, :2] - np.outer(Ht[:2, 2], Ht[2, :2]) / Ht[2, 2]
    T = np.vstack([np.eye(2), -c * g[:2] / (1.0 + c * g[2])])
    return T.T @ Ht @ T


def escape(pb: Problem, eps: float, eps_top: float, value: float, control: str = "load", sgn: int = 1):
    """Where slow relaxation leads from a fold of a two-patch branch at the arcs (eps, eps_top), the held quantity
    (P*, delta/Delta or delta_work/Delta) at value and driven past it in the direction sgn (+1: increasing).

    At a fold the reduced Hessian (:func:`reduced_hessian`) has a null direction v, the branch's tangent; past
    the fold the potential falls along +v or -v, the side on which the drive lowers dPi/dv (the change of the
    descent direction with the held value).  :func:`descend` starts ESCAPE_STEP along it with the held value
    nudged past the fold.  Returns descend's (outcome, (eps, eps_top))."""
    lin = linear(pb, eps, eps_top)
    R = reduced_hessian(pb, eps, eps_top, _held_delta(pb, lin, control, value), control, lin=lin)
    v = np.linalg.eigh(0.5 * (R + R.T))[1][:, 0]
    past = value + sgn * ESCAPE_NUDGE * max(1.0, abs(value))

    def push(val):                             # descend's direction at the fold's arcs
        k = lin.q0[2:4] + _held_delta(pb, lin, control, val) * lin.q1[2:4]
        return -(math.pi ** 2 * k * np.abs(k) - pb.M ** 2)
    v = v if v @ (push(past) - push(value)) >= 0 else -v
    start = np.maximum(np.array([eps, eps_top]) + ESCAPE_STEP * v, DESCENT_START)
    return descend(pb, past, float(start[0]), float(start[1]), control)

