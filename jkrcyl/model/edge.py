"""What an edge law is: the interface through which the model core reaches a law (the laws themselves live in
jkrcyl.laws, one module each).

A law has two faces, as a reference solution of a contact code has:

* the **dimensional law** (:class:`EdgeLaw`), what a user writes, ``Contact(..., law=Dugdale(sigma0=2e6))``: it
  validates its own parameters, says how the work of adhesion w enters the edge (:meth:`EdgeLaw.edge_work`, the
  critical energy release rate), gives the stress-intensity factor at an edge in equilibrium, and turns itself
  into
* the **normalised edge** (:class:`Edge`) of the problem of section 6 (jkrcyl.model.problem.Problem.edge):
  hashable, in the kernel scale, and the only thing the model core asks -- which single-patch solver it has
  (:meth:`Edge.single_patch`), which branch families it models (:attr:`Edge.families`), and, when a family is
  not modelled, the one message that says so (:meth:`Edge.require`).

Every analysis (forward solves, the walker, pull-off, cycles, two patches, the atlas, the fit) reaches a law
only through these two classes; a new law is a new module beside jkrcyl.laws.griffith and jkrcyl.laws.dugdale that subclasses both.
"""
from __future__ import annotations

import math
from typing import FrozenSet

#: branch families beyond the sub-critical single patch (which every law has)
FAMILIES = ("super-critical", "two-patch", "full-contact", "contactless")


class Edge:
    """The normalised edge law of a Problem (kernel scale: nu = N R beta*/(4 pi Delta), lengths over Delta).

    Subclasses are frozen dataclasses (a Problem is a cache key) and set :attr:`name`, :attr:`param` (the user's
    parameter that selects the law, named in messages) and :attr:`families`, and implement
    :meth:`single_patch`."""

    name: str = "edge law"
    param: str = "law"
    families: FrozenSet[str] = frozenset()

    def single_patch(self, problem):            # pragma: no cover - interface
        """The single-patch solver (a jkrcyl.model.patch.SinglePatch) of a problem with this edge."""
        raise NotImplementedError

    def edge_coefficient(self, m: float) -> float:   # pragma: no cover - interface
        """k of nu ~ -k/sqrt(eps - |phi|) at a contact edge in equilibrium, at adhesion m = M vartheta."""
        raise NotImplementedError

    def check(self, problem) -> None:
        """ValueError where the law cannot be used with this problem (called once, when the Problem is made)."""

    def models(self, family: str) -> bool:
        """Whether the branch family (:data:`FAMILIES`) is modelled for this law."""
        return family in self.families

    def require(self, family: str, what: str = "") -> None:
        """ValueError, naming the law's parameter, unless ``family`` is modelled: the one place that says
        'not modelled for this law'."""
        if not self.models(family):
            modelled = ", ".join(sorted(self.families)) or "none beyond the sub-critical single patch"
            raise ValueError(f"{self.param}: {what or family} not modelled for the {self.name} law (its branch "
                             f"families: sub-critical, {modelled})")


class EdgeLaw:
    """A dimensional edge law (what ``Contact(..., law=...)`` takes).  Subclasses are frozen dataclasses.

    The defaults are JKR's: the edge is a crack whose critical energy release rate is w (Griffith, (3.5)-(3.6));
    a law changes what it needs to."""

    name: str = "edge law"
    param: str = "law"          # the user's parameter that selects the law, named in messages

    def edge_work(self, w: float) -> float:
        """The energy per unit area the edge condition asks for, G_c [J/m^2] at a contact edge in equilibrium:
        w for JKR.  It is what enters the normalised adhesion M = sqrt(G_c A R)/(sqrt(2) Delta vartheta)."""
        return w

    def check(self, contact) -> None:
        """ValueError (naming this law's parameter) where the law cannot be used with this contact."""

    def edge(self, contact) -> Edge:             # pragma: no cover - interface
        """The normalised edge of this law for a contact (Delta > 0)."""
        raise NotImplementedError

    def stress_intensity(self, contact) -> float:
        """K [Pa m^1/2] at a contact edge in equilibrium: (pi/4) A K^2 = G_c, A = beta*/(2 pi) (3.5)-(3.6)."""
        return math.sqrt(8 * self.edge_work(contact.w) / contact.beta)

    def range(self, contact) -> float:
        """The range of the adhesive traction [m]: 0 for an edge of zero range (JKR)."""
        return 0.0
