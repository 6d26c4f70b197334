"""The normalised API of sections 6-8: everything as a function of (M, vartheta, gb, alpha*/beta*).

Shared parameters (each function builds one validated :class:`jkrcyl.model.problem.Problem`): ``M``, the adhesion
sqrt(w A R)/(sqrt(2) Delta vartheta) >= 0 (section 6); ``theta``, vartheta >= 1/2 (section 4) or inf (the rigid
cradle of section 7.2, where M and P* are M_R* and P_R* of (7.6), as in jkrcyl.Contact); ``gb``, (1/G_I)/beta* in
[0, 1], keyword and required: delta and the stability at fixed delta depend on it (1/2.8 for identical nu = 0.3
bodies; an incompressible pin: :func:`incompressible_gb`); ``alpha_ratio``, alpha*/beta* in (-1, 1) (0: the paper's
closed forms, else the collocation solver); ``s0``, the Maugis-Dugdale strength sigma0 R beta*/(4 pi Delta) > 0
(jkrcyl.laws.DugdaleEdge; None: JKR).  Every function raises ValueError naming a parameter outside its range.
"""
from __future__ import annotations

import math
from typing import List, Optional, Sequence, Tuple

from numpy.typing import ArrayLike

from ._validate import CONTROLS, control as _check_control, count, finite_scalar, theta as _check_theta
from .analysis import branches as _br, confined as _confined, tracing as _tr
from .critical import a_crit
from .laws.dugdale import edge_of_strength as _law
from .model import full_contact as _full, two_patch as _two
from .model.problem import Problem
from .model.single_patch import solver
from .numerics import cohesive_scales as _scales
from .numerics.zero_load import zero_load_contact, zero_load_max_M
from .results import ConfinedEvents, Curve, FullContact, Point, TwoPatchCurve, TwoPatchState

__all__ = ["CONTROLS", "REGIMES", "a_crit", "adherence", "adherence_of", "confined_events", "curve", "from_contact",
           "full_contact", "incompressible_gb", "problem", "solve_approach", "solve_load", "stationary_points",
           "two_patch", "two_patch_state", "zero_load_contact", "zero_load_max_M", "zone_strength"]

REGIMES = _br.REGIMES
RUBBERY_A_MAX = _br.RUBBERY_A_MAX      # curve(): a branch without a_crit is drawn over 0 < a < 3 (Fig. 7)


def incompressible_gb(theta: float) -> float:
    """gb = (1/G_I)/beta* of an incompressible pin (kappa_I = 1) at vartheta: 1 - 1/(2 vartheta), in [0, 1].

    Parameters
    ----------
    theta : float
        vartheta >= 1/2 (section 4; 1/2: a rigid pin, gb = 0), or inf (a rigid cradle, gb = 1).

    Examples
    --------
    >>> incompressible_gb(1.0), incompressible_gb(math.inf)
    (0.5, 1.0)
    """
    th = _check_theta(theta)
    return 1.0 if math.isinf(th) else 1.0 - 1.0 / (2.0 * th)


def problem(M: float, theta: float, gb: float, alpha_ratio: float = 0.0, s0: Optional[float] = None) -> Problem:
    """The validated normalised problem (section 6), frozen and hashable, that every function here builds.

    Parameters
    ----------
    M, theta, gb, alpha_ratio : float
        Adhesion M >= 0, vartheta >= 1/2 or inf, (1/G_I)/beta* in [0, 1], alpha*/beta* in (-1, 1) (module doc).
    s0 : float, optional
        Maugis-Dugdale strength sigma0 R beta*/(4 pi Delta) > 0 (needs M > 0); None (default): JKR.

    Examples
    --------
    >>> problem(0.3, 1.0, 1 / 2.8).edge.name, problem(0.3, 1.0, 1 / 2.8, s0=0.1).edge.name
    ('JKR', 'Maugis-Dugdale')
    """
    return Problem(M, theta, gb, alpha_ratio, _law(s0))


