"""Two contact arcs and full contact: the pin after the gap closes at phi = pi (issue 12; paper sections 5, 6, 8.2).

Bottom arc |phi| < eps (a = tan(eps/2)), top arc |phi - pi| < eps_top (a_top = tan(eps_top/2)).  On both arcs
the pin and the hole touch, so the relative radial displacement is the rigid one (5.1),
``v_r - u_r = delta cos(phi) - Delta (1 - cos(phi))`` -- the same formula on both arcs, with one approach delta.
Normalised as in section 6 (n = N R beta*/(4 pi Delta vartheta), so P* = int n cos(phi) dphi, B* = int n dphi),
everything is linear in delta for fixed arcs: the engine (jkrcyl.numerics.arcs) returns, for each arc end, the
edge coefficient k of n ~ -k/sqrt(distance to the end in rad), as k = k0 + (delta/Delta) k1.

Griffith (3.5)-(3.6) at an end reads G/w = (pi k/M)^2 = 1, i.e. k = M/pi at both ends (checked against the
closed form (4.4)).  Eliminating delta leaves ONE scalar equation in the half-angles,

    F(eps, eps_top) = (k0_bot - M/pi) k1_top - (k0_top - M/pi) k1_bot = 0,

whose zero set -- curves in the (eps, eps_top) plane -- is the set of two-patch equilibria; they are traced by
pseudo-arclength continuation (jkrcyl.numerics.continuation).

Energy (per unit length, in units 4 pi Delta^2 vartheta/beta*): U* = [(1 + delta/Delta) P* - B*]/2, half the
work of the pressure on the rigid overlap (5.1).  Then dU*/d(delta/Delta) = P* (load and approach conjugate)
and dU*/d eps = 2 vartheta pi^2 k_bot^2 = 2 vartheta M^2 G/w (energy release at fixed grip), which the tests
check by finite differences.  Stability: the total potential Pi* = U* - 2 vartheta M^2 (eps + eps_top)
(minus P* delta/Delta under load control) must be a minimum: under grip the 2x2 Hessian in (eps, eps_top),
under load the 3x3 Hessian in (eps, eps_top, delta/Delta) must be positive definite.

Mirror: turning the picture upside down (phi -> phi + pi) swaps the arcs and maps
P* -> -P*, delta/Delta -> -2 - delta/Delta (the operator only depends on phi - psi).

Full contact (eps + eps_top = pi): no edge, no Griffith condition; n = N0 + N1 cos(phi) all round
(jkrcyl.numerics.green, H2's closed form), N0 = -1/pi: the interface is in tension wherever |P*| < 1.
"""
import math
from dataclasses import dataclass

import numpy as np

from ._validate import finite_scalar, theta as _check_theta
from .numerics import continuation as _cont

N_NODES = 24            # collocation nodes per arc (spectral: 1e-12 at moderate arcs, see tests)
EPS_AXIS = 1e-7         # smallest half-angle traced: a branch reaching it ends on the single-patch state
GAP_FULL = 2e-3         # eps + eps_top >= pi - GAP_FULL: the branch has run into full contact
GAP_SAMPLES = 400       # exterior angles per state for the dense gap check h >= 0

_ENGINE = None


def _engine():
    """The one numerical engine for contact arcs (H3's jkrcyl.numerics.arcs), via this adapter only."""
    global _ENGINE
    if _ENGINE is None:
        from .numerics import arcs
        _ENGINE = arcs.two_patch_linear
    return _ENGINE


def _linear(eps, eps_top, theta, gb, n):
    """Affine pieces at fixed arcs: q0, q1 = [P*, B*, k_bot, k_top] for (Delta-case, unit delta/Delta)."""
    return _engine()(eps, eps_top, theta, gb, n)


# --- residual, one equilibrium -----------------------------------------------------------------------
def _residual_pieces(eps, eps_top, M, theta, gb, n):
    lin = _linear(eps, eps_top, theta, gb, n)
    q0, q1 = lin.q0, lin.q1
    m = M / math.pi
    D = (q0[2] - m) * q1[3] - (q0[3] - m) * q1[2]
    return D / math.hypot(q1[2], q1[3]), lin


def residual(eps, eps_top, M, theta, gb, n=N_NODES):
    """F(eps, eps_top) scaled by |k1|: zero exactly at the two-patch equilibria (distance-like, units of k)."""
    return _residual_pieces(eps, eps_top, M, theta, gb, n)[0]


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
    gap_min = min h/Delta over GAP_SAMPLES exterior angles; feasible = gap_min >= 0.
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
        return fixed_arcs(self.eps_top, self.eps, -2.0 - self.delta_over_Delta, self.M, self.theta, self.gb)


