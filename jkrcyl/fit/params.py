"""The fitted parameters: names, units, internal coordinates (logarithms of the positive ones) and how a set of
values becomes the model's inputs (material pair, modulus factor f, clearance, work of adhesion per point)."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import model

DESCRIPTION = {
    "w": ("J/m^2", "work of adhesion (both legs)"),
    "w_loading": ("J/m^2", "work of adhesion on the loading leg"),
    "w_unloading": ("J/m^2", "work of adhesion on the unloading leg"),
    "E": ("Pa", "contact modulus E* = 4/beta* (both moduli scaled by one factor, their ratio kept)"),
    "E_hole": ("Pa", "Young's modulus of the body with the hole (its nu kept)"),
    "E_pin": ("Pa", "Young's modulus of the pin (its nu kept)"),
    "Delta": ("m", "clearance R - R_D"),
    "offset": ("m", "approach offset: measured delta_work = model delta_work + offset"),
    "sigma0": ("Pa", "cohesive strength of the Maugis-Dugdale law (h0 = w/sigma0)"),
}
ORDER = tuple(DESCRIPTION)
LINEAR = ("offset",)          # every other parameter is positive and fitted as its logarithm


@dataclass(frozen=True)
class Inputs:
    """Model inputs for one set of parameter values."""

    materials: object          # jkrcyl.Materials (the 'shape': moduli before the factor f)
    f: float                   # factor on both moduli
    Delta: float               # [m]
    w: np.ndarray              # [J/m^2] per point
    offset: float              # [m]
    strength: float = None     # [Pa] the cohesive sigma0 (None: JKR)
    law: object = None         # a jkrcyl.laws.EdgeLaw of the superposed path (None: JKR's Griffith)

    @property
    def pair(self):
        """The fitted jkrcyl.Materials (the factor f applied)."""
        return model.scaled(self.materials, self.f) if self.f != 1.0 else self.materials

    def contact(self, R, w):
        """The library's contact at these inputs and the work of adhesion w [J/m^2] (jkrcyl.fit.model.contact)."""
        return model.contact(R, self.Delta, float(w), self.pair, self.strength, self.law)

    def superposed(self, R, w):
        """The superposed states of that contact (JKR: jkrcyl.fit.model.Superposed)."""
        return model.Superposed.of_inputs(R, self.Delta, float(w), self.f, self.materials, self.law)


def names(free):
    """The fitted parameters as a tuple of known names (ValueError naming the offending item otherwise)."""
    if isinstance(free, str):
        free = (free,)
    try:
        free = tuple(free)
    except TypeError:
        raise ValueError(f"free must be a sequence of parameter names ({', '.join(ORDER)}), got {free!r}") from None
    unknown = [n for n in free if not isinstance(n, str) or n not in DESCRIPTION]
    if unknown:
        raise ValueError(f"free: unknown parameter {unknown[0]!r} (allowed: {', '.join(ORDER)})")
    if len(set(free)) != len(free) or not free:
        raise ValueError(f"free must name each parameter once and at least one, got {free!r}")
    return free


