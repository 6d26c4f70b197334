"""The ends of the Maugis-Dugdale single patch's branches and what the analyses ask there (a mixin of
:class:`jkrcyl.model.cohesive.Cohesive`: where a table stops short, how a branch continues, the free and floating
ranges, whether and why the pin adheres or a branch is not followed)."""
from __future__ import annotations

import functools
import math

import numpy as np

from ..numerics import cohesive_branch as _cb
from ..numerics import cohesive_pull_off as _cpo
from ..numerics import cohesive_super as _csu
from ..numerics import cohesive_zones as _cz
from . import cohesive_traced as _ct

CONTACTLESS_POINTS = 64
#: delta/Delta within this (times 1 + |delta/Delta|) of the floating range still floats: its ends reached through
#: metres and back (a cycle under grip: -0.3895900748047466 -> 1e-5 m -> 1 ulp above the end read as a free pin of
#: energy 0 instead of the floating one, -1.445: a snap-in dissipating 0.056 J/m too much, tests/test_loop_work.py)
FREE_SLACK = 1e-12


class CohesiveEnds:
    """The branches' ends of :class:`jkrcyl.model.cohesive.Cohesive` (module docstring)."""

    def stops_short(self, regime, a=None):
        """Why a contact branch's table ends before the branch does ('' where it does not), a: only if a is the
        table's last point.  Sub-critical: traced up to p = P_CAP m^(4/3) (jkrcyl.numerics.cohesive_branch)
        unless it ends first (the receding limit, the zone reaching round).  Super-critical
        (jkrcyl.numerics.cohesive_super): either end (:meth:`_super_short`)."""
        if regime not in ("sub-critical", "super-critical") or not self.has(regime):
            return ""
        br = self._branch(regime)
        if regime == "super-critical":
            return _ct.super_short(self, br, a)
        if br.kind == "all" or (a is not None and a < br.offset + (br.a_end - br.offset) * (1 - 1e-9)):
            return ""
        p_end = self.value("p", self.a_end)
        return f"traced up to P_CAP m^(4/3) = {self.law.p_cap:.6g}" if p_end > 0.5 * self.law.p_cap else ""

    def continues(self, regime, a):
        """The contact branch's touch end (a = 2) continues as the contactless one from the touch (a = 1) and
        back; the super-critical round-zone tail's end next to full contact as the bonded pin (a = inf); the
        sub-critical table's end on eps_crit (a regular crossing) as the super-critical table's end there."""
        if regime == "super-critical" and self.has(regime) and _csu.reaches_full(self._super.tail, a, self._super):
            return "full-contact", math.inf
        join = self._joined(regime, a)
        if join is not None:
            return join
        if self._contactless is None:
            return None
        if regime == "sub-critical" and a <= 2.0 + 1e-9 * max(1.0, self._sub.t[-1]):
            return "contactless", 1.0
        if regime == "contactless" and a >= 1.0 - 1.0 / CONTACTLESS_POINTS:
            return "sub-critical", 2.0
        return None

    def _joined(self, regime, a):
        """(regime, a) of the other table's end where a is the sub-critical table's end on eps_crit or the
        super-critical table's end joined to it (jkrcyl.numerics.cohesive_crossing), else None."""
        if regime not in ("sub-critical", "super-critical") or not self._sub.crossed:
            return None
        sub = self._sub
        if not self.has("super-critical") or not self._super.joined:
            return None
        sup = self._super
        at_end = lambda br, x: x >= br.offset + (br.a_end - br.offset) * (1 - 1e-9)
        at_start = lambda br, x: x <= br.offset + 1e-9 * max(1.0, br.t[-1])
        end_of_super = sup.offset if sup.joined == "start" else sup.offset + float(sup.t[-1])
        if regime == "sub-critical" and at_end(sub, a):
            return "super-critical", end_of_super
        on_join = at_start(sup, a) if sup.joined == "start" else at_end(sup, a)
        return ("sub-critical", sub.offset + float(sub.t[-1])) if regime == "super-critical" and on_join else None

    def grows_under_pull(self, a, control, towards=0):
        """At a fold, whether a further pull makes the contact grow: eps rising the way the walk went (towards,
        the sign of a's change: the stable side is behind it); without a walk, the tangent's (under load the
        approach falls, under grip the load rises).  They agree but where every slope vanishes at the fold
        (tests/test_gap_stop.py, test_fold_direction.py).  The zone-only pin (a <= 1) has no contact."""
        if a <= 1:
            return False
        (deps, _), pt = self._where(a)[2], self.point(a)
        if towards:
            return bool(deps * towards > 0)
        return bool(deps * pt.ddn_dt < 0) if control == "load" else bool(deps * pt.dp_dt > 0)

    def free_range(self):
        """The free pin feels no traction while every gap exceeds h0: -2 + h0 < delta/Delta < -h0; where the
        contact branch starts with its zone round (no zone-only pin touches) and the pin floats in the range all
        round (P = 0, :meth:`floating`) up to a larger approach, or the zone-only pin starts from the floating one
        (h0 > Delta: the ranges of the bottom and the top overlap), that range stands for it (both hold -1)."""
        h0, fl = self.law.h0, self.floating()
        joined = self._contactless is None or self._contactless[0] == math.pi
        return fl if fl is not None and fl[1] > -h0 and joined else (-2.0 + h0, -h0)

    def free_potential(self, dn):
        """The total potential of the pin without contact at delta/Delta = dn (kernel scale): the floating pin's
        (jkrcyl.numerics.cohesive_zones.floating_state: its zone all round) within :meth:`floating`, else 0."""
        fl = self.floating()
        slack = FREE_SLACK * (1.0 + abs(dn))       # an end reached through metres and back (the cycle's held value)
        if fl is None or not fl[0] - slack <= dn <= fl[1] + slack:
            return 0.0
        dn = min(max(dn, fl[0]), fl[1])
        return _cb.potential(_cz.floating_state(dn, self.law.m, self.law.s0, self.law.theta, self.law.gb,
                                                self.law.ar))

    def floats_onto(self):
        """Where the sub-critical branch starts with its zone round (zones 'all' at its touch end), the pin reaches
        the bottom onto its touch end a = 2 without a jump (from the floating range's top, :meth:`free_range`, or
        drawn down from the free one); None otherwise."""
        return None if self._sub.kind == "zone" and self._sub.n_round == 0 else 2.0

    def _super_pulls(self):
        """Branch parameters of the super-critical table's states that pull (p < 0, without their feasibility)."""
        if not self.has("super-critical"):
            return np.zeros(0)
        a, p = self.table_values("super-critical", "p")
        return a[p < 0]

    @functools.cached_property
    def adheres(self):
        """Whether some feasible contact state pulls (p < 0) on either side of a_crit; not when the range reaches
        round (h0 > 2 Delta)."""
        a, p = self.table_values("sub-critical", "p")      # feasibility (a gap check) only where p < 0, first found
        return any(self.point(x).feasible for x in a[p < 0].tolist()) or \
            any(self.point(x).feasible for x in self._super_pulls())

    @property
    def no_adherence_reason(self):
        if self.law.h0 >= 2.0:
            return (f"no adherence force: every state of the cohesive law pushes (P >= 0) -- its range h0 = "
                    f"{self.law.h0:.6g} Delta reaches round the hole (a uniform traction has no resultant)")
        pulls = bool(np.any(self.table_values("sub-critical", "p")[1] < 0)) or self._super_pulls().size > 0
        return ("no adherence force on one patch: every feasible single-patch state pushes (P >= 0)" +
                ("; those that pull overlap the top of the hole (h(pi) < 0), where two patches or full contact take "
                 "over -- " + self.problem.not_modelled("two-patch", "a contact at the bottom and the top (two "
                                                        "patches) is") if pulls else ""))

    @functools.cached_property
    def unmodelled(self):
        """Why the analyses cannot follow the branch ('' when they can): the trace stopped before the branch's end
        (cohesive_follow says why), or its round zone's first root jumps other than onto an S-shaped branch (a top
        bridge or a second zone family: cohesive_branch.top_opens)."""
        if self._sub.reason:                 # the trace stopped before the branch's end: no silent answer
            return self._sub.reason
        opens = _cb.opens_of(self.law) if self._sub.kind == "all" else None     # 'zone': an S traced whole
        return "" if opens is None else _cpo.jump_reason(opens)             # None: h0 >= 2 Delta, nothing pulls

    def floating(self):
        """(lo, hi) of delta/Delta of the pin floating in a range that reaches round (p = 0), or None."""
        return _cz.floating_range(self.law.m, self.law.s0, self.law.theta, self.law.gb, self.law.ar)
