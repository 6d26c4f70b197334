"""What an edge law is: the interface through which the model core reaches a law (the laws themselves live in
jkrcyl.laws, one module each).

A law has two faces, as a reference solution of a contact code has:

* the **dimensional law** (jkrcyl.model.edge_law.EdgeLaw), what a user writes,
  ``Contact(..., law=Dugdale(sigma0=2e6))``: it validates its own parameters, says how the work of adhesion w
  enters the edge (EdgeLaw.edge_work, the critical energy release rate), gives the stress-intensity factor at an
  edge in equilibrium, and turns itself into
* the **normalised edge** (:class:`Edge`) of the problem of section 6 (jkrcyl.model.problem.Problem.edge):
  hashable, in the kernel scale, and the only thing the model core asks -- which single-patch solver it has
  (:meth:`Edge.single_patch`), which branch families it models (:attr:`Edge.families`), and, when a family is
  not modelled, the one message that says so (:meth:`Edge.require`).

Every analysis (forward solves, the walker, pull-off, cycles, two patches, the atlas, the fit) reaches a law
only through these two classes; a new law is a new module beside jkrcyl.laws.griffith and jkrcyl.laws.dugdale
that subclasses both.
"""
from __future__ import annotations

import math
from typing import FrozenSet

#: families beyond the sub-critical single patch; two-patch: also the walker's landing and the confined classes
FAMILIES = ("super-critical", "two-patch", "two-patch-branches", "full-contact", "contactless")


