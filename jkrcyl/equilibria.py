"""Equilibrium curves, stability and adherence forces of sections 6 and 8 (dimensionless).

Everything here is a function of the normalised adhesion M, vartheta and, for the approach only,
the compliance ratio ``gb = (1/G_I)/beta*``.  Normalisation (section 6):

    M = sqrt(w A R)/(sqrt(2) Delta vartheta),   P* = P beta*/(4 pi Delta vartheta).

For the rigid cradle vartheta = inf (section 7.2) the same names carry M_R* = sqrt(w A R)/(sqrt(2) Delta)
and P_R* = P beta*/(4 pi Delta) of (7.6), as :class:`jkrcyl.Contact` does.

Stability: an equilibrium is stable at fixed load when dG/da|_P > 0 and at fixed grip when
dG/da|_delta > 0 (G > w shrinks the contact); both derivatives are emitted kernels
(derive/derivatives.py).  Along the curve dG/da|_P = -(dG/dP) dP/da; dG/dP at fixed a is < 0 on the
sub-critical branch but > 0 on the super-critical one (2 vartheta - L - 2a^4 < 0 there), so fixed-load
stability is dP*/da > 0 sub-critically and dP*/da < 0 super-critically (tests/test_twopatch.py); either
way the adherence force at fixed load is a minimum of P*.  At a super-critical minimum a further pull
lowers G: the contact grows instead of detaching (jkrcyl.twopatch: it zips into full contact).

Root finding (jkrcyl.numerics.roots): sign changes of the kernels on a fine grid, each refined by
Brent's method and bisection to adjacent doubles.  Where no root exists the result is an empty list.
"""
import functools
import math
from dataclasses import dataclass
from typing import List, Optional, Sequence, Tuple

import numpy as np
from numpy.typing import ArrayLike

from ._validate import A_MAX, contact_parameter, count, finite_scalar, theta as _check_theta
from .critical import a_crit as _a_crit
from .numerics import kernels as _k
from .numerics import roots as _roots
from .numerics.zero_load import zero_load_contact, zero_load_max_M   # noqa: F401  (public names)

REGIMES = ("sub-critical", "super-critical")
CONTROLS = ("load", "grip")
RUBBERY_A_MAX = 3.0      # vartheta = inf: curves run over 0 < a < RUBBERY_A_MAX (a_crit = inf)


def default_gb(theta: float) -> float:
    """(1/G_I)/beta* for the incompressible alpha* = 0 pair kappa = kappa_I = 1, G/G_I = 2 vartheta - 1.

    vartheta = 1/2 is a rigid indenter (gb = 0), vartheta = 1 identical incompressible bodies
    (gb = 1/2), vartheta = inf a rigid cradle (gb = 1).  Only the approach delta depends on gb.

    Parameters
    ----------
    theta : float
        vartheta >= 1/2 (section 4), or inf.

    Returns
    -------
    float
        gb = 1 - 1/(2 vartheta) (dimensionless, in [0, 1]).
    """
    th = _check_theta(theta)
    return 1.0 if math.isinf(th) else 1.0 - 1.0 / (2.0 * th)


NUMERIC_ROOT_GRID = 400   # root grid when alpha* != 0 (each point is a collocation solve, numerics.arcs)


def _alpha(alpha_ratio):
    """alpha*/beta* (Materials.alpha_ratio) in (-1, 1); != 0 routes every function here through numerics.arcs."""
    v = finite_scalar("alpha_ratio", alpha_ratio, low=-1.0, high=1.0, low_open=True)
    if v == 1.0:
        raise ValueError("alpha_ratio must be in (-1, 1) (|alpha*| < beta* for every elastic pair), got 1")
    return v


@functools.lru_cache(maxsize=256)     # alpha* != 0: a root search of ~40 solves, asked for by every curve()
def _ac(th, gb, ar):
    """a_crit: the closed form (4.4) at alpha* = 0, the numerical pole of the solver otherwise."""
    if ar == 0.0 or math.isinf(th):
        return 1.0 if math.isinf(th) else _a_crit(th)
    from .numerics.arcs import a_crit
    return a_crit(th, gb, ar)


