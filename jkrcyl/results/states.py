"""Single equilibrium states: :class:`Equilibrium` (any branch, dimensional), :class:`TwoPatchState` and
:class:`FullContact` (normalised)."""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Optional

import numpy as np
from numpy.typing import ArrayLike

from ..units import CONTROLS


@dataclass(frozen=True, repr=False)
class Equilibrium:
    """One equilibrium state, dimensional and normalised: what :meth:`jkrcyl.Contact.solve` returns.

    Attributes
    ----------
    branch : str
        'sub-critical', 'super-critical' (one patch at the bottom, a below or above a_crit), with '-top' (mirrored
        at the top of the hole), 'two-patch', 'full-contact', 'separated'; the cohesive law: 'sub-critical' (a
        contact with its zone), 'contactless' (the zone alone), with '-top'.
    control : str
        'load', 'grip' or 'grip-work' (:data:`jkrcyl.units.CONTROLS`), under which :attr:`stable` is judged.
    a, a_top : float
        tan(eps/2), tan(eps_top/2) (0 for one patch; a = inf in full contact, 0 when separated; the branch
        parameter for the cohesive law: jkrcyl.model.cohesive).
    eps, eps_top, contact_width, K : float
        The half-angles [rad], 2 R (eps + eps_top) [m] and the stress intensity at the bottom edge (3.4)
        [Pa m^1/2] (0 for the cohesive law: finite stress).
    P, delta, delta_work, h_pi : float
        The load [N/m] (positive downward), the paper's approach (5.8), the work-conjugate approach delta +
        P/(8 pi G_I) and the gap at phi = pi (5.10) (0 when the top is in contact) [m].
    P_star, delta_over_Delta, delta_work_over_Delta : float
        Normalised (section 6).
    feasible, stable_load, stable_grip, stable_grip_work : bool
        The gap inequality h >= 0 outside the contact (and the law's); stable at fixed P, delta, delta_work.
    side : str
        'bottom', 'top', 'both' or 'none'.
    energy : float
        The total potential U - w 2 R (eps + eps_top) [J/m] (elastic energy of delta less the work of adhesion;
        plus the Dugdale interface energy for the cohesive law): dE = P d(delta) along every branch.
    extra : dict
        Law-specific fields: the cohesive law's zone ends extra['c'], extra['c_top'] [rad].

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m).solve(P=0.0)[0]
    Equilibrium(sub-critical, a=0.800455, width=0.027 m, P=-0 N/m, delta=2.962e-07 m, feasible=True, stable(load)=True)
    """

    branch: str
    control: str
    a: float
    eps: float
    contact_width: float
    P: float
    delta: float
    delta_work: float
    h_pi: float
    K: float
    P_star: float
    delta_over_Delta: float
    delta_work_over_Delta: float
    feasible: bool
    stable_load: bool
    stable_grip: bool
    stable_grip_work: bool
    side: str = "bottom"
    a_top: float = 0.0
    eps_top: float = 0.0
    energy: float = 0.0
    extra: dict = field(default_factory=dict, compare=False)

    @property
    def regime(self) -> str:
        """The same as :attr:`branch`."""
        return self.branch

    @property
    def stable(self) -> bool:
        """Stable under :attr:`control`."""
        return getattr(self, CONTROLS[self.control].stable)

    @property
    def size(self) -> float:
        """Total contact half-angle eps + eps_top [rad] (the sort key)."""
        return self.eps + self.eps_top

    def held(self, control: Optional[str] = None) -> float:
        """The physical quantity a control holds fixed: P [N/m], delta or delta_work [m].

        Parameters
        ----------
        control : str, optional
            'load', 'grip' or 'grip-work' (default: this state's :attr:`control`; KeyError for another).

        Returns
        -------
        float

        Examples
        --------
        >>> import jkrcyl                                             # the README pin (G = 1 GPa, nu = 0.3)
        >>> s = jkrcyl.Contact(R=1e-2, Delta=1e-6, w=0.05, materials=jkrcyl.Materials(1e9, 1.8, 1e9, 1.8)).solve(P=0)[0]
        >>> s.held("grip") == s.delta, s.held("grip-work") == s.delta_work
        (True, True)
        """
        return getattr(self, CONTROLS[control or self.control].physical)

    def with_control(self, control: str) -> "Equilibrium":
        """This state judged under another control (:attr:`stable` follows it).

        Parameters
        ----------
        control : str
            'load', 'grip' or 'grip-work' (not checked here: :attr:`stable` raises KeyError for another).

        Returns
        -------
        Equilibrium

        Examples
        --------
        >>> import jkrcyl                                             # the README pin (G = 1 GPa, nu = 0.3)
        >>> s = jkrcyl.Contact(R=1e-2, Delta=1e-6, w=0.05, materials=jkrcyl.Materials(1e9, 1.8, 1e9, 1.8)).solve(P=0)[0]
        >>> s.with_control("grip").stable == s.stable_grip
        True
        """
        return replace(self, control=control)

    def as_dict(self) -> dict:
        """Plain values (floats, bools, str) for CSV/JSON output.

        Returns
        -------
        dict
            The fields but ``control``, ``energy`` and ``extra``, and :attr:`stable`.

        Examples
        --------
        >>> import jkrcyl                                             # the README pin (G = 1 GPa, nu = 0.3)
        >>> s = jkrcyl.Contact(R=1e-2, Delta=1e-6, w=0.05, materials=jkrcyl.Materials(1e9, 1.8, 1e9, 1.8)).solve(P=0)[0]
        >>> d = s.as_dict()
        >>> d["branch"], round(d["contact_width"] * 1e3, 3), d["stable"]          # width in mm
        ('sub-critical', 27.001, True)
        """
        keys = ("branch", "side", "a", "a_top", "eps", "eps_top", "contact_width", "P", "delta", "delta_work",
                "h_pi", "K", "P_star", "delta_over_Delta", "delta_work_over_Delta", "feasible", "stable_load",
                "stable_grip", "stable_grip_work", "stable")
        return {k: getattr(self, k) for k in keys}

    def __repr__(self) -> str:
        return (f"Equilibrium({self.branch}, a={self.a:.6g}, width={self.contact_width:.4g} m, "
                f"P={self.P:.6g} N/m, delta={self.delta:.4g} m, feasible={self.feasible}, "
                f"stable({self.control})={self.stable})")


