"""The normalised API of sections 6-8: everything as a function of (M, vartheta, gb, alpha*/beta*).

Normalisation (section 6): M = sqrt(w A R)/(sqrt(2) Delta vartheta), P* = P beta*/(4 pi Delta vartheta); for the
rigid cradle vartheta = inf (section 7.2) the same names carry M_R* and P_R* of (7.6), as :class:`jkrcyl.Contact`.
``gb = (1/G_I)/beta*`` is required: the approach delta, and so the stability at fixed delta, depend on it (e.g.
1/2.8 for identical nu = 0.3 bodies, 1 - 1/(2 vartheta) for an incompressible pin: :func:`incompressible_gb`).
``alpha_ratio = alpha*/beta*`` in (-1, 1): 0 uses the paper's closed forms, any other value the collocation solver
(jkrcyl.model.single_patch decides).  Each function builds one :class:`jkrcyl.model.problem.Problem` (validated
once) and asks the model core (jkrcyl.model) and the analyses (jkrcyl.analysis).
"""
from __future__ import annotations

import math
from typing import List, Optional, Sequence, Tuple

from ._validate import count, finite_scalar, theta as _check_theta
from .analysis import branches as _br
from .analysis import confined as _confined
from .analysis import tracing as _tr
from .model import full_contact as _full
from .model import two_patch as _two
from .critical import a_crit  # noqa: F401  (one a_crit: jkrcyl.critical)
from .laws.dugdale import edge_of_strength
from .model.problem import Problem
from .numerics import cohesive_scales as _scales
from .model.single_patch import solver
from .numerics.zero_load import zero_load_contact, zero_load_max_M   # noqa: F401  (public names)
from .results import ConfinedEvents, Curve, FullContact, Point, TwoPatchCurve, TwoPatchState

REGIMES = _br.REGIMES
RUBBERY_A_MAX = _br.RUBBERY_A_MAX      # curve(): a branch without a_crit is drawn over 0 < a < 3 (Fig. 7)
CONTROLS = ("load", "grip", "grip-work")


def incompressible_gb(theta: float) -> float:
    """gb = (1/G_I)/beta* of an incompressible pin (kappa_I = 1) at vartheta: 1 - 1/(2 vartheta) (0 for a rigid
    pin, vartheta = 1/2; 1 for a rigid cradle, vartheta = inf)."""
    th = _check_theta(theta)
    return 1.0 if math.isinf(th) else 1.0 - 1.0 / (2.0 * th)


def problem(M: float, theta: float, gb: float, alpha_ratio: float = 0.0, s0: Optional[float] = None) -> Problem:
    """The validated :class:`~jkrcyl.model.problem.Problem`; s0 = sigma0 R beta*/(4 pi Delta): the Maugis-Dugdale
    cohesive law (jkrcyl.laws.DugdaleEdge), None: JKR."""
    return Problem(M, theta, gb, alpha_ratio, _law(s0))


def _law(s0):
    return edge_of_strength(s0)


def zone_strength(lam: float, M: float, theta: float) -> float:
    """s0 of the transition parameter lambda at (M, vartheta) in the half-plane convention (Delta/R -> 0):
    lambda = 4 s0/m^(2/3), m = M vartheta (M_R* for vartheta = inf); jkrcyl.numerics.cohesive_scales."""
    pb = Problem(M, theta, 0.0)
    if pb.M == 0:
        raise ValueError("lambda: the transition parameter needs adhesion, M > 0 (w > 0), got M = 0")
    return _scales.zone_strength(finite_scalar("lambda", lam, low=0.0, low_open=True), pb.m)


def curve(M: float, theta: float, regime: str = "sub-critical", n: int = 2000, *, gb: float, a=None,
          alpha_ratio: float = 0.0, s0: Optional[float] = None) -> Curve:
    """The equilibrium branch ``regime`` at (M, vartheta): n points uniform in eps* = 2 atan(a/a_crit)/pi (over
    0 < a < 3 where a_crit = inf, Fig. 7), or at the given contact parameters a on the branch.  P* (section 6),
    delta/Delta (5.8), h(pi)/Delta (5.10), stability at fixed P, delta and delta_work (section 8.3) per point.
    s0: the cohesive law (:func:`problem`; its branches 'sub-critical' and 'contactless', a the branch parameter)."""
    pb = Problem(M, theta, gb, alpha_ratio, _law(s0))
    return _br.curve(pb, regime, count("n", n, low=2) if a is None else n, a=a)


