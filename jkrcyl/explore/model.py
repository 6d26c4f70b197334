"""What the explorer shows, computed from its inputs without a browser: :func:`compute` turns the text of the input
fields (:class:`Inputs`) into a :class:`Picture` -- the single-patch branches on the (delta_work, P) plane with
their stability under the chosen control, first contact, the pull-off under each of the three controls, a load
cycle, the pull-off at a rate under crack kinetics, and the pressure and gap around the hole at a chosen load.
Every number comes from the public :class:`jkrcyl.Contact`; bad input raises the library's own ValueError, which
:func:`field_of` attributes to the input field it names.
"""
from __future__ import annotations

import math
import re
import time
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from .._validate import control as _check_control
from ..analysis import branches as _tables
from ..contact import Contact
from ..laws import CrackKinetics
from ..materials import Materials
from ..model.single_patch import solver
from ..units import CONTROLS as UNIT_CONTROLS

CONTROLS = ("load", "grip-work", "grip")        # jkrcyl._validate.CONTROLS, in the order the page shows them
BRANCHES = ("sub-critical", "super-critical", "contactless")   # one patch at the bottom (a law has two of them)
CYCLE_POINTS = 400
CURVE_POINTS = 500
FIELD_POINTS = 721
CYCLE_LOAD_FACTOR = 1.3      # automatic load limits: +-1.3 |load-control pull-off|
CYCLE_APPROACH = (0.3, -2.3)  # automatic approach limits / Delta: past the top of the hole (delta = -2 Delta)


def _contact_jkr(R, Delta, w, materials, inputs):
    return Contact(R=R, Delta=Delta, w=w, materials=materials)


def _contact_sigma0(R, Delta, w, materials, inputs):
    return Contact(R=R, Delta=Delta, w=w, materials=materials, sigma0=number(inputs.law_value))


def _contact_lambda(R, Delta, w, materials, inputs):
    return Contact.with_lambda(R, Delta, w, materials, number(inputs.law_value))


def _contact_kinetic(R, Delta, w, materials, inputs):
    law = CrackKinetics(v_star=number(inputs.law_value), n=number(inputs.kinetic_n))
    return Contact(R=R, Delta=Delta, w=w, materials=materials, kinetics=law)


#: The edge laws offered: key -> (label, field of its value, how the Contact is made).
LAWS = {"JKR": ("JKR (adhesion of zero range)", None, _contact_jkr),
        "sigma0": ("Maugis-Dugdale, cohesive strength sigma0 [Pa]", "sigma0", _contact_sigma0),
        "lambda": ("Maugis-Dugdale, transition parameter lambda", "lambda", _contact_lambda),
        "kinetic": ("JKR with crack kinetics, G = w[1 + (v/v*)^n]: v* [m/s]", "v_star", _contact_kinetic)}


def number(text):
    """The float a field holds; the text itself when it is not a number, so that the library's own check names
    the parameter ('E must be a real number, got 'abc''); None for an empty optional field."""
    if text is None or isinstance(text, (int, float)):
        return text
    text = str(text).strip()
    try:
        return float(text)
    except ValueError:
        return text


@dataclass(frozen=True)
class Inputs:
    """The explorer's fields as typed (strings or numbers).  E, nu: the body with the hole; E_I, nu_I: the pin
    (plane strain); rigid, rigid_I: E = inf; R, Delta [m], w [J/m^2]; law: a key of :data:`LAWS` and its
    value (sigma0 [Pa], lambda, or v* [m/s] of crack kinetics, whose exponent is kinetic_n); rate: the pulling rate
    of a pull-off in time under crack kinetics (N/m/s under load, m/s under grip; empty: none); control: 'load',
    'grip-work' or 'grip' (stability shown, cycle driven, rate pull-off);
    cycle_max, cycle_min: limits of the driven quantity ([N/m] under load, [m] of the held approach under grip;
    empty: automatic); state_P: the load of the state whose pressure and gap are drawn [N/m] (empty: first
    contact)."""

    E: object = "2.6e9"
    nu: object = "0.3"
    E_I: object = "2.6e9"
    nu_I: object = "0.3"
    rigid: bool = False
    rigid_I: bool = False
    R: object = "0.01"
    Delta: object = "1e-6"
    w: object = "0.05"
    law: str = "JKR"
    law_value: object = ""
    kinetic_n: object = "0.6"
    rate: object = ""
    control: str = "load"
    cycle_max: object = ""
    cycle_min: object = ""
    state_P: object = ""

    def contact(self) -> Contact:
        """The jkrcyl.Contact of these inputs (ValueError naming the bad one)."""
        E = math.inf if self.rigid else number(self.E)
        E_I = math.inf if self.rigid_I else number(self.E_I)
        mats = Materials.from_young(E=E, nu=number(self.nu), E_I=E_I, nu_I=number(self.nu_I))
        if self.law not in LAWS:
            raise ValueError(f"law must be one of {', '.join(LAWS)}, got {self.law!r}")
        make = LAWS[self.law][2]
        return make(number(self.R), number(self.Delta), number(self.w), mats, self)


