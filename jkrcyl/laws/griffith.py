"""JKR's edge law (Griffith): the contact edge is a crack in equilibrium when G = w, (3.5)-(3.6).

Dimensional: :class:`Griffith` (no parameter).  Normalised: :class:`GriffithEdge`, whose edge coefficient of
nu ~ -k/sqrt(eps - |phi|) is k = m/pi (m = M vartheta: (pi k/m)^2 = G/w = 1), with every branch family: the
super-critical side of a_crit, two patches and full contact.  This module is the only place that knows whether a
pair has a closed form: the paper's kernels where alpha* = 0 (jkrcyl.model.closed_form), the collocation of the
bordered arc otherwise (jkrcyl.model.collocation), normalised (:meth:`GriffithEdge.single_patch`) and physical
(:func:`physical`: states, pressure and gap in SI units at a given contact).
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass

from ..model.closed_form import ClosedForm, ClosedFormPhysical
from ..model.collocation import Collocation, CollocationPhysical
from ..model.edge import Edge, EdgeLaw


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


@dataclass(frozen=True)
class Griffith(EdgeLaw):
    """JKR: adhesion of zero range, the edge a crack whose critical energy release rate is w (3.5)-(3.6).

    The default law of :class:`jkrcyl.Contact` (no parameter).

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m, law=jkrcyl.laws.Griffith())
    >>> pin == jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
    True
    """

    name = "JKR"

    def edge(self, contact: "jkrcyl.Contact") -> Edge:
        """:data:`GRIFFITH_EDGE`, whatever the contact (EdgeLaw.edge).

        Parameters
        ----------
        contact : jkrcyl.Contact
            The contact.

        Returns
        -------
        GriffithEdge

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> Griffith().edge(jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)) is GRIFFITH_EDGE
        True
        """
        return GRIFFITH_EDGE

    def physical(self, contact: "jkrcyl.Contact",
                 method: str = "auto") -> "ClosedFormPhysical | CollocationPhysical":
        """The dimensional single-patch solver of a contact (any clearance, Delta = 0 included).

        States, pressure and gap in SI units (jkrcyl.Contact.state, pressure, gap): the closed form where
        alpha* = 0 (method 'auto') or always ('closed-form'), the collocation solver with method 'numeric'.

        Parameters
        ----------
        contact : jkrcyl.Contact
            The contact.
        method : str
            'auto', 'closed-form' or 'numeric' (checked by jkrcyl.Contact.state).

        Returns
        -------
        jkrcyl.model.closed_form.ClosedFormPhysical or jkrcyl.model.collocation.CollocationPhysical
            Cached per contact and method (:func:`physical`).

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
        >>> [type(Griffith().physical(pin, method)).__name__ for method in ("auto", "numeric")]
        ['ClosedFormPhysical', 'CollocationPhysical']
        """
        return physical(contact, method)


@functools.lru_cache(maxsize=64)
def physical(contact: "jkrcyl.Contact", method: str = "auto") -> "ClosedFormPhysical | CollocationPhysical":
    """:meth:`Griffith.physical`, cached per contact and method (functools.lru_cache, 64 entries).

    Parameters
    ----------
    contact : jkrcyl.Contact
        The contact.
    method : str
        'auto', 'closed-form' or 'numeric'.

    Returns
    -------
    jkrcyl.model.closed_form.ClosedFormPhysical or jkrcyl.model.collocation.CollocationPhysical

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
    >>> physical(pin, "auto") is physical(pin, "auto")
    True
    """
    closed = method == "closed-form" or (method == "auto" and closed_form(contact.materials.alpha_ratio))
    return (ClosedFormPhysical if closed else CollocationPhysical)(contact)
