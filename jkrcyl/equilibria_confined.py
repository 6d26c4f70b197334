"""The normalised API of the confined regime (sections 5 and 8): two patches, full contact and what slow pulling
does, as functions of (M, vartheta, gb, alpha*/beta*) -- re-exported by :mod:`jkrcyl.equilibria` (its module
docstring has the shared parameters)."""
from __future__ import annotations

from typing import Optional, Tuple

from .analysis import confined as _confined
from .analysis.two_patch_family import family as _family
from .laws.dugdale import edge_of_strength
from .model import full_contact as _full, two_patch as _two
from .model.problem import Problem
from .results import ConfinedEvents, FullContact, TwoPatchCurve, TwoPatchState

__all__ = ["confined_events", "full_contact", "two_patch", "two_patch_state"]


def two_patch(M: float, theta: float, n: Optional[int] = None, *, gb: float, alpha_ratio: float = 0.0,
              s0: Optional[float] = None) -> Tuple[TwoPatchCurve, ...]:
    """Every two-patch branch (contact at the bottom and the top at once), traced; cached per problem.

    Parameters
    ----------
    M, theta, gb, alpha_ratio, s0
        The problem (:func:`problem`; vartheta finite; s0: the Maugis-Dugdale law, alpha_ratio = 0, its branches
        followed from JKR's by jkrcyl.analysis.cohesive_two_patch).
    n : int, optional
        Points per branch, evenly along it (default: the continuation steps of jkrcyl.analysis.tracing; with s0,
        JKR's branch resampled to 12 points, the states down to an arc of 1e-4 rad added at an end on an axis).

    Returns
    -------
    tuple of jkrcyl.results.TwoPatchCurve
        Every branch, each ordered along the curve with how its ends finish; () where no single patch closes the
        gap at the top.

    Raises
    ------
    ValueError
        Naming theta (inf: no top to close), n, alpha_ratio (not 0 with s0) or a problem parameter.

    Examples
    --------
    >>> [b.ends for b in two_patch(0.5, 1.0, gb=1 / 2.8)]
    [('single', 'mirror')]
    """
    return _family(Problem(M, theta, gb, alpha_ratio, edge_of_strength(s0))).branches(n)


def two_patch_state(M: float, theta: float, *, gb: float, eps: Optional[float] = None, eps_top: Optional[float] = None,
                    guess: Optional[float] = None, alpha_ratio: float = 0.0, s0: Optional[float] = None
                    ) -> TwoPatchState:
    """The two-patch equilibrium (G = w at both edges) with one half-angle given, the other found from ``guess``.

    Parameters
    ----------
    M, theta, gb, alpha_ratio, s0
        The problem (:func:`problem`; vartheta finite; s0: the Maugis-Dugdale law, solved from JKR's state).
    eps, eps_top : float
        Exactly one: the half-angle of the bottom or the top contact [rad], in (0, pi).
    guess : float, optional
        Start of the other half-angle [rad]; the error names guess where no equilibrium is found near it.

    Returns
    -------
    jkrcyl.results.TwoPatchState
        Both half-angles, P*, delta/Delta, the gap and G/w at both edges.

    Raises
    ------
    ValueError
        Naming eps/eps_top (not exactly one, outside (0, pi)) or guess (no equilibrium near it).

    Examples
    --------
    >>> s = two_patch_state(0.5, 1.0, gb=1 / 2.8, eps=1.0, guess=0.003)
    >>> round(float(s.eps_top), 5), round(s.P_star, 4), round(s.G_bot, 9), round(s.G_top, 9)
    (0.00268, -0.7062, 1.0, 1.0)
    """
    return _family(Problem(M, theta, gb, alpha_ratio, edge_of_strength(s0))).state(eps, eps_top, guess)


def confined_events(M: float, theta: float, *, gb: float, alpha_ratio: float = 0.0,
                    s0: Optional[float] = None) -> ConfinedEvents:
    """What slow pulling under load control does to the pin in the hole (jkrcyl.analysis.confined).

    Parameters
    ----------
    M, theta, gb, alpha_ratio, s0
        The problem (:func:`problem`; vartheta finite; s0: the Maugis-Dugdale law, alpha_ratio = 0, where the
        top closes the walker landing on the law's traced two-patch branch).

    Returns
    -------
    jkrcyl.results.ConfinedEvents
        The regime (:data:`jkrcyl.results.paths.REGIMES`), the fold or gap-closing load and the branches.

    Raises
    ------
    ValueError
        Naming theta (inf), a problem parameter, or s0 where the law's two-patch branches are not followed.

    Examples
    --------
    >>> (ev := confined_events(0.3, 1.0, gb=1 / 2.8)).regime, round(ev.P_fold, 4)
    ('detachment', -0.2856)
    """
    pb = Problem(M, theta, gb, alpha_ratio, edge_of_strength(s0)).require("two-patch-branches",
                                                                          "confined_events() is")
    return _confined.confined_events(_two.require_two_patch(pb))


def full_contact(theta: float, P_star: Optional[float] = None, delta_over_Delta: Optional[float] = None, *,
                 gb: float, alpha_ratio: float = 0.0) -> FullContact:
    """The pin bonded all round at a given P* or delta/Delta: n(phi) = N0 + N1 cos(phi), N1 = P*/pi.

    Parameters
    ----------
    theta, gb, alpha_ratio
        The problem (:func:`problem`; vartheta finite; no M: full contact has no edge).
    P_star, delta_over_Delta : float
        Exactly one: the load (section 6) or the approach over the clearance.

    Returns
    -------
    jkrcyl.results.FullContact
        The pressure N0 + N1 cos(phi), P*, delta/Delta and the energy.

    Raises
    ------
    ValueError
        Naming P_star/delta_over_Delta (not exactly one; an approach that fixes no load) or theta.

    Examples
    --------
    >>> import math
    >>> f = full_contact(1.0, P_star=1.5, gb=1 / 2.8)        # -pi N0 = 1 at alpha* = 0
    >>> round(-math.pi * f.N0, 12), round(math.pi * f.N1, 12)
    (1.0, 1.5)
    """
    return _full.state(Problem(0.0, theta, gb, alpha_ratio), P_star=P_star, delta_over_Delta=delta_over_Delta)