@dataclass(frozen=True)
class TwoPatchState:
    """One two-patch equilibrium (or any fixed-arc state: jkrcyl.model.two_patch.fixed_arcs), normalised.

    What :func:`jkrcyl.equilibria.two_patch_state` returns.

    Attributes
    ----------
    M, theta, gb, alpha_ratio : float
        The problem (section 6).
    eps, eps_top : float
        The half-angles of the bottom and top contacts [rad] (:attr:`a`, :attr:`a_top`: their tan(eps/2)).
    P_star, B_star, delta_over_Delta, energy : float
        Normalised load, B (4.5a), approach (section 6) and U* (units 4 pi Delta^2 vartheta/beta*).
    G_bot, G_top, gap_min : float
        G/w at the bottom and top edges (1 at an equilibrium); min h/Delta outside both arcs (>= 0: feasible).

    Examples
    --------
    >>> import jkrcyl
    >>> s = jkrcyl.equilibria.two_patch_state(0.5, 1.0, gb=1 / 2.8, eps=1.0, guess=0.003)
    >>> round(s.a, 4), round(s.a_top, 6), s.feasible
    (0.5463, 0.001341, True)
    """

    M: float
    theta: float
    gb: float
    eps: float
    eps_top: float
    P_star: float
    B_star: float
    delta_over_Delta: float
    G_bot: float
    G_top: float
    energy: float
    gap_min: float
    alpha_ratio: float = 0.0
    _lin: object = None

    @property
    def a(self) -> float:
        """tan(eps/2)."""
        return math.tan(self.eps / 2)

    @property
    def a_top(self) -> float:
        """tan(eps_top/2)."""
        return math.tan(self.eps_top / 2)

    @property
    def feasible(self) -> bool:
        """The gap inequality, gap_min >= 0 (to 1e-9)."""
        return self.gap_min >= -1e-9

    def pressure(self, phi: ArrayLike) -> np.ndarray:
        """The normalised pressure n(phi) = N R beta*/(4 pi Delta vartheta) inside the arcs, 0 outside.

        Parameters
        ----------
        phi : float or array_like
            Angles from the bottom of the hole [rad].

        Examples
        --------
        >>> import jkrcyl
        >>> s = jkrcyl.equilibria.two_patch_state(0.5, 1.0, gb=1 / 2.8, eps=1.0, guess=0.003)
        >>> [round(float(n), 4) for n in s.pressure([0.0, 2.0])]           # in the bottom arc; outside both
        [-0.3786, 0.0]
        """
        return self._lin.pressure(np.asarray(phi, dtype=float), self.delta_over_Delta)

    def gap(self, phi: ArrayLike) -> np.ndarray:
        """h(phi)/Delta (5.9) at exterior angles phi [rad] (outside both arcs).

        Parameters
        ----------
        phi : float or array_like
            Angles from the bottom of the hole [rad], outside the arcs.

        Examples
        --------
        >>> import jkrcyl
        >>> s = jkrcyl.equilibria.two_patch_state(0.5, 1.0, gb=1 / 2.8, eps=1.0, guess=0.003)
        >>> round(float(s.gap([2.0])[0]), 4), bool(s.gap([2.0])[0] >= s.gap_min)
        (0.9611, True)
        """
        return self._lin.gap(np.asarray(phi, dtype=float), self.delta_over_Delta)


