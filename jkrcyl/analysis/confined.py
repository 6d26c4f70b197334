"""The confined regime under load control: what slow pulling does to the pin in the hole.

The load path is the one of pull-off (jkrcyl.analysis.path: first contact, then the walk down in P through
stable, feasible single-patch states).  Its first event decides (results.paths.REGIMES):

* a fold (P* minimum): a further pull opens the edge (G > w, the fixed-arc dp/dk < 0): ``detachment`` (in the
  hole the pin lands on the top), or closes it (G < w): ``zip-full``;
* h(pi) = 0 first: the top contact forms at that load, and what follows is where the total potential at fixed load
  leads from the onset with a nascent top contact (jkrcyl.model.two_patch.descend): ``two-patch`` (a stable
  two-patch state), ``snap-in-full`` (the arcs run into full contact) or ``snap-in-transfer`` (the bottom arc
  vanishes: the pin ends on the top of the hole);
* full contact at first touch (no zero-load contact): ``bonded``.
"""
from __future__ import annotations

import functools
import math
from dataclasses import replace

from ..model import full_contact as _full
from ..model import two_patch as _two
from ..model.problem import Problem
from ..results import ConfinedEvents
from . import branches as _br
from ..units import Units
from . import landing as _land
from . import path as _path
from . import pull_off as _po
from . import tracing as _tr
from .two_patch_family import family as _family

_DESCENT = {"full": "snap-in-full", "transfer": "snap-in-transfer", "two-patch": "two-patch",
            "single": "two-patch"}


@functools.lru_cache(maxsize=32)
def confined_events(pb: Problem) -> ConfinedEvents:
    """Classify the confined regime of a problem (finite vartheta, M > 0): see the module docstring."""
    _two.require_two_patch(pb)
    un = Units.normalised(pb, K_edge=1.0)           # normalised: P = P*, delta = delta/Delta
    law = not pb.models("two-patch")                # a law landing on its traced branch (the cohesive one)
    bs = _family(pb, "confined_events() is").branches() if law else _tr.branches(pb)
    grip = [a for r in _br.solver(pb).regimes() for a, kind in _br.stationary_roots(pb, "grip", r)
            if kind == "min" and bool(_br.values_at(pb, r, a).feasible[0])]
    common = dict(onsets=_land.top_onsets(pb), grip_detachment=bool(grip),
                  two_patch_stable_load=any(b.stable_load.any() for b in bs),
                  two_patch_stable_grip=any(b.stable_grip.any() for b in bs),
                  full_contact=any("full" in b.ends for b in bs), branches=bs, gb=pb.gb, alpha_ratio=pb.alpha_ratio)
    nan = math.nan
    start, event, s, towards = _path.pull_path(pb, un, "load")
    if event in ("none", "elsewhere"):
        return ConfinedEvents(pb.M, pb.theta, "no-path", (nan, nan), nan, nan, **common)
    if event == "bonded":
        return ConfinedEvents(pb.M, pb.theta, "bonded", (math.inf, nan), nan, nan, **common)
    begin = (float(start.a), float(start.P_star))
    if event == "round":          # the cohesive round-zone tail closing into the bonded pin: no fold on the way
        return ConfinedEvents(pb.M, pb.theta, "zip-full", begin, s.P_star, nan, fold_in_tension=_full.state(
            pb, P_star=s.P_star).tension_everywhere, **common)
    if event in ("fold", "end"):
        zip_full = _po.grows_under_pull(pb, s.a, "load", towards)
        tension = _full.state(pb, P_star=s.P_star).tension_everywhere if zip_full else None
        return ConfinedEvents(pb.M, pb.theta, "zip-full" if zip_full else "detachment", begin, s.P_star, nan,
                              fold_in_tension=tension, **common)
    if law:                     # where the walker lands from the onset at that load (jkrcyl.analysis.landing)
        on = _land.top_onset(pb, un, s, "load")
        to, _ = _land.land(pb, un, on, "gap", "load", on.P, False)
        if to is None:
            raise ValueError(_land.two_patch_refusal(pb) or f"sigma0: no stable state where the top closes at "
                             f"P* = {on.P_star:.6g} on the law's branches")
        regime = ("two-patch" if to.branch == "two-patch" else "snap-in-full" if to.branch == "full-contact"
                  else "snap-in-transfer")
        return ConfinedEvents(pb.M, pb.theta, regime, begin, nan, on.P_star, **common)
    e_on, P_on, _, _ = min(common["onsets"], key=lambda o: abs(o[0] - s.eps))   # the onset the walk met
    outcome, _ = _two.descend(pb, P_on, e_on, control="load")
    return ConfinedEvents(pb.M, pb.theta, _DESCENT[outcome], begin, nan, P_on, **common)


def outcomes(pb: Problem, points):
    """Point.outcome of fixed-load adherence points: what a further pull does there -- the fold rule where
    feasible (the fixed-arc dp/dk: 'detachment' or 'zip-full'), the confined analysis where the gap closes
    first ('gap-closes-first' where it does not apply: M = 0, or a cohesive law)."""
    regime = None
    if any(not p.feasible for p in points):
        regime = ("gap-closes-first" if pb.M == 0 or not pb.models("two-patch")
                  else confined_events(pb).regime)           # (a law: its confined_events costs its branches)
    return [replace(p, outcome=(regime if not p.feasible else
                                "zip-full" if _po.grows_under_pull(pb, p.a, "load") else "detachment"))
            for p in points]