def zone_strength(lam: float, M: float, theta: float) -> float:
    """s0 of the transition parameter lambda = 4 s0/m^(2/3), m = M vartheta (half-plane convention, Delta/R -> 0).

    Parameters
    ----------
    lam : float
        lambda > 0 (Baney-Hui's, R_eff = R R_D/Delta: jkrcyl.numerics.cohesive_scales).
    M, theta : float
        Adhesion M > 0 (else the error names lambda) and vartheta (m = M_R* when vartheta = inf).

    Examples
    --------
    >>> round(zone_strength(1.0, 0.3, 1.0), 6), round(0.3 ** (2 / 3) / 4, 6)
    (0.112035, 0.112035)
    """
    pb = Problem(M, theta, 0.0)
    if pb.M == 0:
        raise ValueError("lambda: the transition parameter needs adhesion, M > 0 (w > 0), got M = 0")
    return _scales.zone_strength(finite_scalar("lambda", lam, low=0.0, low_open=True), pb.m)


def curve(M: float, theta: float, regime: str = "sub-critical", n: int = 2000, *, gb: float,
          a: Optional[ArrayLike] = None, alpha_ratio: float = 0.0, s0: Optional[float] = None) -> Curve:
    """The equilibrium branch ``regime``: P* (section 6), delta/Delta (5.8), h(pi)/Delta (5.10), stability (8.3).

    Parameters
    ----------
    M, theta, gb, alpha_ratio, s0
        The problem (:func:`problem`).
    regime : str
        'sub-critical', 'super-critical' (a below, above a_crit); cohesive: 'sub-critical', 'contactless'.
    n : int
        Points uniform in eps* = 2 atan(a/a_crit)/pi (over 0 < a < 3 where a_crit = inf, Fig. 7), >= 2.
    a : array_like, optional
        The contact parameters on the branch instead of the uniform grid.

    Examples
    --------
    >>> c = curve(0.3, 1.0, n=5, gb=1 / 2.8)
    >>> [round(float(p), 4) for p in c.P_star], c.stable_load.tolist()
    ([-0.1569, -0.2507, -0.2851, -0.2482, 0.1787], [False, False, False, True, True])
    """
    pb = Problem(M, theta, gb, alpha_ratio, _law(s0))
    return _br.curve(pb, regime, count("n", n, low=2) if a is None else n, a=a)


def stationary_points(M: float, theta: float, control: str = "load", regime: str = "sub-critical", *, gb: float,
                      alpha_ratio: float = 0.0, n: Optional[int] = None, s0: Optional[float] = None) -> List[Point]:
    """Every point of one branch where the quantity ``control`` holds is stationary (``kind`` 'min', 'max').

    Parameters
    ----------
    M, theta, gb, alpha_ratio, s0
        The problem (:func:`problem`).
    control, regime : str
        'load' (P*), 'grip' (delta/Delta of (5.8)) or 'grip-work' (delta_work/Delta); the branch (:func:`curve`).
    n : int, optional
        Search a grid of n >= 2 points instead of the branch's dense table.

    Examples
    --------
    >>> [(p.kind, round(p.a, 4), round(p.P_star, 4)) for p in stationary_points(0.3, 1.0, gb=1 / 2.8)]
    [('min', 0.3994, -0.2856)]
    """
    pb = Problem(M, theta, gb, alpha_ratio, _law(s0))
    _check_control(control)
    _br.check_regime(pb, regime)
    return _br.stationary_points(pb, control, regime, n=None if n is None else count("n", n, low=2))


def adherence(M: float, theta: float, control: str = "load", *, gb: float, regimes: Optional[Sequence[str]] = None,
              alpha_ratio: float = 0.0, confined: bool = True, s0: Optional[float] = None) -> List[Point]:
    """Adherence points, sub-critical branch first: the 'x' (fixed load) and the 'o' (fixed grip) of Fig. 3.

    Parameters
    ----------
    M, theta, gb, alpha_ratio, s0
        The problem (:func:`problem`).
    control : str
        'load': per branch the lowest local minimum of P*, whose ``outcome`` says what a further pull does;
        'grip', 'grip-work': every stationary point of the approach delta or delta_work.
    regimes : sequence of str, optional
        The branches to search (default: every branch of the problem).
    confined : bool
        Under load, the ``outcome`` of an infeasible point from the confined analysis (jkrcyl.analysis.confined).

    Examples
    --------
    >>> [(p.kind, round(p.P_star, 4), p.outcome) for p in adherence(0.3, 1.0, gb=1 / 2.8)]
    [('min', -0.2856, 'detachment')]
    """
    return adherence_of(Problem(M, theta, gb, alpha_ratio, _law(s0)), control, regimes, confined)