def _params(M, theta, gb):
    M = finite_scalar("M", M, low=0.0)
    th = _check_theta(theta)
    gb = default_gb(th) if gb is None else finite_scalar("gb", gb, low=0.0, high=1.0)   # (1/G_I)/beta* <= 1
    return M, th, gb


def _check_regime(regime, th):
    if regime not in REGIMES:
        raise ValueError(f"regime must be one of {', '.join(REGIMES)}, got {regime!r}")
    if regime == "super-critical" and math.isinf(th):
        raise ValueError("regime: no super-critical equilibria for theta = inf (a_crit = inf, section 7.2)")


def _a_of(eps_star, th, ac=None):
    """a = a_crit tan(pi eps*/2); for vartheta = inf, eps* is eps/pi (a = tan(pi eps*/2))."""
    ac = (1.0 if math.isinf(th) else _a_crit(th)) if ac is None else ac
    return ac * np.tan(np.pi * np.asarray(eps_star, dtype=float) / 2)


def _eps_star(a, th, ac=None):
    ac = (1.0 if math.isinf(th) else _a_crit(th)) if ac is None else ac
    return 2 * np.arctan(np.asarray(a) / ac) / np.pi


def _branch_range(regime, th):
    """Open interval of eps* for a branch."""
    if math.isinf(th):
        return 0.0, 2 * math.atan(RUBBERY_A_MAX) / math.pi
    return (0.0, 0.5) if regime == "sub-critical" else (0.5, 1.0)


def _grid(regime, th, n, ac=None):
    lo, hi = _branch_range(regime, th)
    s = lo + (hi - lo) * (np.arange(n) + 0.5) / n
    return _a_of(s, th, ac)


def _star(a, m, inv_t, gb, ar=0.0):
    """Normalised equilibrium as a dict p (= vartheta P*), dp, dn, ddn, gP, gd, h and, for the work-conjugate
    approach, dw, ddw, gw; m = M vartheta (tests/test_arcs.py compares the solver with it)."""
    a = np.ascontiguousarray(np.atleast_1d(np.asarray(a, dtype=float)))
    if ar != 0.0:
        from .numerics.arcs import star
        return star(a, m, math.inf if inv_t == 0 else 1.0 / inv_t, gb, ar)
    s = _k.star_m(a, inv_theta=inv_t, m=m, gb=gb)
    return dict(p=s.p, dp=s.dp_da, dn=s.delta_over_Delta, ddn=s.ddelta_da, gP=s.dG_da_P, gd=s.dG_da_delta,
                h=s.h_pi_over_Delta, dw=s.delta_work_over_Delta, ddw=s.ddelta_work_da, gw=s.dG_da_delta_work)


def _star_of(a, M, th, gb, ar=0.0):
    """The normalised equilibrium (jkrcyl.numerics.kernels.Star) at the contact parameters a."""
    if ar == 0.0:
        return _k.star(np.atleast_1d(a), M, th, gb)
    n = _k.normalise(M, th)
    s = _star(a, n.m, n.inv_theta, gb, ar)
    return _k.Star(P_star=s["p"] / n.scale, dP_star_da=s["dp"] / n.scale, delta_over_Delta=s["dn"],
                   ddelta_da=s["ddn"], dG_da_P=s["gP"], dG_da_delta=s["gd"], h_pi_over_Delta=s["h"],
                   delta_work_over_Delta=s["dw"], ddelta_work_da=s["ddw"], dG_da_delta_work=s["gw"])


_star_root = _roots.brent_solver(_k.star_residual_nb)


def _star_roots(field, M, th, gb, ar, grid, target=0.0):
    """Where the Star field crosses target on the grid: [(a, sign of field - target right of a)]."""
    values = getattr(_star_of(grid, M, th, gb, ar), field) - target
    if ar != 0.0:      # each evaluation is a collocation solve (numerics.arcs)
        f = lambda x, args: float(getattr(_star_of(np.array([x]), M, th, gb, ar), field)[0]) - target
        return _roots.grid_roots(values, grid, lambda lo, hi, flo, fhi: _roots.brent(f, lo, hi, (), flo, fhi))
    n = _k.normalise(M, th)
    args = (n.inv_theta, n.m if n.m > 0 else 1e-150, gb, _k.STAR_FIELDS[field], n.scale, target)
    return _roots.grid_roots(values, grid, lambda lo, hi, flo, fhi: _star_root(lo, hi, flo, fhi, args))


