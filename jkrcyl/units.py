"""Controls and units, one home: the names a held quantity goes by, and the one object that makes a normalised
answer physical.

Three scales meet in jkrcyl (section 6):

* **physical** -- P [N/m] (positive downward), delta, delta_work, h [m]: what a :class:`jkrcyl.Contact` takes and
  returns;
* **normalised** -- P* = P/load_scale with load_scale = 4 pi Delta vartheta/beta* (P_R* of (7.6), 4 pi
  Delta/beta*, for a rigid cradle), delta/Delta, delta_work/Delta, h/Delta: the results' ``*_star`` and
  ``*_over_Delta`` fields, and what :mod:`jkrcyl.equilibria` works in;
* **kernel** -- the solvers' scale (jkrcyl.model.patch): p = vartheta P* (p = P* for a rigid cradle), lengths
  over Delta, energies in units of 4 pi Delta^2/beta*.

:class:`Control` names the quantity a control holds in each scale (and its slope and stability flag);
:data:`CONTROLS` has the three.  :class:`Units` carries the factors of one contact; every result is made
physical through it (``with_units``), every physical target reaches a solver through it (:meth:`Units.to_kernel`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Dict, Tuple


@dataclass(frozen=True)
class Control:
    """What a control holds fixed, under each of its names.

    Attributes
    ----------
    name : str
        'load', 'grip' (the paper's approach delta (5.8) held) or 'grip-work' (the work-conjugate delta_work =
        delta + P/(8 pi G_I) held: what a testing machine holding the pin's axis holds).
    physical, unit : str
        The physical field of a result ('P', 'delta', 'delta_work') and its unit ('N/m', 'm').
    normalised, slope, stable : str
        The normalised field of a result ('P_star', ...), its slope along a Curve ('dP_star_da', ...) and the
        stability flag under this control ('stable_load', ...).
    field, field_slope : str
        The single-patch solver's field in the kernel scale ('p', 'dn', 'dw') and its slope ('dp_da', ...).

    Examples
    --------
    >>> from jkrcyl.units import CONTROLS
    >>> CONTROLS["grip-work"].physical, CONTROLS["grip-work"].stable
    ('delta_work', 'stable_grip_work')
    """

    name: str
    physical: str
    unit: str
    normalised: str
    slope: str
    stable: str
    field: str
    field_slope: str

    @property
    def is_load(self) -> bool:
        """True for 'load' (the kernel load p = vartheta P* differs from P* by the factor vartheta)."""
        return self.name == "load"


#: the three controls, by name
CONTROLS: Dict[str, Control] = {c.name: c for c in (
    Control("load", "P", "N/m", "P_star", "dP_star_da", "stable_load", "p", "dp_da"),
    Control("grip", "delta", "m", "delta_over_Delta", "ddelta_da", "stable_grip", "dn", "ddn_da"),
    Control("grip-work", "delta_work", "m", "delta_work_over_Delta", "ddelta_work_da", "stable_grip_work", "dw",
            "ddw_da"))}

#: solver field (kernel scale) -> (the normalised field of a Curve, True where the two differ by vartheta)
CURVE_FIELD: Dict[str, Tuple[str, bool]] = {
    **{c.field: (c.normalised, c.is_load) for c in CONTROLS.values()},
    **{c.field_slope: (c.slope, c.is_load) for c in CONTROLS.values()},
    "h": ("h_pi_over_Delta", False)}


def control_of_physical(name: str) -> Control:
    """The control holding the physical field ``name`` ('P', 'delta' or 'delta_work'); KeyError otherwise.

    Examples
    --------
    >>> control_of_physical("delta").name
    'grip'
    """
    for c in CONTROLS.values():
        if c.physical == name:
            return c
    raise KeyError(name)


@dataclass(frozen=True)
class Units:
    """The factors between the physical, normalised and kernel scales of one contact (module docstring).

    Attributes
    ----------
    R, Delta : float
        Hole radius and radial clearance [m] (1 for normalised answers).
    load_scale : float
        P/P* [N/m]: 4 pi Delta vartheta/beta*, or 4 pi Delta/beta* for vartheta = inf (section 6, (7.6)).
    kernel : float
        p/P*: vartheta, or 1 for vartheta = inf (jkrcyl.model.problem.Problem.scale).
    K_edge : float
        The stress intensity at an edge in equilibrium [Pa m^1/2] (the law's; 0 for a cohesive law).
    energy_scale : float
        The kernel unit of energy per unit length, 4 pi Delta^2/beta* [J/m].

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> u = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m).units
    >>> u.physical("load", 1.0) == u.load_scale, u.to_kernel("grip", 2e-6)
    (True, 2.0)
    """

    R: float = 1.0
    Delta: float = 1.0
    load_scale: float = 1.0
    kernel: float = 1.0
    K_edge: float = 0.0
    energy_scale: float = 1.0

    @classmethod
    def of(cls, contact) -> "Units":
        """The units of a :class:`jkrcyl.Contact` (Delta > 0)."""
        return cls(R=contact.R, Delta=contact.Delta, load_scale=contact.load_scale, kernel=contact.problem.scale,
                   K_edge=contact.law.stress_intensity(contact),
                   energy_scale=4 * math.pi * contact.Delta ** 2 / contact.beta)

    @classmethod
    def normalised(cls, problem, K_edge: float = 0.0) -> "Units":
        """Units in which a 'physical' answer is the normalised one (P = P*, delta = delta/Delta); energies stay in
        the kernel unit, vartheta P* delta/Delta (a jump's dissipation: jkrcyl.analysis.landing.dissipated; a
        cycle's loop_energy in these units is vartheta times its loop work -- use a Contact's units for cycles)."""
        return cls(kernel=problem.scale, K_edge=K_edge)

    def per_normalised(self, control: str) -> float:
        """The physical value of one normalised unit of the held quantity: load_scale [N/m] or Delta [m]."""
        return self.load_scale if CONTROLS[control].is_load else self.Delta

    def per_kernel(self, control: str) -> float:
        """The physical value of one kernel unit of the held quantity: load_scale/vartheta [N/m] or Delta [m]."""
        return self.load_scale / self.kernel if CONTROLS[control].is_load else self.Delta

    def physical(self, control: str, normalised: float) -> float:
        """P [N/m], delta or delta_work [m] from P*, delta/Delta or delta_work/Delta."""
        return normalised * self.per_normalised(control)

    def normalise(self, control: str, value: float) -> float:
        """P*, delta/Delta or delta_work/Delta from P [N/m], delta or delta_work [m]."""
        return value / self.per_normalised(control)

    def to_kernel(self, control: str, value: float) -> float:
        """The solver's held field (p, dn or dw) from P [N/m], delta or delta_work [m]."""
        return value / self.per_kernel(control)

    def from_kernel(self, control: str, value: float) -> float:
        """P [N/m], delta or delta_work [m] from the solver's held field."""
        return value * self.per_kernel(control)