def adherence_of(pb: Problem, control: str = "load", regimes: Optional[Sequence[str]] = None,
                 confined: bool = True) -> List[Point]:
    """:func:`adherence` of a validated problem (:func:`problem`; any edge law).

    Parameters
    ----------
    pb, control, regimes, confined
        The validated problem (jkrcyl.model.problem.Problem) and the rest as :func:`adherence`.

    Examples
    --------
    >>> adherence_of(problem(0.3, 1.0, 1 / 2.8)) == adherence(0.3, 1.0, gb=1 / 2.8)
    True
    """
    _check_control(control)
    regs = solver(pb).regimes() if regimes is None else _regimes(regimes)
    out = []
    for regime in regs:
        pts = _br.stationary_points(pb, control, _br.check_regime(pb, regime))
        if control != "load":
            out += pts
        elif any(p.kind == "min" for p in pts):
            out.append(min((p for p in pts if p.kind == "min"), key=lambda p: p.P_star))
    return _confined.outcomes(pb, out) if control == "load" and confined else out


def solve_load(M: float, theta: float, P_star: float, regime: str = "sub-critical", *, gb: float,
               alpha_ratio: float = 0.0, n: Optional[int] = None, s0: Optional[float] = None) -> List[float]:
    """The contact parameters a on one branch where P*(a) = P_star (section 6): sorted, [] if none.

    Parameters
    ----------
    M, theta, gb, alpha_ratio, s0
        The problem (:func:`problem`).
    P_star : float
        The normalised load.
    regime, n
        The branch and an optional root grid, as :func:`stationary_points`.

    Examples
    --------
    >>> [round(a, 4) for a in solve_load(0.3, 1.0, 0.0, gb=1 / 2.8)]        # the smaller root of (8.1)
    [0.7371]
    >>> [round(a, 4) for a in zero_load_contact(0.3, 1.0)]
    [0.7371, 11.6072]
    """
    return _solve_field("p", "P_star", P_star, M, theta, regime, gb, alpha_ratio, n, s0)


def solve_approach(M: float, theta: float, delta_over_Delta: float, regime: str = "sub-critical", *, gb: float,
                   alpha_ratio: float = 0.0, n: Optional[int] = None) -> List[float]:
    """The contact parameters a on one branch where delta/Delta (5.8) takes the given value: sorted, [] if none.

    Parameters
    ----------
    M, theta, gb, alpha_ratio
        The problem (:func:`problem`).
    delta_over_Delta : float
        The paper's approach over the clearance.
    regime, n
        As :func:`solve_load`.

    Examples
    --------
    >>> [round(a, 4) for a in solve_approach(0.3, 1.0, 0.0, gb=1 / 2.8)]
    [0.6268]
    """
    return _solve_field("dn", "delta_over_Delta", delta_over_Delta, M, theta, regime, gb, alpha_ratio, n)


def _solve_field(field, name, value, M, theta, regime, gb, alpha_ratio, n, s0=None):
    pb = Problem(M, theta, gb, alpha_ratio, _law(s0))
    _br.check_regime(pb, regime)
    target = finite_scalar(name, value) * (pb.scale if field == "p" else 1.0)
    return [r for r, _ in _br.roots(pb, regime, field, target, n=None if n is None else count("n", n, low=2))]