SMALL_A_POINTS = 200      # log-spaced points below the root grid (small M, issue 11)


def _root_grid(regime, th, n, ac, M):
    """:func:`_grid` plus log-spaced points below its first one on the branch starting at a = 0: for small M the
    stationary points sit near a ~ (vartheta M/2)^(2/3) (the half-plane limit (7.3b), section 8.1), below the
    first point of a grid uniform in eps* (found for M down to 1e-12, tests/test_bad_input.py)."""
    grid = _grid(regime, th, n, ac)
    if regime != "sub-critical" or M == 0:
        return grid
    lo = (M * (1.0 if math.isinf(th) else th) / 2) ** (2 / 3) / 100
    if lo >= grid[0]:
        return grid
    return np.concatenate([np.geomspace(max(lo, 1e-100), grid[0], SMALL_A_POINTS, endpoint=False), grid])


def _on_branch(a, regime, th, ac):
    """Contact parameters given to :func:`curve` must lie on the branch asked for (a_crit separates them)."""
    a = contact_parameter(a)
    if not math.isinf(th):
        off = a >= ac if regime == "sub-critical" else a <= ac
        if off.any():
            side = "<" if regime == "sub-critical" else ">"
            raise ValueError(f"a must be {side} a_crit = {ac:.6g} on the {regime} branch, got {a[off].flat[0]:g}")
    return a


@dataclass(frozen=True)
class Curve:
    """One branch of equilibria (numpy arrays over the contact parameter a, increasing).

    eps [rad] = 2 atan(a); eps_star = 2 atan(a/a_crit)/pi (eps/pi when vartheta = inf);
    P_star (P_R* when vartheta = inf); delta_over_Delta; h_pi_over_Delta = h(pi)/Delta;
    feasible = gap inequality (h(pi) >= 0); stable_load = dG/da|_P > 0; stable_grip = dG/da|_delta > 0;
    dP_star_da, ddelta_da: slopes; dG_da_P, dG_da_delta: (1/w) dG/da.
    Work-conjugate approach delta_work = delta + P/(8 pi G_I) (derive/green.py: the pin's centroid, load
    spread over the pin; the paper's delta is the rims' approach, not the work conjugate of P):
    delta_work_over_Delta, its slope ddelta_work_da, dG_da_delta_work and stable_grip_work = dG/da|_delta_work > 0
    (stable at fixed delta_work).  The release rates come from the chain rule dG/da|_X = -(dG/dp)|_a
    (dX/da)/(dX/dp)|_a (jkrcyl.numerics.kernels.release_rates).  As (d delta_work/dp)|_a > 0 (the fixed arc's
    compliance in the conjugate approach, positive like its elastic energy), stable_grip_work is
    d delta_work/da > 0 below a_crit and < 0 above it -- the load rule with delta_work for P
    (tests/test_work_conjugate.py).  Without adhesion (M = 0) the (1/w) dG/da fields are NaN (w = 0).
    """

    M: float
    theta: float
    gb: float
    regime: str
    a: np.ndarray
    eps: np.ndarray
    eps_star: np.ndarray
    P_star: np.ndarray
    delta_over_Delta: np.ndarray
    h_pi_over_Delta: np.ndarray
    feasible: np.ndarray
    stable_load: np.ndarray
    stable_grip: np.ndarray
    dP_star_da: np.ndarray
    ddelta_da: np.ndarray
    dG_da_P: np.ndarray
    dG_da_delta: np.ndarray
    delta_work_over_Delta: np.ndarray
    ddelta_work_da: np.ndarray
    dG_da_delta_work: np.ndarray
    stable_grip_work: np.ndarray
    P: np.ndarray = None          # [N/m], set when the curve comes from a Contact (Contact.curve)
    delta: np.ndarray = None      # [m], likewise
    delta_work: np.ndarray = None  # [m], likewise

    COLUMNS = ("a", "eps", "eps_star", "P_star", "delta_over_Delta", "delta_work_over_Delta", "h_pi_over_Delta",
               "feasible", "stable_load", "stable_grip", "stable_grip_work")

    def table(self):
        """Columns of :attr:`COLUMNS` (plus P [N/m], delta, delta_work [m] when dimensional) as a dict of arrays
        (booleans as 0/1)."""
        cols = self.COLUMNS + (("P", "delta", "delta_work") if self.P is not None else ())
        return {k: np.asarray(getattr(self, k), dtype=float) for k in cols}

    def __repr__(self):
        return (f"Curve({self.regime}, M={self.M:.6g}, theta={self.theta:.6g}, {np.size(self.a)} points"
                f"{', dimensional' if self.P is not None else ''})")