@dataclass(frozen=True)
class FullContact:
    """The pin in contact all round (eps + eps_top = pi): n(phi) = N0 + N1 cos(phi), no edge, no Griffith.

    What :func:`jkrcyl.equilibria.full_contact` returns.

    Attributes
    ----------
    theta, gb, alpha_ratio : float
        The problem (section 6).
    P_star, delta_over_Delta : float
        Load and approach (section 6); P* = pi N1.
    N0, N1 : float
        The normalised pressure n = N R beta*/(4 pi Delta vartheta) = N0 + N1 cos(phi).

    Examples
    --------
    >>> import jkrcyl
    >>> f = jkrcyl.equilibria.full_contact(1.0, P_star=1.5, gb=1 / 2.8)
    >>> round(f.B_star, 12), round(f.energy, 6), f.tension_everywhere
    (-2.0, 1.160714, False)
    >>> round(f.tension_half_angle, 12) == round(math.pi - math.acos(1 / 1.5), 12)     # cos(phi) < -N0/N1
    True
    """

    theta: float
    gb: float
    P_star: float
    delta_over_Delta: float
    N0: float
    N1: float
    alpha_ratio: float = 0.0

    @property
    def B_star(self) -> float:
        """B* = 2 pi N0."""
        return 2 * math.pi * self.N0

    @property
    def energy(self) -> float:
        """U* = [(1 + delta/Delta) P* - B*]/2, as for the arcs."""
        return 0.5 * ((1 + self.delta_over_Delta) * self.P_star - self.B_star)

    @property
    def tension_everywhere(self) -> bool:
        """n < 0 all round: |P*| < -pi N0 (= 1 at alpha* = 0)."""
        return abs(self.N1) < -self.N0

    def pressure(self, phi: ArrayLike) -> np.ndarray:
        """n(phi) = N0 + N1 cos(phi), compressive positive.

        Parameters
        ----------
        phi : float or array_like
            Angles from the bottom of the hole [rad].

        Examples
        --------
        >>> import jkrcyl
        >>> f = jkrcyl.equilibria.full_contact(1.0, P_star=1.5, gb=1 / 2.8)
        >>> [round(float(n) * math.pi, 12) for n in f.pressure([0.0, math.pi])]      # (-1 + 1.5), (-1 - 1.5)
        [0.5, -2.5]
        """
        return self.N0 + self.N1 * np.cos(np.asarray(phi, dtype=float))

    def in_tension(self, phi: ArrayLike) -> np.ndarray:
        """Where the interface is in tension (n < 0) at the angles phi.

        For P* > 0 where cos(phi) < -N0/N1 (the top and the sides), for P* < 0 where cos(phi) > N0/|N1| (the
        bottom and the sides).

        Parameters
        ----------
        phi : float or array_like
            Angles from the bottom of the hole [rad].

        Examples
        --------
        >>> import jkrcyl
        >>> jkrcyl.equilibria.full_contact(1.0, P_star=1.5, gb=1 / 2.8).in_tension([0.0, math.pi]).tolist()
        [False, True]
        """
        return self.pressure(phi) < 0

    @property
    def tension_half_angle(self) -> float:
        """The tensile zone as a half-angle about phi = pi (P* > 0) or phi = 0 (P* < 0) [rad].

        pi if the whole circle is in tension, 0 if none of it is (n >= 0 everywhere needs N0 >= |N1|, impossible
        for N0 < 0)."""
        if self.tension_everywhere:
            return math.pi
        return math.pi - math.acos(min(1.0, -self.N0 / abs(self.N1)))
