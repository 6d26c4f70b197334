"""The one load-path walker: the walk along a track (a branch as a polyline in the held quantity:
jkrcyl.analysis.tracks) and the path of slow pulling (where a jump lands and first contact:
jkrcyl.analysis.landing).  Used by pull-off, the
confined analysis and cycles (the atlas has a numba twin, tested equal to it).

A walk follows a track from a state towards a target value of the held quantity (P under load control, delta or
delta_work under grip) through stable, feasible states, and ends at an event:

* ``target``: the held quantity reaches the target (refined between grid points);
* ``fold``: the next state is unstable or the held quantity turns (refined to the stationary point);
* ``gap``: the next state is infeasible (JKR: h(pi) < 0, the top of the hole closes first, the confined regime;
  the cohesive law also where the gap closes beside the contact) and no feasible fold lies in the cell before it;
* ``end``: the track ends (the contact grows towards a_crit or round the circle).
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ..model.problem import Problem
from ..model.single_patch import solver
from ..units import CONTROLS, Units
from . import forward as _fw
from . import landing as _land
from . import tracing as _tr
from . import tracks as _tracks
from . import two_patch_fold as _fold2
from .two_patch_family import family as _family


def walk(track: "_tracks.SingleTrack", i: int, target: float):
    """From grid index i towards target (the held quantity; -inf: down to the end): (indices passed, event,
    end state), events as in the module docstring."""
    y, stable, feas = track.y, track.stable, track.feasible
    sgn = 1 if target > y[i] else -1
    if sgn * (target - y[i]) <= 0:
        return [i], "target", track.state_at(track.a[i])
    nxt = [k for k in (i - 1, i + 1) if 0 <= k < y.size and sgn * (y[k] - y[i]) > 0 and stable[k] and feas[k]]
    if not nxt:
        if _junction(track, i, sgn):     # a walk starting at the table's end where its branch goes on as another
            return [i], "end", track.state_at(track.a[i])
        return [i], "fold", _fold(track, i, sgn)
    step = nxt[0] - i
    j, passed = i, [i]
    while 0 <= j + step < y.size:
        k = j + step
        if sgn * (y[k] - target) >= 0:
            return passed, "target", track.exact(j, k, target)
        if not feas[k]:                  # a feasible fold inside the cell comes first (the atlas's order too)
            f = _fold_in_cell(track, j, k, sgn)
            return (passed, "fold", f) if f is not None else (passed, "gap", track.state_at(track.a[j]))
        if not stable[k] or sgn * (y[k] - y[j]) <= 0:
            return passed, "fold", _fold(track, j, sgn)
        j = k
        passed.append(j)
    return passed, "end", track.state_at(track.a[j])


def _junction(track, i: int, sgn: int) -> bool:
    """Whether grid index i is an end of the table where the held quantity grows past it the walk's way and the
    branch goes on as another there (SinglePatch.continues: the cohesive zone-only pin's touch and the contact
    branch's; a walk from a state between the last two points starts at the nearest, the end: lambda 1.2, M 0.04,
    vartheta 10 under grip read it as a fold, 'no stable state to jump to after the snap-in')."""
    regime, inner = getattr(track, "regime", None), _inner(track, i)
    if regime is None or inner is None or sgn * (track.y[i] - track.y[inner]) <= 0:
        return False
    sv = solver(track.pb)
    if not sv.has(regime):
        return False
    other = sv.continues(regime, float(track.a[i]))
    return other is not None and _goes_on(track, other, sgn)


def _goes_on(track, other, sgn: int) -> bool:
    """Whether the branch a table's end continues as, other = (regime, a), takes the held quantity on the walk's way
    from the junction; else the junction is a corner of the held quantity, a fold, and no end: the walk would go
    back and forth between the two ends (rigid cradle round a rubber pin, lambda 3, h0 0.1 Delta, under grip: the
    contact branch's touch end and the zone-only pin's are a minimum of delta, tests/test_lazy_track.py)."""
    regime, a = other
    if regime == "full-contact":                 # the bonded pin: no single-patch table (the round-zone tail's end)
        return True
    nxt = _tracks.track(track.pb, track.un, regime, track.side, track.control)
    j = nxt.index(a)
    inner = _inner(nxt, j)
    return inner is not None and sgn * (nxt.y[inner] - nxt.y[j]) > 0


def _inner(track, i: int):
    """The grid index next to i inside the table where i is one of its ends, else None."""
    size = track.y.size
    inner = 1 if i == 0 else size - 2 if i == size - 1 else -1
    return inner if 0 <= inner < size else None


def _fold(track, j: int, sgn: int):
    """The fold next to grid index j; the point j itself where the refined stationary point holds less than it
    (a corner of the branch, as the cohesive round-zone tail's join: no smooth extremum between the points)."""
    f = track.fold(j)
    held = getattr(f, "held", None)           # (a track of the fit's own states: no held value to compare)
    return f if held is None or sgn * (held() - track.y[j]) >= 0 else track.state_at(track.a[j])


def _fold_in_cell(track, j: int, k: int, sgn: int):
    """The fold of the held quantity between grid points j (feasible) and k (infeasible), if it is feasible and
    holds beyond y[j] in the walk's direction; else None (the gap closes first)."""
    vj, vk = track.slope(j), track.slope(k)
    if not np.sign(vj) * np.sign(vk) < 0:
        return None
    (lo, flo), (hi, fhi) = sorted(((float(track.a[j]), vj), (float(track.a[k]), vk)))
    r = solver(track.pb).root(CONTROLS[track.control].field_slope, lo, hi, flo, fhi)
    if r is None:
        return None
    f = track.state_at(r)
    return f if f.feasible and sgn * (f.held() - track.y[j]) >= 0 else None


def walk_two_patch(pb: Problem, un: Units, s, target: float, control: str):
    """On a traced two-patch branch of the law (its family: jkrcyl.analysis.two_patch_family) from state s towards
    target: (visited points, event, end state).  JKR: the target state and the fold (the root of the held
    quantity's slope) solved on the branch between its points (jkrcyl.analysis.two_patch_fold); a law whose branch
    is sampled coarsely (the cohesive one): the target state by Brent and the fold by Brent's search between
    branch points."""
    fam = _family(pb)
    exact = not pb.models("two-patch")
    bs = fam.branches() if exact else _tr.branches(pb)
    best = None
    for b in bs:
        d = np.hypot(b.eps - s.eps, b.eps_top - s.eps_top)
        if best is None or d.min() < best[0]:
            best = (d.min(), b, int(np.argmin(d)))
    _, b, i = best
    ctl = CONTROLS[control]
    y = np.asarray(getattr(b, ctl.normalised)) * un.per_normalised(control)
    stable = getattr(b, ctl.stable)
    state = lambda e, et: _fw.two_patch_state(pb, un, _tr._two.equilibrium_state(pb, e, et), control)
    as_eq = lambda x: _fw.two_patch_state(pb, un, x, control)
    sgn = 1 if target > y[i] else -1
    goal = target / un.per_normalised(control)
    if exact and sgn * (target - s.held()) <= 0:
        return [], "target", s
    step = next((k - i for k in (i - 1, i + 1) if 0 <= k < y.size and sgn * (y[k] - y[i]) > 0), None)
    if step is None:
        return [], "fold", s
    j, seen = i, []
    while 0 <= j + step < y.size:
        k = j + step
        if sgn * (y[k] - target) >= 0:
            if exact:
                return seen, "target", as_eq(fam._refine(b, min(j, k), ctl.normalised, goal, fam.n))
            got = _fold2.at_target(pb, b, j, k, ctl.normalised, goal)
            if got is not None:
                return seen, "target", as_eq(got)
            t = (target - y[j]) / (y[k] - y[j])          # no equilibrium solved on the chord: interpolated
            return seen, "target", state(float(b.eps[j] + t * (b.eps[k] - b.eps[j])),
                                         float(b.eps_top[j] + t * (b.eps_top[k] - b.eps_top[j])))
        if not stable[k] or not b.feasible[k] or sgn * (y[k] - y[j]) <= 0:
            if exact:                    # the fold in (j - step, k): the sampled branch may hide its extremum
                f, event = fam.fold(b, j - step if j != i else j, k, ctl.normalised, sgn, goal)
                return seen, event, as_eq(f)
            return seen, *_jkr_fold(pb, b, j - step if j != i else j, k, j, ctl.normalised, sgn, goal, as_eq)
        j = k
        seen.append((un.physical("load", b.P_star[j]), un.physical("grip", b.delta_over_Delta[j]), "two-patch", b.a[j]))
    if not exact:
        return seen, *_jkr_fold(pb, b, j - step, j, j, ctl.normalised, sgn, goal, as_eq)
    f, event = fam.fold(b, j - step, j, ctl.normalised, sgn, goal)
    return seen, event, as_eq(f)


def _jkr_fold(pb, b, lo: int, hi: int, j: int, key: str, sgn: int, goal: float, as_eq):
    """(event, state) of JKR's walk stopping between points lo and hi of branch b (j: its last stable, feasible
    point): the fold refined on the branch (jkrcyl.analysis.two_patch_fold) where it is feasible and holds beyond
    point j, or the target between j and it where it lies past the target; point j itself where no fold is
    bracketed there (the walk stopped at a feasibility or stability bound, not at an extremum)."""
    got = _fold2.fold(pb, b, lo, hi, key)
    if got is not None:
        f, x = got
        v = _fold2.held(pb, f, key)
        if f.gap_min >= -1e-9 and sgn * (v - float(getattr(b, key)[j])) >= 0:
            if sgn * (v - goal) <= 0:
                return "fold", as_eq(f)
            t = _fold2.at_target(pb, b, lo, hi, key, goal, span=(_fold2.coordinate(b, lo, hi, j), x))
            if t is not None:
                return "target", as_eq(t)
    return "fold", as_eq(_tr._two.equilibrium_state(pb, float(b.eps[j]), float(b.eps_top[j])))


class PullPath(NamedTuple):
    """The path of slow pulling from first contact (:func:`pull_path`): start, event, the state where it ends,
    and towards, the sign of the branch parameter's change along the last walk (0 where there was none): a fold
    reached that way is left that way (the stable side is behind it)."""

    start: object
    event: str
    state: object
    towards: int = 0


def pull_path(pb: Problem, un: Units, control: str) -> PullPath:
    """The path of slow pulling from first contact: (start, event, state, towards).  start is the state first
    contact snaps into (None: no stable, feasible one); event: 'bonded' (start is full contact), 'elsewhere' (start
    is not a bottom single patch), 'round' (the branch closes into the bonded pin without a jump: the cohesive
    round-zone tail; state: the bonded pin), else the walk's event down the start's branch to -inf (fold, gap, end) and the
    state where it ends; 'let-go' where a branch ends on an unstable continuation under a pull (the cohesive
    contact at its touch end: the pin lets go there).  pull_off, confined_events and the confined figure all read
    this one path.  'float': a floating pin (cohesive range reaching round) went on onto the contact branch at
    first touch and the walk brought it back to that touch."""
    _, start, _ = _land.first_contact(pb, un, control)
    if start is None:
        return PullPath(None, "none", None)
    if start.branch == "full-contact":
        return PullPath(start, "bonded", start)
    if start.side != "bottom":
        return PullPath(start, "elsewhere", start)
    track = _tracks.track(pb, un, start.branch, "bottom", control)
    began = start.a
    _, event, state = walk(track, track.index(start.a), -math.inf)
    if event in ("fold", "end") and state.a <= track.a[0] and solver(pb).floats_onto() == track.a[0]:
        return PullPath(start, "float", state)   # back at the touch end: the contact vanishes, the pin floats again
    legs = {(start.branch, start.a)}
    while event == "end":                  # a branch going on as another (cohesive: contact -> zone-only pin)
        nxt = _land.continuation(pb, un, state, control)
        if nxt is None:
            break                          # the branch just ends (JKR: the contact grows towards a_crit)
        if (nxt.branch, nxt.a) in legs:    # never expected (walk's _goes_on): fail, not loop
            raise RuntimeError(f"the pull path came back to the {nxt.branch} state at a = {nxt.a:g}")
        legs.add((nxt.branch, nxt.a))
        if nxt.branch == "full-contact" and nxt.stable and nxt.feasible:
            return PullPath(start, "round", nxt)     # a cohesive round-zone tail closing into the bonded pin
        if not (nxt.stable and nxt.feasible):
            return PullPath(start, ("end" if state.P >= 0 else "let-go"), nxt)   # let-go: detaches at its end
        track = _tracks.track(pb, un, nxt.branch, "bottom", control)
        began = nxt.a
        _, event, state = walk(track, track.index(nxt.a), -math.inf)
    return PullPath(start, event, state, int(np.sign(state.a - began)))
