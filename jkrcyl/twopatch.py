"""Two contact arcs and full contact: the pin after the gap closes at phi = pi (issue 12; paper sections 5, 6, 8.2).

Bottom arc |phi| < eps (a = tan(eps/2)), top arc |phi - pi| < eps_top (a_top = tan(eps_top/2)).  On both arcs
the pin and the hole touch, so the relative radial displacement is the rigid one (5.1),
``v_r - u_r = delta cos(phi) - Delta (1 - cos(phi))`` -- the same formula on both arcs, with one approach delta.
Normalised as in section 6 (n = N R beta*/(4 pi Delta vartheta), so P* = int n cos(phi) dphi, B* = int n dphi),
everything is linear in delta for fixed arcs: the engine jkrcyl.numerics.arcs.two_patch_linear returns, for
each arc end, the edge coefficient k of n ~ -k/sqrt(distance to the end in rad), as k = k0 + (delta/Delta) k1.

Griffith (3.5)-(3.6) at an end reads G/w = (pi k/M)^2 = 1, i.e. k = M/pi at both ends (checked against the
closed form (4.4)).  Eliminating delta leaves ONE scalar equation in the half-angles,

    F(eps, eps_top) = sign(det A) [(k0_bot - M/pi) k1_top - (k0_top - M/pi) k1_bot] / |k1| = 0,

whose zero set -- curves in the (eps, eps_top) plane -- is the set of two-patch equilibria (A: the fixed-arc
collocation matrix, singular on curves such as eps = 2 atan(a_crit); the sign factor keeps F smooth there).
The curves are traced by pseudo-arclength continuation (jkrcyl.numerics.continuation) in log half-angles,
started at each single-patch onset h(pi) = 0 (a_top -> 0), at its mirror (a -> 0) and at the roots of F along
a few rows eps_top = const (loops) -- no plane grid.

Findings at vartheta = 1, M = 0.3 ... 0.8 (docs/confined.png, tests): every two-patch branch joins the onset to
its mirror and is unstable under load (parts of a loop at M = 0.4 are stable under grip); slow pulling
from the zero-load contact meets the fixed-load adherence point before the gap at pi closes; at a sub-critical
adherence point the pin detaches (and lands on the top of the hole), at a super-critical one dG/dP* > 0, so
a further pull lets the contact grow round into full contact.

Energy (per unit length, in units 4 pi Delta^2 vartheta/beta*): U* = [(1 + delta/Delta) P* - B*]/2, half the
work of the pressure on the rigid overlap (5.1).  Then dU*/d(delta/Delta) = P* (load and approach conjugate)
and dU*/d eps = 2 vartheta pi^2 k_bot^2 = 2 vartheta M^2 G/w (energy release at fixed grip), which the tests
check by finite differences.  Stability: the total potential Pi* = U* - 2 vartheta M^2 (eps + eps_top)
(minus P* delta/Delta under load control) must be a minimum: under grip the 2x2 Hessian in (eps, eps_top),
under load the 3x3 Hessian in (eps, eps_top, delta/Delta) must be positive definite, with the pin's own n = 1
energy (c/2) P*^2 that the paper's delta leaves out (see :func:`stability`; also grip on delta_work).

Mirror: turning the picture upside down (phi -> phi + pi) swaps the arcs and maps
P* -> -P*, delta/Delta -> -2 - delta/Delta (the operator only depends on phi - psi).

Any alpha* (alpha_ratio = alpha*/beta*, every function here): the kernel of numerics.arcs gains
ar (pi sin|t| - t sin t) - (ar/2) cos t, still even and 2 pi-periodic in t = phi - psi, so the mirror, the
energy U* (Clapeyron: a symmetric operator, frictionless arcs) and dU*/d delta = P* hold unchanged; the
alpha* part is bounded, so the edges stay square-root and Griffith is still k = M/pi (tests: finite
differences of U* give G = w to 1e-6).  Full contact changes: N0 = -1/(pi (1 - 2 vartheta ar)).

Full contact (eps + eps_top = pi): no edge, no Griffith condition; n = N0 + N1 cos(phi) all round
(the Fourier modes 0 and 1 of the kernel), N0 = -1/pi at alpha* = 0: the interface is in tension wherever
|P*| < 1.
"""
import functools
import math
from dataclasses import dataclass

import numpy as np

from ._validate import finite_scalar, theta as _check_theta
from .numerics import arcs as _arcs
from .numerics import continuation as _cont

N_NODES = 24            # collocation nodes per arc (spectral: 1e-12 at moderate arcs, see tests)
EPS_AXIS = 1e-12        # smallest half-angle traced: a branch reaching it ends on the single-patch state
                        # (within ~sqrt(EPS_AXIS) log(1/EPS_AXIS) ~ 1e-5 relative, the top arc's own load)
GAP_FULL = 0.02         # eps + eps_top >= pi - GAP_FULL: the branch has run into full contact
NODES_PER_GAP = 8       # near-touching arcs: the density varies on the scale of the gap g between them, so
                        # Chebyshev needs ~ sqrt(eps/g) times more nodes (Bernstein ellipse through the gap);
                        # 8 sqrt(eps/g) keeps F to ~1e-11 (measured against 96 nodes down to g = 0.02)
N_NODES_ALPHA = 32      # alpha* != 0: at least this many (1e-12 at moderate arcs against 128 nodes)
AR_NODES_FACTOR = 2     # alpha* != 0 near-touching arcs: 16 sqrt(eps/g) nodes (7e-10 at g = 0.24, eps = 2)
GAP_SAMPLES = 128       # exterior angles per state for the gap check h >= 0 (Chebyshev points of the
                        # open gap, clustered at the arc ends where h ~ distance^(3/2) is smallest)


def _nodes(eps, eps_top, n, ar):
    """Nodes per arc: n, more for near-touching arcs; alpha* != 0: the algebraic end terms need about twice
    as many, in multiples of 8 (the engine builds one table per node count, ~0.1-0.5 s each)."""
    g = math.pi - eps - eps_top
    need = NODES_PER_GAP * math.sqrt(max(eps, eps_top) / g) if g > 0 else 0.0
    if ar == 0.0:
        return max(n, int(need))
    return min(8 * math.ceil(max(n, N_NODES_ALPHA, AR_NODES_FACTOR * need) / 8), 256)


def _linear(eps, eps_top, theta, gb, n, ar=0.0):
    """Affine pieces at fixed arcs: q0, q1 = [P*, B*, k_bot, k_top] for (Delta-case, unit delta/Delta)."""
    return _arcs.two_patch_linear(eps, eps_top, theta, gb, _nodes(eps, eps_top, n, ar), ar)


