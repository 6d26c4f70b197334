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
from typing import Optional, Tuple

from numpy.typing import ArrayLike

from ._validate import CONTROLS, count, finite_scalar, theta as _check_theta
from .analysis import branches as _br
from . import equilibria_bridge as _bridge
from .critical import a_crit
from .equilibria_confined import confined_events, full_contact, two_patch, two_patch_state
from .equilibria_points import adherence, adherence_of, solve_approach, solve_load, stationary_points
from .laws.dugdale import edge_of_strength as _law
from .model.problem import Problem
from .numerics import cohesive_scales as _scales
from .numerics.zero_load import zero_load_contact, zero_load_max_M
from .results import Curve

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

    Returns
    -------
    float
        gb in [0, 1].

    Raises
    ------
    ValueError
        Naming theta.

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

    Returns
    -------
    jkrcyl.model.problem.Problem
        Validated, hashable (the cache key of every table).

    Raises
    ------
    ValueError
        Naming the parameter outside its range.

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

    Returns
    -------
    float
        s0 = sigma0 R beta*/(4 pi Delta) > 0.

    Raises
    ------
    ValueError
        Naming lambda (not > 0, or M = 0).

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
        'sub-critical', 'super-critical' (a below, above a_crit); cohesive: 'sub-critical', 'contactless',
        'top-bridge' (a zone at the top held by its own traction: jkrcyl.equilibria_bridge.curve, as traced).
    n : int
        Points uniform in eps* = 2 atan(a/a_crit)/pi (over 0 < a < 3 where a_crit = inf, Fig. 7), >= 2 (not used
        for 'top-bridge').
    a : array_like, optional
        The contact parameters on the branch instead of the uniform grid.

    Returns
    -------
    jkrcyl.results.Curve
        Normalised fields, slopes and the stability flags under the three controls, over a increasing.

    Raises
    ------
    ValueError
        Naming M, theta, gb, alpha_ratio, s0, regime or n outside its range; naming regime for 'top-bridge'
        where there is none (JKR: its top adheres at h(pi) = 0).

    Examples
    --------
    >>> c = curve(0.3, 1.0, n=5, gb=1 / 2.8)
    >>> [round(float(p), 4) for p in c.P_star], c.stable_load.tolist()
    ([-0.1569, -0.2507, -0.2851, -0.2482, 0.1787], [False, False, False, True, True])
    """
    pb = Problem(M, theta, gb, alpha_ratio, _law(s0))
    if _bridge.check_regime(regime) == _bridge.TOP_BRIDGE:
        count("n", n, low=2)
        return _bridge.curve(pb, a)
    return _br.curve(pb, regime, count("n", n, low=2) if a is None else n, a=a)


def from_contact(contact: "jkrcyl.Contact") -> Tuple[float, float, float]:
    """(M, vartheta, gb) of a :class:`jkrcyl.Contact` (M is M_R* when vartheta = inf; ValueError for Delta = 0).

    Parameters
    ----------
    contact : jkrcyl.Contact
        A contact with clearance Delta > 0 (the normalisation divides by it).

    Returns
    -------
    tuple of float
        (M, vartheta, gb): the arguments of every function here.

    Raises
    ------
    ValueError
        Naming Delta (= 0).

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