def curve(M: float, theta: float, regime: str = "sub-critical", n: int = 2000, gb: Optional[float] = None,
          a: "Optional[ArrayLike]" = None, alpha_ratio: float = 0.0) -> "Curve":
    """The equilibrium branch ``regime`` at (M, vartheta): n points uniform in eps*, or at given a.

    alpha_ratio = alpha*/beta* != 0: numerical solution (jkrcyl.numerics.arcs); eps* then uses its pole a_crit.

    Parameters
    ----------
    M : float
        Normalised adhesion sqrt(w A R)/(sqrt(2) Delta vartheta) (section 6; M_R* of (7.6) for vartheta = inf), >= 0.
    theta : float
        vartheta >= 1/2 (section 4), or inf (rigid cradle, section 7.2).
    regime : {'sub-critical', 'super-critical'}
        The branch: a < a_crit or a > a_crit of (4.4) (only 'sub-critical' for vartheta = inf).
    n : int
        Points, uniform in eps* = 2 atan(a/a_crit)/pi (ignored when a is given), 2 <= n <= 1e6.
    gb : float, optional
        (1/G_I)/beta* in [0, 1], used by the approach only (default: :func:`default_gb`).
    a : array_like, optional
        Contact parameters tan(eps/2) on the branch, instead of the grid.
    alpha_ratio : float
        alpha*/beta* in (-1, 1) (0: the paper's closed forms).

    Returns
    -------
    Curve
        P* (section 6), delta/Delta (5.8), h(pi)/Delta (5.10), stability from dG/da (section 8.3), per point.
    """
    M, th, gb = _params(M, theta, gb)
    ar = _alpha(alpha_ratio)
    _check_regime(regime, th)
    ac = _ac(th, gb, ar)
    if a is None:
        n = count("n", n, low=2)
        a = _grid(regime, th, n, ac)
        a = a[a <= A_MAX]          # huge vartheta: a_crit ~ vartheta^(1/4) pushes the grid past the domain of a
        if a.size < 2:
            raise ValueError(f"theta: the {regime} branch lies beyond a = {A_MAX:g} (the supported domain of a) "
                             f"for theta = {th:g}")
    a = np.ascontiguousarray(_on_branch(a, regime, th, ac))
    st = _star_of(a, M, th, gb, ar)
    return Curve(M=M, theta=th, gb=gb, regime=regime, a=a, eps=2 * np.arctan(a), eps_star=_eps_star(a, th, ac),
                 P_star=st.P_star, delta_over_Delta=st.delta_over_Delta, h_pi_over_Delta=st.h_pi_over_Delta,
                 feasible=st.h_pi_over_Delta >= 0, stable_load=st.dG_da_P > 0, stable_grip=st.dG_da_delta > 0,
                 dP_star_da=st.dP_star_da, ddelta_da=st.ddelta_da, dG_da_P=st.dG_da_P, dG_da_delta=st.dG_da_delta,
                 delta_work_over_Delta=st.delta_work_over_Delta, ddelta_work_da=st.ddelta_work_da,
                 dG_da_delta_work=st.dG_da_delta_work, stable_grip_work=st.dG_da_delta_work > 0)