class Spec:
    """Which parameters are free, the fixed values, and the map between values and internal coordinates.

    Parameters
    ----------
    free : sequence of str
        Names of :data:`DESCRIPTION`.
    data : jkrcyl.fit.data.Data
    R : float
        Hole radius [m].
    Delta, materials, w, offset, strength
        Fixed values, or the starting values of free parameters (w may be None when fitted; strength: the
        cohesive sigma0 [Pa], None for JKR or, when 'sigma0' is fitted, a start chosen by jkrcyl.fit.cohesive).

    ``superposes``: whether the JKR superposition surrogate of jkrcyl.fit.model holds (no 'sigma0' fitted or
    given); otherwise every state is evaluated directly (jkrcyl.fit.cohesive).
    """

    def __init__(self, free, data, R, Delta, materials, w, offset, strength=None, law=None):
        free = names(free)
        self.names = tuple(n for n in ORDER if n in free)
        self.data, self.materials0, self.n, self.R = data, materials, data.n, R
        self._check_combination(data)
        self.E_star0 = model.contact_modulus(materials)
        self.fixed = {"Delta": Delta, "offset": offset, "E": self.E_star0}
        for body in ("hole", "pin"):
            if f"E_{body}" in self.names:
                E = model.young(materials, body)
                if math.isinf(E):
                    raise ValueError(f"E_{body}: the {body} is rigid in materials (E = inf); a rigid body's "
                                     "modulus cannot be fitted (give a finite starting modulus)")
                self.fixed[f"E_{body}"] = E
        self.fixed["w"] = w
        self.fixed["sigma0"] = strength
        self.law = law                        # the edge law of the superposed path (None: JKR)
        self.superposes = strength is None and "sigma0" not in self.names
        if not self.superposes and data.kind != "width":
            raise ValueError("sigma0: the cohesive law is fitted to load against contact width only (delta_work "
                             "data: fit the JKR law, sigma0=None)")
        if w is not None:
            self.fixed["w_loading"] = self.fixed["w_unloading"] = w
        if w is None and not any(n.startswith("w") for n in self.names):
            raise ValueError("w: give the work of adhesion [J/m^2] when it is not fitted")
        if "Delta" in self.names and not Delta > 0:
            raise ValueError("Delta: a fitted clearance needs a starting value > 0")

    def _check_combination(self, data):
        names = set(self.names)
        legs = {"w_loading", "w_unloading"} & names
        if legs:
            if data.unloading is None:
                raise ValueError(f"{sorted(legs)[0]}: separate works of adhesion need the leg of each point (leg=)")
            if legs != {"w_loading", "w_unloading"} or "w" in names:
                raise ValueError("w_loading, w_unloading: fit both (separate legs) or 'w' alone (one for both)")
            for flag, leg in ((False, "loading"), (True, "unloading")):
                if not (data.unloading == flag).any():
                    raise ValueError(f"w_{leg}: the data have no '{leg}' rows")
        if "E" in names and names & {"E_hole", "E_pin"}:
            raise ValueError("E: scales both moduli; fit it or E_hole/E_pin, not both")
        if "offset" in names and data.kind != "delta_work":
            raise ValueError("offset: an approach offset needs delta_work data")
        stiffness = names & {"E", "E_hole", "E_pin"}
        if data.kind == "width" and "Delta" in names and stiffness and names & {"w", "w_loading", "w_unloading"}:
            raise ValueError(
                "Delta, E, w: from load against width the model depends on them only through E* Delta and E* w "
                "(P = f Delta p1(a) - sqrt(f w) p2(a), f the modulus factor): fix one of them, or fit delta_work "
                "data (the approach separates them)")

    # --- coordinates --------------------------------------------------------------------------------------
    def length_scale(self):
        """Scale of the linear coordinate (offset): the spread of the measured approaches [m]."""
        x = self.data.x
        return float(max(np.ptp(x), np.abs(x).max(), 1e-300))

    def to_internal(self, values):
        return np.array([values[n] / self.length_scale() if n in LINEAR else math.log(values[n])
                         for n in self.names])

    def values(self, u):
        """All parameter values (free from u, the others fixed) as a dict."""
        out = dict(self.fixed)
        for n, x in zip(self.names, np.asarray(u, dtype=float)):
            out[n] = x * self.length_scale() if n in LINEAR else math.exp(x)
        if "w" in self.names:
            out["w_loading"] = out["w_unloading"] = out["w"]
        return out

    def derivative(self, u):
        """d value / d u for each free parameter (the Jacobian of the coordinate change, diagonal)."""
        v = self.values(u)
        return np.array([self.length_scale() if n in LINEAR else v[n] for n in self.names])

    def inputs(self, u) -> Inputs:
        """Model inputs at internal coordinates u."""
        v = self.values(u)
        mat, f = self.materials0, 1.0
        if "E" in self.names:
            f = v["E"] / self.E_star0
        for body in ("hole", "pin"):
            if f"E_{body}" in self.names:
                mat = model.with_young(mat, body, v[f"E_{body}"])
        if self.data.unloading is None:
            w = np.full(self.n, v["w"] if v["w"] is not None else v["w_loading"])
        else:
            w = np.where(self.data.unloading, v["w_unloading"], v["w_loading"])
        return Inputs(materials=mat, f=f, Delta=v["Delta"], w=w, offset=v["offset"], strength=v["sigma0"],
                      law=self.law)

    def fitted_materials(self, u):
        """The fitted pair (the factor f applied)."""
        return self.inputs(u).pair