@dataclass
class Branch:
    """One single-patch branch: delta_work [m], P [N/m], stable under the control, feasible (h(pi) >= 0)."""

    regime: str
    delta_work: np.ndarray
    P: np.ndarray
    stable: np.ndarray
    feasible: np.ndarray


@dataclass
class Picture:
    """Everything the explorer draws and prints for one set of inputs (SI units)."""

    inputs: Inputs
    contact: Contact
    branches: list
    pull_offs: dict                  # control -> jkrcyl.results.PullOff
    cycle: object                    # jkrcyl.results.Cycle
    first_contact: Optional[object]  # jkrcyl.results.Equilibrium: where the free pin snaps in
    state: Optional[object]          # the Equilibrium whose fields are drawn (None: first contact is no patch)
    phi: np.ndarray
    pressure: np.ndarray             # [Pa], compressive positive
    gap: np.ndarray                  # [m]
    timings: dict = field(default_factory=dict)
    rate_pull_off: Optional[object] = None   # jkrcyl.kinetics.RatePullOff under the control, at inputs.rate

    @property
    def regime(self) -> str:
        """What slow pulling under load control does (the load pull-off's outcome), in words."""
        return self.pull_offs["load"].reason


def _branches(c: Contact, control: str) -> list:
    """The law's single-patch branches at the bottom, as the dense tables the pull-off and the cycle walk on
    (jkrcyl.analysis.branches.table: filled by the first pull-off, so drawing them costs nothing and every
    marker lies on them), thinned to at most :data:`CURVE_POINTS` points."""
    pb = c.problem
    out = []
    for regime in solver(pb).regimes():
        cv = _tables.table(pb, regime).with_units(c.units)
        keep = np.unique(np.linspace(0, len(cv.P) - 1, min(len(cv.P), CURVE_POINTS)).astype(int))
        out.append(Branch(regime, np.asarray(cv.delta_work)[keep], np.asarray(cv.P)[keep],
                          np.asarray(getattr(cv, UNIT_CONTROLS[control].stable), dtype=bool)[keep],
                          np.asarray(cv.feasible, dtype=bool)[keep]))
    return out


def _cycle(c: Contact, inputs: Inputs, pull_off):
    """The cycle under the chosen control, between the given limits or the automatic ones."""
    hi, lo = number(inputs.cycle_max), number(inputs.cycle_min)
    if inputs.control == "load":
        ref = abs(pull_off.P) if pull_off.detached else c.load_scale
        hi = CYCLE_LOAD_FACTOR * ref if hi in (None, "") else hi
        lo = -CYCLE_LOAD_FACTOR * ref if lo in (None, "") else lo
        return c.cycle(P_max=hi, P_min=lo, control="load", n=CYCLE_POINTS)
    hi = CYCLE_APPROACH[0] * c.Delta if hi in (None, "") else hi
    lo = CYCLE_APPROACH[1] * c.Delta if lo in (None, "") else lo
    return c.cycle(delta_max=hi, delta_min=lo, control=inputs.control, n=CYCLE_POINTS)


def _state(c: Contact, P, first):
    """The state whose fields are drawn: at load P [N/m] at the bottom of the hole (stable under load and feasible
    if there is one), or, for an empty field, first contact (None if that is not a single patch)."""
    if number(P) in (None, ""):
        return first if first is not None and first.branch in BRANCHES else None
    states = c.solve(P=number(P), branches=list(BRANCHES))
    ranked = sorted(states, key=lambda s: (not (s.stable and s.feasible), not s.feasible))
    if not ranked:
        raise ValueError(f"P: no single-patch equilibrium at the bottom of the hole at P = {number(P)} N/m "
                         "(choose a load on the branches drawn)")
    return ranked[0]