# --- residual, one equilibrium -----------------------------------------------------------------------
def _residual_pieces(eps, eps_top, M, theta, gb, n, ar=0.0):
    lin = _linear(eps, eps_top, theta, gb, n, ar)
    q0, q1 = lin.q0, lin.q1
    m = M / math.pi
    D = (q0[2] - m) * q1[3] - (q0[3] - m) * q1[2]
    # k0, k1 ~ 1/det(A): D/|k1| ~ sign(det) x smooth, so the sign factor makes F smooth across det = 0;
    # det's sign is taken relative to two tiny arcs at the same node count (with alpha* != 0 the enrichment
    # columns flip the sign of det with n mod 3, which would flip F wherever the node count changes)
    sign = lin.sign_det * _reference_sign(lin.sys.n, theta, gb, ar)
    return sign * D / math.hypot(q1[2], q1[3]), lin


@functools.lru_cache(maxsize=None)
def _reference_sign(n, theta, gb, ar):
    """sign(det A) for two arcs of 1e-3 rad (far from every singular configuration: the log term dominates)."""
    return _arcs.two_patch_linear(1e-3, 1e-3, theta, gb, n, ar).sign_det


def residual(eps, eps_top, M, theta, gb, n=N_NODES, alpha_ratio=0.0):
    """F(eps, eps_top) scaled by |k1|: zero exactly at the two-patch equilibria (distance-like, units of k)."""
    return _residual_pieces(eps, eps_top, M, theta, gb, n, alpha_ratio)[0]


def _delta(lin, M):
    """delta/Delta from the Griffith condition at the better-conditioned end."""
    q0, q1 = lin.q0, lin.q1
    i = 2 if abs(q1[2]) >= abs(q1[3]) else 3
    return (M / math.pi - q0[i]) / q1[i]


@dataclass(frozen=True)
class TwoPatchState:
    """One two-patch equilibrium (or any fixed-arc state when built by :func:`fixed_arcs`).

    eps, eps_top [rad]; a, a_top = tan(half-angle/2); P_star, B_star, delta_over_Delta (section 6);
    G_bot, G_top = G/w at the bottom and top ends; energy = U* (units 4 pi Delta^2 vartheta/beta*);
    gap_min = min h/Delta over GAP_SAMPLES exterior angles; feasible = gap_min >= 0;
    alpha_ratio = alpha*/beta* of the kernel.
    """

    M: float
    theta: float
    gb: float
    eps: float
    eps_top: float
    P_star: float
    B_star: float
    delta_over_Delta: float
    G_bot: float
    G_top: float
    energy: float
    gap_min: float
    alpha_ratio: float = 0.0
    _lin: object = None

    @property
    def a(self):
        return math.tan(self.eps / 2)

    @property
    def a_top(self):
        return math.tan(self.eps_top / 2)

    @property
    def feasible(self):
        return self.gap_min >= -1e-9

    def pressure(self, phi):
        """n(phi) = N R beta*/(4 pi Delta vartheta) inside the arcs, 0 outside."""
        return self._lin.pressure(np.asarray(phi, dtype=float), self.delta_over_Delta)

    def gap(self, phi):
        """h(phi)/Delta (5.9) at exterior angles phi."""
        return self._lin.gap(np.asarray(phi, dtype=float), self.delta_over_Delta)

    def mirror(self):
        """The upside-down state: arcs swapped, P* -> -P*, delta/Delta -> -2 - delta/Delta."""
        return fixed_arcs(self.eps_top, self.eps, -2.0 - self.delta_over_Delta, self.M, self.theta, self.gb,
                          alpha_ratio=self.alpha_ratio)


def exterior_angles(eps, eps_top, k=GAP_SAMPLES):
    """k angles in the open gap eps < phi < pi - eps_top, clustered at both ends (Chebyshev points)."""
    lo, hi = eps, math.pi - eps_top
    s = np.cos(np.pi * (np.arange(k) + 0.5) / k)
    return 0.5 * (lo + hi) + 0.5 * (hi - lo) * s


def fixed_arcs(eps, eps_top, delta_over_Delta, M, theta, gb, n=N_NODES, lin=None, alpha_ratio=0.0):
    """The state with given arcs and approach (Griffith not imposed): for energy and stability checks."""
    lin = _linear(eps, eps_top, theta, gb, n, alpha_ratio) if lin is None else lin
    d = float(delta_over_Delta)
    q = lin.q0 + d * lin.q1
    gap_min = float(np.min(lin.gap(exterior_angles(eps, eps_top), d)))
    scale = (math.pi / M) ** 2 if M > 0 else math.inf
    return TwoPatchState(M=M, theta=theta, gb=gb, eps=eps, eps_top=eps_top, P_star=float(q[0]),
                         B_star=float(q[1]), delta_over_Delta=d, G_bot=float(q[2] ** 2 * scale),
                         G_top=float(q[3] ** 2 * scale), energy=0.5 * ((1 + d) * q[0] - q[1]),
                         gap_min=gap_min, alpha_ratio=alpha_ratio, _lin=lin)


def equilibrium_state(eps, eps_top, M, theta, gb, n=N_NODES, alpha_ratio=0.0):
    """State at a point of the zero set of F (delta from Griffith)."""
    lin = _linear(eps, eps_top, theta, gb, n, alpha_ratio)
    return fixed_arcs(eps, eps_top, _delta(lin, M), M, theta, gb, n, lin=lin, alpha_ratio=alpha_ratio)


def _params(M, theta, gb, alpha_ratio=0.0):
    from .equilibria import default_gb
    M = finite_scalar("M", M, low=0.0, low_open=True)
    th = _check_theta(theta)
    if math.isinf(th):
        raise ValueError("theta: two-patch states need a finite vartheta (M, P* normalise by vartheta)")
    gb = default_gb(th) if gb is None else finite_scalar("gb", gb, low=0.0)
    return M, th, gb, _alpha_ratio(alpha_ratio, th)


def _alpha_ratio(alpha_ratio, theta):
    """alpha*/beta* in (-1, 1/(2 vartheta)): every material pair has 1/vartheta - 2 alpha*/beta* =
    (2/G + (kappa_I - 1)/G_I)/beta* > 0, the compliance of the uniform mode (full contact's N0 stays finite)."""
    ar = finite_scalar("alpha_ratio", alpha_ratio, low=-1.0, high=1.0, low_open=True)
    if ar >= 0.5 / theta:
        raise ValueError(f"alpha_ratio must be in (-1, 1/(2 theta)) = (-1, {0.5 / theta:g}) at theta = {theta:g} "
                         f"(no material pair has more), got {ar:g}")
    return ar


