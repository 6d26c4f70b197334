"""JKR's Griffith edge, normalised: the model core's default edge law (jkrcyl.model.problem.Problem).

The edge coefficient of nu ~ -k/sqrt(eps - |phi|) is k = m/pi (m = M vartheta: (pi k/m)^2 = G/w = 1, (3.5)-(3.6)),
with every branch family: the super-critical side of a_crit, two patches and full contact.  This module is the
only place that knows whether a pair has a closed form: the paper's kernels where alpha* = 0
(jkrcyl.model.closed_form), the collocation of the bordered arc otherwise (jkrcyl.model.collocation).  It lives in
the core (not in jkrcyl.laws, which re-exports it with the dimensional law jkrcyl.laws.Griffith) so that the core
imports no law: the laws build on it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .closed_form import ClosedForm
from .collocation import Collocation
from .edge import Edge


def closed_form(alpha_ratio: float) -> bool:
    """Whether the paper's closed forms hold: alpha* = 0 (section 2).

    Parameters
    ----------
    alpha_ratio : float
        alpha*/beta*, snapped to 0.0 once where the ratio is made (jkrcyl.materials.snap_alpha).

    Returns
    -------
    bool

    Examples
    --------
    >>> closed_form(0.0), closed_form(0.1167)
    (True, False)
    """
    return alpha_ratio == 0.0


@dataclass(frozen=True)
class GriffithEdge(Edge):
    """The normalised Griffith edge: k = m/pi at an edge in equilibrium ((pi k/m)^2 = G/w = 1).

    Every branch family is modelled: the super-critical side of a_crit, two patches and full contact.  The one
    instance is :data:`GRIFFITH_EDGE`.

    Examples
    --------
    >>> GRIFFITH_EDGE == GriffithEdge(), GRIFFITH_EDGE.edge_coefficient(math.pi)
    (True, 1.0)
    """

    name = "JKR"
    param = "law"
    families = frozenset({"super-critical", "two-patch", "two-patch-branches", "full-contact"})
    two_patch_family = "JKRTwoPatch"

    def single_patch(self, problem: "jkrcyl.model.problem.Problem") -> "ClosedForm | Collocation":
        """The single-patch solver: the closed forms where alpha* = 0, the collocation solver otherwise.

        Parameters
        ----------
        problem : jkrcyl.model.problem.Problem
            The normalised problem (section 6).

        Returns
        -------
        jkrcyl.model.closed_form.ClosedForm or jkrcyl.model.collocation.Collocation

        Examples
        --------
        >>> import jkrcyl
        >>> [type(GRIFFITH_EDGE.single_patch(jkrcyl.equilibria.problem(0.3, 1.0, 0.3, ar))).__name__ for ar in (0, 0.1)]
        ['ClosedForm', 'Collocation']
        """
        return ClosedForm(problem) if closed_form(problem.alpha_ratio) else Collocation(problem)

    def edge_coefficient(self, m: float) -> float:
        """k = m/pi (Edge.edge_coefficient).

        Parameters
        ----------
        m : float
            The adhesion M vartheta (M_R* for vartheta = inf).

        Returns
        -------
        float

        Examples
        --------
        >>> GRIFFITH_EDGE.edge_coefficient(2 * math.pi)
        2.0
        """
        return m / math.pi


GRIFFITH_EDGE = GriffithEdge()