def _jkr_fields(c, s, phi):
    return c.pressure(s.a, phi), c.gap(s.a, phi)


def _cohesive_fields(c, s, phi):
    f = c.fields(s)
    return f.pressure(phi), f.gap(phi)


#: The fields of a state by law (JKR: the closed forms at a = tan(eps/2); cohesive: the state's own fields).
FIELDS = {"JKR": _jkr_fields, "sigma0": _cohesive_fields, "lambda": _cohesive_fields, "kinetic": _jkr_fields}


def _timed(timings: dict, name: str, f, *args):
    """f(*args), its wall time [s] stored in timings[name] (the explorer prints them; the benchmark reads them)."""
    start = time.perf_counter()
    out = f(*args)
    timings[name] = time.perf_counter() - start
    return out


def _fields(law: str, c: Contact, s, phi):
    """Pressure [Pa] and gap [m] at the angles phi of the state s (NaN without a state)."""
    return (np.full_like(phi, np.nan),) * 2 if s is None else FIELDS[law](c, s, phi)


def compute(inputs: Inputs) -> Picture:
    """Everything the explorer shows for ``inputs``.

    Parameters
    ----------
    inputs : Inputs
        The fields as typed (strings or numbers; SI units).

    Returns
    -------
    Picture
        The branches, the pull-off under each control, the cycle, first contact, the chosen state and its
        pressure [Pa] and gap [m] around the hole, and the time each part took [s].

    Raises
    ------
    ValueError
        The library's own message, naming the bad parameter (:func:`field_of` finds its field).

    Examples
    --------
    >>> from jkrcyl.explore import Inputs, compute
    >>> picture = compute(Inputs(w="0.05"))          # the README pin
    >>> round(picture.pull_offs["load"].P)           # N/m
    -1555
    >>> picture.regime
    'detachment: the contact shrinks away (G > w)'
    """
    _check_control(inputs.control)
    timings = {}
    start = time.perf_counter()
    c = _timed(timings, "contact", inputs.contact)
    pull_offs = _timed(timings, "pull-offs", lambda: {control: c.pull_off(control) for control in CONTROLS})
    branches = _timed(timings, "branches", _branches, c, inputs.control)
    cy = _timed(timings, "cycle", _cycle, c, inputs, pull_offs["load"])
    first = next((j.after for j in cy.jumps if j.kind == "snap-in"), None)
    s = _timed(timings, "state", _state, c, inputs.state_P, first)
    phi = np.linspace(-math.pi, math.pi, FIELD_POINTS)
    pressure, gap = _timed(timings, "fields", _fields, inputs.law, c, s, phi)
    rate = number(inputs.rate)
    ramp = None if rate in (None, "") else _timed(timings, "rate", c.pull_off, inputs.control, rate)
    timings["total"] = time.perf_counter() - start
    return Picture(inputs, c, branches, pull_offs, cy, first, s, phi, np.asarray(pressure), np.asarray(gap), timings,
                   ramp)


#: The parameter a library message names -> the input field it belongs to.
FIELD_OF_NAME = {"E": "E", "G": "E", "nu": "nu", "kappa": "nu", "E_I": "E_I", "G_I": "E_I", "nu_I": "nu_I",
                 "kappa_I": "nu_I", "R": "R", "Delta": "Delta", "w": "w", "sigma0": "law_value",
                 "lambda": "law_value", "law": "law", "control": "control", "P_max": "cycle_max",
                 "delta_max": "cycle_max", "P_min": "cycle_min", "delta_min": "cycle_min", "P": "state_P",
                 "v_star": "law_value", "n": "kinetic_n", "rate": "rate", "kinetics": "law"}


def field_of(message: str) -> str:
    """The input field a library ValueError is about: its first word names the parameter ('E must be ...',
    'Delta must be in ...', 'sigma0: ...'); 'general' when it names none of the fields.

    Examples
    --------
    >>> from jkrcyl.explore import Inputs, compute, field_of
    >>> try:
    ...     compute(Inputs(nu="0.7"))
    ... except ValueError as exc:
    ...     print(exc, "->", field_of(str(exc)))
    nu must be in (-1, 0.5], got 0.7 -> nu
    """
    m = re.match(r"\s*([A-Za-z_][A-Za-z0-9_]*)", message)
    return FIELD_OF_NAME.get(m.group(1), "general") if m else "general"
