"""The single-patch solver interface (implemented by jkrcyl.model.closed_form and jkrcyl.model.collocation; the
factory jkrcyl.model.single_patch chooses): see jkrcyl.model.single_patch for what a solver gives."""
from __future__ import annotations

import functools
import math
from typing import NamedTuple

import numpy as np

from ..numerics import roots as _roots
from .problem import Problem

FIELDS = ("p", "dp_da", "dn", "ddn_da", "dw", "ddw_da", "h")
SLOPE_OF = {"p": "dp_da", "dn": "ddn_da", "dw": "ddw_da"}


class Slice(NamedTuple):
    """Single-patch equilibria at the contact parameters a (arrays), kernel scale (see the module docstring)."""

    a: np.ndarray
    p: np.ndarray
    dp_da: np.ndarray
    dn: np.ndarray
    ddn_da: np.ndarray
    dw: np.ndarray
    ddw_da: np.ndarray
    h: np.ndarray
    p_k: np.ndarray
    dn_k: np.ndarray
    B: np.ndarray

    @property
    def energy(self):
        """Elastic energy [(1 + delta/Delta) p - B]/2 (units 4 pi Delta^2/beta*: the pressure's work on the rigid
        overlap (5.1)); the total potential subtracts 2 m^2 eps (jkrcyl.analysis.forward)."""
        return 0.5 * ((1 + self.dn) * self.p - self.B)


class SinglePatch:
    """The interface: states, field values for root refinement, the pole a_crit and the branches' extent."""

    problem: Problem
    dense_points: int          # points of a branch's search table: what the solver's cost allows
    a_max: float               # the largest contact parameter the solver resolves (the tables stop there)
    noise: float               # relative rounding of its states (what a difference quotient must stay above)

    def states(self, a) -> Slice:                       # pragma: no cover - interface
        raise NotImplementedError

    @functools.cached_property
    def a_crit(self) -> float:                          # pragma: no cover - interface
        raise NotImplementedError

    def value(self, field: str, a: float) -> float:
        """One field of :data:`FIELDS` at one contact parameter."""
        return float(getattr(self.states(np.array([a])), field)[0])

    def root(self, field, lo, hi, flo, fhi, target=0.0):
        """The root of field - target in [lo, hi] (a sign change), or None where the change is a pole."""
        return _roots.brent_or_pole(lambda x, _: self.value(field, x) - target, lo, hi, (), flo, fhi)

    @property
    def a_norm(self) -> float:
        """a_crit, or 1 where it is infinite: eps* = 2 atan(a/a_norm)/pi (section 6; eps/pi without a_crit)."""
        return 1.0 if math.isinf(self.a_crit) else self.a_crit

    def eps_star(self, a):
        return 2 * np.arctan(np.asarray(a, dtype=float) / self.a_norm) / np.pi

    def a_of(self, eps_star):
        return self.a_norm * np.tan(np.pi * np.asarray(eps_star, dtype=float) / 2)

    def regimes(self):
        """The branches that exist: a < a_crit, and a > a_crit where a_crit is finite."""
        return ("sub-critical",) if math.isinf(self.a_crit) else ("sub-critical", "super-critical")

    def regime_of(self, a: float) -> str:
        return "sub-critical" if a < self.a_crit else "super-critical"

    def eps_star_range(self, regime):
        """The open interval of eps* a branch spans."""
        if math.isinf(self.a_crit):
            return 0.0, 1.0
        return (0.0, 0.5) if regime == "sub-critical" else (0.5, 1.0)
