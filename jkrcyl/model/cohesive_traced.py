"""One traced contact branch of the Maugis-Dugdale law (jkrcyl.model.cohesive): its points, its parameter and the
state at any parameter.

A traced branch (jkrcyl.numerics.cohesive_branch.trace, the sub-critical one; jkrcyl.numerics.cohesive_super.trace,
the super-critical one) is a polyline x = (log eps, log(c - eps)) along the curve k = 0, h(c) = h0 (kind 'zone'),
or contacts with the zone all round sampled in eps (kind 'all', x = (log eps, 0)).  Its branch parameter is
a = offset + t: t the arclength of the polyline ('zone') or log(eps/eps_first) ('all'), the offset keeping the
branches' parameters apart (sub-critical from 2, super-critical from SUPER_OFFSET).
"""
from __future__ import annotations

import math

import numpy as np

from ..numerics import cohesive_branch as _cb
from ..numerics import cohesive_crossing as _cx
from ..numerics import cohesive_super as _csu

SUB_OFFSET = 2.0
JOIN = 1e-6              # the parameter step from a trace's last zone point to its round-zone tail (the zone
                         # states between, pi - c < cohesive_super.JOIN_S_MIN: Traced.gap, solved at the contact)
SUPER_OFFSET = 1000.0     # above any sub-critical parameter: that trace's arclength is at most 1500 x 0.25 = 375


