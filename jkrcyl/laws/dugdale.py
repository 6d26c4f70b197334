"""The Maugis-Dugdale cohesive law: the traction sigma0 wherever 0 < gap <= h0 (anywhere on the circumference),
w = sigma0 h0.

Dimensional: :class:`Dugdale` (sigma0 [Pa]).  Normalised: :class:`DugdaleEdge`, s0 = sigma0 R beta*/(4 pi Delta)
(the zone traction in the units of nu = N R beta*/(4 pi Delta)), range h0/Delta = m^2/s0; the contact edge has a
finite stress in equilibrium (edge coefficient 0, Maugis).  Its single-patch solver is jkrcyl.model.cohesive (the
contact branch with its zone, traced; the zone-only pin); the super-critical side, two patches and full contact are
not modelled for it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .._validate import HUGE, TINY, finite_scalar
from ..model.cohesive import Cohesive
from ..model.edge import Edge, EdgeLaw
from .griffith import GRIFFITH_EDGE


@dataclass(frozen=True)
class DugdaleEdge(Edge):
    """The normalised Maugis-Dugdale law: s0 > 0."""

    s0: float
    name = "Maugis-Dugdale"
    param = "sigma0"
    families = frozenset({"contactless"})

    def __post_init__(self):
        object.__setattr__(self, "s0", finite_scalar("s0", self.s0, low=0.0, low_open=True))

    def check(self, problem) -> None:
        if problem.M == 0:
            raise ValueError("M must be > 0 with the Maugis-Dugdale law (w > 0: lambda and h0 = w/sigma0 need it)")

    def single_patch(self, problem):
        return Cohesive(problem)

    def edge_coefficient(self, m: float) -> float:
        return 0.0

    def range_over_Delta(self, m: float) -> float:
        """h0/Delta = m^2/s0."""
        return m * m / self.s0


def edge_of_strength(s0):
    """The normalised edge of a cohesive strength s0 (the normalised API's shorthand): None -> JKR's Griffith
    edge, else DugdaleEdge(s0)."""
    return GRIFFITH_EDGE if s0 is None else DugdaleEdge(s0)


@dataclass(frozen=True)
class Dugdale(EdgeLaw):
    """The Maugis-Dugdale cohesive law of strength sigma0 [Pa] > 0: range h0 = w/sigma0, needs w > 0 and Delta > 0.
    ``Contact(..., sigma0=s)`` is the shorthand of ``Contact(..., law=Dugdale(s))`` (the same contact).

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m, law=jkrcyl.laws.Dugdale(sigma0=5e6))
    >>> pin == jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m, sigma0=5e6)
    True
    >>> round(pin.h0 * 1e9, 3)       # w/sigma0 [nm]
    10.0
    """

    sigma0: float
    name = "Maugis-Dugdale"
    param = "sigma0"

    def __post_init__(self):
        object.__setattr__(self, "sigma0", finite_scalar("sigma0", self.sigma0, low=0.0, low_open=True))

    def check(self, contact) -> None:
        if contact.w == 0 or contact.Delta == 0:
            raise ValueError(f"sigma0: a cohesive law needs w > 0 and Delta > 0 (h0 = w/sigma0, lengths over "
                             f"Delta), got w = {contact.w!r}, Delta = {contact.Delta!r}")
        unit = contact.R * contact.beta / (4 * math.pi * contact.Delta)      # s0 = sigma0 unit
        if not TINY <= self.sigma0 * unit <= HUGE:
            raise ValueError(f"sigma0 must be in [{TINY / unit:.6g}, {HUGE / unit:.6g}] Pa for this contact (the "
                             f"normalised strength sigma0 R beta*/(4 pi Delta) in [{TINY:g}, {HUGE:g}]), got "
                             f"{self.sigma0!r}")

    def edge(self, contact) -> Edge:
        return DugdaleEdge(self.sigma0 * contact.R * contact.beta / (4 * math.pi * contact.Delta))

    def stress_intensity(self, contact) -> float:
        """0: the zone carries the adhesion, the contact edge has a finite stress."""
        return 0.0

    def range(self, contact) -> float:
        """h0 = w/sigma0 [m]."""
        return contact.w / self.sigma0
