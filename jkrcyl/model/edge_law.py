"""The dimensional face of an edge law (jkrcyl.model.edge has the normalised one and the overview): what
``Contact(..., law=...)`` takes, validating its parameters, saying how w enters the edge and giving its normalised
twin (:meth:`EdgeLaw.edge`)."""
from __future__ import annotations

import math

from .edge import Edge


class EdgeLaw:
    """A dimensional edge law (what ``Contact(..., law=...)`` takes).  Subclasses are frozen dataclasses.

    The defaults are JKR's: the edge is a crack whose critical energy release rate is w (Griffith, (3.5)-(3.6));
    a law changes what it needs to, and implements :meth:`edge`.

    Examples
    --------
    >>> import jkrcyl
    >>> [law.name for law in (jkrcyl.laws.Griffith(), jkrcyl.laws.Dugdale(sigma0=5e6))]
    ['JKR', 'Maugis-Dugdale']
    """

    name: str = "edge law"
    param: str = "law"          # the user's parameter that selects the law, named in messages

    def edge_work(self, w: float) -> float:
        """The energy per unit area the edge condition asks for, G_c [J/m^2] at a contact edge in equilibrium.

        It is what enters the normalised adhesion M = sqrt(G_c A R)/(sqrt(2) Delta vartheta) (section 6).

        Parameters
        ----------
        w : float
            The work of adhesion [J/m^2].

        Returns
        -------
        float
            G_c [J/m^2]: w for JKR.

        Examples
        --------
        >>> import jkrcyl
        >>> jkrcyl.laws.Griffith().edge_work(0.05)
        0.05
        """
        return w

    def check(self, contact: "jkrcyl.Contact") -> None:
        """Reject a contact the law cannot be used with (called once, when the Contact is made).

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
            Naming this law's parameter (the Maugis-Dugdale law: sigma0, for w = 0, Delta = 0 or a strength
            outside the domain); none for JKR.

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.0, materials=m, sigma0=1e6)
        Traceback (most recent call last):
        ...
        ValueError: sigma0: a cohesive law needs w > 0 and Delta > 0 (h0 = w/sigma0, lengths over Delta), ...
        """

    def arguments(self) -> dict:
        """The keyword arguments of jkrcyl.Contact that make this law: ``{"law": self}``, or a law's shorthand.

        Returns
        -------
        dict
            ``{"law": self}`` (Dugdale: ``{"sigma0": sigma0}``, its shorthand: the same contact either way).

        Examples
        --------
        >>> import jkrcyl
        >>> jkrcyl.laws.Griffith().arguments()
        {'law': Griffith()}
        >>> jkrcyl.laws.Dugdale(sigma0=5e6).arguments()
        {'sigma0': 5000000.0}
        """
        return {"law": self}

    def edge(self, contact: "jkrcyl.Contact") -> Edge:             # pragma: no cover - interface
        """The normalised edge of this law for a contact (Delta > 0): what the model core asks.

        Parameters
        ----------
        contact : jkrcyl.Contact
            The contact (its ``problem`` carries the edge).

        Returns
        -------
        Edge

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
        >>> round(jkrcyl.laws.Dugdale(sigma0=5e6).edge(pin).s0, 6)         # sigma0 R beta*/(4 pi Delta)
        11.140846
        """
        raise NotImplementedError

    def stress_intensity(self, contact: "jkrcyl.Contact") -> float:
        """K [Pa m^1/2] at a contact edge in equilibrium: (pi/4) A K^2 = G_c, A = beta*/(2 pi) (3.5)-(3.6).

        Parameters
        ----------
        contact : jkrcyl.Contact
            The contact (its w and beta*).

        Returns
        -------
        float

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
        >>> round(pin.law.stress_intensity(pin)), round(float(pin.state(0.5).K))         # the state's K (3.4)
        (11952, 11952)
        """
        return math.sqrt(8 * self.edge_work(contact.w) / contact.beta)

    def range(self, contact: "jkrcyl.Contact") -> float:
        """The range of the adhesive traction [m]: 0 for an edge of zero range (JKR).

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
        >>> jkrcyl.laws.Griffith().range(jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m))
        0.0
        """
        return 0.0