def solve(M, theta, eps_top=None, eps=None, gb=None, guess=None, n=N_NODES, tol=1e-13, alpha_ratio=0.0):
    """A two-patch equilibrium with ONE half-angle given (eps_top or eps): the other by Newton on F.

    guess: starting value of the unknown half-angle; alpha_ratio = alpha*/beta*.  Returns a
    :class:`TwoPatchState`; ValueError if Newton does not converge (no equilibrium near the guess).
    """
    M, th, gb, ar = _params(M, theta, gb, alpha_ratio)
    if (eps_top is None) == (eps is None):
        raise ValueError("eps_top: give exactly one of eps_top and eps")
    name, given = ("eps_top", eps_top) if eps is None else ("eps", eps)
    given = finite_scalar(name, given, low=0.0, low_open=True)
    if given >= math.pi:
        raise ValueError(f"{name} must be in (0, pi), got {given:g}")
    last = {}

    def f(x):                                           # keeps each solve for the final state
        e, et = (x, given) if eps is None else (given, x)
        r, last[x] = _residual_pieces(e, et, M, th, gb, n, ar)
        return r
    hi = math.pi - given - SCAN_GAP
    x0 = float(guess) if guess is not None else 0.5 * (math.pi - given)
    x1 = x0 * (1 + 1e-4)
    f0, f1 = f(x0), f(x1)
    for _ in range(40):                                 # secant: one residual per step
        if f1 == f0:
            break
        x2 = min(max(x1 - f1 * (x1 - x0) / (f1 - f0), 0.5 * x1), 0.5 * (x1 + hi))
        x0, f0, x1 = x1, f1, x2
        if abs(x1 - x0) <= tol * x1:
            break
        f1 = f(x1)
    else:
        raise ValueError(f"guess: no two-patch equilibrium found near {x1!r}")
    x = x0                                              # the last evaluated iterate, |x1 - x0| <= tol x
    if not abs(f0) < 1e-8:
        raise ValueError(f"guess: no two-patch equilibrium found near {x!r}")
    e, et = (x, given) if eps is None else (given, x)
    lin = last[x]
    return fixed_arcs(e, et, _delta(lin, M), M, th, gb, n, lin=lin, alpha_ratio=ar)


# --- stability ------------------------------------------------------------------------------------
def hessian(eps, eps_top, delta_over_Delta, M, theta, gb, n=N_NODES, h=1e-6, alpha_ratio=0.0, lin=None):
    """3x3 Hessian of Pi* in (eps, eps_top, delta/Delta) at fixed load (the last row/column drops at fixed grip),
    and the gradient of P* in the same variables.

    d Pi*/d eps_i = 2 vartheta (pi^2 k_i^2 - M^2), d Pi*/d delta = P* - P*_applied, so the entries are
    4 vartheta pi^2 k_i dk_i/d eps_j (central differences at fixed delta), 4 vartheta pi^2 k_i k1_i and
    dP*/d delta = q1[P].  The eps block is symmetrised (Maxwell; the asymmetry is a check in the tests).
    lin: the fixed-arc pieces at (eps, eps_top) if already computed (e.g. the state's own).
    Returns (H, He, gP): He the unsymmetrised eps block, gP = (dP*/d eps, dP*/d eps_top, dP*/d(delta/Delta)).
    """
    d = delta_over_Delta
    ar = alpha_ratio
    pick = [2, 3, 0]                                          # k_bot, k_top, P* of the fixed-arc pieces
    kP = lambda e, et: (lambda L: L.q0[pick] + d * L.q1[pick])(_linear(e, et, theta, gb, n, ar))
    lin = _linear(eps, eps_top, theta, gb, n, ar) if lin is None else lin
    kk = lin.q0[2:4] + d * lin.q1[2:4]
    dkP = np.zeros((3, 2))
    h0, h1 = min(h, 0.1 * eps), min(h, 0.1 * eps_top)        # relative steps near an axis
    dkP[:, 0] = (kP(eps + h0, eps_top) - kP(eps - h0, eps_top)) / (2 * h0)
    # eps_top = 0: the single arc; the top row/column is decoupled (set to the identity)
    if eps_top > 0:
        dkP[:, 1] = (kP(eps, eps_top + h1) - kP(eps, eps_top - h1)) / (2 * h1)
    dk = dkP[:2]
    c = 4 * theta * math.pi ** 2
    H = np.empty((3, 3))
    He = c * kk[:, None] * dk
    H[:2, :2] = 0.5 * (He + He.T)
    H[:2, 2] = H[2, :2] = c * kk * lin.q1[2:4]
    H[2, 2] = lin.q1[0]
    if eps_top == 0:
        H[1, :] = H[:, 1] = 0.0
        H[1, 1] = 1.0
    return H, He, np.array([dkP[2, 0], dkP[2, 1], lin.q1[0]])


def _positive_definite(H):
    return bool(np.all(np.linalg.eigvalsh(H) > 0))


def stability(eps, eps_top, delta_over_Delta, M, theta, gb, n=N_NODES, alpha_ratio=0.0, lin=None):
    """(stable_load, stable_grip, stable_grip_work): second variations of the total potential.

    Pi* uses the elastic energy U* = [(1 + delta/Delta) P* - B*]/2 of the paper's approach delta; the true elastic
    energy adds the pin's own n = 1 field, (c/2) P*^2 with c = (gb/2) vartheta, the step from delta/Delta to the
    work-conjugate delta_work/Delta = delta/Delta + c P* (derive/green.py).  So, in (eps, eps_top, delta/Delta):

    * load: H + c gP gP^T positive definite (3x3; H alone misjudges where the paper's delta has a negative
      fixed-arc stiffness q1[P] < 0);
    * grip (the paper's delta held, as section 8): the eps block of H positive definite (2x2);
    * grip-work (delta_work held): H + c gP gP^T restricted to the directions that keep delta_work fixed
      (d delta = -c dP*), positive definite (2x2).
    """
    H, _, g = hessian(eps, eps_top, delta_over_Delta, M, theta, gb, n, alpha_ratio=alpha_ratio, lin=lin)
    cw = 0.5 * gb * (1.0 if math.isinf(theta) else theta)
    Ht = H + cw * np.outer(g, g)
    T = np.vstack([np.eye(2), -cw * g[:2] / (1.0 + cw * g[2])])       # (d eps, d eps_top) at fixed delta_work
    return _positive_definite(Ht), _positive_definite(H[:2, :2]), _positive_definite(T.T @ Ht @ T)


# --- branches -----------------------------------------------------------------------------------------
SCAN_TOP = (0.05, 0.3, 0.7, 1.2, 1.8, 2.5)    # eps_top rows scanned for branches not reached otherwise
SCAN_POINTS = 32
H_MAX = 10              # longest continuation step, in units of h0 (log half-angles)
SCAN_GAP = 0.1          # rows stop this far from full contact: with resolved gaps no branch hugs that line
                        # (F keeps one sign there, tending to 0 linearly in the gap; see the tests)