def two_patch(M: float, theta: float, n: Optional[int] = None, *, gb: float,
              alpha_ratio: float = 0.0) -> Tuple[TwoPatchCurve, ...]:
    """Every two-patch branch (contact at the bottom and the top at once), traced; cached per problem.

    Parameters
    ----------
    M, theta, gb, alpha_ratio
        The problem (:func:`problem`; vartheta finite).
    n : int, optional
        Points per branch, evenly along it (default: the continuation steps of jkrcyl.analysis.tracing).

    Examples
    --------
    >>> [b.ends for b in two_patch(0.5, 1.0, gb=1 / 2.8)]
    [('single', 'mirror')]
    """
    return _tr.branches(_two.require_finite_theta(Problem(M, theta, gb, alpha_ratio)), n)


def two_patch_state(M: float, theta: float, *, gb: float, eps: Optional[float] = None, eps_top: Optional[float] = None,
                    guess: Optional[float] = None, alpha_ratio: float = 0.0) -> TwoPatchState:
    """The two-patch equilibrium (G = w at both edges) with one half-angle given, the other found from ``guess``.

    Parameters
    ----------
    M, theta, gb, alpha_ratio
        The problem (:func:`problem`; vartheta finite).
    eps, eps_top : float
        Exactly one: the half-angle of the bottom or the top contact [rad], in (0, pi).
    guess : float, optional
        Start of the other half-angle [rad]; the error names guess where no equilibrium is found near it.

    Examples
    --------
    >>> s = two_patch_state(0.5, 1.0, gb=1 / 2.8, eps=1.0, guess=0.003)
    >>> round(float(s.eps_top), 5), round(s.P_star, 4), round(s.G_bot, 9), round(s.G_top, 9)
    (0.00268, -0.7062, 1.0, 1.0)
    """
    return _two.solve(Problem(M, theta, gb, alpha_ratio), eps_top=eps_top, eps=eps, guess=guess)


def confined_events(M: float, theta: float, *, gb: float, alpha_ratio: float = 0.0) -> ConfinedEvents:
    """What slow pulling under load control does to the pin in the hole (jkrcyl.analysis.confined).

    Parameters
    ----------
    M, theta, gb, alpha_ratio
        The problem (:func:`problem`; vartheta finite).

    Examples
    --------
    >>> (ev := confined_events(0.3, 1.0, gb=1 / 2.8)).regime, round(ev.P_fold, 4)
    ('detachment', -0.2856)
    """
    return _confined.confined_events(_two.require_finite_theta(Problem(M, theta, gb, alpha_ratio)))


def full_contact(theta: float, P_star: Optional[float] = None, delta_over_Delta: Optional[float] = None, *,
                 gb: float, alpha_ratio: float = 0.0) -> FullContact:
    """The pin bonded all round at a given P* or delta/Delta: n(phi) = N0 + N1 cos(phi), N1 = P*/pi.

    Parameters
    ----------
    theta, gb, alpha_ratio
        The problem (:func:`problem`; vartheta finite; no M: full contact has no edge).
    P_star, delta_over_Delta : float
        Exactly one: the load (section 6) or the approach over the clearance.

    Examples
    --------
    >>> f = full_contact(1.0, P_star=1.5, gb=1 / 2.8)        # -pi N0 = 1 at alpha* = 0
    >>> round(-math.pi * f.N0, 12), round(math.pi * f.N1, 12)
    (1.0, 1.5)
    """
    return _full.state(Problem(0.0, theta, gb, alpha_ratio), P_star=P_star, delta_over_Delta=delta_over_Delta)


def from_contact(contact: "jkrcyl.Contact") -> Tuple[float, float, float]:
    """(M, vartheta, gb) of a :class:`jkrcyl.Contact` (M is M_R* when vartheta = inf; ValueError for Delta = 0).

    Parameters
    ----------
    contact : jkrcyl.Contact
        A contact with clearance Delta > 0 (the normalisation divides by it).

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> M, th, gb = from_contact(jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m))
    >>> round(M, 4), th, round(gb * 2.8, 12)
    (0.3338, 1.0, 1.0)
    """
    pb = Problem.of(contact)
    return pb.M, pb.theta, pb.gb


def _regimes(regimes):
    if isinstance(regimes, str) or not hasattr(regimes, "__iter__"):
        raise ValueError(f"regimes must be a list of {', '.join(REGIMES)}, got {regimes!r}")
    return list(regimes)
