"""The normalised API of sections 6-8 on one branch: its stationary points, the adherence points of Fig. 3 and the
contacts at a given load or approach, as functions of (M, vartheta, gb, alpha*/beta*) -- re-exported by
:mod:`jkrcyl.equilibria` (its module docstring has the shared parameters)."""
from __future__ import annotations

from typing import List, Optional, Sequence

from ._validate import control as _check_control, count, finite_scalar
from .analysis import branches as _br, confined as _confined, forward as _fw
from .laws.dugdale import edge_of_strength as _law
from .model.problem import Problem
from .model.single_patch import solver
from .results import Point
from .units import CONTROLS, Units

__all__ = ["adherence", "adherence_of", "solve_approach", "solve_load", "stationary_points"]


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

    Returns
    -------
    list of jkrcyl.results.Point
        In increasing a; [] where the held quantity is monotonic.

    Raises
    ------
    ValueError
        Naming control, regime, n or a problem parameter.

    Examples
    --------
    >>> [(p.kind, round(p.a, 4), round(p.P_star, 4)) for p in stationary_points(0.3, 1.0, gb=1 / 2.8)]
    [('min', 0.3994, -0.2856)]
    """
    pb = Problem(M, theta, gb, alpha_ratio, _law(s0))
    _check_control(control)
    _br.check_regime(pb, regime)
    n = None if n is None else count("n", n, low=2)
    return _fw.stationary_points(pb, Units.normalised(pb), control, regime, n=n)


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

    Returns
    -------
    list of jkrcyl.results.Point
        Per branch (sub-critical first), with ``outcome`` under load.

    Raises
    ------
    ValueError
        Naming control, regimes or a problem parameter.

    Examples
    --------
    >>> [(p.kind, round(p.P_star, 4), p.outcome) for p in adherence(0.3, 1.0, gb=1 / 2.8)]
    [('min', -0.2856, 'detachment')]
    """
    return adherence_of(Problem(M, theta, gb, alpha_ratio, _law(s0)), control, regimes, confined)


def adherence_of(pb: Problem, control: str = "load", regimes: Optional[Sequence[str]] = None,
                 confined: bool = True, units: Optional[Units] = None) -> List[Point]:
    """:func:`adherence` of a validated problem (:func:`problem`; any edge law).

    Parameters
    ----------
    pb, control, regimes, confined
        The validated problem (jkrcyl.model.problem.Problem) and the rest as :func:`adherence`.
    units : jkrcyl.Units, optional
        The scales of the points' physical fields (default: normalised, P = P*; jkrcyl.Contact passes its own).

    Returns
    -------
    list of jkrcyl.results.Point
        As :func:`adherence`.

    Raises
    ------
    ValueError
        Naming control or regimes.

    Examples
    --------
    >>> adherence_of(Problem(0.3, 1.0, 1 / 2.8)) == adherence(0.3, 1.0, gb=1 / 2.8)
    True
    """
    _check_control(control)
    un = Units.normalised(pb) if units is None else units
    regs = solver(pb).regimes() if regimes is None else _regimes(regimes)
    out = []
    for regime in regs:
        pts = _fw.stationary_points(pb, un, control, _br.check_regime(pb, regime))
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

    Returns
    -------
    list of float
        The contact parameters a = tan(eps/2), increasing.

    Raises
    ------
    ValueError
        Naming P_star (not finite), regime, n or a problem parameter.

    Examples
    --------
    >>> [round(a, 4) for a in solve_load(0.3, 1.0, 0.0, gb=1 / 2.8)]        # the smaller root of (8.1)
    [0.7371]
    >>> from jkrcyl import zero_load_contact                                  # (8.1) solved directly
    >>> [round(a, 4) for a in zero_load_contact(0.3, 1.0)]
    [0.7371, 11.6072]
    """
    return _solve_field("load", "P_star", P_star, M, theta, regime, gb, alpha_ratio, n, s0)


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

    Returns
    -------
    list of float
        The contact parameters a = tan(eps/2), increasing.

    Raises
    ------
    ValueError
        Naming delta_over_Delta (not finite), regime, n or a problem parameter.

    Examples
    --------
    >>> [round(a, 4) for a in solve_approach(0.3, 1.0, 0.0, gb=1 / 2.8)]
    [0.6268]
    """
    return _solve_field("grip", "delta_over_Delta", delta_over_Delta, M, theta, regime, gb, alpha_ratio, n)


def _solve_field(control, name, value, M, theta, regime, gb, alpha_ratio, n, s0=None):
    field = CONTROLS[control].field
    pb = Problem(M, theta, gb, alpha_ratio, _law(s0))
    _br.check_regime(pb, regime)
    target = Units.normalised(pb).to_kernel(control, finite_scalar(name, value))
    return [r for r, _ in _br.roots(pb, regime, field, target, n=None if n is None else count("n", n, low=2))]


def _regimes(regimes):
    if isinstance(regimes, str) or not hasattr(regimes, "__iter__"):
        raise ValueError(f"regimes must be a list of {', '.join(_br.REGIMES)}, got {regimes!r}")
    return list(regimes)