@dataclass(frozen=True)
class TwoPatchCurve:
    """One branch of two-patch equilibria, ordered along the curve (numpy arrays).

    Fields as :class:`jkrcyl.equilibria.Curve` (a, eps, eps_star, P_star, delta_over_Delta, feasible,
    stable_load, stable_grip; stable_grip_work: at fixed work-conjugate approach) plus a_top, eps_top,
    eps_top_star, gap_min (min h/Delta outside both arcs),
    G_bot, G_top (G/w, = 1 on the branch) and ``ends``: how each end finishes -- 'single' (a_top -> 0,
    the single-patch state with h(pi) = 0), 'mirror' (a -> 0, the upside-down single patch),
    'full' (eps + eps_top -> pi: runs into full contact) or 'loop' (closed curve).
    """

    M: float
    theta: float
    gb: float
    a: np.ndarray
    a_top: np.ndarray
    eps: np.ndarray
    eps_top: np.ndarray
    eps_star: np.ndarray
    eps_top_star: np.ndarray
    P_star: np.ndarray
    delta_over_Delta: np.ndarray
    gap_min: np.ndarray
    feasible: np.ndarray
    stable_load: np.ndarray
    stable_grip: np.ndarray
    stable_grip_work: np.ndarray
    G_bot: np.ndarray
    G_top: np.ndarray
    ends: tuple
    alpha_ratio: float = 0.0

    COLUMNS = ("a", "a_top", "eps", "eps_top", "eps_star", "eps_top_star", "P_star", "delta_over_Delta",
               "delta_work_over_Delta", "gap_min", "feasible", "stable_load", "stable_grip", "stable_grip_work")

    @property
    def delta_work_over_Delta(self):
        """Work-conjugate approach delta_work/Delta = delta/Delta + (gb/2) vartheta P* (derive/green.py)."""
        from .numerics import kernels
        return kernels.work_over_Delta(self.delta_over_Delta, self.P_star, theta=self.theta, gb=self.gb)

    def table(self, raw=False):
        """Columns of :attr:`COLUMNS` as a dict of arrays (booleans as 0/1; raw=True keeps them boolean)."""
        return {k: np.asarray(getattr(self, k)) if raw else np.asarray(getattr(self, k), dtype=float)
                for k in self.COLUMNS}

    def __repr__(self):
        return (f"TwoPatchCurve(M={self.M:.6g}, theta={self.theta:.6g}, {np.size(self.a)} points, ends "
                f"{self.ends[0]} -> {self.ends[1]}, {int(np.sum(self.stable_load))} stable under load)")


LOG_AXIS = math.log(EPS_AXIS)


def _domain(u):
    """Inside the traced region, in log half-angles u = (log eps, log eps_top)."""
    return u[0] >= LOG_AXIS and u[1] >= LOG_AXIS and math.exp(u[0]) + math.exp(u[1]) <= math.pi - GAP_FULL


# the boundaries in log half-angles: (label, g(u) >= 0 inside, grad g)
_BOUNDARIES = (
    ("single", lambda u: u[1] - LOG_AXIS, lambda u: np.array([0.0, 1.0])),        # a_top -> 0
    ("mirror", lambda u: u[0] - LOG_AXIS, lambda u: np.array([1.0, 0.0])),        # a -> 0
    ("full", lambda u: math.pi - GAP_FULL - math.exp(u[0]) - math.exp(u[1]),     # arcs meet
     lambda u: -np.exp(np.asarray(u))),
)


def _clipper(f):
    """Exit point of the curve between u (inside) and v (outside): on the first boundary crossed."""
    def clip(u, v):
        best = None
        for label, g, grad in _BOUNDARIES:
            if g(v) < 0 <= g(u):
                lo, hi = 0.0, 1.0                        # bisection for the crossing on the segment
                for _ in range(60):
                    mid = 0.5 * (lo + hi)
                    lo, hi = (mid, hi) if g(u + mid * (v - u)) >= 0 else (lo, mid)
                if best is None or lo < best[0]:
                    best = (lo, label, g, grad)
        if best is None:
            return None, "domain"
        s, label, g, grad = best
        z = u + s * (v - u)
        ok = False
        for _ in range(3):                               # along the boundary onto F = 0, then back onto it
            gz = grad(z)
            z, ok = _cont.project(f, z, direction=np.array([-gz[1], gz[0]]) / np.linalg.norm(gz))
            gz = grad(z)
            z = z - g(z) * gz / (gz @ gz)
        return (z if ok and abs(f(z)) < 1e-9 else None), label
    return clip


def _near(x, polylines, tol):
    """Is x within tol of one of the traced polylines (distance to their segments)?"""
    for p in polylines:
        a, b = p[:-1], p[1:]
        d = b - a
        t = np.clip(np.einsum("ij,ij->i", x - a, d) / np.maximum(np.einsum("ij,ij->i", d, d), 1e-300), 0, 1)
        if a.shape[0] and np.min(np.linalg.norm(a + t[:, None] * d - x, axis=1)) < tol:
            return True
    return False


def _crosses_row(polylines, row, lo, hi):
    """Does a traced polyline (log half-angles) cross the row u[1] = row with lo <= u[0] <= hi?"""
    for p in polylines:
        y0, y1 = p[:-1, 1] - row, p[1:, 1] - row
        for j in np.nonzero((y0 * y1 <= 0) & (y0 != y1))[0]:
            x = p[j, 0] + (p[j + 1, 0] - p[j, 0]) * y0[j] / (y0[j] - y1[j])
            if lo <= x <= hi:
                return True
    return False


def onset_angles(M, theta, gb=None, alpha_ratio=0.0, segments=None):
    """Half-angles eps where a single-patch equilibrium has h(pi) = 0 (sub- and super-critical branches).

    segments: the single-patch curves (jkrcyl.equilibria.Curve, one per regime) to scan, if already computed."""
    from . import equilibria as eq
    ar = alpha_ratio
    gb = eq.default_gb(theta) if gb is None else gb
    if segments is None:
        # alpha* != 0: each grid point is a collocation solve (numerics.arcs), so a coarser grid
        n = ONSET_GRID if ar == 0.0 else ONSET_GRID_ALPHA
        segments = [eq.curve(M, theta, regime, n=n, gb=gb, alpha_ratio=ar) for regime in eq.REGIMES]
    return [2 * math.atan(a) for a in _segment_roots(segments, "h_pi_over_Delta", M, theta, gb, ar)]


def _segment_roots(segments, field, M, theta, gb, ar):
    """Roots in a of a Curve field (sign changes on each curve's grid, refined by Brent on single points)."""
    from . import equilibria as eq
    from scipy.optimize import brentq
    out = []
    for c in segments:
        v = getattr(c, field)
        f = lambda x: float(getattr(eq.curve(M, theta, c.regime, a=np.array([x]), gb=gb, alpha_ratio=ar), field)[0])
        for i in np.nonzero(np.sign(v[:-1]) * np.sign(v[1:]) < 0)[0]:
            out.append(brentq(f, c.a[i], c.a[i + 1], xtol=1e-16, rtol=1e-15))
    return sorted(out)


ONSET_GRID = 600          # h(pi) sign changes along each single-patch branch
ONSET_GRID_ALPHA = 200


def _trace_both(f, clip, x0, t0, h0):
    """Trace from x0 in direction t0 and, unless that closes a loop, in the opposite direction; join."""
    fw = _cont.trace(f, x0, t0, _domain, clip, h0=h0, h_max=H_MAX * h0)
    if fw.end == "loop":
        return fw.points, ("loop", "loop")
    bw = _cont.trace(f, x0, -np.asarray(t0, float), _domain, clip, h0=h0, h_max=H_MAX * h0)
    pts = np.vstack([bw.points[::-1], fw.points[1:]])
    return pts, (bw.boundary or bw.end, fw.boundary or fw.end)


