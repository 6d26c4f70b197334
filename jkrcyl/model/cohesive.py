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
* ``super-critical``: the same curve past the receding limit a_crit (the pole of the load of every law),
  a = 1000 + t, t its arclength from just past the pole (or from the load cap |p| = P_CAP m^(4/3)) towards the
  full circle -- jkrcyl.numerics.cohesive_super.  At finite lambda it turns back in eps at a fold where the zone
  end's first root meets its second (a longer zone), and follows that root back until the zone reaches round
  (h(pi) = h0); as lambda -> inf the fold moves to eps -> pi and the branch tends to JKR's.  Present where the
  pair has a receding contact below pi - 0.05 (not a rigid cradle at alpha* = 0).
* Across eps_crit: a table's end at the traces' margin there is followed on where the branch crosses eps_crit
  with a finite load (jkrcyl.numerics.cohesive_crossing): the sub-critical end up to eps_crit, a super-critical
  end back across it to the load cap or to that sub-critical end, the two tables then continuing into each other
  (:meth:`continues`).

Slopes are per point: along the branch's tangent (implicit differentiation of k = 0, h(c) = h0 with finite
differences in eps and c at a fixed approach), never across table points.  Stability: the rule of
jkrcyl.model.stability with the derivatives D_X of jkrcyl.numerics.cohesive_branch (the zone end's energy
dE/dc = 2 (s0 h(c) - m^2); the contactless pin is a saddle under load, stable under grip where the opening at its
zone end grows with the zone).  The total potential (elastic + Dugdale interface energy - w over the contact) has
dE = p d(delta/Delta) along the branches.  A zone reaching round at the touch end that stops reaching round by a
jump of its first zone-end root (jkrcyl.numerics.cohesive_branch.top_opens) is an S-shaped branch, narrow or not
(the round zone, the root near the top back to a fold, the first root), traced whole (jkrcyl.numerics.cohesive_round);
a round zone that would part beside the top instead (none found), or that goes on while a second zone family
is born at a fold (cohesive_branch.top_opens), is refused (:attr:`unmodelled`).  The top bridge
(a zone at the top held by its own traction, from where the single patch's h(pi) = h0): :attr:`top_bridges`,
jkrcyl.model.cohesive_bridge.  Full contact: the bonded pin of
jkrcyl.model.full_contact (tension below s0); two patches: jkrcyl.analysis.cohesive_two_patch.
"""
from __future__ import annotations

import functools
import math

import numpy as np
from ..numerics import cohesive as _co
from ..numerics import cohesive_branch as _cb
from ..numerics import cohesive_contactless as _cl
from ..numerics import cohesive_crossing as _cx
from ..numerics import cohesive_zones as _cz
from ..numerics import one_arc as _one
from ..numerics import roots as _roots
from ..numerics import cohesive_super as _csu
from . import cohesive_bridge as _bridge
from . import cohesive_traced as _ct
from .cohesive_ends import CONTACTLESS_POINTS, CohesiveEnds
from .patch import SinglePatch, Slice

_SLOPES = ("dp_da", "ddn_da", "ddw_da")
ROOT_XTOL = 1e-12         # roots on the branch parameter a = 2 + t (t: arclength in log space, O(1-10))
SLOPE_XTOL = 1e-9         # folds (roots of a slope): below, the slopes' noise moves the root (tested: 1e-6)


class Cohesive(CohesiveEnds, SinglePatch):
    """The Maugis-Dugdale single patch of a Problem with a Dugdale edge law (module docstring)."""

    noise = 1e-9                 # the states are converged to ~1e-10 (jkrcyl.numerics.cohesive)
    a_max = math.inf

    def __init__(self, problem):
        self.problem = problem
        self.law = _cb.Law(problem.m, problem.edge.s0, problem.theta, problem.gb, problem.alpha_ratio)
        self._cache = {}
        self._values = {}            # (p, dn, h or (eps, c) till h is asked for) at branch parameters off the table

    # --- the traced branches ---------------------------------------------------------------------------
    @functools.cached_property
    def _sub(self):
        """The sub-critical branch (jkrcyl.numerics.cohesive_branch.trace), a = 2 + t."""
        got = _cb.trace(self.law)                  # (x, kind, reason[, n_round]: the S-branch's round prefix)
        x, n_after, crossed = _cx.sub_extended(self.law, got)        # on past the margin next to eps_crit
        br = _ct.Traced(self.law, (x,) + got[1:3], _ct.SUB_OFFSET, n_round=got[3] if len(got) > 3 else 0,
                        cross=(0, n_after))
        br.crossed = crossed
        return br

    @functools.cached_property
    def _super(self):
        """The super-critical branch (jkrcyl.numerics.cohesive_super.trace), a = SUPER_OFFSET + t; None where
        there is none or it has no state below the load cap."""
        got = _csu.trace(self.law)
        if got is None or len(got[0]) < 2:
            return None
        tail, n_join = (got[3], got[4]) if len(got) > 3 else ((), 0)         # the round-zone tail and the join
        x, before, after, joined, why = _cx.super_extended(self.law, got,
                                                           self._sub.x[-1] if self._sub.crossed else None)
        br = _ct.Traced(self.law, (x,) + got[1:3], _ct.SUPER_OFFSET, tail=tail, n_join=n_join, cross=(before, after))
        br.joined, br.cross_reasons = joined, why
        return br

    def _branch(self, regime):
        if regime == "super-critical":
            if self._super is None:
                raise ValueError("regime: this cohesive law has no super-critical state below the load cap "
                                 f"|P*| = P_CAP m^(4/3) = {self.law.p_cap / self.problem.scale:.6g} (past the "
                                 "receding limit a_crit)")
            return self._super
        return self._sub

    def _where(self, a):
        """(eps, c, direction) at the branch parameter a > 1 (jkrcyl.model.cohesive_traced.Traced.where)."""
        br = self._branch(self.regime_of(a))
        return br.where(a - br.offset)

    def _join_chord(self, a):
        """Between the super-critical trace's last zone point and its tail's join (Traced.gap: pi - c below
        JOIN_S_MIN, where the states' finite-difference steps, scaled by pi - c, vanish): (dp/da, d(delta)/da) of
        the chord across (p, delta monotone there: the fold is the join) and the last zone point's D_p, D_dn (the
        zone family's stability); None elsewhere."""
        br = self._super if a >= _ct.SUPER_OFFSET else None
        if br is None or br.gap(a - br.offset) is None:
            return None
        a0, a1 = br.offset + br.t[len(br.x) - 1], br.offset + br.t[len(br.x)]     # table points: cached
        p0, p1 = self.point(a0), self.point(a1)
        return (p1.p - p0.p) / (a1 - a0), (p1.delta - p0.delta) / (a1 - a0), p0.D_p, p0.D_dn

    @functools.cached_property
    def _contactless(self):
        """(c_far, c_touch) of the zone-only branch (c = c_far + a (c_touch - c_far), a in (0, 1]), or None: from
        the free pin (c_far = 0) or, for a touch beyond pi/2 (h0 > Delta), from the pin floating all round (c_far
        = pi; jkrcyl.numerics.cohesive_contactless.contactless_end: between pi/2 and such a touch the pin would
        overlap the bottom, delta > 0 -- the branch once taken there, every state infeasible)."""
        c, touches = _cl.contactless_end(self.law)
        if not touches:
            return None
        return (0.0, c) if c < math.pi / 2 else (math.pi, c)

    @functools.cached_property
    def top_bridges(self):
        """The top-bridge families (jkrcyl.model.cohesive_bridge.Family; () where none), traced once."""
        return _bridge.trace(self)

    @property
    def dense_points(self):
        return len(self._sub.t)

    @property
    def a_end(self) -> float:
        """The end of the sub-critical branch's parameter a = 2 + t."""
        return self._sub.a_end

    @functools.cached_property
    def a_crit(self) -> float:
        """The pair's receding contact tan(eps_crit/2) (the one meaning of a_crit: jkrcyl.critical); the
        traces stop short of it on either side (jkrcyl.numerics.cohesive_branch.EPS_MARGIN), the tables go on
        across it where the branch crosses it with a finite load (jkrcyl.numerics.cohesive_crossing)."""
        return _one.receding_contact(self.problem.theta, self.problem.gb, self.problem.alpha_ratio)

    def regimes(self):
        """The contactless pin where its zone touches, the sub-critical branch, and the super-critical one where
        the pair has a receding contact below pi - 0.05 and a state past it below the load cap
        (jkrcyl.numerics.cohesive_super; traced here, once)."""
        return tuple(r for r in ("contactless", "sub-critical", "super-critical") if self.has(r))

    def has(self, regime):
        """Whether the branch exists: the super-critical one is traced only when asked about."""
        if regime == "super-critical":
            return self._super is not None
        return regime == "sub-critical" or (regime == "contactless" and self._contactless is not None)

    def regime_of(self, a: float) -> str:
        return "contactless" if a <= 1 else ("super-critical" if a >= _ct.SUPER_OFFSET else "sub-critical")

    def eps_star_of(self, s: Slice):
        """eps/pi (no receding contact on this parametrisation)."""
        return s.contact / math.pi

    def grid(self, regime, n, small=0, a_max=None):
        """The traced points (n = dense_points) or n points uniform in t; contactless: uniform in c, the table
        with its touch end a = 1 (where the walk goes on onto the contact branch: a held value between the last
        midpoint and the touch is reached on the table, not past the junction)."""
        if regime == "contactless":
            if n == self.dense_points:
                return np.append((np.arange(CONTACTLESS_POINTS) + 0.5) / CONTACTLESS_POINTS, 1.0)
            return (np.arange(n) + 0.5) / n
        return self._branch(regime).grid(n, n == self.dense_points)

    def on_branch(self, regime, a):
        if regime == "contactless":
            lo, hi = 0.0, 1.0
        else:
            br = self._branch(regime) if self.has(regime) else self._sub
            lo, hi = br.offset, br.a_end
        bad = (a <= lo) | (a > hi) if regime == "contactless" else (a < lo) | (a > hi)
        if not self.has(regime) or np.any(bad):
            raise ValueError(f"a must be in ({lo!r}, {hi!r}) on the {regime} branch of this cohesive law "
                             f"(a: the branch parameter), got {np.ravel(a)[0]!r}")
        return a

    # --- states ------------------------------------------------------------------------------------------
    def point(self, a):
        """Per-point data (jkrcyl.numerics.cohesive_branch.Point) at the parameter a (cached)."""
        a = float(a)
        if a not in self._cache:
            if a <= 1:
                lo, hi = self._contactless
                pt = _cl.contactless_point(self.law, lo + a * (hi - lo))
            else:
                eps, c, direction = self._where(a)
                pt = _cb.point(self.law, eps, c, direction)
                chord = self._join_chord(a)
                if chord is not None:
                    pt = pt._replace(dp_dt=chord[0], ddn_dt=chord[1], D_p=chord[2], D_dn=chord[3])
            if len(self._cache) > 20000:
                self._cache.clear()
            self._cache[a] = pt
        return self._cache[a]

    def states(self, a) -> Slice:
        a = np.atleast_1d(np.asarray(a, dtype=float))
        pts = [self.point(x) for x in a.tolist()]
        col = lambda name: np.array([getattr(q, name) for q in pts], dtype=float)
        span = self._contactless[1] - self._contactless[0] if self._contactless else 1.0
        c_scale = np.where(a <= 1, span, 1.0)                           # contactless: d/da = (c_touch - c_far) d/dc
        cw = self.problem.work_shift
        p, dn = col("p"), col("delta")
        dp, ddn = col("dp_dt") * c_scale, col("ddn_dt") * c_scale
        turn = np.sign(c_scale)                   # D_X: oriented along t = c; a runs against c from c_far = pi
        return Slice(a=a, p=p, dp_da=dp, dn=dn, ddn_da=ddn, dw=dn + cw * p, ddw_da=ddn + cw * dp, h=col("h_pi"),
                     p_k=col("D_p") * turn, dn_k=col("D_dn") * turn, B=col("B"), eps=col("eps"), c=col("c"),
                     c_top=np.zeros(a.size), feasible=col("feasible").astype(bool))

    def potential(self, s):
        """The total potential of the states s (each point's, a quadrature over the zones: computed only when an
        energy is asked for, not for a branch table)."""
        return np.array([self.point(x).potential for x in np.atleast_1d(s.a).tolist()], dtype=float)

    def table_values(self, regime, field):
        """(a, values) of p, dn, dw or h on a branch's table grid without slopes, flags and energy (the trace's
        cached fixed contacts, the zone-only pin's closed form: a search for a held value needs no more); None
        otherwise."""
        if field not in ("p", "dn", "dw", "h") or (regime == "contactless" and self._contactless is None):
            return None
        a = self.grid(regime, self.dense_points)
        return a, np.array([self.value(field, x) for x in a.tolist()])

    def value(self, field, a):
        """p, dn, dw or h at one branch parameter without the slopes, feasibility and energy, or a slope of p, dn
        or dw without the feasibility and energy (root refinement)."""
        a = float(a)
        chord = self._join_chord(a) if field in _SLOPES else None
        if chord is not None:
            return {"dp_da": chord[0], "ddn_da": chord[1], "ddw_da": chord[1] + self.problem.work_shift * chord[0]}[field]
        if field in _SLOPES and a > 1 and a not in self._cache:
            eps, c, direction = self._where(a)
            dp, ddn = _cb.slopes(self.law, eps, c, direction)
            return {"dp_da": dp, "ddn_da": ddn, "ddw_da": ddn + self.problem.work_shift * dp}[field]
        if field not in ("p", "dn", "dw", "h"):
            return super().value(field, a)
        # one route whatever was computed before (not the cached point's p, equal to ~1e-13): a root refined on
        # a nearly flat, noisy stretch (the super-critical round-zone tail near full contact, p to ~5e-9) must not
        # depend on which states an earlier walk left in the cache (tests/test_lazy_track.py)
        if a in self._values:
            p, dn, h = self._values[a]
        else:
            if len(self._values) > 20000:
                self._values.clear()
            if a <= 1:
                lo, hi = self._contactless
                st = _cz.contactless_state(lo + a * (hi - lo), self.law.m, self.law.s0, self.law.theta, self.law.gb,
                                           self.law.ar)
                got = st.p, st.delta_over_Delta, st.h_pi_over_Delta
            else:
                eps, c, _ = self._where(a)
                got = _cb.load_approach(self.law, eps, c) + ((eps, c),)     # h(pi): computed when asked
            p, dn, h = self._values.setdefault(a, got)
        if field == "h" and isinstance(h, tuple):
            h = _cb.state_values(self.law, *h)[2]
            self._values[a] = (p, dn, h)
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