@dataclass(frozen=True)
class Point:
    """A stationary point on a branch: P* minimum (control = load) or d delta/da = 0 (control = grip).

    kind: 'min' or 'max' of P* (load) or of delta/Delta (grip) along the branch.
    outcome (control = load, from :func:`adherence`): what a further pull does there -- 'detachment' (a
    feasible sub-critical minimum: the contact shrinks away), 'zip-full' (a feasible super-critical minimum: the
    contact grows round into full contact); for an infeasible point (h(pi) < 0: the gap at the top closes before
    it is reached) the answer of the confined analysis, a key of :data:`jkrcyl.twopatch.REGIMES`
    ('snap-in-full', 'snap-in-transfer', 'two-patch', ... ; jkrcyl.twopatch.confined_events), or
    'gap-closes-first' where that analysis does not apply (vartheta = inf).
    """

    control: str
    regime: str
    kind: str
    M: float
    theta: float
    a: float
    eps: float
    eps_star: float
    P_star: float
    delta_over_Delta: float
    h_pi_over_Delta: float
    feasible: bool
    delta_work_over_Delta: float = None   # work-conjugate approach delta_work/Delta (Curve)
    P: float = None               # [N/m], set when the point comes from a Contact (Contact.adherence)
    delta: float = None           # [m], likewise
    delta_work: float = None      # [m], likewise
    outcome: str = None           # control = load: see the class docstring


ROOT_GRID = 4000


def stationary_points(M: float, theta: float, control: str = "load", regime: str = "sub-critical",
                      gb: Optional[float] = None, n: int = ROOT_GRID, alpha_ratio: float = 0.0) -> List["Point"]:
    """All points of one branch where dP*/da = 0 (load) or d(delta/Delta)/da = 0 (grip) (section 8).

    Parameters
    ----------
    M, theta, gb, alpha_ratio
        As for :func:`curve`.
    control : {'load', 'grip'}
        Stationary points of P* (fixed load) or of delta/Delta (fixed grip).
    regime : {'sub-critical', 'super-critical'}
        The branch searched.
    n : int
        Root grid (sign changes refined by Brent's method).

    Returns
    -------
    list of Point
        Increasing in a; ``kind`` says 'min' or 'max'.
    """
    if control not in CONTROLS:
        raise ValueError(f"control must be 'load' or 'grip', got {control!r}")
    M, th, gb = _params(M, theta, gb)
    ar = _alpha(alpha_ratio)
    _check_regime(regime, th)
    ac = _ac(th, gb, ar)
    if ar != 0.0 and n == ROOT_GRID:
        n = NUMERIC_ROOT_GRID
    field = "dP_star_da" if control == "load" else "ddelta_da"
    out = []
    for r, sgn in _star_roots(field, M, th, gb, ar, _root_grid(regime, th, n, ac, M)):
        st = _star_of(np.array([r]), M, th, gb, ar)
        out.append(Point(control=control, regime=regime, kind="min" if sgn > 0 else "max", M=M, theta=th,
                         a=r, eps=2 * math.atan(r), eps_star=float(_eps_star(r, th, ac)),
                         P_star=float(st.P_star[0]), delta_over_Delta=float(st.delta_over_Delta[0]),
                         h_pi_over_Delta=float(st.h_pi_over_Delta[0]), feasible=bool(st.h_pi_over_Delta[0] >= 0),
                         delta_work_over_Delta=float(st.delta_work_over_Delta[0])))
    return out


def adherence(M: float, theta: float, control: str = "load", gb: Optional[float] = None,
              regimes: Optional[Sequence[str]] = None, alpha_ratio: float = 0.0,
              confined: bool = True) -> List["Point"]:
    """Adherence points, sub-critical branch first.

    control='load': per branch, the lowest local minimum of P* (the 'x' of Fig. 3), if any.
    control='grip': every point with d delta/da = 0 (the 'o' of Fig. 3; .kind says min or max).

    Parameters
    ----------
    M, theta, gb, alpha_ratio
        As for :func:`curve`.
    control : {'load', 'grip'}
    regimes : sequence of str, optional
        Branches searched (default both; only 'sub-critical' for vartheta = inf).
    confined : bool
        control = load: set :attr:`Point.outcome` of infeasible points from the confined analysis
        (jkrcyl.twopatch.confined_events: seconds, up to about a minute when alpha* != 0); False leaves it None.

    Returns
    -------
    list of Point
        Normalised P* (section 6) and delta/Delta (5.8) at each point; empty if none.
    """
    th = _check_theta(theta)
    regimes = (("sub-critical",) if math.isinf(th) else REGIMES) if regimes is None else regimes
    out = []
    for regime in regimes:
        pts = stationary_points(M, th, control, regime, gb, alpha_ratio=alpha_ratio)
        if control == "load":
            mins = [p for p in pts if p.kind == "min"]
            if mins:
                out.append(min(mins, key=lambda p: p.P_star))
        else:
            out += pts
    return _outcomes(out, M, th, gb, alpha_ratio) if control == "load" and confined else out