def branches(M, theta, gb=None, n=None, nodes=N_NODES, h0=0.05, alpha_ratio=0.0, onsets=None):
    """Every branch of two-patch equilibria at (M, vartheta): a list of :class:`TwoPatchCurve`.

    n: points per branch, equally spaced in arclength in the half-angle plane (default: the continuation
    steps); nodes: collocation nodes per arc (alpha* != 0: at least N_NODES_ALPHA); alpha_ratio = alpha*/beta*;
    onsets: the half-angles of :func:`onset_angles` if already known.

    Starts: each single-patch onset h(pi) = 0 (a_top -> 0), its mirror (a -> 0), then the roots of F along
    the rows eps_top in SCAN_TOP (curves touching neither axis: loops, branches ending in full contact).
    """
    M, th, gb, ar = _params(M, theta, gb, alpha_ratio)
    if n is not None:
        n = int(finite_scalar("n", n, low=4))
    # traced in u = log(half-angles): branches span scales from EPS_AXIS to pi (they hug the axes near the
    # onsets and may run into the corner of two small arcs); clamped so that stray Newton iterates stay evaluable
    lo, hi = 0.1 * EPS_AXIS, math.pi - 0.1 * GAP_FULL
    fx = lambda x: residual(max(x[0], lo), max(x[1], lo), M, th, gb, nodes, ar) if x[0] + x[1] < hi else math.nan
    f = lambda u: fx(np.exp(np.minimum(u, 1.2)))      # exp(1.2) > pi: stray iterates give nan, not overflow
    clip = _clipper(f)
    found = []          # (points in u, ends)
    for e in (onset_angles(M, th, gb, ar) if onsets is None else onsets):
        for k, label in ((0, "single"), (1, "mirror")):     # a_top -> 0 at the onset, a -> 0 at its mirror
            u0 = np.full(2, LOG_AXIS)
            u0[k] = math.log(e)
            along = np.eye(2)[k]
            u, ok = _cont.project(f, u0, direction=along)
            if not ok or not _domain(u) or _near(u, [p for p, _ in found], 2 * h0):
                continue
            path = _cont.trace(f, u, np.eye(2)[1 - k], _domain, clip, h0=h0, h_max=H_MAX * h0)
            found.append((np.vstack([u, path.points[1:]]), (label, path.boundary or path.end)))
    for et in SCAN_TOP:
        top = math.pi - et - SCAN_GAP
        if top <= 0.05:
            continue
        es = np.linspace(1e-3, top, SCAN_POINTS)
        v = np.array([fx(np.array([e, et])) for e in es])
        for i in np.nonzero(np.sign(v[:-1]) * np.sign(v[1:]) < 0)[0]:
            if _crosses_row([p for p, _ in found], math.log(et), math.log(es[i]), math.log(es[i + 1])):
                continue                                # a traced branch already passes through this bracket
            u, ok = _cont.project(f, np.log([0.5 * (es[i] + es[i + 1]), et]), direction=np.array([1.0, 0.0]))
            if not ok or not _domain(u) or _near(u, [p for p, _ in found], 2 * h0):
                continue
            pts, ends = _trace_both(f, clip, u, np.array([0.0, 1.0]), h0)
            found.append((pts, ends))
    found = [(np.exp(p), ends) for p, ends in found]
    f = fx
    found = [(p if n is None else _resample(f, p, n), ends) for p, ends in found if len(p) >= 4]
    return [_curve(p, ends, M, th, gb, nodes, ar) for p, ends in found]


def _resample(f, points, n):
    """n points equally spaced in arclength along the traced polyline, each projected back onto F = 0."""
    seg = np.linalg.norm(np.diff(points, axis=0), axis=1)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    t = np.linspace(0.0, s[-1], n)
    out = np.column_stack([np.interp(t, s, points[:, 0]), np.interp(t, s, points[:, 1])])
    for i in range(1, n - 1):                      # the ends are exact already
        d = points[min(np.searchsorted(s, t[i]), len(points) - 1)] - points[max(np.searchsorted(s, t[i]) - 1, 0)]
        normal = np.array([-d[1], d[0]]) / (np.linalg.norm(d) or 1.0)
        y, ok = _cont.project(f, out[i], direction=normal)
        if ok:
            out[i] = y
    return out


def _curve(points, ends, M, th, gb, n, ar=0.0):
    from .equilibria import _ac
    states = [equilibrium_state(e, et, M, th, gb, n, ar) for e, et in points]
    stab = np.array([stability(s.eps, s.eps_top, s.delta_over_Delta, M, th, gb, n, ar, lin=s._lin) for s in states])
    ac = _ac(th, gb, ar)
    arr = lambda k: np.array([getattr(s, k) for s in states])
    a, at = np.tan(points[:, 0] / 2), np.tan(points[:, 1] / 2)
    return TwoPatchCurve(M=M, theta=th, gb=gb, a=a, a_top=at, eps=points[:, 0], eps_top=points[:, 1],
                         eps_star=2 * np.arctan(a / ac) / math.pi, eps_top_star=2 * np.arctan(at / ac) / math.pi,
                         P_star=arr("P_star"), delta_over_Delta=arr("delta_over_Delta"), gap_min=arr("gap_min"),
                         feasible=arr("gap_min") >= -1e-9, stable_load=stab[:, 0], stable_grip=stab[:, 1],
                         stable_grip_work=stab[:, 2],
                         G_bot=arr("G_bot"), G_top=arr("G_top"), ends=tuple(ends), alpha_ratio=ar)


# --- full contact -------------------------------------------------------------------------------------
@dataclass(frozen=True)
class FullContact:
    """The pin in contact all round (eps + eps_top = pi): n(phi) = N0 + N1 cos(phi), no edge, no Griffith.

    P_star = pi N1, B_star = 2 pi N0; energy U* = [(1 + delta/Delta) P* - B*]/2 as for the arcs;
    tension_everywhere: n < 0 all round (|P*| < -pi N0, = 1 at alpha* = 0).
    """

    theta: float
    gb: float
    P_star: float
    delta_over_Delta: float
    N0: float
    N1: float
    alpha_ratio: float = 0.0

    @property
    def B_star(self):
        return 2 * math.pi * self.N0

    @property
    def energy(self):
        return 0.5 * ((1 + self.delta_over_Delta) * self.P_star - self.B_star)

    @property
    def tension_everywhere(self):
        return abs(self.N1) < -self.N0

    def pressure(self, phi):
        return self.N0 + self.N1 * np.cos(np.asarray(phi, dtype=float))

    def in_tension(self, phi):
        """Where the interface is in tension (n < 0) at the angles phi: for P* > 0 where cos(phi) < -N0/N1
        (the top and the sides), for P* < 0 where cos(phi) > N0/|N1| (the bottom and the sides)."""
        return self.pressure(phi) < 0

    @property
    def tension_half_angle(self):
        """The tensile zone as a half-angle about phi = pi (P* > 0) or phi = 0 (P* < 0): pi if the whole
        circle is in tension, 0 if none of it is (n >= 0 everywhere needs N0 >= |N1|, impossible for N0 < 0)."""
        if self.tension_everywhere:
            return math.pi
        return math.pi - math.acos(min(1.0, -self.N0 / abs(self.N1)))


