"""Where a jump lands, how a branch continues past its end, and first contact: the landing half of the load-path
walker (jkrcyl.analysis.path walks the tracks; pull-off, the confined analysis, cycles and the kinetics read
both).  A jump keeps the held value: :func:`land` picks the stable, feasible state it lands on among the
solutions of every branch at that value (jkrcyl.analysis.forward.solve_normalised) that the jump dissipates energy
to (:func:`_landable`); where the top closes, the relaxation of jkrcyl.analysis.top_closing says which.
"""
from __future__ import annotations

import functools
import math

import numpy as np

from ..model import two_patch as _two
from ..model.problem import Problem
from ..model.single_patch import solver
from ..units import CONTROLS, Units
from . import branches as _br
from . import cohesive_two_patch as _cohesive
from . import forward as _fw
from . import two_patch_fold as _fold2
from .top_closing import POLE, into_pole, top_onset, top_onsets      # noqa: F401 (the walker reads them here)
from .top_closing import arcs as _arcs, jkr_onset as _jkr_onset, land_on_top_contact as _land_on_top_contact, \
    other_side
from .two_patch_family import family as _family


ZONE_PARTS = ("the zone-only pin's gap at the bottom leaves the range (h(0) = h0: the pin drawn across the "
              "middle of the hole, its gap nearly uniform): its zone would part into two beside the bottom -- a zone "
              "that does not hold phi = 0 is not modelled")
ZONES_BOTH_SIDES = ("the zone-only pin's top gap reaches the range h0: the pin held by zones at the bottom and the "
                    "top without contact is not followed")


def across_a_crit(pb: Problem, un: Units, control: str, target: float) -> str:
    """Why a jump at the held value target (normalised) may have its landing on the untraced piece of a branch
    crossing the receding limit with a finite load (the super-critical table turning back to a_crit: cohesive
    model, jkrcyl.model.cohesive_traced.super_short): target between the two tables' ends there; else ''."""
    sv = solver(pb)
    if not sv.has("super-critical"):
        return ""
    end = float(np.asarray(_br.table(pb, "super-critical").a)[-1])
    if "crosses it" not in sv.stops_short("super-critical", end):         # (only a traced law's table says so)
        return ""
    ends = [float(np.asarray(_br.table(pb, "sub-critical").a)[-1]), end]
    key = CONTROLS[control].normalised
    x, y = (getattr(_fw.single_patch_states(pb, un, r, [a], control)[0], key)
            for r, a in zip(("sub-critical", "super-critical"), ends))
    mirror = -target if control == "load" else -2.0 - target          # the top's states: the bottom's mirrored
    if not any(min(x, y) <= v <= max(x, y) for v in (target, mirror)):
        return ""
    return (f"the state at this held {key} lies on the contact branch's crossing of the receding "
            f"limit a_crit, between the sub-critical table's end ({x:.6g}) and the super-critical one's ({y:.6g}), "
            "not traced")


