"""The Maugis-Dugdale (cohesive-zone) law behind the single-patch interface.

:class:`Cohesive` gives, like the Griffith solvers, a :class:`~jkrcyl.model.patch.Slice` per branch parameter a
(kernel scale: p = P beta*/(4 pi Delta), lengths over Delta).  Its branches:

* ``sub-critical``: one contact |phi| < eps at the bottom with its zone |phi| < c (h(c) = h0), k = 0 at the
  contact end.  The branch can turn back in eps (several states per contact size), so a is NOT tan(eps/2) but
  2 + t, t the arclength of the traced branch in (log eps, log(c - eps)) from its touch end (eps -> 0) up to
  p = P_CAP (towards the receding limit) -- jkrcyl.numerics.cohesive_branch; the Slice carries eps and c.  Where
  the range reaches round at the touch end (zones 'all') t = log(eps/eps_touch).
* ``contactless``: the pin without contact, held by its bottom zone |phi| < c (closed form,
  jkrcyl.numerics.cohesive_zones), a in (0, 1] with c = c_lo + a (c_touch - c_lo): from the pin entering the
  range (c -> c_lo = 0, delta = -h0) to the touch (h(0) = 0), where the contact branch starts
  (:meth:`Cohesive.continues`); a touch beyond pi/2 (the approach's pole) starts from c_lo = pi/2.  Present
  when the contact branch starts from a touch (not when the range reaches round there).

Slopes are per point: along the branch's tangent (implicit differentiation of k = 0, h(c) = h0 with finite
differences in eps and c at a fixed approach), never across table points.  Stability: the rule of
jkrcyl.model.stability with the derivatives D_X of jkrcyl.numerics.cohesive_branch (the zone end's energy
dE/dc = 2 (s0 h(c) - m^2); the contactless pin is a saddle under load, stable under grip where the opening at its
zone end grows with the zone).  The total potential (elastic + Dugdale interface energy - w over the contact) has
dE = p d(delta/Delta) along the branches.  Not modelled: two patches and full contact (jkrcyl.laws.dugdale: the law's families),
the super-critical side of the receding limit, top-zone bridges (jkrcyl.numerics.cohesive_zones finds them),
a round zone that stops reaching round by a jump (a top bridge or an S-shape: :attr:`unmodelled` says so).
"""
from __future__ import annotations

import functools
import math

import numpy as np
from ..numerics import cohesive as _co
from ..numerics import cohesive_branch as _cb
from ..numerics import cohesive_pull_off as _cpo
from ..numerics import cohesive_zones as _cz
from ..numerics import one_arc as _one
from ..numerics import roots as _roots
from .patch import SinglePatch, Slice

CONTACTLESS_POINTS = 64
_SLOPES = ("dp_da", "ddn_da", "ddw_da")
ROOT_XTOL = 1e-12         # roots on the branch parameter a = 2 + t (t: arclength in log space, O(1-10))
SLOPE_XTOL = 1e-9         # folds (roots of a slope): below, the slopes' noise moves the root (tested: 1e-6)


