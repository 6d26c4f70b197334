"""The Maugis-Dugdale cohesive law: the traction sigma0 wherever 0 < gap <= h0 (anywhere on the circumference),
w = sigma0 h0.

Dimensional: :class:`Dugdale` (sigma0 [Pa]).  Normalised: :class:`DugdaleEdge`, s0 = sigma0 R beta*/(4 pi Delta)
(the zone traction in the units of nu = N R beta*/(4 pi Delta)), range h0/Delta = m^2/s0; the contact edge has a
finite stress in equilibrium (edge coefficient 0, Maugis).  Its single-patch solver is jkrcyl.model.cohesive (the
contact branches with their zone on either side of the receding limit, traced; the zone-only pin); full contact
is JKR's bonded pin where the tension stays below s0 (:meth:`DugdaleEdge.bond_strength`,
jkrcyl.model.full_contact.holds); its two-patch branches are traced from JKR's where the zones are small, and as the
law's own (seeded at the top's closing) elsewhere -- none where those states fold in lambda
(jkrcyl.analysis.cohesive_two_patch, alpha* = 0) -- and where the top closes the walker lands on them
(jkrcyl.analysis.landing) and confined_events classifies them as JKR's (beyond lambda = 1000 a ValueError names
sigma0).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .._validate import HUGE, TINY, finite_scalar
from ..model.cohesive import Cohesive
from ..model.edge import Edge
from ..model.edge_law import EdgeLaw
from .griffith import GRIFFITH_EDGE


@dataclass(frozen=True)
class DugdaleEdge(Edge):
    """The normalised Maugis-Dugdale law: the zone traction s0 = sigma0 R beta*/(4 pi Delta) > 0.

    Its branch families: the sub- and super-critical single patch with its zone, the zone alone
    ('contactless'), the bonded pin ('full-contact', where the tension stays below s0) and the two-patch branches
    ('two-patch-branches'; not 'two-patch', JKR's landing on every jump: the walker lands on the law's branch
    where the top closes, jkrcyl.analysis.landing).

    Examples
    --------
    >>> DugdaleEdge(s0=0.1).models("contactless"), DugdaleEdge(s0=0.1).models("two-patch")
    (True, False)
    >>> DugdaleEdge(s0=-1.0)
    Traceback (most recent call last):
    ...
    ValueError: s0 must be in (0, inf], got -1.0
    """

    s0: float
    name = "Maugis-Dugdale"
    param = "sigma0"
    families = frozenset({"contactless", "super-critical", "full-contact", "two-patch-branches"})
    two_patch_family = "CohesiveTwoPatch"

    def __post_init__(self):
        object.__setattr__(self, "s0", finite_scalar("s0", self.s0, low=0.0, low_open=True))

    def check(self, problem: "jkrcyl.model.problem.Problem") -> None:
        """Reject a problem without adhesion (Edge.check).

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
            Naming M where M = 0 (w = 0: lambda and h0 = w/sigma0 need adhesion).

        Examples
        --------
        >>> import jkrcyl
        >>> jkrcyl.equilibria.problem(0.0, 1.0, 1 / 2.8, s0=0.1)
        Traceback (most recent call last):
        ...
        ValueError: M must be > 0 with the Maugis-Dugdale law (w > 0: lambda and h0 = w/sigma0 need it)
        """
        if problem.M == 0:
            raise ValueError("M must be > 0 with the Maugis-Dugdale law (w > 0: lambda and h0 = w/sigma0 need it)")

    def single_patch(self, problem: "jkrcyl.model.problem.Problem") -> Cohesive:
        """The cohesive single-patch solver (jkrcyl.model.cohesive): the contact branches with their zone, traced.

        Parameters
        ----------
        problem : jkrcyl.model.problem.Problem
            The normalised problem with this edge.

        Returns
        -------
        jkrcyl.model.cohesive.Cohesive

        Examples
        --------
        >>> import jkrcyl
        >>> type(DugdaleEdge(s0=0.1).single_patch(jkrcyl.equilibria.problem(0.3, 1.0, 1 / 2.8, s0=0.1))).__name__
        'Cohesive'
        """
        return Cohesive(problem)

    def bond_strength(self) -> float:
        """s0: the bonded pin holds a tension up to the zone traction (Edge.bond_strength).

        Examples
        --------
        >>> DugdaleEdge(s0=0.1).bond_strength()
        0.1
        """
        return self.s0

    def edge_coefficient(self, m: float) -> float:
        """0: a finite stress at the contact edge in equilibrium (Maugis; Edge.edge_coefficient).

        Parameters
        ----------
        m : float
            The adhesion M vartheta.

        Returns
        -------
        float

        Examples
        --------
        >>> DugdaleEdge(s0=0.1).edge_coefficient(0.3)
        0.0
        """
        return 0.0

    def range_over_Delta(self, m: float) -> float:
        """The range over the clearance, h0/Delta = m^2/s0.

        Parameters
        ----------
        m : float
            The adhesion M vartheta (M_R* for vartheta = inf).

        Returns
        -------
        float

        Examples
        --------
        >>> round(DugdaleEdge(s0=0.1).range_over_Delta(0.3), 12)
        0.9
        """
        return m * m / self.s0


def edge_of_strength(s0: "float | None") -> Edge:
    """The normalised edge of a cohesive strength s0, the normalised API's shorthand (jkrcyl.equilibria).

    Parameters
    ----------
    s0 : float or None
        sigma0 R beta*/(4 pi Delta) > 0, or None for JKR.

    Returns
    -------
    Edge
        :data:`jkrcyl.laws.GRIFFITH_EDGE` for None, else ``DugdaleEdge(s0)``.

    Raises
    ------
    ValueError
        Naming s0 outside (0, inf).

    Examples
    --------
    >>> edge_of_strength(None), edge_of_strength(0.1)
    (GriffithEdge(), DugdaleEdge(s0=0.1))
    """
    return GRIFFITH_EDGE if s0 is None else DugdaleEdge(s0)


@dataclass(frozen=True)
class Dugdale(EdgeLaw):
    """The Maugis-Dugdale cohesive law of strength sigma0 [Pa] > 0: range h0 = w/sigma0, needs w > 0 and Delta > 0.

    ``Contact(..., sigma0=s)`` is the shorthand of ``Contact(..., law=Dugdale(s))`` (the same contact); or give the
    transition parameter: :meth:`jkrcyl.Contact.with_lambda`.

    Parameters
    ----------
    sigma0 : float
        The traction wherever 0 < gap <= h0 [Pa], > 0.

    Raises
    ------
    ValueError
        Naming sigma0 outside (0, inf) (and, made into a Contact, outside the domain of its normalised strength,
        or with w = 0 or Delta = 0: :meth:`check`).

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

    def arguments(self) -> dict:
        """``{"sigma0": sigma0}``: the shorthand of this law in jkrcyl.Contact (EdgeLaw.arguments)."""
        return {"sigma0": self.sigma0}

    def check(self, contact: "jkrcyl.Contact") -> None:
        """Reject a contact without adhesion or clearance, or with a strength outside the domain (EdgeLaw.check).

        Parameters
        ----------
        contact : jkrcyl.Contact
            The contact being made.

        Returns
        -------
        None

        Raises
        ------
        ValueError
            Naming sigma0: w = 0 or Delta = 0, or sigma0 R beta*/(4 pi Delta) outside [1e-100, 1e100].

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> jkrcyl.Contact(R=10e-3, Delta=0.0, w=0.05, materials=m, sigma0=1e6)
        Traceback (most recent call last):
        ...
        ValueError: sigma0: a cohesive law needs w > 0 and Delta > 0 (h0 = w/sigma0, lengths over Delta), ...
        """
        if contact.w == 0 or contact.Delta == 0:
            raise ValueError(f"sigma0: a cohesive law needs w > 0 and Delta > 0 (h0 = w/sigma0, lengths over "
                             f"Delta), got w = {contact.w!r}, Delta = {contact.Delta!r}")
        unit = contact.R * contact.beta / (4 * math.pi * contact.Delta)      # s0 = sigma0 unit
        if not TINY <= self.sigma0 * unit <= HUGE:
            raise ValueError(f"sigma0 must be in [{TINY / unit:.6g}, {HUGE / unit:.6g}] Pa for this contact (the "
                             f"normalised strength sigma0 R beta*/(4 pi Delta) in [{TINY:g}, {HUGE:g}]), got "
                             f"{self.sigma0!r}")

    def edge(self, contact: "jkrcyl.Contact") -> DugdaleEdge:
        """The normalised law, s0 = sigma0 R beta*/(4 pi Delta) (EdgeLaw.edge).

        Parameters
        ----------
        contact : jkrcyl.Contact
            The contact (Delta > 0).

        Returns
        -------
        DugdaleEdge

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
        >>> round(Dugdale(sigma0=5e6).edge(pin).s0, 6), round(5e6 * 1e-2 * 2.8e-9 / (4 * math.pi * 1e-6), 6)
        (11.140846, 11.140846)
        """
        return DugdaleEdge(self.sigma0 * contact.R * contact.beta / (4 * math.pi * contact.Delta))

    def stress_intensity(self, contact: "jkrcyl.Contact") -> float:
        """0: the zone carries the adhesion, the contact edge has a finite stress (EdgeLaw.stress_intensity).

        Parameters
        ----------
        contact : jkrcyl.Contact
            The contact.

        Returns
        -------
        float

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
        >>> Dugdale(sigma0=5e6).stress_intensity(pin)
        0.0
        """
        return 0.0

    def range(self, contact: "jkrcyl.Contact") -> float:
        """h0 = w/sigma0 [m], the range of the traction (EdgeLaw.range).

        Parameters
        ----------
        contact : jkrcyl.Contact
            The contact (its w).

        Returns
        -------
        float

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
        >>> round(Dugdale(sigma0=5e6).range(pin) * 1e9, 9)                 # nm
        10.0
        """
        return contact.w / self.sigma0