def zone_only_stop(pb: Problem, s) -> str:
    """Why the zone-only pin s (at the end of its feasible states: jkrcyl.analysis.top_closing.top_onset) has no
    state to go on to: where its gap reaches h0 -- at the bottom (its zone's middle leaves the range) or at the
    top (a zone forms there)."""
    side = solver(pb).point(s.a).state.fields
    h0 = pb.m ** 2 / pb.edge.s0
    bottom, top = (abs(float(side.gap(phi)[0]) - h0) for phi in (0.0, math.pi))
    return ZONE_PARTS if bottom < top else ZONES_BOTH_SIDES


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
            across = _floats_onto(pb, un, control, other_side(s.side)) if nxt.branch == "separated" else None
            if across is not None:   # a floating pin under load (P = 0 only) floats across onto the other side's
                return across, "continue"      # touch end: no jump, the contact vanishes and forms continuously
            event = "fold"           # its continuation is unstable: the path jumps from the branch's end
    # two-patch states are traced by continuation: only where the contact grows or the top closes
    quick = event == "touch" or (event == "fold" and s.branch.startswith("sub-critical"))
    names = [b for b in _fw.BRANCH_SOLVERS if not (quick and b == "two-patch")]
    target = un.normalise(control, value)

    def candidates(branches):
        return _landable(pb, un, s, _fw.solve_normalised(pb, un, control, target, branches))
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
        if up == (s.side == "bottom"):      # driven towards its own side (on the top: the held value falls)
            into = [x for x in cands if x.side == s.side and x.size > 0]
            return (min(into, key=lambda x: x.size), "snap-in") if into else (None, "snap-in")
        off = [x for x in cands if x.branch == "separated" or x.side == other_side(s.side)]
        return (min(off, key=lambda x: x.size), "pull-off") if off else (None, "pull-off")
    # a cohesive S-shaped branch's fold met pushing, or one the pull-off rule has no state for: the nearest in size
    nearest = lambda xs: min(xs, key=lambda x: abs(x.size - s.size)) if xs else None
    if event == "fold" and s.branch.startswith("sub-critical") and up:
        got = nearest([x for x in cands if x.side == s.side])
        if got is None and first != names:    # pushed past a round zone's opening (h0 4.21: vartheta 10, gb 0,
            got = nearest([x for x in candidates(names) if x.side == s.side])   # lambda 3.155): super-critical
        if got is not None:
            return got, "snap-in"
    if event == "fold" and s.branch.startswith("sub-critical"):
        got = _pull_off_landing(s, cands, control)
        if got is None and first != names:
            got = _pull_off_landing(s, candidates(names), control)
        if got is None:
            got = nearest([x for x in candidates(names) if x.side == s.side])
        return got, "pull-off"
    if s.branch == "full-contact":     # the bond breaks at its limit with no branch going on from the bonded pin
        # (vartheta 10, gb 0, lambda 19.9, M 0.122 pulled to P* -0.785): the contact recedes onto the largest
        # stable state the jump dissipates to (there the top's super-critical patch, 4.26 of 6.28 wide)
        return (max(cands, key=lambda x: x.size) if cands else None), "pull-off"
    if event == "fold" and s.branch == "two-patch":
        return _leave_two_patch(pb, un, s, cands, control, target, up)
    if event == "fold":          # a super-critical fold: the contact grows (zips round), else pushed (the round-zone
        grow = [x for x in cands if x.size > s.size and x.side in (s.side, "both")]    # tail's largest load: the
        if grow:                 # bond at the top breaks) onto the nearest stable state on its side; a cohesive
            return min(grow, key=lambda x: x.size), "zip"      # super-critical S met pulling: its other stable part
        same = [x for x in cands if x.side == s.side]            # (cands: stable, feasible, dissipating)
        if same:
            return nearest(same), "zip"
        # zipping round where the bond cannot hold: onto the other side's contact reaching round (open where the
        # bond breaks; vartheta 10, gb 0, lambda 7.9, M 0.246: P* -0.1351 past the bond limit -0.1341)
        over = [x for x in cands if x.size > s.size]
        return (min(over, key=lambda x: x.size) if over else None), "zip"
    if s.branch.startswith("contactless"):    # the zone-only pin's gap reaches h0 beyond its zone or in its
        # middle (h0 ~ Delta): onto a stable state the jump dissipates to, the pin floating all round if it does
        floating = [x for x in cands if x.branch == "separated"]
        return (floating[0] if floating else None), "top-contact"
    if not pb.models("two-patch"):       # the top closes: the law's traced two-patch branch, where it has one
        if not pb.models("two-patch-branches") or two_patch_refusal(pb):
            return None, "top-contact"
        two = [_fw.two_patch_state(pb, un, x, control) for x, _ in _cohesive.land_two_patch(pb, control, target)]
        cands = [x for x in cands if x.branch != "two-patch"] + _landable(pb, un, s, two)
        jkr = Problem(pb.M, pb.theta, pb.gb)
        return _land_on_top_contact(pb, s, cands, control, _jkr_onset(jkr, s, control), jkr), "top-contact"
    return _land_on_top_contact(pb, s, cands, control, target), "top-contact"