def exterior_angles(eps, eps_top, k=GAP_SAMPLES):
    """k angles in the open gap eps < phi < pi - eps_top, clustered at both ends (Chebyshev points)."""
    lo, hi = eps, math.pi - eps_top
    s = np.cos(np.pi * (np.arange(k) + 0.5) / k)
    return 0.5 * (lo + hi) + 0.5 * (hi - lo) * s


def fixed_arcs(eps, eps_top, delta_over_Delta, M, theta, gb, n=N_NODES):
    """The state with given arcs and approach (Griffith not imposed): for energy and stability checks."""
    lin = _linear(eps, eps_top, theta, gb, n)
    d = float(delta_over_Delta)
    q = lin.q0 + d * lin.q1
    gap_min = float(np.min(lin.gap(exterior_angles(eps, eps_top), d)))
    scale = (math.pi / M) ** 2 if M > 0 else math.inf
    return TwoPatchState(M=M, theta=theta, gb=gb, eps=eps, eps_top=eps_top, P_star=float(q[0]),
                         B_star=float(q[1]), delta_over_Delta=d, G_bot=float(q[2] ** 2 * scale),
                         G_top=float(q[3] ** 2 * scale), energy=0.5 * ((1 + d) * q[0] - q[1]),
                         gap_min=gap_min, _lin=lin)


def equilibrium_state(eps, eps_top, M, theta, gb, n=N_NODES):
    """State at a point of the zero set of F (delta from Griffith)."""
    lin = _linear(eps, eps_top, theta, gb, n)
    return fixed_arcs(eps, eps_top, _delta(lin, M), M, theta, gb, n)


def _params(M, theta, gb):
    from .equilibria import default_gb
    M = finite_scalar("M", M, low=0.0, low_open=True)
    th = _check_theta(theta)
    if math.isinf(th):
        raise ValueError("theta: two-patch states need a finite vartheta (M, P* normalise by vartheta)")
    gb = default_gb(th) if gb is None else finite_scalar("gb", gb, low=0.0)
    return M, th, gb


def solve(M, theta, eps_top, gb=None, eps_guess=None, n=N_NODES, tol=1e-13):
    """A two-patch equilibrium with the given top half-angle: the bottom half-angle by Newton on F.

    Returns a :class:`TwoPatchState`; ValueError if Newton does not converge (no equilibrium near the guess).
    """
    M, th, gb = _params(M, theta, gb)
    eps_top = finite_scalar("eps_top", eps_top, low=0.0, high=math.pi, low_open=True)
    if eps_top >= math.pi:
        raise ValueError(f"eps_top must be in (0, pi), got {eps_top:g}")
    f = lambda e: residual(e, eps_top, M, th, gb, n)
    e = float(eps_guess) if eps_guess is not None else 0.5 * (math.pi - eps_top)
    for _ in range(40):
        h = 1e-7 * max(1.0, e)
        fe = f(e)
        step = fe * 2 * h / (f(e + h) - f(e - h))
        e_new = min(max(e - step, 0.5 * e), 0.5 * (e + math.pi - eps_top))
        if abs(e_new - e) <= tol * e:
            e = e_new
            break
        e = e_new
    else:
        raise ValueError(f"eps_guess: no two-patch equilibrium found near eps = {e!r}")
    return equilibrium_state(e, eps_top, M, th, gb, n)


# --- stability ------------------------------------------------------------------------------------
def hessian(eps, eps_top, delta_over_Delta, M, theta, gb, n=N_NODES, h=1e-6):
    """3x3 Hessian of Pi* in (eps, eps_top, delta/Delta) at fixed load (the last row/column drops at fixed grip).

    d Pi*/d eps_i = 2 vartheta (pi^2 k_i^2 - M^2), d Pi*/d delta = P* - P*_applied, so the entries are
    4 vartheta pi^2 k_i dk_i/d eps_j (central differences at fixed delta), 4 vartheta pi^2 k_i k1_i and
    dP*/d delta = q1[P].  The eps block is symmetrised (Maxwell; the asymmetry is a check in the tests).
    """
    d = delta_over_Delta
    k = lambda e, et: (lambda L: L.q0[2:4] + d * L.q1[2:4])(_linear(e, et, theta, gb, n))
    lin = _linear(eps, eps_top, theta, gb, n)
    kk = lin.q0[2:4] + d * lin.q1[2:4]
    dk = np.empty((2, 2))
    h0, h1 = min(h, 0.1 * eps), min(h, 0.1 * eps_top)        # relative steps near an axis
    dk[:, 0] = (k(eps + h0, eps_top) - k(eps - h0, eps_top)) / (2 * h0)
    dk[:, 1] = (k(eps, eps_top + h1) - k(eps, eps_top - h1)) / (2 * h1)
    c = 4 * theta * math.pi ** 2
    H = np.empty((3, 3))
    He = c * kk[:, None] * dk
    H[:2, :2] = 0.5 * (He + He.T)
    H[:2, 2] = H[2, :2] = c * kk * lin.q1[2:4]
    H[2, 2] = lin.q1[0]
    return H, He