def stationary_points(M: float, theta: float, control: str = "load", regime: str = "sub-critical", *, gb: float,
                      alpha_ratio: float = 0.0, n: Optional[int] = None, s0: Optional[float] = None) -> List[Point]:
    """All points of one branch where P* (control 'load'), delta/Delta ('grip') or delta_work/Delta
    ('grip-work') is stationary, increasing in a; ``kind`` says 'min' or 'max'.  n: a root grid of n points
    instead of the branch's dense table."""
    pb = Problem(M, theta, gb, alpha_ratio, _law(s0))
    _check_control(control)
    _br.check_regime(pb, regime)
    return _br.stationary_points(pb, control, regime, n=None if n is None else count("n", n, low=2))


def adherence(M: float, theta: float, control: str = "load", *, gb: float, regimes: Optional[Sequence[str]] = None,
              alpha_ratio: float = 0.0, confined: bool = True, s0: Optional[float] = None) -> List[Point]:
    """Adherence points, sub-critical branch first: per branch the lowest local minimum of P* (control 'load',
    the 'x' of Fig. 3), or every stationary point of the approach (the 'o'); under load ``outcome`` says what a
    further pull does (from the confined analysis where the point is infeasible, when confined=True)."""
    return adherence_of(Problem(M, theta, gb, alpha_ratio, _law(s0)), control, regimes, confined)


def adherence_of(pb: Problem, control: str = "load", regimes: Optional[Sequence[str]] = None,
                 confined: bool = True) -> List[Point]:
    """:func:`adherence` of a validated Problem (any edge law: the cohesive law's branches too)."""
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
    """Contact parameters a on a branch where P*(a) = P_star (sorted; [] if none)."""
    return _solve_field("p", "P_star", P_star, M, theta, regime, gb, alpha_ratio, n, s0)


def solve_approach(M: float, theta: float, delta_over_Delta: float, regime: str = "sub-critical", *, gb: float,
                   alpha_ratio: float = 0.0, n: Optional[int] = None) -> List[float]:
    """Contact parameters a on a branch where delta/Delta (5.8) equals the given value (sorted)."""
    return _solve_field("dn", "delta_over_Delta", delta_over_Delta, M, theta, regime, gb, alpha_ratio, n)


def _solve_field(field, name, value, M, theta, regime, gb, alpha_ratio, n, s0=None):
    pb = Problem(M, theta, gb, alpha_ratio, _law(s0))
    _br.check_regime(pb, regime)
    target = finite_scalar(name, value) * (pb.scale if field == "p" else 1.0)
    return [r for r, _ in _br.roots(pb, regime, field, target, n=None if n is None else count("n", n, low=2))]


def two_patch(M: float, theta: float, n: Optional[int] = None, *, gb: float,
              alpha_ratio: float = 0.0) -> Tuple[TwoPatchCurve, ...]:
    """Every two-patch branch (contact at the bottom and the top at once) at (M, vartheta): TwoPatchCurve fields
    plus a_top, ends; n points per branch (default: the continuation steps).  Cached per problem."""
    return _tr.branches(_two.require_finite_theta(Problem(M, theta, gb, alpha_ratio)), n)


def two_patch_state(M: float, theta: float, *, gb: float, eps: Optional[float] = None,
                    eps_top: Optional[float] = None, guess: Optional[float] = None,
                    alpha_ratio: float = 0.0) -> TwoPatchState:
    """A two-patch equilibrium with one half-angle given (eps or eps_top [rad]), the other found near ``guess``."""
    return _two.solve(Problem(M, theta, gb, alpha_ratio), eps_top=eps_top, eps=eps, guess=guess)


def confined_events(M: float, theta: float, *, gb: float, alpha_ratio: float = 0.0) -> ConfinedEvents:
    """What slow pulling under load control does to the pin in the hole (jkrcyl.analysis.confined)."""
    return _confined.confined_events(_two.require_finite_theta(Problem(M, theta, gb, alpha_ratio)))


def full_contact(theta: float, P_star: Optional[float] = None, delta_over_Delta: Optional[float] = None, *,
                 gb: float, alpha_ratio: float = 0.0) -> FullContact:
    """The pin bonded all round at a given P* or delta/Delta (exactly one): n = N0 + N1 cos(phi)."""
    return _full.state(Problem(0.0, theta, gb, alpha_ratio), P_star=P_star, delta_over_Delta=delta_over_Delta)


def from_contact(contact) -> Tuple[float, float, float]:
    """(M, vartheta, gb) of a :class:`jkrcyl.Contact` with Delta > 0 (M is M_R* when vartheta = inf)."""
    pb = Problem.of(contact)
    return pb.M, pb.theta, pb.gb


def _check_control(control):
    if not isinstance(control, str) or control not in CONTROLS:
        raise ValueError(f"control must be one of {', '.join(repr(c) for c in CONTROLS)}, got {control!r}")


def _regimes(regimes):
    if isinstance(regimes, str) or not hasattr(regimes, "__iter__"):
        raise ValueError(f"regimes must be a list of {', '.join(REGIMES)}, got {regimes!r}")
    return list(regimes)