@functools.lru_cache(maxsize=32)
def two_patch_refusal(pb: Problem) -> str:
    """Why the law's traced two-patch branch is not followed on this problem ('' where it is: the law's family
    refuses it, e.g. the cohesive law's zones too thin or too thick, alpha* != 0, or neither of its routes finds
    a state from JKR's branch -- vartheta 10, gb 0, lambda 19.9, M 0.122: JKR's smaller arc <= 0.0011 rad against
    zones of 0.0115, where a load cycle raised that ValueError from inside its walk).  Cached: a refusal costs the
    trace (the branches themselves are cached by their family)."""
    if pb.models("two-patch"):                  # JKR's branches: solved directly (jkrcyl.model.two_patch)
        return ""
    try:
        _family(pb).branches()                  # the law's branches: its refusal, if any
    except ValueError as why:
        return str(why)
    return ""


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
    other = [x for x in cands if x.side == other_side(s.side)]
    return min(other, key=lambda x: x.size) if other else None


def dissipated(pb: Problem, un: Units, a, b) -> float:
    """The energy a jump from state a to state b at a held value dissipates, kernel scale (units 4 pi Delta^2/
    beta*): the work of the held quantity's conjugate, (P*_a + P*_b)/2 (delta_b - delta_a) vartheta, less the change
    of the total potential (Equilibrium.energy, dE = P d delta along every branch).  >= 0 for a jump that can
    happen (a straight segment at fixed P, delta or delta_work: cycle.loop_energy)."""
    work = pb.scale * 0.5 * (a.P_star + b.P_star) * (b.delta_over_Delta - a.delta_over_Delta)
    return work - (b.energy - a.energy) / un.energy_scale


def _landable(pb, un, s, states):
    """The states a jump from s can land on: stable, feasible, not s itself, and dissipating energy (>= 0 up to
    1e-9 of the potential): every jump at a held value lowers the total potential less the held quantity's work
    (the levels of every state kind agree, tests/test_energy_levels.py; a landing on full contact where the top
    closes while pushing hard raised it by ~1300 kernel units: M 0.40, vartheta 1, gb 0, load P* 48.8)."""
    tol = 1e-9 * max(abs(s.energy / un.energy_scale), 1.0)
    # (x.a == s.a first: full contact has a = inf, where inf - inf is nan)
    same = lambda x: x.branch == s.branch and (x.a == s.a or abs(x.a - s.a) <= 1e-6 * max(s.a, 1e-300))
    return [x for x in states if x.stable and x.feasible and dissipated(pb, un, s, x) >= -tol and not same(x)]


def _leave_two_patch(pb, un, s, cands, control, target, up):
    """A fold of the two-patch branch: (landing, kind).  The edges relax from the fold driven past it (JKR's
    two_patch.escape: its descent along the fold's unstable direction; a law with thin zones asks JKR's own fold
    next to it, its limit); the landing is the candidate where that ends -- full contact ('zip'), the patch on
    one side (the other arc let go: 'pull-off') or the two-patch state nearest to the end point (cands: those the
    jump dissipates energy to, :func:`_landable`)."""
    sgn = 1 if up else -1
    if pb.models("two-patch"):
        outcome, end = _two.escape(pb, s.eps, s.eps_top, target, control, sgn)
    else:
        outcome, end = _jkr_escape(pb, un, s, control, target, sgn)
    if outcome == "pole":            # the paper's delta held: relaxing, the load grows without bound
        return None, "zip" if up else "pull-off"
    pools = {"full": [x for x in cands if x.branch == "full-contact"],
             "transfer": [x for x in cands if x.side == "top"],
             "single": [x for x in cands if x.side == "bottom"],
             "two-patch": [x for x in cands if x.branch == "two-patch"]}
    pool = pools[outcome] or cands
    if not pool:
        return None, "zip" if outcome == "full" else "pull-off"
    to = min(pool, key=lambda x: math.dist(_arcs(x), end))
    grew = to.branch == "full-contact" or (to.branch == "two-patch" and to.size > s.size)
    return to, ("zip" if grew else "pull-off")


def _jkr_escape(pb, un, s, control, target, sgn):
    """JKR's escape (outcome, end arcs) from its own fold next to a law's two-patch fold s (at the law's fold where
    JKR's branch has none there)."""
    jkr = Problem(pb.M, pb.theta, pb.gb)
    key = CONTROLS[control].normalised
    f = _fold2.fold_near(jkr, s.eps, s.eps_top, key, sgn)
    value = target if f is None else _fold2.held(jkr, f, key)
    f = s if f is None else f
    return _two.escape(jkr, f.eps, f.eps_top, value, control, sgn)


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
