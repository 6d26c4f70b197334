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
    """Whether the paper's closed forms hold: alpha* = 0 (section 2; snapped to 0.0 once, where the ratio is made:
    jkrcyl.materials.snap_alpha)."""
    return alpha_ratio == 0.0


@dataclass(frozen=True)
class GriffithEdge(Edge):
    """The normalised Griffith edge: k = m/pi at an edge in equilibrium."""

    name = "JKR"
    param = "law"
    families = frozenset({"super-critical", "two-patch", "full-contact"})

    def single_patch(self, problem):
        """The closed forms where alpha* = 0, the collocation solver otherwise."""
        return ClosedForm(problem) if closed_form(problem.alpha_ratio) else Collocation(problem)

    def edge_coefficient(self, m: float) -> float:
        return m / math.pi


GRIFFITH_EDGE = GriffithEdge()


@dataclass(frozen=True)
class Griffith(EdgeLaw):
    """JKR: adhesion of zero range, the edge a crack whose critical energy release rate is w (3.5)-(3.6).

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m, law=jkrcyl.laws.Griffith())
    >>> pin == jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
    True
    """

    name = "JKR"

    def edge(self, contact) -> Edge:
        return GRIFFITH_EDGE

    def physical(self, contact, method: str = "auto"):
        """The dimensional single-patch solver of a contact (any clearance, Delta = 0 included): states, pressure
        and gap in SI units -- closed form where alpha* = 0 (method 'auto'), the collocation solver always with
        method 'numeric'."""
        return physical(contact, method)


@functools.lru_cache(maxsize=64)
def physical(contact, method="auto"):
    """:meth:`Griffith.physical` (cached per contact and method)."""
    closed = method == "closed-form" or (method == "auto" and closed_form(contact.materials.alpha_ratio))
    return (ClosedFormPhysical if closed else CollocationPhysical)(contact)
