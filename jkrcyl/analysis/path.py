"""The one load-path walker: tracks (branches as polylines in the held quantity), the walk along a track, where a
jump lands, and first contact.  Used by pull-off, the confined analysis and cycles (the atlas has a numba twin,
tested equal to it).

A walk follows a track from a state towards a target value of the held quantity (P under load control, delta or
delta_work under grip) through stable, feasible states, and ends at an event:

* ``target``: the held quantity reaches the target (refined between grid points);
* ``fold``: the next state is unstable or the held quantity turns (refined to the stationary point);
* ``gap``: the next state has h(pi) < 0 (the top of the hole closes first, the confined regime);
* ``end``: the track ends (the contact grows towards a_crit or round the circle).
"""
from __future__ import annotations

import math

import numpy as np

from ..model import two_patch as _two
from ..model.problem import Problem
from ..model.single_patch import solver
from ..units import CONTROLS, CURVE_FIELD, Units
from . import branches as _br
from . import forward as _fw
from . import tracing as _tr


class SingleTrack:
    """A single-patch branch (bottom or top, the mirror) on its dense table, the held quantity physical."""

    def __init__(self, pb: Problem, un: Units, regime: str, side: str, control: str):
        c = _br.table(pb, regime)
        self.pb, self.un, self.regime, self.side, self.control = pb, un, regime, side, control
        self.name = regime + ("-top" if side == "top" else "")
        self.a = np.asarray(c.a)
        sgn = -1.0 if side == "top" else 1.0
        self.P = un.physical("load", sgn * np.asarray(c.P_star))
        d, dw = np.asarray(c.delta_over_Delta), np.asarray(c.delta_work_over_Delta)
        self.delta = un.physical("grip", -2 - d if side == "top" else d)
        self.delta_work = un.physical("grip-work", -2 - dw if side == "top" else dw)
        self.stable = np.asarray(getattr(c, CONTROLS[control].stable))
        self.feasible = np.asarray(c.feasible)

    @property
    def y(self):
        return getattr(self, CONTROLS[self.control].physical)

    def state_at(self, a):
        return _fw.single_patch_states(self.pb, self.un, self.regime, a, self.control, self.side)[0]

    def _field_target(self, value):
        """The solver field of the held quantity and the bottom branch's target for a physical value."""
        ctl = CONTROLS[self.control]
        if ctl.is_load:                                     # mirror: P -> -P, either approach -> -2 Delta - itself
            return ctl.field, self.un.to_kernel("load", -value if self.side == "top" else value)
        t = self.un.to_kernel(self.control, value)
        return ctl.field, (-2 - t if self.side == "top" else t)

    def exact(self, j, k, target):
        """The state between grid indices j, k where the held quantity equals target."""
        field, t = self._field_target(target)
        lo, hi = sorted((float(self.a[j]), float(self.a[k])))
        sv = solver(self.pb)
        flo, fhi = sv.value(field, lo) - t, sv.value(field, hi) - t
        r = sv.root(field, lo, hi, flo, fhi, t) if flo * fhi < 0 else None
        return self.state_at(float(self.a[k]) if r is None else r)

    def fold_a(self, j):
        """Contact parameter of the stationary point of the held quantity next to grid index j: the sign change
        of its slope in the table cell on either side of j, refined exactly as branches.roots refines it (the
        same bracket, so the same double as jkrcyl.analysis.branches.stationary_roots)."""
        field = CONTROLS[self.control].field_slope
        name, scaled = CURVE_FIELD[field]
        v = np.asarray(getattr(_br.table(self.pb, self.regime), name)) * (self.pb.scale if scaled else 1.0)
        sv = solver(self.pb)
        for i in (j - 1, j):
            if 0 <= i < v.size - 1 and np.sign(v[i]) * np.sign(v[i + 1]) < 0:
                r = sv.root(field, float(self.a[i]), float(self.a[i + 1]), float(v[i]), float(v[i + 1]))
                if r is not None:
                    return r
        return float(self.a[j])

    def fold(self, j):
        return self.state_at(self.fold_a(j))

    def index(self, a):
        return int(np.argmin(np.abs(np.log(self.a) - math.log(a))))


def walk(track: SingleTrack, i: int, target: float):
    """From grid index i towards target (the held quantity; -inf: down to the end): (indices passed, event,
    end state), events as in the module docstring."""
    y, stable, feas = track.y, track.stable, track.feasible
    sgn = 1 if target > y[i] else -1
    if sgn * (target - y[i]) <= 0:
        return [i], "target", track.state_at(track.a[i])
    nxt = [k for k in (i - 1, i + 1) if 0 <= k < y.size and sgn * (y[k] - y[i]) > 0 and stable[k] and feas[k]]
    if not nxt:
        return [i], "fold", _fold(track, i, sgn)
    step = nxt[0] - i
    j, passed = i, [i]
    while 0 <= j + step < y.size:
        k = j + step
        if sgn * (y[k] - target) >= 0:
            return passed, "target", track.exact(j, k, target)
        if not feas[k]:
            return passed, "gap", track.state_at(track.a[j])
        if not stable[k] or sgn * (y[k] - y[j]) <= 0:
            return passed, "fold", _fold(track, j, sgn)
        j = k
        passed.append(j)
    return passed, "end", track.state_at(track.a[j])