def _full_contact_law(theta, gb, ar=0.0):
    """(N0, c) with n = N0 + N1 cos(phi) and delta/Delta = -1 + c P* in full contact.

    The kernel K(t) = cos t log(2 - 2 cos t) + k1 cos t + k0 + ar (pi sin|t| - t sin t) of (5.2)
    (numerics.arcs.Kernel, any alpha*) is a convolution on the circle, so the modes 1 and cos(phi) of the
    right-hand side (delta/Delta) cos(phi) - (1 - cos(phi)) are answered mode by mode (nu = vartheta n):
    int K dt = 2 pi (k0 - 1 + ar) (= -pi/vartheta + 2 pi ar) and int K cos(t) dt = pi (k1 - 1/2 + ar/2),
    so N0 = 1/(vartheta int K dt) = -1/(pi (1 - 2 vartheta ar)) and delta/Delta + 1 = -vartheta (k1 - 1/2 + ar/2) P*
    (the constants k0, k1 are the engine's, so the law follows its definition of delta; at alpha* = 0,
    k1 = gb: c = 0 is the identical-material degeneracy gb = 1/2).
    tests/test_twopatch.py checks both integrals by quadrature and the law as the limit of closing gaps.
    """
    kn = _arcs.Kernel(theta, gb, ar)
    mode0 = 2 * math.pi * (kn.k0 - 1.0 + kn.ar)
    mode1 = math.pi * (kn.k1 - 0.5 + 0.5 * kn.ar)
    return 1.0 / (theta * mode0), -theta * mode1 / math.pi


def full_contact(theta, P_star=None, delta_over_Delta=None, gb=None, alpha_ratio=0.0):
    """Full contact at a given load P* or approach delta/Delta (exactly one of them); alpha_ratio = alpha*/beta*."""
    from .equilibria import default_gb
    th = _check_theta(theta)
    if math.isinf(th):
        raise ValueError("theta: full contact needs a finite vartheta (n and P* normalise by vartheta)")
    gb = default_gb(th) if gb is None else finite_scalar("gb", gb, low=0.0)
    ar = _alpha_ratio(alpha_ratio, th)
    if (P_star is None) == (delta_over_Delta is None):
        raise ValueError("P_star: give exactly one of P_star and delta_over_Delta")
    N0, c = _full_contact_law(th, gb, ar)
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
    return FullContact(theta=th, gb=gb, P_star=P, delta_over_Delta=d, N0=N0, N1=P / math.pi, alpha_ratio=ar)


# --- confined-regime events ---------------------------------------------------------------------------
REGIMES = {
    "detachment": "the fixed-load adherence point comes first (gap at pi still open) and a further pull makes "
                  "G > w: the contact shrinks, the pin leaves the bottom and, in the hole, lands on the top "
                  "(the mirrored single patch at the same load)",
    "zip-full": "the fixed-load adherence point comes first, but there a further pull makes G < w: the "
                "contact grows past h(pi) = 0 and zips round into full contact (no detachment)",
    "snap-in-full": "the gap closes at pi first; the two-patch state growing from there is unstable under "
                    "load: the top contact snaps in and the path runs into full contact",
    "snap-in-transfer": "the gap closes at pi first; the two-patch branch is unstable under load and leads to "
                        "the mirrored single patch (the pin is transferred to the top)",
    "two-patch": "the gap closes at pi first and a two-patch state stable under load follows",
    "no-path": "no stable single-patch state to start from (no stable, feasible equilibrium at any load)",
}


@dataclass(frozen=True)
class ConfinedEvents:
    """What happens to the pin under slow upward loading (load control) at (M, vartheta).

    regime: a key of :data:`REGIMES`; start: (a, P*) where the load path starts (the stable zero-load
    contact, else the stable state of largest P*); P_fold: P* at the fixed-load adherence point met first
    (nan if the gap closes first); P_top_contact: P* at which the top contact forms on that path (nan if
    the fold comes first); onsets: every single-patch state with h(pi) = 0 as (eps, P*, delta/Delta,
    stable under load); grip_detachment: a feasible fixed-grip stationary point (min of delta) before
    the gap closes, i.e. the pin can be held free in the hole (true detachment under grip control);
    two_patch_stable_load / _grip: any two-patch state stable under load / grip; full_contact: some
    two-patch branch runs into full contact; branches: the :class:`TwoPatchCurve` list; gb, alpha_ratio:
    the compliance ratio and alpha*/beta* of the analysis (the full-contact law in :attr:`summary`).
    """

    M: float
    theta: float
    regime: str
    start: tuple
    P_fold: float
    P_top_contact: float
    onsets: tuple
    grip_detachment: bool
    two_patch_stable_load: bool
    two_patch_stable_grip: bool
    full_contact: bool
    branches: tuple
    gb: float = None            # (1/G_I)/beta* and alpha*/beta* of the analysis (the full-contact law)
    alpha_ratio: float = 0.0

    def __repr__(self):
        return (f"ConfinedEvents({self.regime}: M={self.M:.6g}, theta={self.theta:.6g}, P_fold={self.P_fold:.6g}, "
                f"P_top_contact={self.P_top_contact:.6g}, {len(self.branches)} two-patch branches)")

    @property
    def description(self):
        return REGIMES[self.regime]

    @property
    def summary(self):
        """One line: the event, its load and what follows (no true detachment under load control in a hole)."""
        if self.regime == "detachment":
            return (f"fixed-load detachment at P* = {self.P_fold:.6g}; the pin lands on the top of the hole "
                    f"(transfer); held at fixed grip it can be freed: {self.grip_detachment}")
        if self.regime == "zip-full":
            fc = full_contact(self.theta, P_star=self.P_fold, gb=self.gb, alpha_ratio=self.alpha_ratio)
            fc = "entirely in tension" if fc.tension_everywhere else "partly compressed"
            return (f"fold at P* = {self.P_fold:.6g}; the contact grows into full contact ({fc} there); "
                    f"no detachment under load")
        if self.regime == "no-path":
            return REGIMES[self.regime]
        return f"top contact forms at P* = {self.P_top_contact:.6g}: {REGIMES[self.regime]}"


def _segments(M, th, gb, ar=0.0):
    """The single-patch branches on the load-path grid (jkrcyl.equilibria.curve, one per regime)."""
    from . import equilibria as eq
    n = LOAD_PATH_GRID if ar == 0.0 else LOAD_PATH_GRID_ALPHA
    return [eq.curve(M, th, regime, n=n, gb=gb, alpha_ratio=ar) for regime in eq.REGIMES]


