"""JKR's edge law (Griffith): the contact edge is a crack in equilibrium when G = w, (3.5)-(3.6).

Dimensional: :class:`Griffith` (no parameter) and :func:`physical` (states, pressure and gap in SI units at a
given contact: the closed form where alpha* = 0, else the collocation).  Normalised: :class:`GriffithEdge` (k =
m/pi, every branch family), the model core's default edge, defined in jkrcyl.model.griffith (the core imports no
law) and re-exported here with :func:`closed_form` (whether a pair has the paper's closed forms).
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

from ..model.closed_form import ClosedFormPhysical
from ..model.collocation import CollocationPhysical
from ..model.edge import Edge
from ..model.edge_law import EdgeLaw
from ..model.griffith import GRIFFITH_EDGE, GriffithEdge, closed_form

__all__ = ["GRIFFITH_EDGE", "Griffith", "GriffithEdge", "closed_form", "physical"]


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