def _fold(track, j: int, sgn: int):
    """The fold next to grid index j; the point j itself where the refined stationary point holds less than it
    (a corner of the branch, as the cohesive round-zone tail's join: no smooth extremum between the points)."""
    f = track.fold(j)
    held = getattr(f, "held", None)           # (a track of the fit's own states: no held value to compare)
    return f if held is None or sgn * (held() - track.y[j]) >= 0 else track.state_at(track.a[j])


def walk_two_patch(pb: Problem, un: Units, s, target: float, control: str):
    """On a traced two-patch branch from state s towards target: (visited states, event, end state); states
    between branch points by linear interpolation of the half-angles, solved afresh."""
    best = None
    for b in _tr.branches(pb):
        d = np.hypot(b.eps - s.eps, b.eps_top - s.eps_top)
        if best is None or d.min() < best[0]:
            best = (d.min(), b, int(np.argmin(d)))
    _, b, i = best
    ctl = CONTROLS[control]
    y = np.asarray(getattr(b, ctl.normalised)) * un.per_normalised(control)
    stable = getattr(b, ctl.stable)
    state = lambda e, et: _fw.two_patch_state(pb, un, _tr._two.equilibrium_state(pb, e, et), control)
    sgn = 1 if target > y[i] else -1
    step = next((k - i for k in (i - 1, i + 1) if 0 <= k < y.size and sgn * (y[k] - y[i]) > 0), None)
    if step is None:
        return [], "fold", s
    j, seen = i, []
    while 0 <= j + step < y.size:
        k = j + step
        if sgn * (y[k] - target) >= 0:
            t = (target - y[j]) / (y[k] - y[j])
            return seen, "target", state(float(b.eps[j] + t * (b.eps[k] - b.eps[j])),
                                         float(b.eps_top[j] + t * (b.eps_top[k] - b.eps_top[j])))
        if not stable[k] or not b.feasible[k] or sgn * (y[k] - y[j]) <= 0:
            return seen, "fold", state(float(b.eps[j]), float(b.eps_top[j]))
        j = k
        seen.append((un.physical("load", b.P_star[j]), un.physical("grip", b.delta_over_Delta[j]), "two-patch", b.a[j]))
    return seen, "fold", state(float(b.eps[j]), float(b.eps_top[j]))


def _other(side):
    return {"bottom": "top", "top": "bottom"}.get(side, side)


def continuation(pb: Problem, un: Units, s, control: str):
    """The state where the branch of s continues past its end (the cohesive contact branch's touch end and the
    zone-only branch, SinglePatch.continues; the round-zone tail and the bonded pin at its bond limit, into each
    other; a floats_onto touch end: the free pin at its range's end), or None."""
    if s.branch == "full-contact":            # the bond breaks: at the top pushing (P > 0), at the bottom pulling
        sv = solver(pb)
        end = float(np.asarray(_br.table(pb, "super-critical").a)[-1]) if sv.has("super-critical") else None
        ok = end is not None and sv.continues("super-critical", end) == ("full-contact", math.inf)
        return _fw.single_patch_states(pb, un, "super-critical", [end], control,
                                       "bottom" if s.P_star > 0 else "top")[0] if ok else None
    regime = s.branch.replace("-top", "")
    if regime == "sub-critical" and s.a == solver(pb).floats_onto():     # back to the touch: the pin floats
        hi = solver(pb).free_range()[1]
        return _fw.separated_state(pb, un, -2 - hi if s.side == "top" else hi, control)
    nxt = solver(pb).continues(regime, s.a) if solver(pb).has(regime) else None
    if nxt is None:
        return None
    if nxt[0] == "full-contact":              # the round-zone tail closing into the bonded pin, at the held value
        key = CONTROLS[control].normalised
        return _fw.full_contact_state(pb, un, key, getattr(s, key), control)     # either side: the same pin
    return _fw.single_patch_states(pb, un, nxt[0], [nxt[1]], control, s.side)[0]