def _outcomes(points, M, th, gb, alpha_ratio):
    """Point.outcome of fixed-load adherence points: the branch's fold rule where feasible (derive/confined.py:
    detachment below a_crit, zip into full contact above), the confined analysis where the gap closes first."""
    from dataclasses import replace
    from . import twopatch
    regime = None
    if any(not p.feasible for p in points):
        regime = ("gap-closes-first" if math.isinf(th) or M == 0 else     # no confined analysis there
                  twopatch.confined_events(M, th, gb=gb, alpha_ratio=alpha_ratio).regime)
    return [replace(p, outcome=(regime if not p.feasible else
                                "detachment" if p.regime == "sub-critical" else "zip-full")) for p in points]


def solve_load(M: float, theta: float, P_star: float, regime: str = "sub-critical", gb: Optional[float] = None,
               n: int = ROOT_GRID, alpha_ratio: float = 0.0) -> List[float]:
    """Contact parameters a on a branch where P*(a) = P_star (sorted; [] if none).

    Parameters
    ----------
    M, theta, regime, gb, alpha_ratio
        As for :func:`curve`.
    P_star : float
        Normalised load P beta*/(4 pi Delta vartheta) (section 6).
    n : int
        Root grid.

    Returns
    -------
    list of float
        Contact parameters tan(eps/2) (the dimensional forward problem is :meth:`jkrcyl.Contact.solve`).
    """
    return _solve_field("P_star", P_star, M, theta, regime, gb, n, alpha_ratio)


def solve_approach(M: float, theta: float, delta_over_Delta: float, regime: str = "sub-critical",
                   gb: Optional[float] = None, n: int = ROOT_GRID, alpha_ratio: float = 0.0) -> List[float]:
    """Contact parameters a on a branch where delta/Delta = the given value (sorted).

    Parameters
    ----------
    M, theta, regime, gb, alpha_ratio
        As for :func:`curve`.
    delta_over_Delta : float
        Normalised approach (5.8).
    n : int
        Root grid.

    Returns
    -------
    list of float
        Contact parameters tan(eps/2); empty if none.
    """
    return _solve_field("delta_over_Delta", delta_over_Delta, M, theta, regime, gb, n, alpha_ratio)


def _solve_field(field, value, M, theta, regime, gb, n, alpha_ratio):
    """Sorted contact parameters on a branch where the Star field equals value (validated under its name)."""
    M, th, gb = _params(M, theta, gb)
    ar = _alpha(alpha_ratio)
    _check_regime(regime, th)
    if ar != 0.0 and n == ROOT_GRID:
        n = NUMERIC_ROOT_GRID
    target = finite_scalar(field, value)
    grid = _grid(regime, th, n, _ac(th, gb, ar))
    return sorted(r for r, _ in _star_roots(field, M, th, gb, ar, grid, target))


def two_patch(M: float, theta: float, n: Optional[int] = None, gb: Optional[float] = None,
              alpha_ratio: float = 0.0) -> list:
    """Two-patch equilibrium branches (top contact at phi = pi, issue 12): :func:`jkrcyl.twopatch.branches`.

    A list of :class:`jkrcyl.twopatch.TwoPatchCurve` (Curve fields plus a_top, stable_load, stable_grip);
    n points per branch (default: the continuation steps); alpha_ratio = alpha*/beta* (any material pair).
    """
    from . import twopatch
    return twopatch.branches(M, theta, gb=gb, n=n, alpha_ratio=alpha_ratio)


def from_contact(contact) -> Tuple[float, float, float]:
    """(M, vartheta, gb) of a :class:`jkrcyl.Contact` (M is M_R* when vartheta = inf).

    Parameters
    ----------
    contact : jkrcyl.Contact
        Needs Delta > 0 (M divides by it).

    Returns
    -------
    (float, float, float)
        M (section 6), vartheta (section 4), gb = (1/G_I)/beta*.
    """
    return contact.M, contact.theta, contact.materials.inv_G_I / contact.beta
