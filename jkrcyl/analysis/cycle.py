"""Quasi-static load cycles: the path an experiment follows, its jumps and the energy it dissipates.

The cycle starts at first contact -- the free pin touching the bottom of the hole (P = 0, delta = 0) snaps in
(jkrcyl.analysis.landing.first_contact) -- drives the held quantity up to the maximum, down to the minimum and up
again, following stable, feasible branches (jkrcyl.analysis.path.walk), and jumps where a branch ends:

* ``pull-off``: a sub-critical fold: the contact shrinks away; under load the pin lands on the top of the hole
  (mirrored single patch at the same P), under grip it hangs free (P = 0) until it touches the other side;
* ``snap-in``: the free pin touches a side (delta = 0 or -2 Delta) and the contact jumps open;
* ``zip``: a super-critical fold: a further pull lowers G, the contact grows (two patches, full contact);
* ``top-contact``: the gap at phi = pi closes (h(pi) = 0): the next stable state at the same load/approach;
* a fold of two patches: where the edges relax past it (jkrcyl.analysis.landing: a ``pull-off`` where one arc
  lets go, a ``zip`` onto full contact), on a state of lower total potential (every jump dissipates).

The energy dissipated per cycle is the area of the closed steady loop, int P d(delta) [J/m] (a closed loop has the
same area in delta and in delta_work = delta + c P): the sum over the loop's jumps of the energy each dissipates
(:func:`loop_energy`).
"""
from __future__ import annotations

import numpy as np

from ..model import full_contact as _full
from ..model.problem import Problem
from ..results import Cycle, Jump
from ..units import CONTROLS, Units
from . import forward as _fw
from . import landing as _land
from . import path as _path
from . import reasons as _reasons
from . import tracks as _tracks

MAX_REPEATS = 3          # cycles driven until the loop closes (the state at the top of the cycle repeats)
MAX_JUMPS = 20           # jumps per leg at most


class _Run:
    """A cycle being driven: the recorded points (P, delta, branch, a, stable, leg), jumps and tracks."""

    def __init__(self, pb: Problem, un: Units, control: str):
        self.pb, self.un, self.control = pb, un, control
        self.pts, self.jumps, self.tracks = [], [], {}

    def track(self, s):
        if s.branch not in self.tracks:
            side = "top" if s.branch.endswith("-top") else "bottom"
            self.tracks[s.branch] = _tracks.track(self.pb, self.un, s.branch.replace("-top", ""), side,
                                                self.control)
        return self.tracks[s.branch]

    def add(self, s, leg):
        self.pts.append((s.P, s.delta, s.branch, s.a, s.stable, leg))

    def leg(self, s, target, leg):
        """Drive from state s to target: (end state, '') or (None, why it stopped)."""
        up = target > s.held()
        self.add(s, leg)                                  # the leg starts where the last one ended
        for _ in range(MAX_JUMPS):
            s, event = self._follow(s, target, leg)
            if event == "target":
                return s, ""
            if event == "gap" and not self.pb.models("two-patch"):    # a coarse table: from where the top closes
                s = _land.top_onset(self.pb, self.un, s, self.control)
                self.add(s, leg)
            value = s.held()
            short = _short(self.pb, s) if event == "end" else ""
            if short:
                return None, (f"leg {leg}: the {s.branch} branch's table ends at P = {s.P:.6g} N/m, delta = "
                              f"{s.delta:.6g} m ({short}); the cycle stops there")
            if s.branch == "separated" and self.control != "load":
                lo, hi = _fw.solver(self.pb).free_range()      # where the free pin touches a side (or its range)
                end = hi if up else lo
                value = end * self.un.Delta
                s = _fw.separated_state(self.pb, self.un, end, self.control)   # the end itself, not through metres
                self.add(s, leg)
            to, kind = _land.land(self.pb, self.un, s, event, self.control, value, up)
            if to is None:
                why = self.pb.not_modelled("full-contact", "the contact growing round after a zip (two patches, "
                                           "full contact) is") if kind == "zip" else ""
                if kind == "top-contact" and s.branch.startswith("contactless"):
                    why = _land.zone_only_stop(self.pb, s)
                elif kind == "top-contact" and not self.pb.models("two-patch"):
                    why = _land.two_patch_refusal(self.pb) or self.pb.not_modelled(
                        "two-patch-branches", "the contact at the bottom and the top (two patches) is")
                elif kind == "top-contact" and _land.into_pole(self.pb, self.un, s, self.control, value):
                    why = _land.POLE
                why = why or _land.across_a_crit(self.pb, self.un, self.control, self.un.normalise(self.control,
                                                                                                   value))
                if not why and kind == "zip":
                    why = _reasons.bond_breaks(self.pb, self.un, s, self.control, value)
                return None, f"leg {leg}: no stable state to jump to after the {kind} at {s!r}" + (
                    f" -- {why}" if why else "")
            if kind != "continue":                           # a branch going on as another is no jump
                self.jumps.append(Jump(kind, leg, s, to))
            s = to
            self.add(s, leg)
        return None, f"leg {leg}: more than {MAX_JUMPS} jumps"

    def _follow(self, s, target, leg):
        """Move along the current branch: (state, event)."""
        pb, un, ctl = self.pb, self.un, self.control
        if s.branch == "full-contact":
            e = _fw.full_contact_state(pb, un, CONTROLS[ctl].normalised, un.normalise(ctl, target), ctl)
            if e is not None and not e.feasible:      # the bond breaks first (a law of finite strength)
                e = _fw.full_contact_state(pb, un, "P_star", _full.bond_limit(pb, e.P_star), ctl)
                self.add(e, leg)
                return e, "end"
            self.add(e, leg)
            return e, "target"
        if s.branch == "separated":
            lo, hi = _fw.solver(pb).free_range()
            if ctl != "load" and lo * un.Delta < target < hi * un.Delta:
                e = _fw.separated_state(pb, un, target / un.Delta, ctl)
                self.add(e, leg)
                return e, "target"
            return s, "touch"
        if s.branch == "two-patch":
            seen, event, e = _path.walk_two_patch(pb, un, s, target, ctl)
            self.pts += [p + (True, leg) for p in seen]
            self.add(e, leg)
            return e, event
        tr = self.track(s)
        passed, event, end = _path.walk(tr, tr.index(s.a), target)
        self.pts += [(tr.P[k], tr.delta[k], tr.name, tr.a[k], True, leg) for k in passed[1:]]
        self.add(end, leg)
        return end, event