def land(pb: Problem, un: Units, s, event: str, control: str, value: float, up: bool):
    """The state a jump from s lands on, at the same held value, and the jump's kind ('snap-in', 'pull-off',
    'zip', 'top-contact'; 'continue' where a branch goes on as another, without a jump); (None, kind) when no
    stable, feasible state is there."""
    if event == "end":
        nxt = continuation(pb, un, s, control)
        if nxt is not None:
            if nxt.stable and nxt.feasible:
                return nxt, "continue"
            across = _floats_onto(pb, un, control, _other(s.side)) if nxt.branch == "separated" else None
            if across is not None:   # a floating pin under load (P = 0 only) floats across onto the other side's
                return across, "continue"      # touch end: no jump, the contact vanishes and forms continuously
            event = "fold"           # its continuation is unstable: the path jumps from the branch's end
    # two-patch states are traced by continuation: only where the contact grows or the top closes
    quick = event == "touch" or (event == "fold" and s.branch.startswith("sub-critical"))
    names = [b for b in _fw.BRANCH_SOLVERS if not (quick and b == "two-patch")]
    target = un.normalise(control, value)

    def candidates(branches):
        return [x for x in _fw.solve_normalised(pb, un, control, target, branches) if x.stable and x.feasible
                and not (x.branch == s.branch and abs(x.a - s.a) <= 1e-6 * max(s.a, 1e-300))]
    # a snap-in takes the smallest state on its side, a sub-critical pull-off a smaller one or the smallest on the
    # other side: a super-critical state (eps > eps_crit) is larger than any sub-critical one, so those branches
    # (for a traced law, a trace of their own) are searched only where the others leave no candidate
    small = s.branch == "separated" or (event == "fold" and s.branch.startswith("sub-critical"))
    first = [b for b in names if not b.startswith("super-critical")] if small else names
    cands = candidates(first)
    if s.branch == "separated":                          # free pin touching a side: snap-in there
        side = ("bottom" if up else "top") if control == "load" else \
            ("bottom" if value >= -un.Delta else "top")
        floated = _floats_onto(pb, un, control, side)     # or a floating pin going on onto its contact
        if floated is not None:
            return floated, "continue"
        if first != names and not any(x.side == side for x in cands):
            cands = candidates(names)
        on = [x for x in cands if x.side == side] or [x for x in cands if x.side == "both" and
                                                      _zips_round(pb, un, control, target, side)]
        return (min(on, key=lambda x: x.size), "snap-in") if on else (None, "snap-in")
    if event in ("fold", "end") and s.branch.startswith("contactless"):    # the zone-only pin (cohesive)
        if up:
            into = [x for x in cands if x.side == s.side and x.size > 0]
            return (min(into, key=lambda x: x.size), "snap-in") if into else (None, "snap-in")
        off = [x for x in cands if x.branch == "separated" or x.side == _other(s.side)]
        return (min(off, key=lambda x: x.size), "pull-off") if off else (None, "pull-off")
    # a cohesive S-shaped branch's fold met pushing, or one the pull-off rule has no state for: the nearest in size
    nearest = lambda xs: min(xs, key=lambda x: abs(x.size - s.size)) if xs else None
    if event == "fold" and s.branch.startswith("sub-critical") and up:
        got = nearest([x for x in cands if x.side == s.side])
        if got is not None:
            return got, "snap-in"
    if event == "fold" and s.branch.startswith("sub-critical"):
        got = _pull_off_landing(s, cands, control)
        if got is None and first != names:
            got = _pull_off_landing(s, candidates(names), control)
        if got is None:
            got = nearest([x for x in candidates(names) if x.side == s.side])
        return got, "pull-off"
    if event == "fold":
        grow = [x for x in cands if x.size > s.size and x.side in (s.side, "both")]
        return (min(grow, key=lambda x: x.size), "zip") if grow else (None, "zip")
    if not pb.models("two-patch"):       # the top closes: the nascent top contact needs two patches
        return None, "top-contact"
    return _land_on_top_contact(pb, s, cands, control, target), "top-contact"


def _zips_round(pb, un, control, target, side):
    """Whether a pin with no stable, feasible state on its side at first touch zips round (lands on both): with
    two patches modelled always, else where it has no single-patch state there at all (one overlapping the top
    would form a second patch)."""
    if pb.models("two-patch"):
        return True
    names = [b for b in _fw.BRANCH_SOLVERS if b not in ("separated", "full-contact", "two-patch")]
    return not any(x.side == side for x in _fw.solve_normalised(pb, un, control, target, names))


def _pull_off_landing(s, cands, control):
    """Where a sub-critical fold's pull-off lands among cands: the largest smaller state on its side, else (grip)
    the free pin, else the smallest state on the other side; None."""
    same = [x for x in cands if x.side == s.side and x.size < s.size]
    if same:
        return max(same, key=lambda x: x.size)
    if control != "load":
        sep = [x for x in cands if x.branch == "separated"]
        if sep:
            return sep[0]
    other = [x for x in cands if x.side == _other(s.side)]
    return min(other, key=lambda x: x.size) if other else None