def stability(eps, eps_top, delta_over_Delta, M, theta, gb, n=N_NODES):
    """(stable_load, stable_grip): positive definiteness of the 3x3 and the 2x2 Hessians."""
    H, _ = hessian(eps, eps_top, delta_over_Delta, M, theta, gb, n)
    grip = bool(np.all(np.linalg.eigvalsh(H[:2, :2]) > 0))
    load = bool(np.all(np.linalg.eigvalsh(H) > 0))
    return load, grip


# --- branches -----------------------------------------------------------------------------------------
SCAN_TOP = (0.05, 0.3, 0.7, 1.2, 1.8, 2.5)    # eps_top rows scanned for branches not reached otherwise
SCAN_POINTS = 48


@dataclass(frozen=True)
class TwoPatchCurve:
    """One branch of two-patch equilibria, ordered along the curve (numpy arrays).

    Fields as :class:`jkrcyl.equilibria.Curve` (a, eps, eps_star, P_star, delta_over_Delta, feasible,
    stable_load, stable_grip) plus a_top, eps_top, eps_top_star, gap_min (min h/Delta outside both arcs),
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
    G_bot: np.ndarray
    G_top: np.ndarray
    ends: tuple

    COLUMNS = ("a", "a_top", "eps", "eps_top", "eps_star", "eps_top_star", "P_star", "delta_over_Delta",
               "gap_min", "feasible", "stable_load", "stable_grip")

    def table(self):
        """Columns of :attr:`COLUMNS` as a dict of arrays (booleans as 0/1)."""
        return {k: np.asarray(getattr(self, k), dtype=float) for k in self.COLUMNS}


def _domain(x):
    return x[0] >= EPS_AXIS and x[1] >= EPS_AXIS and x[0] + x[1] <= math.pi - GAP_FULL


def _clipper(f):
    """Exit point of the curve between x (inside) and y (outside): on the first boundary crossed."""
    lines = (("single", np.array([0.0, 1.0]), EPS_AXIS, np.array([1.0, 0.0])),     # eps_top = EPS_AXIS
             ("mirror", np.array([1.0, 0.0]), EPS_AXIS, np.array([0.0, 1.0])),     # eps = EPS_AXIS
             ("full", np.array([1.0, 1.0]), math.pi - GAP_FULL, np.array([1.0, -1.0]) / math.sqrt(2)))

    def clip(x, y):
        best = None
        for label, nrm, level, along in lines:
            gx, gy = nrm @ x - level, nrm @ y - level
            if label == "full":
                gx, gy = -gx, -gy
            if gx >= 0 > gy:
                s = gx / (gx - gy)
                if best is None or s < best[0]:
                    best = (s, label, nrm, level, along)
        if best is None:
            return None, "domain"
        s, label, nrm, level, along = best
        z = x + s * (y - x)
        z, ok = _cont.project(f, z, direction=along)
        z = z - (nrm @ z - level) / (nrm @ nrm) * nrm       # stay exactly on the line
        return (z if ok and z.min() > 0 else None), label
    return clip


def _near(x, paths, tol):
    return any(np.min(np.linalg.norm(p.points - x, axis=1)) < tol for p in paths)


def onset_angles(M, theta, gb=None):
    """Half-angles eps where a single-patch equilibrium has h(pi) = 0 (sub- and super-critical branches)."""
    from . import equilibria as eq
    from scipy.optimize import brentq
    out = []
    for regime in eq.REGIMES:
        a = eq._grid(regime, theta, 2000)
        h = eq.curve(M, theta, regime, a=a, gb=gb).h_pi_over_Delta
        hp = lambda x: float(eq.curve(M, theta, regime, a=np.array([x]), gb=gb).h_pi_over_Delta[0])
        for i in np.nonzero(np.sign(h[:-1]) * np.sign(h[1:]) < 0)[0]:
            out.append(2 * math.atan(brentq(hp, a[i], a[i + 1], xtol=1e-16, rtol=1e-15)))
    return sorted(out)


def _trace_both(f, clip, x0, t0, paths, h0):
    """Trace from x0 in direction t0 and, unless that closes a loop, in the opposite direction; join."""
    fw = _cont.trace(f, x0, t0, _domain, clip, h0=h0)
    if fw.end == "loop":
        return fw.points, ("loop", "loop")
    bw = _cont.trace(f, x0, -np.asarray(t0, float), _domain, clip, h0=h0)
    pts = np.vstack([bw.points[::-1], fw.points[1:]])
    return pts, (bw.boundary or bw.end, fw.boundary or fw.end)


def branches(M, theta, gb=None, n=N_NODES, h0=0.02):
    """Every branch of two-patch equilibria at (M, vartheta): a list of :class:`TwoPatchCurve`.

    Starts: each single-patch onset h(pi) = 0 (a_top -> 0), its mirror (a -> 0), then the roots of F along
    the rows eps_top in SCAN_TOP (curves touching neither axis: loops, branches ending in full contact).
    """
    M, th, gb = _params(M, theta, gb)
    # clamped so that Newton iterates straying across an axis or the full-contact line stay evaluable
    lo, hi = 0.1 * EPS_AXIS, math.pi - 0.1 * GAP_FULL
    f = lambda x: residual(max(x[0], lo), max(x[1], lo), M, th, gb, n) if x[0] + x[1] < hi else math.nan
    clip = _clipper(f)
    found = []          # (points, ends)
    starts = []
    for e in onset_angles(M, th, gb):
        starts.append((np.array([e, EPS_AXIS]), np.array([1.0, 0.0]), np.array([0.0, 1.0])))
        starts.append((np.array([EPS_AXIS, e]), np.array([0.0, 1.0]), np.array([1.0, 0.0])))
    for x0, along, t0 in starts:
        x, ok = _cont.project(f, x0, direction=along)
        if not ok or not _domain(x) or _near(x, [_P(p) for p, _ in found], 5 * h0):
            continue
        pts = _cont.trace(f, x, t0, _domain, clip, h0=h0)
        found.append((np.vstack([x0[None, :] * 0 + x, pts.points[1:]]), ("single" if x0[1] == EPS_AXIS else "mirror",
                                                                           pts.boundary or pts.end)))
    for et in SCAN_TOP:
        es = np.linspace(EPS_AXIS * 10, math.pi - et - GAP_FULL * 2, SCAN_POINTS)
        if es[-1] <= es[0]:
            continue
        v = np.array([f(np.array([e, et])) for e in es])
        for i in np.nonzero(np.sign(v[:-1]) * np.sign(v[1:]) < 0)[0]:
            x, ok = _cont.project(f, np.array([0.5 * (es[i] + es[i + 1]), et]), direction=np.array([1.0, 0.0]))
            if not ok or not _domain(x) or _near(x, [_P(p) for p, _ in found], 3 * h0):
                continue
            pts, ends = _trace_both(f, clip, x, np.array([0.0, 1.0]), [], h0)
            found.append((pts, ends))
    return [_curve(p, ends, M, th, gb, n) for p, ends in found]


class _P:
    def __init__(self, points):
        self.points = points


def _curve(points, ends, M, th, gb, n):
    from .critical import a_crit
    states = [equilibrium_state(e, et, M, th, gb, n) for e, et in points]
    stab = np.array([stability(s.eps, s.eps_top, s.delta_over_Delta, M, th, gb, n) for s in states])
    ac = a_crit(th)
    arr = lambda k: np.array([getattr(s, k) for s in states])
    a, at = np.tan(points[:, 0] / 2), np.tan(points[:, 1] / 2)
    return TwoPatchCurve(M=M, theta=th, gb=gb, a=a, a_top=at, eps=points[:, 0], eps_top=points[:, 1],
                         eps_star=2 * np.arctan(a / ac) / math.pi, eps_top_star=2 * np.arctan(at / ac) / math.pi,
                         P_star=arr("P_star"), delta_over_Delta=arr("delta_over_Delta"), gap_min=arr("gap_min"),
                         feasible=arr("gap_min") >= -1e-9, stable_load=stab[:, 0], stable_grip=stab[:, 1],
                         G_bot=arr("G_bot"), G_top=arr("G_top"), ends=tuple(ends))