class Cohesive(SinglePatch):
    """The Maugis-Dugdale single patch of a Problem with a Dugdale edge law (module docstring)."""

    noise = 1e-9                 # the states are converged to ~1e-10 (jkrcyl.numerics.cohesive)
    a_max = math.inf

    def __init__(self, problem):
        self.problem = problem
        self.law = _cb.Law(problem.m, problem.edge.s0, problem.theta, problem.gb, problem.alpha_ratio)
        self._cache = {}
        self._values = {}            # (p, dn, h) at branch parameters off the table (root refinements)

    # --- the traced branch ---------------------------------------------------------------------------
    @functools.cached_property
    def _traced(self):
        return _cb.trace(self.law)           # (x, kind, why it stopped early: '' when it did not)

    @functools.cached_property
    def _trace(self):
        x, kind, _ = self._traced
        keep = np.concatenate([[True], np.any(np.diff(x, axis=0) != 0, axis=1)])
        x = x[keep]
        t = x[:, 0] - x[0, 0] if kind == "all" else _cb.arclength(x)
        return x, t, kind

    @functools.cached_property
    def _contactless(self):
        """(c_lo, c_touch) of the zone-only branch, or None."""
        c, touches = _cb.contactless_end(self.law)
        if not touches:
            return None
        return (0.0, c) if c < math.pi / 2 else (math.pi / 2 * (1 + 1e-6), c)

    @property
    def dense_points(self):
        return len(self._trace[1])

    @property
    def a_end(self) -> float:
        """The end of the contact branch's parameter a = 2 + t."""
        return 2.0 + float(self._trace[1][-1]) * (1 + 1e-12)

    @functools.cached_property
    def a_crit(self) -> float:
        """The pair's receding contact tan(eps_crit/2) (the one meaning of a_crit: jkrcyl.critical); the traced
        branch stops below it (jkrcyl.numerics.cohesive_branch.EPS_MARGIN)."""
        return _one.receding_contact(self.problem.theta, self.problem.gb, self.problem.alpha_ratio)

    def regimes(self):
        return ("contactless", "sub-critical") if self._contactless is not None else ("sub-critical",)

    def regime_of(self, a: float) -> str:
        return "contactless" if a <= 1 else "sub-critical"

    def eps_star_of(self, s: Slice):
        """eps/pi (no receding contact on this parametrisation)."""
        return s.contact / math.pi

    def grid(self, regime, n, small=0, a_max=None):
        """The traced points (n = dense_points) or n points uniform in t; contactless: uniform in c."""
        if regime == "contactless":
            n = CONTACTLESS_POINTS if n == self.dense_points else n
            return (np.arange(n) + 0.5) / n
        t = self._trace[1]
        return 2.0 + (t if n == self.dense_points else np.linspace(t[0], t[-1], n))

    def on_branch(self, regime, a):
        lo, hi = (0.0, 1.0) if regime == "contactless" else (2.0, self.a_end)
        bad = (a <= lo) | (a > hi) if regime == "contactless" else (a < lo) | (a > hi)
        if regime not in self.regimes() or np.any(bad):
            raise ValueError(f"a must be in ({lo!r}, {hi!r}) on the {regime} branch of this cohesive law "
                             f"(a: the branch parameter), got {np.ravel(a)[0]!r}")
        return a

    # --- states ------------------------------------------------------------------------------------------
    def _where(self, t):
        """(eps, c, direction) of the contact branch at parameter t (exact: projected onto the curve)."""
        x, tt, kind = self._trace
        j = int(np.clip(np.searchsorted(tt, t) - 1, 0, len(tt) - 2))
        f = (t - tt[j]) / (tt[j + 1] - tt[j])
        chord = x[j + 1] - x[j]
        if kind == "all":
            eps = math.exp(x[0, 0] + t)
            c = self._all_c(eps)
            return eps, c, (1.0, 0.0)
        if f <= 0 or f >= 1:
            xp = x[j] if f <= 0 else x[j + 1]
        else:
            normal = np.array([-chord[1], chord[0]]) / np.hypot(*chord)
            xp = _cb.project(self.law, x[j] + f * chord, normal, np.hypot(*chord))
            if xp is None:
                raise ValueError(f"a: no cohesive state found at the branch parameter {2 + t!r}")
        eps, d = math.exp(xp[0]), math.exp(xp[1])
        de = eps * chord[0]
        return eps, eps + d, (de, de + d * chord[1])

    def _all_c(self, eps):
        s = self.law.state(eps)
        return math.pi if s.zones == "all" else s.c

    def point(self, a):
        """Per-point data (jkrcyl.numerics.cohesive_branch.Point) at the parameter a (cached)."""
        a = float(a)
        if a not in self._cache:
            if a <= 1:
                lo, hi = self._contactless
                pt = _cb.contactless_point(self.law, lo + a * (hi - lo))
            else:
                eps, c, direction = self._where(a - 2.0)
                pt = _cb.point(self.law, eps, c, direction)
            if len(self._cache) > 20000:
                self._cache.clear()
            self._cache[a] = pt
        return self._cache[a]

    def states(self, a) -> Slice:
        a = np.atleast_1d(np.asarray(a, dtype=float))
        pts = [self.point(x) for x in a.tolist()]
        col = lambda name: np.array([getattr(q, name) for q in pts], dtype=float)
        span = self._contactless[1] - self._contactless[0] if self._contactless else 1.0
        c_scale = np.where(a <= 1, span, 1.0)                           # contactless: d/da = (c_touch - c_lo) d/dc
        cw = self.problem.work_shift
        p, dn = col("p"), col("delta")
        dp, ddn = col("dp_dt") * c_scale, col("ddn_dt") * c_scale
        return Slice(a=a, p=p, dp_da=dp, dn=dn, ddn_da=ddn, dw=dn + cw * p, ddw_da=ddn + cw * dp, h=col("h_pi"),
                     p_k=col("D_p"), dn_k=col("D_dn"), B=col("B"), eps=col("eps"), c=col("c"),
                     c_top=np.zeros(a.size), total=col("potential"), feasible=col("feasible").astype(bool))

    def value(self, field, a):
        """p, dn, dw or h at one branch parameter without the slopes, feasibility and energy, or a slope of p, dn
        or dw without the feasibility and energy (root refinement)."""
        a = float(a)
        if field in _SLOPES and a > 1 and a not in self._cache:
            eps, c, direction = self._where(a - 2.0)
            dp, ddn = _cb.slopes(self.law, eps, c, direction)
            return {"dp_da": dp, "ddn_da": ddn, "ddw_da": ddn + self.problem.work_shift * dp}[field]
        if field not in ("p", "dn", "dw", "h"):
            return super().value(field, a)
        if a in self._cache:
            pt = self._cache[a]
            p, dn, h = pt.p, pt.delta, pt.h_pi
        elif a <= 1:
            lo, hi = self._contactless
            st = _cz.contactless_state(lo + a * (hi - lo), self.law.m, self.law.s0, self.law.theta, self.law.gb,
                                       self.law.ar)
            p, dn, h = st.p, st.delta_over_Delta, st.h_pi_over_Delta
        elif a in self._values:
            p, dn, h = self._values[a]
        else:
            eps, c, _ = self._where(a - 2.0)
            if len(self._values) > 20000:
                self._values.clear()
            p, dn, h = self._values.setdefault(a, _cb.state_values(self.law, eps, c))
        return {"p": p, "dn": dn, "dw": dn + self.problem.work_shift * p, "h": h}[field]

    def root(self, field, lo, hi, flo, fhi, target=0.0):
        """The root of field - target in [lo, hi] (a sign change; None where it is a pole): Brent to ROOT_XTOL in
        a (SLOPE_XTOL for a slope: a fold) -- the states carry ~1e-10 of noise and the slopes (finite differences)
        ~1e-9, so the bisection to adjacent doubles of the other solvers buys nothing but evaluations (each a
        state, and for a slope two more contacts)."""
        seen = {lo: flo, hi: fhi}
        f = lambda x, _: seen[x] if x in seen else seen.setdefault(x, self.value(field, x) - target)
        xtol = SLOPE_XTOL if field in _SLOPES else ROOT_XTOL
        return _roots.brent_or_pole(f, lo, hi, (), flo, fhi, xtol=xtol)

    def at_contact(self, eps):
        """(c, p, dn, dw, h) at contact half-angles eps: the zone end's first root above the Dugdale estimate
        (jkrcyl.numerics.cohesive.cohesive_state, ~1e-10), the root that tends to JKR -- on the traced branch below
        its first turn in eps, the first root (off the branch) beyond it."""
        law = self.law
        st = [_co.cohesive_state(e, law.m, law.s0, law.theta, law.gb, law.ar) for e in np.asarray(eps).tolist()]
        col = lambda name: np.array([getattr(q, name) for q in st], dtype=float)
        return col("c"), col("p"), col("delta_over_Delta"), col("delta_work_over_Delta"), col("h_pi_over_Delta")

    def release_rates(self, s):
        """No Griffith edge: NaN."""
        return {ctl: np.full(np.shape(s.p), np.nan) for ctl in ("load", "grip", "grip-work")}

    # --- the branches' ends and what the analyses ask ------------------------------------------------------
    def stops_short(self, regime, a=None):
        """The contact branch is traced up to p = P_CAP m^(4/3) (jkrcyl.numerics.cohesive_branch) unless it ends
        first (the receding limit, the zone reaching round); a: only if a is the table's last point."""
        if regime != "sub-critical" or self._trace[2] == "all":
            return ""
        if a is not None and a < 2.0 + (self.a_end - 2.0) * (1 - 1e-9):
            return ""
        p_end = self.value("p", self.a_end)
        return f"traced up to P_CAP m^(4/3) = {self.law.p_cap:.6g}" if p_end > 0.5 * self.law.p_cap else ""

    def continues(self, regime, a):
        """The contact branch's touch end (a = 2) continues as the contactless one from the touch (a = 1) and
        back."""
        if self._contactless is None:
            return None
        if regime == "sub-critical" and a <= 2.0 + 1e-9 * max(1.0, self._trace[1][-1]):
            return "contactless", 1.0
        if regime == "contactless" and a >= 1.0 - 1.0 / CONTACTLESS_POINTS:
            return "sub-critical", 2.0
        return None

    def grows_under_pull(self, a, control):
        """At a fold, the state leaves along the branch's tangent in the direction a further pull drives it:
        under load the approach falls, under grip the load rises towards 0; the contact grows if eps rises
        that way.  The tangent at the point (d eps, and the per-point slopes of p and delta along it), not a
        difference across points; the zone-only pin (a <= 1) has no contact to grow."""
        if a <= 1:
            return False
        (deps, _), pt = self._where(a - 2.0)[2], self.point(a)
        return bool(deps * pt.ddn_dt < 0) if control == "load" else bool(deps * pt.dp_dt > 0)

    def free_range(self):
        """The free pin feels no traction while every gap exceeds h0: -2 + h0 < delta/Delta < -h0."""
        h0 = self.law.h0
        return -2.0 + h0, -h0

    @functools.cached_property
    def adheres(self):
        """Whether some feasible contact state pulls (p < 0); not when the range reaches round (h0 > 2 Delta)."""
        s = self.states(self.grid("sub-critical", self.dense_points))
        return bool(np.any((s.p < 0) & s.feasible))

    @property
    def no_adherence_reason(self):
        if self.law.h0 >= 2.0:
            return (f"no adherence force: every state of the cohesive law pushes (P >= 0) -- its range h0 = "
                    f"{self.law.h0:.6g} Delta reaches round the hole (a uniform traction has no resultant)")
        s = self.states(self.grid("sub-critical", self.dense_points))
        return ("no adherence force on one patch: every feasible single-patch state pushes (P >= 0)" +
                ("; those that pull overlap the top of the hole (h(pi) < 0), where two patches or full contact, "
                 "not modelled for the law, take over" if np.any(s.p < 0) else ""))

    @functools.cached_property
    def unmodelled(self):
        """Why the analyses cannot follow the branch ('' when they can): the trace stopped before the branch's end
        (jkrcyl.numerics.cohesive_follow says where and why), or its zone stops reaching round by a jump
        (jkrcyl.numerics.cohesive_branch.top_opens: a top bridge or an S-shaped branch, not traced)."""
        if self._traced[2]:                  # the trace stopped before the branch's end: no silent answer
            return self._traced[2]
        if self._trace[2] != "all" or self.law.h0 >= 2.0:      # h0 >= 2 Delta: no state pulls, nothing to follow
            return ""
        opens = _cb.top_opens(self.law)
        return "" if opens is None else _cpo.jump_reason(opens)

    def floating(self):
        """(lo, hi) of delta/Delta of the pin floating in a range that reaches round (p = 0), or None."""
        return _cz.floating_range(self.law.m, self.law.s0, self.law.theta, self.law.gb, self.law.ar)