def _land_on_top_contact(pb, s, cands, control, target):
    """The gap at phi = pi closes (h(pi) = 0, the walk's 'gap'): a nascent top contact appears and the edges relax
    at the held value (jkrcyl.model.two_patch.descend); the landing is the candidate where that relaxation ends
    -- full contact, the patch on the other side (the bottom arc vanished), or the two-patch state nearest to
    the end point."""
    if s.side == "top":            # the mirror (P* -> -P*, approach -> -2 - approach): solve it at the bottom
        mirrored = -target if control == "load" else -2.0 - target
        outcome, end = _two.descend(pb, mirrored, s.eps, control=control)
        end = end[::-1]
        outcome = {"transfer": "single", "single": "transfer"}.get(outcome, outcome)
    else:
        outcome, end = _two.descend(pb, target, s.eps, control=control)
    pools = {"full": [x for x in cands if x.branch == "full-contact"],
             "transfer": [x for x in cands if x.side == _other(s.side)],
             "single": [x for x in cands if x.side == s.side and x.size < s.size],
             "two-patch": [x for x in cands if x.branch == "two-patch"]}
    pool = pools[outcome] or [x for x in cands if x.side in ("both", _other(s.side))]
    if not pool:
        return None
    return min(pool, key=lambda x: math.hypot(x.eps - end[0], x.eps_top - end[1]))


def first_contact(pb: Problem, un: Units, control: str):
    """(free pin touching the bottom, the state it snaps into, kind): at P = 0 under load control (the zero-load
    contact (8.1); full contact when there is none, M > M_max), at the held approach 0 under grip.

    A cohesive law attracts the pin before it touches: the free pin reaches the range of the bottom at
    delta = -h0 (the top of the solver's free range); under grip that is where it snaps in (the zone-only
    states there are unstable under grip for a thin zone) onto the stable state at that approach, under load
    it is drawn in at P = 0 onto the zero-load contact (the zone-only pin is a saddle under load)."""
    hi = solver(pb).free_range()[1]
    sep = _fw.separated_state(pb, un, hi, control)
    to, kind = land(pb, un, sep, "touch", control, 0.0 if control == "load" else hi * un.Delta, True)
    return sep, to, kind


def _floats_onto(pb: Problem, un: Units, control: str, side: str):
    """The touch end (SinglePatch.floats_onto) a pin floating in a cohesive range goes on onto at the side, no
    jump, if stable, feasible and, under load, pushing (else the pin is drawn in); else None."""
    a = solver(pb).floats_onto()
    if a is None:
        return None
    s, hi = _fw.single_patch_states(pb, un, "sub-critical", [a], control, side)[0], solver(pb).free_range()[1]
    at = (s.P >= 0) == (side == "bottom") if control == "load" else \
        abs(s.delta / un.Delta - (hi if side == "bottom" else -2 - hi)) < 1e-4       # grip: at the free range's end
    return s if s.stable and s.feasible and at else None


def pull_path(pb: Problem, un: Units, control: str):
    """The path of slow pulling from first contact: (start, event, state).  start is the state first contact
    snaps into (None: no stable, feasible one); event: 'bonded' (start is full contact), 'elsewhere' (start is
    not a bottom single patch), else the walk's event down the start's branch to -inf (fold, gap, end) and the
    state where it ends; 'let-go' where a branch ends on an unstable continuation under a pull (the cohesive
    contact at its touch end: the pin lets go there).  pull_off, confined_events and the confined figure all read
    this one path.  'float': a floating pin (cohesive range reaching round) went on onto the contact branch at
    first touch and the walk brought it back to that touch."""
    _, start, _ = first_contact(pb, un, control)
    if start is None:
        return None, "none", None
    if start.branch == "full-contact":
        return start, "bonded", start
    if start.side != "bottom":
        return start, "elsewhere", start
    track = SingleTrack(pb, un, start.branch, "bottom", control)
    _, event, state = walk(track, track.index(start.a), -math.inf)
    if event in ("fold", "end") and state.a <= track.a[0] and solver(pb).floats_onto() == track.a[0]:
        return start, "float", state       # back at the touch end: the contact vanishes, the pin floats again
    while event == "end":                  # a branch going on as another (cohesive: contact -> zone-only pin)
        nxt = continuation(pb, un, state, control)
        if nxt is None:
            break                          # the branch just ends (JKR: the contact grows towards a_crit)
        if not (nxt.stable and nxt.feasible):
            return start, ("end" if state.P >= 0 else "let-go"), nxt    # let-go: detaches at the branch's end
        track = SingleTrack(pb, un, nxt.branch, "bottom", control)
        _, event, state = walk(track, track.index(nxt.a), -math.inf)
    return start, event, state