class Traced:
    """A traced branch: ``x`` (n, 2), ``t`` (n,), ``kind`` ('zone' or 'all'), ``reason`` ('' when the trace ended
    where the branch leaves its domain) and ``offset`` (a = offset + t).  A sub-critical trace can start with a
    round prefix (``n_round`` points with the zone all round: the S-shaped branch, jkrcyl.numerics.cohesive_round).
    A super-critical 'zone' trace whose zone reached round can carry a tail (``tail``: the eps of its states with
    the zone all round, beyond the last point, from its join): t goes on there as JOIN + log(eps/eps_join); its
    last ``n_join`` points run back in eps towards that join with c -> pi (jkrcyl.numerics.cohesive_super
    .join_points), a state between them solved at its contact (cohesive_super.top_gap).  ``cross`` (n_before,
    n_after): how many of the first and last points follow the branch next to and across the receding contact
    eps_crit (jkrcyl.numerics.cohesive_crossing), a state between them solved without the pole there;
    ``crossed`` (the sub-critical table ends on eps_crit, a regular crossing) and ``joined`` ('start', 'end':
    that end of the super-critical table is the sub-critical table's end there) are set by the solver."""

    def __init__(self, law, traced, offset, n_round=0, tail=(), n_join=0, cross=(0, 0)):
        x, kind, reason = traced
        keep = np.concatenate([[True], np.any(np.diff(x, axis=0) != 0, axis=1)])
        self.law, self.x, self.kind, self.reason, self.offset = law, x[keep], kind, reason, offset
        self.n_round = int(np.count_nonzero(keep[:n_round]))
        self.n_join = int(np.count_nonzero(keep[len(keep) - n_join:])) if n_join else 0
        self.cross = tuple(int(np.count_nonzero(k)) if n else 0 for n, k in
                           zip(cross, (keep[:cross[0]], keep[len(keep) - cross[1]:])))
        self.crossed, self.joined, self.cross_reasons = False, "", ("", "")
        self.t = self.x[:, 0] - self.x[0, 0] if kind == "all" else _cb.arclength(self.x)
        self.tail = np.asarray(tail, dtype=float)
        self.t_round = float(self.t[-1])               # the last zone point; the tail starts JOIN past it
        if self.tail.size:
            self.t = np.concatenate([self.t, self.t_round + JOIN + np.log(self.tail / self.tail[0])])

    def gap(self, t):
        """Where t lies in the step JOIN from the trace's last zone point to its tail's join: the fraction f in
        (0, 1) of it (the states there: :meth:`where`); None elsewhere (within a few roundings of a - offset of
        either end: that end)."""
        if not self.tail.size:
            return None
        f = (t - self.t_round) / JOIN
        snap = 1e-14 * (abs(self.offset) + self.t_round) / JOIN
        return f if snap < f < 1 - snap else None

    def on_tail(self, a) -> bool:
        """Whether the parameter a lies on the round-zone tail (beyond the traced zone end)."""
        return bool(self.tail.size) and a - self.offset > self.t_round + 0.5 * JOIN

    @property
    def a_end(self) -> float:
        """The branch parameter of the trace's last point (a hair beyond: the end itself is on the branch)."""
        return self.offset + float(self.t[-1]) * (1 + 1e-12)

    def holds(self, a) -> bool:
        """Whether the parameter a lies on this branch's parameter range [offset, a_end]."""
        return self.offset <= a <= self.a_end

    def grid(self, n, table):
        """The traced points (table) or n points uniform in t, as branch parameters -- past the stretch from the
        zone-only pin's touch up to eps_lo (its table points kept: a straight run in log eps, c - c_touch ~ eps^2,
        as long in t as the rest of the branch; uniform in t it took 40-58 % of a curve's points)."""
        if table:
            return self.offset + self.t
        k = int(np.count_nonzero(self.x[:, 0] < math.log(self.law.eps_lo) - 1e-9)) if self.kind == "zone" else 0
        k = k if n > k + 2 else 0
        return self.offset + np.concatenate([self.t[:k], np.linspace(self.t[k], self.t[-1], n - k)])

    def where(self, t):
        """(eps, c, direction) of the branch at t (exact: projected onto the curve); direction = (d eps, d c) of
        increasing t."""
        f = self.gap(t)
        if f is not None:           # from the last zone point to the join: the zone state at eps between theirs
            return self._join_state(f)
        # the round-zone tail, t = t_round + JOIN + log(eps/eps_join) (half a JOIN: a - offset rounds t_round up)
        if self.tail.size and t > self.t_round + 0.5 * JOIN:
            return self.tail[0] * math.exp(max(t - self.t_round - JOIN, 0.0)), math.pi, (1.0, 0.0)
        x, tt = self.x, self.t[:len(self.x)]
        j = int(np.clip(np.searchsorted(tt, t) - 1, 0, len(tt) - 2))
        f = (t - tt[j]) / (tt[j + 1] - tt[j])
        chord = x[j + 1] - x[j]
        snap = 1e-12 * (abs(self.offset) + tt[-1]) / (tt[j + 1] - tt[j])      # a - offset rounds t at a table point
        f = 0.0 if abs(f) <= snap else (1.0 if abs(f - 1) <= snap else f)
        if self.kind == "all":
            eps = math.exp(x[0, 0] + t)
            s = self.law.state(eps)
            return eps, (math.pi if s.zones == "all" else s.c), (1.0, 0.0)
        if j + (f > 0) < self.n_round:             # the round prefix (t = log eps there) and its last point
            return math.exp(x[0, 0] + min(t, tt[self.n_round - 1])), math.pi, (1.0, 0.0)
        if f <= 0 or f >= 1:
            xp = x[j] if f <= 0 else x[j + 1]
        elif j < self.cross[0] or j >= len(x) - 1 - self.cross[1]:      # next to eps_crit: without its pole
            xp = _cx.project(self.law, x[j] + f * chord, chord)
            if xp is None:
                raise ValueError(f"a: no cohesive state found at the branch parameter {self.offset + t!r}")
        elif j >= len(x) - 1 - self.n_join:        # towards the join (c -> pi): the zone end at the contact
            eps = math.exp(x[j, 0] + f * chord[0])
            s = _csu.top_gap(self.law, eps)
            if s is None:
                raise ValueError(f"a: no cohesive state found at the branch parameter {self.offset + t!r}")
            xp = np.array([math.log(eps), math.log(math.pi - s - eps)])
        else:
            normal = np.array([-chord[1], chord[0]]) / np.hypot(*chord)
            xp = _cb.project(self.law, x[j] + f * chord, normal, np.hypot(*chord))
            if xp is None and j + 1 == self.n_round:     # next to the opening (c within START_DC of pi)
                xp = x[j + 1]
            if xp is None:
                raise ValueError(f"a: no cohesive state found at the branch parameter {self.offset + t!r}")
        eps, d = math.exp(xp[0]), math.exp(xp[1])
        de = eps * chord[0]
        return eps, eps + d, (de, de + d * chord[1])

    def _join_state(self, f):
        """(eps, c, direction) a fraction f of the way from the trace's last zone point (pi - c >= JOIN_S_MIN) to
        the join (c = pi): eps linear between theirs, pi - c the zone end's at that contact (cohesive_super
        .top_gap).  The states between them are on the branch (lambda 3.87, M 1, vartheta 1: P* rises from
        2.7248121 to the fold's 2.7248170 there; a step from one end to the other put states of either end's
        load at every load between)."""
        e0, ej = math.exp(self.x[-1, 0]), float(self.tail[0])
        eps = e0 + f * (ej - e0)
        s = _csu.top_gap(self.law, eps)
        if s is None and f < 0.99:
            raise ValueError(f"a: no cohesive state found at the branch parameter "
                             f"{self.offset + self.t_round + f * JOIN!r}")
        c0 = e0 + math.exp(self.x[-1, 1])
        return eps, (math.pi if s is None else math.pi - s), (ej - e0, math.pi - c0)