def _short(pb, s) -> str:
    """Why the branch of s ended at s short of its end ('' where it really ends: a_crit, round, a continuation)."""
    regime = s.branch.replace("-top", "")
    sv = _fw.solver(pb)
    return sv.stops_short(regime, s.a) if sv.has(regime) and sv.continues(regime, s.a) is None else ""


def _same(s1, s2, rel=1e-6):
    return s1.branch == s2.branch and (s1.a == s2.a or abs(s1.a - s2.a) <= rel * max(abs(s1.a), 1e-300) + 1e-12) \
        and \
        abs(s1.P - s2.P) <= rel * max(abs(s1.P), 1e-300) + 1e-300


def cycle(pb: Problem, un: Units, control: str, hi: float, lo: float, n: int, delta_work_of) -> Cycle:
    """The cycle between the held limits lo < hi (P [N/m] or an approach [m]); delta_work_of(P, delta) the
    work-conjugate approach [m] of the Contact (for the returned path)."""
    run = _Run(pb, un, control)
    sep, to, kind = _land.first_contact(pb, un, control)
    run.add(sep, 0)
    if to is None or _reasons.unmodelled(pb):
        why = _reasons.unmodelled(pb) or _reasons.no_first_contact_reason(pb, control)
        return _finish(run, n, None, why, delta_work_of, (lo, hi))
    if kind != "continue":                   # a floating pin goes on onto its contact without a jump
        run.jumps.append(Jump(kind, 0, sep, to))
    run.add(to, 0)
    s, note = run.leg(to, hi, 0)
    tops, closed, leg = [s], None, 1
    while s is not None and leg < 2 * MAX_REPEATS + 1:
        s, note = run.leg(s, lo, leg)
        if s is None:
            break
        s, note = run.leg(s, hi, leg + 1)
        if s is None:
            break
        if _same(s, tops[-1]):
            closed = leg
            break
        tops.append(s)
        leg += 2
    return _finish(run, n, closed, note, delta_work_of, (lo, hi))


def _finish(run, n, closed, note, delta_work_of, limits):
    P, d, br, a, st, lg = (np.array(v) for v in zip(*run.pts))
    energy = None if closed is None else loop_energy(run, closed)
    keep = _thin(len(P), n, run, lg)
    P, d = P[keep].astype(float), d[keep].astype(float)
    return Cycle(control=run.control, P=P, delta=d, branch=br[keep], a=a[keep].astype(float),
                 stable=st[keep].astype(bool), leg=lg[keep].astype(int), jumps=run.jumps, dissipated=energy,
                 closed_from_leg=closed, delta_work=delta_work_of(P, d), note=note, limits=limits)


def _thin(m, n, run, legs):
    """At most n of the m points, evenly, keeping both ends of every jump and every leg change."""
    if m <= n:
        return np.arange(m)
    keep = set(np.linspace(0, m - 1, max(n - 2 * len(run.jumps) - 2, 2)).astype(int)) | {0, m - 1}
    for i in range(1, m):
        if legs[i] != legs[i - 1] or run.pts[i][2] != run.pts[i - 1][2]:
            keep |= {i - 1, i}
    return np.array(sorted(keep))


def loop_energy(run, first_leg: int) -> float:
    """int P d(delta) [J/m] around the steady loop (legs first_leg, first_leg + 1), from its jumps alone.

    Along every equilibrium branch the total potential E (Equilibrium.energy: elastic energy less the work of
    adhesion over the contact) changes by dE = P d(delta) (G = w at the edges); a jump from state A to B is a
    straight segment (fixed P, delta or delta_work) that takes the work (P_A + P_B)(delta_B - delta_A)/2.  Round
    the closed loop the branches give -sum over the jumps of (E_B - E_A), so the loop work is the energy the jumps
    dissipate: sum of [(P_A + P_B)(delta_B - delta_A)/2 - (E_B - E_A)], each >= 0.  No quadrature: exact to the
    rounding of the states (tests compare a trapezoid over the dense path).  Each jump's by
    jkrcyl.analysis.landing.dissipated (kernel units, times the energy unit: J/m for a Contact's units; in
    Units.normalised the kernel unit, vartheta P* delta/Delta)."""
    return float(sum(_land.dissipated(run.pb, run.un, j.before, j.after) for j in run.jumps
                     if j.leg in (first_leg, first_leg + 1))) * run.un.energy_scale