def _load_path(M, th, gb, ar=0.0, segs=None):
    """Stable, feasible single-patch states and the first event when P* decreases from the start."""
    from . import equilibria as eq
    segs = _segments(M, th, gb, ar) if segs is None else segs
    if ar == 0.0:
        a0s = eq.zero_load_contact(M, th)
    else:               # (8.1) is the alpha* = 0 zero-load law: the solver's roots of P* = 0 on the same grid
        a0s = _segment_roots(segs, "P_star", M, th, gb, ar)
    start = None
    for c in segs:
        ok = c.stable_load & c.feasible
        for x in a0s:
            i = int(np.searchsorted(c.a, x))
            if 0 < i < c.a.size and ok[i - 1] and ok[min(i, c.a.size - 1)]:
                start = (c, i)
    if start is None:
        best = None
        for c in segs:
            ok = np.nonzero(c.stable_load & c.feasible)[0]
            if ok.size and (best is None or c.P_star[ok].max() > best[0]):
                best = (c.P_star[ok].max(), c, int(ok[np.argmax(c.P_star[ok])]))
        if best is None:
            return None
        start = best[1:]
    c, i = start
    step = -1 if i > 0 and c.P_star[i - 1] < c.P_star[i] else 1     # the direction of decreasing P*
    j = i
    while 0 <= j + step < c.a.size:
        k = j + step
        if not c.feasible[k]:
            return c, i, "top", j
        if not c.stable_load[k] or c.P_star[k] >= c.P_star[j]:
            return c, i, "fold", j
        j = k
    return c, i, "none", j


LOAD_PATH_GRID = 3000        # points per single-patch branch on which the load path is followed
LOAD_PATH_GRID_ALPHA = 800   # alpha* != 0: one collocation solve per point


def _local_min_P(a_lo, a_hi, M, th, gb, n, ar):
    """min of P* over single arcs with a_lo <= a <= a_hi (bounded Brent in eps; Griffith k = M/pi)."""
    from scipy.optimize import minimize_scalar

    def P(eps):
        lin = _linear(eps, 0.0, th, gb, n, ar)
        return float(lin.q0[0] + (M / math.pi - lin.q0[2]) / lin.q1[2] * lin.q1[0])
    lo, hi = 2 * math.atan(a_lo), 2 * math.atan(a_hi)
    if not hi > lo:
        return P(lo)
    return float(minimize_scalar(P, bounds=(lo, hi), method="bounded", options={"xatol": 1e-12 * hi}).fun)


def _grows_under_pull(eps, th, gb, n, ar=0.0):
    """At fixed single arc eps: does a lower P* lower G (dG/dP* > 0), so that the contact grows?

    G is proportional to k^2 with k = k0 + d k1 and P* = P0 + d P1 along the approach d: dG/dP* ~ k k1/P1.
    """
    lin = _linear(eps, 0.0, th, gb, n, ar)
    return lin.q1[2] / lin.q1[0] > 0


def confined_events(M, theta, gb=None, n=N_NODES, alpha_ratio=0.0):
    """Classify the confined regime at (M, vartheta): see :class:`ConfinedEvents` and :data:`REGIMES`.

    alpha_ratio = alpha*/beta* != 0: every single-patch quantity from the solver (jkrcyl.numerics.arcs).
    Cached per (M, vartheta, gb, n, alpha_ratio) after validation (the result is immutable; tracing takes seconds)."""
    return _confined_events(*_params(M, theta, gb, alpha_ratio), n)


@functools.lru_cache(maxsize=32)
def _confined_events(M, th, gb, ar, n):
    segs = _segments(M, th, gb, ar)
    # alpha* = 0: the onsets on their own grid (closed form, cheap); otherwise on the load path's curves
    on = onset_angles(M, th, gb, ar, segments=None if ar == 0.0 else segs)
    bs = tuple(branches(M, th, gb, nodes=n, alpha_ratio=ar, onsets=on))
    onsets = []
    from . import equilibria as eq
    ac = eq._ac(th, gb, ar)
    for e in on:
        a = math.tan(e / 2)
        regime = "sub-critical" if a < ac else "super-critical"
        c = eq.curve(M, th, regime, a=np.array([a]), gb=gb, alpha_ratio=ar)
        onsets.append((e, float(c.P_star[0]), float(c.delta_over_Delta[0]), bool(c.stable_load[0])))
    path = _load_path(M, th, gb, ar, segs)
    grip_pts = [p for p in eq.adherence(M, th, "grip", gb=gb, alpha_ratio=ar) if p.kind == "min" and p.feasible]
    any_load = any(b.stable_load.any() for b in bs)
    any_grip = any(b.stable_grip.any() for b in bs)
    full = any("full" in b.ends for b in bs)
    nan = math.nan
    if path is None:
        return ConfinedEvents(M, th, "no-path", (nan, nan), nan, nan, tuple(onsets), bool(grip_pts), any_load,
                              any_grip, full, bs, gb, ar)
    c, i, event, j = path
    start = (float(c.a[i]), float(c.P_star[i]))
    if event in ("fold", "none"):
        P_fold = float(c.P_star[j])
        if ar == 0.0:
            pts = eq.stationary_points(M, th, "load", c.regime, gb=gb, alpha_ratio=ar)
            if pts:                                 # the exact P* minimum next to the grid point
                P_fold = min(pts, key=lambda p: abs(p.a - c.a[j])).P_star
        else:       # the solver's stationary points cost a root grid over the whole branch: refine locally
            P_fold = min(P_fold, _local_min_P(c.a[max(j - 1, 0)], c.a[min(j + 1, c.a.size - 1)], M, th, gb, n, ar))
        regime = "zip-full" if _grows_under_pull(float(c.eps[j]), th, gb, n, ar) else "detachment"
        return ConfinedEvents(M, th, regime, start, P_fold, nan, tuple(onsets), bool(grip_pts), any_load,
                              any_grip, full, bs, gb, ar)
    P_on = float(c.P_star[j])
    e_on = float(c.eps[j])
    near = [b for b in bs if abs(b.eps[0] - e_on) < 0.05 and b.eps_top[0] < 1e-3 and b.ends[0] == "single"]
    if near and near[0].stable_load[:3].any():
        regime = "two-patch"
    elif near and near[0].ends[1] == "full":
        regime = "snap-in-full"
    else:
        regime = "snap-in-transfer"
    return ConfinedEvents(M, th, regime, start, nan, P_on, tuple(onsets), bool(grip_pts), any_load, any_grip,
                          full, bs, gb, ar)


# --- figure: load-approach paths through the confined regime ------------------------------------------
FIGURE_MS = (0.3, 0.4, 0.5, 0.8)
# series: (label, colour, marker) -- viridis at strictly ordered luminance (dark, mid, light) plus a marker,
# so the families stay apart in greyscale; the line style carries stability (below)
_SERIES = (("single patch, bottom", 0.0, "o"), ("single patch, top (mirror)", 0.42, "s"),
           ("two patches", 0.78, "^"))
_STABILITY = (("-", 1.6, "stable under load (and grip)"), ("--", 1.2, "stable under grip only"),
              (":", 1.4, "unstable"))