def super_short(sv, br, a):
    """Why the super-critical table of the solver sv (jkrcyl.model.cohesive.Cohesive) ends at a (None: its last
    point): both of its ends are short of the branch -- the first point lies next to the pole a_crit (|p| unbounded
    past it), the last one where the trace failed, the zone reaches round, the load cap, the branch turns back to
    the pole with a finite load (it crosses onto the sub-critical branch there) or eps = pi - 0.05 (the last two
    only to a walker at that point: for the table's extent, a = None, they end the branch, as the sub-critical
    one ends there)."""
    if a is not None and a <= br.offset + 1e-9 * max(1.0, br.t[-1]):
        if br.cross[0] and br.cross_reasons[0] != "cap":      # followed back across a_crit (cohesive_crossing)
            return (f"the super-critical branch is followed back across the receding limit a_crit down to eps = "
                    f"{sv._where(br.offset)[0]:.6g} rad ({br.cross_reasons[0]}): the part beyond is not traced")
        return (f"the super-critical branch is traced from eps = {sv._where(br.offset)[0]:.6g} rad, next to "
                "the receding limit a_crit, where |P| grows without bound")
    if a is not None and a < br.offset + (br.a_end - br.offset) * (1 - 1e-9):
        return ""
    if br.reason:
        return br.reason
    eps, c, _ = sv._where(br.a_end)
    if br.kind == "zone" and c >= math.pi - 2 * _csu.ROUND_MARGIN:
        return _csu.round_end(eps, br.tail)
    if eps < _csu.EPS_TOP - 1e-2 and abs(sv.value("p", br.a_end)) > 0.5 * sv.law.p_cap:
        return f"traced up to |p| = P_CAP m^(4/3) = {sv.law.p_cap:.6g}"
    if a is None:              # the table's extent (forward searches): the branch's end, as the sub-critical one
        return ""
    lo = _csu.eps_range(sv.law)[0]
    if eps < lo * (1 + _cb.EPS_MARGIN):      # turned back in eps: it crosses the pole with P finite
        return (f"the super-critical branch turns back to the receding limit a_crit (eps = {eps:.6g} rad, "
                f"c = {c:.6g} rad) and crosses it onto the sub-critical one with a finite load: the crossing is "
                "not traced")
    return f"traced up to eps = {eps:.6g} rad (pi - 0.05): the states nearer full contact are not traced"
