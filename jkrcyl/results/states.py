"""Single equilibrium states: :class:`Equilibrium` (any branch, dimensional), :class:`TwoPatchState` and
:class:`FullContact` (normalised)."""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

#: The controls: what is held fixed -> (normalised field, its slope along a Curve, the stability field, the
#: physical field).  'grip' holds the paper's approach delta (5.8) (the rims' approach, as in section 8);
#: 'grip-work' the work-conjugate delta_work = delta + P/(8 pi G_I) (derive/green.py), the displacement a
#: testing machine holding the pin controls.
CONTROLS = {"load": ("P_star", "dP_star_da", "stable_load", "P"),
            "grip": ("delta_over_Delta", "ddelta_da", "stable_grip", "delta"),
            "grip-work": ("delta_work_over_Delta", "ddelta_work_da", "stable_grip_work", "delta_work")}


@dataclass(frozen=True, repr=False)
class Equilibrium:
    """One equilibrium state, dimensional and normalised.

    branch (= regime): 'sub-critical', 'super-critical' (one patch at the bottom, a below or above a_crit),
    the same with '-top' (the patch at the top of the hole, mirrored), 'two-patch', 'full-contact', 'separated'.
    control: 'load', 'grip' or 'grip-work' (:data:`CONTROLS`), under which :attr:`stable` is judged.
    a, a_top = tan(eps/2), tan(eps_top/2) (a_top = 0 for one patch; a = inf in full contact, 0 when separated);
    eps, eps_top [rad]; contact_width = 2 R (eps + eps_top) [m]; P [N/m] positive downward; delta [m] the paper's
    approach (5.8); delta_work = delta + P/(8 pi G_I) [m] the work-conjugate approach; h_pi [m] the gap at
    phi = pi (5.10) (0 when the top is in contact); K [Pa m^1/2] the stress intensity at the bottom edge (3.4);
    P_star, delta_over_Delta, delta_work_over_Delta normalised (section 6); feasible: gap inequality h >= 0
    outside the contact; stable_load, stable_grip, stable_grip_work; side: 'bottom', 'top', 'both' or 'none';
    energy [J/m]: the total potential U - w 2 R (eps + eps_top) (elastic energy of the paper's approach delta, less
    the work of adhesion over the contact), so that dE = P d(delta) along every equilibrium branch.
    Cohesive (Maugis-Dugdale) law: branches 'sub-critical' (one contact with its zone) and 'contactless' (the zone
    alone), with '-top'; a is the branch parameter (jkrcyl.model.cohesive), K = 0 (finite stress at the edge),
    extra['c'] the zone end [rad], energy adds the Dugdale interface energy, feasible includes the law.
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
        return self.branch

    @property
    def stable(self) -> bool:
        """Stable under :attr:`control`."""
        return getattr(self, CONTROLS[self.control][2])

    @property
    def size(self) -> float:
        """Total contact half-angle eps + eps_top [rad] (the sort key)."""
        return self.eps + self.eps_top

    def held(self, control=None) -> float:
        """The physical quantity a control holds fixed: P [N/m], delta or delta_work [m]."""
        return getattr(self, CONTROLS[control or self.control][3])

    def with_control(self, control: str) -> "Equilibrium":
        return replace(self, control=control)

    def as_dict(self) -> dict:
        """Plain values (floats, bools, str) for CSV/JSON output."""
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

    eps, eps_top [rad]; a, a_top; P_star, B_star, delta_over_Delta (section 6); G_bot, G_top = G/w at the bottom
    and top ends; energy = U* (units 4 pi Delta^2 vartheta/beta*); gap_min = min h/Delta outside both arcs;
    feasible = gap_min >= 0 (to 1e-9); alpha_ratio = alpha*/beta*.
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
    def a(self):
        return math.tan(self.eps / 2)

    @property
    def a_top(self):
        return math.tan(self.eps_top / 2)

    @property
    def feasible(self):
        return self.gap_min >= -1e-9

    def pressure(self, phi):
        """n(phi) = N R beta*/(4 pi Delta vartheta) inside the arcs, 0 outside."""
        return self._lin.pressure(np.asarray(phi, dtype=float), self.delta_over_Delta)

    def gap(self, phi):
        """h(phi)/Delta (5.9) at exterior angles phi."""
        return self._lin.gap(np.asarray(phi, dtype=float), self.delta_over_Delta)


@dataclass(frozen=True)
class FullContact:
    """The pin in contact all round (eps + eps_top = pi): n(phi) = N0 + N1 cos(phi), no edge, no Griffith.

    P_star = pi N1, B_star = 2 pi N0; energy U* = [(1 + delta/Delta) P* - B*]/2 as for the arcs;
    tension_everywhere: n < 0 all round (|P*| < -pi N0, = 1 at alpha* = 0).
    """

    theta: float
    gb: float
    P_star: float
    delta_over_Delta: float
    N0: float
    N1: float
    alpha_ratio: float = 0.0

    @property
    def B_star(self):
        return 2 * math.pi * self.N0

    @property
    def energy(self):
        return 0.5 * ((1 + self.delta_over_Delta) * self.P_star - self.B_star)

    @property
    def tension_everywhere(self):
        return abs(self.N1) < -self.N0

    def pressure(self, phi):
        return self.N0 + self.N1 * np.cos(np.asarray(phi, dtype=float))

    def in_tension(self, phi):
        """Where the interface is in tension (n < 0) at the angles phi: for P* > 0 where cos(phi) < -N0/N1
        (the top and the sides), for P* < 0 where cos(phi) > N0/|N1| (the bottom and the sides)."""
        return self.pressure(phi) < 0

    @property
    def tension_half_angle(self):
        """The tensile zone as a half-angle about phi = pi (P* > 0) or phi = 0 (P* < 0): pi if the whole
        circle is in tension, 0 if none of it is (n >= 0 everywhere needs N0 >= |N1|, impossible for N0 < 0)."""
        if self.tension_everywhere:
            return math.pi
        return math.pi - math.acos(min(1.0, -self.N0 / abs(self.N1)))