_INFEASIBLE = "0.82"      # light grey, thin: the gap inequality h >= 0 fails


def draw_confined(path, Ms=FIGURE_MS, theta=1.0, gb=None):
    """docs/confined.png (``jkrcyl two-patch --figure docs/confined.png``): P* against delta/Delta for each
    M -- single patch at the bottom and (mirrored) at the top, two-patch branches, full contact -- solid where
    stable under load, dashed where stable only under grip, dotted where unstable, light grey where the gap
    inequality fails; the load path's start (o), its event (x: fold; diamond: gap closes at pi) and the
    jump at fixed load (arrow).  alpha* = 0 (closed-form single patch).  Returns the path."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from . import equilibria as eq
    th = _check_theta(theta)
    gb = eq.default_gb(th) if gb is None else finite_scalar("gb", gb, low=0.0)
    cmap = plt.get_cmap("viridis")
    colour = {lab: cmap(x) for lab, x, _ in _SERIES}
    marker = {lab: m for lab, _, m in _SERIES}
    Ms = [finite_scalar("M", M, low=0.0, low_open=True) for M in Ms]
    fig, axs = plt.subplots(1, len(Ms), figsize=(3.9 * len(Ms), 4.6), sharey=True, squeeze=False)
    axs = axs[0]
    for ax, M in zip(axs, Ms):
        ev = confined_events(M, th, gb)
        for regime in eq.REGIMES:
            c = eq.curve(M, th, regime, n=1500, gb=gb)
            for sign, lab in ((1, _SERIES[0][0]), (-1, _SERIES[1][0])):
                d = c.delta_over_Delta if sign == 1 else -2 - c.delta_over_Delta
                _styled(ax, d, sign * c.P_star, c.stable_load, c.stable_grip, c.feasible, colour[lab], marker[lab])
        for b in ev.branches:
            lab = _SERIES[2][0]
            _styled(ax, b.delta_over_Delta, b.P_star, b.stable_load, b.stable_grip, b.feasible, colour[lab],
                    marker[lab])
        fc = [full_contact(th, P_star=p, gb=gb) for p in (-3.0, 3.0)]
        ax.plot([f.delta_over_Delta for f in fc], [f.P_star for f in fc], color="k", ls="-.", lw=1)
        for e, P, d, _ in ev.onsets:
            ax.plot([d, -2 - d], [P, -P], "kD", ms=4.5, mfc="w")
        _mark_jump(ax, ev, M, th, gb)
        ax.set_xlim(-2.8, 0.8)
        ax.set_ylim(-2.0, 2.0)
        ax.axhline(0, color="0.9", lw=0.5, zorder=0)
        ax.set_title(f"$M = {M:g}$: {ev.regime}", fontsize=10)
        ax.set_xlabel("$\\delta/\\Delta$")
    axs[0].set_ylabel("$P^*$")
    handles = [Line2D([], [], color=colour[lab], marker=m, mfc="none", ls="none", label=lab) for lab, _, m in _SERIES]
    handles += [Line2D([], [], color="k", ls="-.", lw=1, label="full contact")]
    handles += [Line2D([], [], color="k", ls=ls, lw=lw, label=txt) for ls, lw, txt in _STABILITY]
    handles += [Line2D([], [], color=_INFEASIBLE, lw=2, label="gap $h < 0$ somewhere (infeasible)")]
    handles += [Line2D([], [], color="k", marker="o", ls="none", ms=5, label="start: zero-load contact"),
                Line2D([], [], color="k", marker="x", ls="none", ms=7, label="fold at fixed load (adherence)"),
                Line2D([], [], color="k", marker="D", mfc="w", ls="none", ms=5, label="gap closes at $\\phi = \\pi$"),
                Line2D([], [], color="k", marker=r"$\rightarrow$", ls="none", ms=12, label="jump at fixed load")]
    fig.legend(handles=handles, loc="lower center", ncol=6, fontsize=7.5, frameon=False)
    fig.suptitle(f"Load-approach paths through the confined regime: $\\vartheta = {th:g}$, "
                 f"$(1/G_I)/\\beta^* = {gb:.4g}$, $\\alpha^*/\\beta^* = 0$", fontsize=11)
    fig.tight_layout(rect=(0, 0.1, 1, 1))
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def _styled(ax, x, y, load, grip, feasible, color, marker=None):
    """One series: the stability styles where feasible (+ sparse markers), light grey where infeasible."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    for (style, lw, _), mask in zip(_STABILITY, (feasible & load, feasible & grip & ~load, feasible & ~grip & ~load)):
        ax.plot(np.where(mask, x, np.nan), np.where(mask, y, np.nan), ls=style, color=color, lw=lw)
    ax.plot(np.where(~feasible, x, np.nan), np.where(~feasible, y, np.nan), "-", color=_INFEASIBLE, lw=0.8, zorder=0)
    if marker is not None:           # markers on the feasible part, about every 0.6 in delta/Delta-P* distance
        ok = feasible & (np.abs(y) <= 2.0) & (x >= -2.8) & (x <= 0.8)
        if ok.any():
            xs, ys = x[ok], y[ok]
            s = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(xs), np.diff(ys)))])
            k = np.unique(np.searchsorted(s, np.arange(0.3, s[-1], 0.6)).clip(0, xs.size - 1))
            ax.plot(xs[k], ys[k], ls="none", marker=marker, mfc="none", color=color, ms=4.5)


def _mark_jump(ax, ev, M, th, gb):
    """The load path: start (o), the event (x) and the jump at fixed load (arrow)."""
    from . import equilibria as eq
    ax.plot(*_state_of(ev.start[0], M, th, gb), "ko", ms=4.5)
    if ev.regime in ("detachment", "zip-full"):
        pts = [p for r in eq.REGIMES for p in eq.stationary_points(M, th, "load", r, gb=gb)
               if abs(p.P_star - ev.P_fold) < 1e-9]
        if not pts:
            return
        x0, P = pts[0].delta_over_Delta, pts[0].P_star
        if ev.regime == "zip-full":
            x1 = full_contact(th, P_star=P, gb=gb).delta_over_Delta
        else:
            a = eq.solve_load(M, th, -P, gb=gb)               # the mirrored single patch at the same load
            ok = [x for x in a if eq.curve(M, th, a=np.array([x]), gb=gb).stable_load[0]]
            x1 = -2 - float(eq.curve(M, th, a=np.array([ok[-1]]), gb=gb).delta_over_Delta[0]) if ok else x0
        ax.plot([x0], [P], "kx", ms=7)
        ax.annotate("", xy=(x1, P), xytext=(x0, P), arrowprops=dict(arrowstyle="->", color="k", lw=1),
                    annotation_clip=False)


def _state_of(a, M, th, gb):
    from . import equilibria as eq
    regime = "sub-critical" if a < eq._a_crit(th) else "super-critical"
    c = eq.curve(M, th, regime, a=np.array([a]), gb=gb)
    return [float(c.delta_over_Delta[0])], [float(c.P_star[0])]
