"""The single-patch solver interface (implemented by jkrcyl.model.closed_form and jkrcyl.model.collocation; the
factory jkrcyl.model.single_patch chooses): see jkrcyl.model.single_patch for what a solver gives."""
from __future__ import annotations

import functools
import math
from typing import NamedTuple

import numpy as np

from .._validate import A_MAX
from ..units import CONTROLS
from ..numerics import roots as _roots
from . import stability as _stab

A_SMALLEST = 1e-15       # the dense tables reach down to this contact parameter (or below, for tiny M)

FIELDS = ("p", "dp_da", "dn", "ddn_da", "dw", "ddw_da", "h")
#: solver field of a held quantity -> its slope along the branch (jkrcyl.units.CONTROLS)
SLOPE_OF = {c.field: c.field_slope for c in CONTROLS.values()}


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
    # edge laws beyond Griffith's (jkrcyl.model.cohesive): the contact half-angle when a is a branch parameter
    # (None: eps = 2 atan(a)), the zone ends, the total potential, the feasibility (None: h(pi) >= 0)
    eps: np.ndarray = None
    c: np.ndarray = None
    c_top: np.ndarray = None
    total: np.ndarray = None
    feasible: np.ndarray = None

    @property
    def energy(self):
        """Elastic energy [(1 + delta/Delta) p - B]/2 (units 4 pi Delta^2/beta*: the pressure's work on the rigid
        overlap (5.1))."""
        return 0.5 * ((1 + self.dn) * self.p - self.B)

    @property
    def contact(self):
        """The contact half-angle eps [rad] of each state."""
        return 2 * np.arctan(self.a) if self.eps is None else self.eps

    @property
    def gap_open(self):
        """Feasibility: the gap inequality (h(pi) >= 0 for one Griffith patch) and, for a cohesive law, the law."""
        return self.h >= 0 if self.feasible is None else self.feasible


