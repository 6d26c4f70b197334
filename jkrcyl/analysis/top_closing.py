"""Where the top of the hole closes: the onsets where the top adheres (h(pi) = 0, or the law's range h0) and the
landing there (jkrcyl.analysis.landing.land: the top-contact jump), predicted by the relaxation of the edges at the
held value (jkrcyl.model.two_patch.descend)."""
from __future__ import annotations

import math

import numpy as np

from ..model import two_patch as _two
from ..model.problem import Problem
from ..model.single_patch import solver
from ..units import Units
from . import branches as _br
from . import forward as _fw
from . import tracing as _tr


def other_side(side):
    return {"bottom": "top", "top": "bottom"}.get(side, side)


def top_onset(pb: Problem, un: Units, s, control: str):
    """The state of the branch of s where the gap at the top reaches the law's range, h(pi) = h0 (JKR: 0),
    between s (a feasible table point, the walk's 'gap') and its infeasible neighbour below it: where the top
    adheres (the law's table is coarse there: the walk lands from this state).  Under the cohesive law the single
    patch ends there, not where h(pi) = 0: below h0 the law pulls at the top, and the top-zone states beyond
    (jkrcyl.numerics.cohesive_top_zone) are saddles, the barrier to two patches vanishing at h(pi) = h0 -- a
    fold of the combined branch.  s itself where no such neighbour brackets a root."""
    regime = s.branch.replace("-top", "")
    t = _br.table(pb, regime)
    h0 = pb.edge.range_over_Delta(pb.m)
    a, h = np.asarray(t.a), np.asarray(t.h_pi_over_Delta) - h0
    i = int(np.argmin(np.abs(a - s.a)))
    for k in (i - 1, i + 1):
        if 0 <= k < a.size and h[k] <= 0 < h[i]:
            (lo, flo), (hi, fhi) = sorted(((float(a[i]), float(h[i])), (float(a[k]), float(h[k]))))
            r = solver(pb).root("h", lo, hi, flo, fhi, target=h0)
            if r is not None:
                return _fw.single_patch_states(pb, un, regime, [r], control, s.side)[0]
    return s


def top_onsets(pb: Problem):
    """(eps, P*, delta/Delta, stable under load) of every single-patch state where the top adheres: h(pi) equal
    to the law's range (JKR: h(pi) = 0; the cohesive law: h0, top_onset)."""
    if not pb.models("two-patch"):     # a law's branch parameter is not tan(eps/2): its states at the roots of h
        un = Units.normalised(pb, K_edge=1.0)
        h0 = pb.edge.range_over_Delta(pb.m)
        return tuple(sorted((s.eps, s.P_star, s.delta_over_Delta, s.stable_load) for r in _br.solver(pb).regimes()
                            if r != _br.ZONE_ONLY for s in _fw.single_patch_states(
                                pb, un, r, [a for a, _ in _br.roots(pb, r, "h", h0)], "load")))
    out = []
    for e in _tr.onset_angles(pb):
        a = math.tan(e / 2)
        c = _br.values_at(pb, _br.solver(pb).regime_of(a), a)
        out.append((e, float(c.P_star[0]), float(c.delta_over_Delta[0]), bool(c.stable_load[0])))
    return tuple(out)


def jkr_onset(jkr: Problem, s, control: str) -> float:
    """The held value (normalised: P*, delta/Delta, delta_work/Delta) of JKR's top onset (h(pi) = 0,
    :func:`top_onsets`) nearest to the contact of s: where JKR's descent predicts what follows a law's top onset
    (the law's top adheres at h(pi) = h0, earlier than JKR's by ~h0 log(lambda): jkrcyl.numerics.cohesive_top_zone)."""
    _, P, d, _ = min(top_onsets(jkr), key=lambda o: abs(o[0] - s.eps))
    v = {"load": P, "grip": d, "grip-work": d + jkr.work_shift * jkr.scale * P}[control]
    return v if s.side != "top" else -v if control == "load" else -2.0 - v     # a walk at the top: its mirror


POLE = ("the paper's delta held ('grip'): relaxing from there the contact runs into the pole of the fixed arcs, "
        "where the load is unbounded and the potential of a held delta unbounded below (it is E_work - c p^2/2: a "
        "grip of negative compliance); control='grip-work' holds the pin")


def into_pole(pb: Problem, un: Units, s, control: str, value: float) -> bool:
    """Whether the relaxation where the top closes from s at the held value runs into a pole of the fixed arcs
    (jkrcyl.model.two_patch.descend: 'pole'; JKR, the paper's delta held)."""
    if control != "grip" or not pb.models("two-patch") or s.side not in ("bottom", "top"):
        return False
    target = un.normalise(control, value)
    target = -2.0 - target if s.side == "top" else target
    return _two.descend(pb, target, s.eps, control=control)[0] == "pole"


def land_on_top_contact(pb, s, cands, control, target, jkr=None):
    """The gap at phi = pi closes (h(pi) = 0, the walk's 'gap'; the law's range h0 for a cohesive law): a nascent
    top contact appears and the edges relax at the held value (jkrcyl.model.two_patch.descend); the landing is the
    candidate where that relaxation ends -- full contact, the patch on the other side (the bottom arc vanished),
    or the two-patch state nearest to the end point; None where it runs into a pole of the fixed arcs (the
    paper's delta held: the potential of a held delta is unbounded below there, two_patch.descend).  jkr: the
    problem whose descent predicts it (a law with thin zones: JKR's, its limit, at its own onset: target is then
    JKR's held value there, :func:`jkr_onset`)."""
    pb = pb if jkr is None else jkr
    if s.side == "top":            # the mirror (P* -> -P*, approach -> -2 - approach): solve it at the bottom
        mirrored = -target if control == "load" else -2.0 - target
        outcome, end = _two.descend(pb, mirrored, s.eps, control=control)
        end = end[::-1]
        outcome = {"transfer": "single", "single": "transfer"}.get(outcome, outcome)
    else:
        outcome, end = _two.descend(pb, target, s.eps, control=control)
    if outcome == "pole":            # the paper's delta held: relaxing, the load grows without bound
        return None
    pools = {"full": [x for x in cands if x.branch == "full-contact"],
             "transfer": [x for x in cands if x.side == other_side(s.side)],
             "single": [x for x in cands if x.side == s.side and x.size < s.size],
             "two-patch": [x for x in cands if x.branch == "two-patch"]}
    pool = pools[outcome] or [x for x in cands if x.side in ("both", other_side(s.side))]
    if not pool:
        return None
    return min(pool, key=lambda x: math.dist(arcs(x), end))


def arcs(x):
    """(bottom, top) half-angles of a state, the frame of descend's end point (a patch at the top: (0, eps))."""
    return (0.0, x.eps) if x.side == "top" else (min(x.eps, math.pi), x.eps_top)