class Edge:
    """The normalised edge law of a Problem (kernel scale: nu = N R beta*/(4 pi Delta), lengths over Delta).

    Subclasses are frozen dataclasses (a Problem is a cache key), set :attr:`name`, :attr:`param` (the user's
    parameter that selects the law, named in messages) and :attr:`families`, and implement :meth:`single_patch`
    and :meth:`edge_coefficient`.

    Examples
    --------
    >>> from jkrcyl.laws import GRIFFITH_EDGE, DugdaleEdge
    >>> GRIFFITH_EDGE.name, sorted(GRIFFITH_EDGE.families)
    ('JKR', ['full-contact', 'super-critical', 'two-patch', 'two-patch-branches'])
    >>> DugdaleEdge(s0=0.1).param
    'sigma0'
    """

    name: str = "edge law"
    param: str = "law"
    families: FrozenSet[str] = frozenset()
    two_patch_family: str = ""          # its two-patch family's name (jkrcyl.analysis.two_patch_family.REGISTRY)

    def single_patch(self, problem: "jkrcyl.model.problem.Problem") -> "SinglePatch":  # pragma: no cover - interface
        """The single-patch solver of a problem with this edge (the model core's only way to the law's states).

        Parameters
        ----------
        problem : jkrcyl.model.problem.Problem
            The normalised problem (section 6), with this edge.

        Returns
        -------
        jkrcyl.model.patch.SinglePatch

        Examples
        --------
        >>> import jkrcyl
        >>> from jkrcyl.laws import GRIFFITH_EDGE
        >>> type(GRIFFITH_EDGE.single_patch(jkrcyl.equilibria.problem(0.3, 1.0, 1 / 2.8))).__name__
        'ClosedForm'
        """
        raise NotImplementedError

    def edge_coefficient(self, m: float) -> float:   # pragma: no cover - interface
        """k of nu ~ -k/sqrt(eps - |phi|) at a contact edge in equilibrium, at adhesion m = M vartheta.

        Parameters
        ----------
        m : float
            The adhesion in the kernel scale, M vartheta (M_R* for vartheta = inf), >= 0.

        Returns
        -------
        float

        Examples
        --------
        >>> import math
        >>> from jkrcyl.laws import GRIFFITH_EDGE, DugdaleEdge
        >>> GRIFFITH_EDGE.edge_coefficient(math.pi), DugdaleEdge(s0=0.1).edge_coefficient(math.pi)   # (pi k/m)^2 = G/w
        (1.0, 0.0)
        """
        raise NotImplementedError

    def bond_strength(self) -> float:
        """The largest tension -nu (kernel scale) a bonded interface holds: inf (JKR; the Maugis-Dugdale law: s0,
        an opening of the bonded pin costs s0 h and releases the tension times h)."""
        return math.inf

    def check(self, problem: "jkrcyl.model.problem.Problem") -> None:
        """Reject a problem the law cannot be used with (called once, when the Problem is made).

        Parameters
        ----------
        problem : jkrcyl.model.problem.Problem
            The problem being made.

        Returns
        -------
        None

        Raises
        ------
        ValueError
            Where the law cannot be used with the problem (the Maugis-Dugdale law: M = 0); none for JKR.

        Examples
        --------
        >>> import jkrcyl
        >>> jkrcyl.equilibria.problem(0.0, 1.0, 1 / 2.8, s0=0.1)
        Traceback (most recent call last):
        ...
        ValueError: M must be > 0 with the Maugis-Dugdale law (w > 0: lambda and h0 = w/sigma0 need it)
        """

    def range_over_Delta(self, m: float) -> float:
        """The range of the adhesive traction over the clearance: a gap below it is pulled (the top of the hole
        adheres where h(pi) falls below it, jkrcyl.analysis.landing.top_onset); 0 for an edge of zero range.

        Parameters
        ----------
        m : float
            The adhesion M vartheta (M_R* for vartheta = inf).

        Returns
        -------
        float

        Examples
        --------
        >>> from jkrcyl.laws import GRIFFITH_EDGE
        >>> GRIFFITH_EDGE.range_over_Delta(0.3)
        0.0
        """
        return 0.0

    def models(self, family: str) -> bool:
        """Whether the branch family is modelled for this law.

        Parameters
        ----------
        family : str
            One of :data:`FAMILIES` (the sub-critical single patch every law has).

        Returns
        -------
        bool

        Examples
        --------
        >>> from jkrcyl.laws import GRIFFITH_EDGE, DugdaleEdge
        >>> GRIFFITH_EDGE.models("two-patch"), DugdaleEdge(s0=0.1).models("two-patch-branches")
        (True, True)
        """
        return family in self.families

    def require(self, family: str, what: str = "", param: str = "") -> None:
        """The one place that says 'not modelled for this law'.

        Parameters
        ----------
        family : str
            One of :data:`FAMILIES`.
        what : str
            The operation, quoted in the message (default: the family).
        param : str
            The name the caller's user gave the law (e.g. the CLI's lambda); default :attr:`param`.

        Returns
        -------
        None

        Raises
        ------
        ValueError
            Naming the law's parameter (:attr:`param`), unless ``family`` is modelled.

        Examples
        --------
        >>> from jkrcyl.laws import DugdaleEdge
        >>> DugdaleEdge(s0=0.1).require("two-patch", "confined_events() is")
        Traceback (most recent call last):
        ...
        ValueError: sigma0: confined_events() is not modelled for the Maugis-Dugdale law (its branch families: ...)
        """
        why = self.not_modelled(family, what, param)
        if why:
            raise ValueError(why)

    def not_modelled(self, family: str, what: str = "", param: str = "") -> str:
        """The message of :meth:`require` where the family is not modelled, '' where it is (for a path that
        stops there rather than an error).

        Parameters
        ----------
        family, what, param : str
            As :meth:`require`.

        Returns
        -------
        str

        Examples
        --------
        >>> from jkrcyl.laws import GRIFFITH_EDGE, DugdaleEdge
        >>> GRIFFITH_EDGE.not_modelled("two-patch"), DugdaleEdge(s0=0.1).not_modelled("two-patch").split(" law")[0]
        ('', 'sigma0: two-patch not modelled for the Maugis-Dugdale')
        """
        if self.models(family):
            return ""
        modelled = ", ".join(sorted(self.families)) or "none beyond the sub-critical single patch"
        return (f"{param or self.param}: {what or family} not modelled for the {self.name} law (its branch "
                f"families: sub-critical, {modelled})")