class SinglePatch:
    """The interface: states, field values for root refinement, the pole a_crit and the branches' extent."""

    problem: "Problem"     # jkrcyl.model.problem (not imported: the problem imports the default law, whose solvers this)
    dense_points: int          # points of a branch's search table: what the solver's cost allows
    a_max: float               # the largest contact parameter the solver resolves (the tables stop there)
    noise: float               # relative rounding of its states (what a difference quotient must stay above)
    pole_needs_gb = True       # whether a_crit depends on gb = (1/G_I)/beta* (not for the closed forms)

    def states(self, a) -> Slice:                       # pragma: no cover - interface
        raise NotImplementedError

    def at_contact(self, eps):
        """(c, p, dn, dw, h) arrays of the bottom patch at contact half-angles eps (1-D, in (0, pi)), kernel scale:
        c the zone end (eps itself without a zone).  Griffith's edge: the state at a = tan(eps/2)."""
        s = self.states(np.tan(np.asarray(eps, dtype=float) / 2))
        return np.asarray(eps, dtype=float), s.p, s.dn, s.dw, s.h

    @functools.cached_property
    def a_crit(self) -> float:                          # pragma: no cover - interface
        raise NotImplementedError

    def potential(self, s: Slice):
        """Total potential of the states (kernel scale, units 4 pi Delta^2/beta*): the elastic energy less the work
        of adhesion over the contact, 2 m^2 eps (Griffith), so that dE = p d(delta/Delta) along the branch."""
        return s.energy - 2 * self.problem.m ** 2 * s.contact if s.total is None else s.total

    def release_rates(self, s: Slice):
        """{control: (1/w) dG/da at fixed X} (section 8.3; jkrcyl.model.stability)."""
        return _stab.release_rates(s, self.problem.m, self.problem.work_shift)

    def grows_under_pull(self, a: float, control: str, towards: int = 0) -> bool:
        """At a fold at a: does a further pull (the held quantity lowered) make the contact grow (G < w, the
        fixed-arc derivative (dX/dk)|_a > 0, jkrcyl.model.stability) rather than shrink away?  (towards, the
        direction of the walk that reached it, is read by laws whose slopes can all vanish at a fold.)"""
        return bool(_stab.fixed_arc_derivatives(self.states([a]), self.problem.work_shift)[control][0] > 0)

    def free_range(self):
        """(lo, hi) of delta/Delta where the free pin (no contact, no traction) is an equilibrium."""
        return -2.0, 0.0

    def free_potential(self, dn):
        """The total potential of the pin without contact at delta/Delta = dn (kernel scale): 0, no traction."""
        return 0.0

    def stops_short(self, regime: str, a=None) -> str:
        """Why the branch's table ends before the branch does ('' where it reaches the end: a_crit, round);
        with a: only where a is the table's last point (the end the table stops short at)."""
        return ""

    def continues(self, regime: str, a: float):
        """Where a branch continues past its end at a: (regime, a) on another branch, or None."""
        return None

    def floats_onto(self):
        """The sub-critical branch parameter onto which a pin floating in its range touches without a jump (a
        cohesive range reaching round), or None."""
        return None

    adheres = True               # some state pulls (P < 0) where M > 0
    no_adherence_reason = ""
    unmodelled = ""              # why the analyses cannot follow the branch ('' when they can)

    def grid(self, regime: str, n: int, small=0, a_max=None) -> np.ndarray:
        """n contact parameters uniform in eps* over a branch (midpoints; eps* <= that of a_max if given), with
        ``small`` log-spaced ones below (sub-critical): down to A_SMALLEST or a hundredth of the half-plane contact
        (vartheta M/2)^(2/3) (7.3b)."""
        lo, hi = self.eps_star_range(regime)
        if a_max is not None:
            hi = min(hi, float(self.eps_star(a_max)))
        a = self.a_of(lo + (hi - lo) * (np.arange(n) + 0.5) / n)
        if small and regime == "sub-critical":
            bottom = max(min(A_SMALLEST, (self.problem.m / 2) ** (2 / 3) / 100), 1e-100)
            if bottom < a[0]:
                a = np.concatenate([np.geomspace(bottom, a[0], small, endpoint=False), a])
        return a[a <= min(A_MAX, self.a_max)]

    def on_branch(self, regime: str, a):
        """ValueError unless every a lies on the branch."""
        ac = self.a_crit
        off = a >= ac if regime == "sub-critical" else a <= ac
        if np.any(off):
            side = "<" if regime == "sub-critical" else ">"
            raise ValueError(f"a must be {side} a_crit = {ac!r} on the {regime} branch, got {a[off].flat[0]!r}")
        return a

    def table_values(self, regime: str, field: str):
        """(a, values) of a field on the branch's table grid by a route cheaper than the full table, or None (the
        analyses then read the table: jkrcyl.analysis.branches.table_values)."""
        return None

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

    def eps_star_of(self, s: Slice):
        """eps* of the states of a Slice."""
        return self.eps_star(s.a)

    def a_of(self, eps_star):
        return self.a_norm * np.tan(np.pi * np.asarray(eps_star, dtype=float) / 2)

    def regimes(self):
        """The branches that exist: a < a_crit, and a > a_crit where a_crit is finite."""
        return ("sub-critical",) if math.isinf(self.a_crit) else ("sub-critical", "super-critical")

    def has(self, regime: str) -> bool:
        """Whether the branch exists (``regime in regimes()``, which a solver may answer without building the
        branches it is not asked about)."""
        return regime in self.regimes()

    def regime_of(self, a: float) -> str:
        return "sub-critical" if a < self.a_crit else "super-critical"

    def eps_star_range(self, regime):
        """The open interval of eps* a branch spans."""
        if math.isinf(self.a_crit):
            return 0.0, 1.0
        return (0.0, 0.5) if regime == "sub-critical" else (0.5, 1.0)
