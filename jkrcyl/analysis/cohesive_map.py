"""The load-control pull-off of the Maugis-Dugdale pin over (lambda, M): where it vanishes.

Every point is independent: the stand-alone pull-off by continuation of jkrcyl.numerics.cohesive_pull_off (the
second route to Contact.pull_off('load'), tested equal to the walker's to 1e-8, and over random pairs near the
range reaching round incl. S-shaped branches to 1e-6: tests/test_cohesive_map_property.py; no branch table per
point -- the walker's cold pull-off traces and tabulates the whole branch, ~20 times the cost,
benchmarks/bench_cohesive_round.py; with longer continuation steps, MAP_STEPS), so
the map is computed by Dask (optional dependency: ``pip install jkrcyl[map]``), one task per lambda row, on a
local process pool of ``workers`` (a distributed scheduler takes the same graph off one machine).

Outcome codes (:data:`OUTCOMES`): the pull-off at a fold of the contact branch (JKR-like), at its touch end (the
contact vanishes: small lambda), none because the range reaches round (h0 > 2 Delta less the uniform pull: no
adherence force), none because the branch has no zero-load contact (the zone's pull exceeds the clearance's
push at every contact size: the pin is drawn into contact on its own), none from first contact because the pin
floats in a range reaching round and touches onto round-zone contacts that push, whose zone jumps only when pushed
further (an S-shaped branch, narrow or not: Contact.pull_off says the same).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..model.problem import Problem
from ..numerics import cohesive_pull_off as _cpo
from ..numerics import cohesive_scales as _scales
from ..units import Units
from . import pull_off as _po

OUTCOMES = ("fold", "touch", "no adherence force", "no zero-load contact",
            "no adherence force from first contact (a round zone that jumps when pushed)")
MAP_STEPS = (0.3, 1.2)      # continuation steps of a map point (longer than the default: the same pull-off to 1e-10;
#                             a 'touch' is confirmed with the default steps, _point)


@dataclass(frozen=True)
class PullOffMap:
    """P_star[i, j] (P* of the load-control pull-off, NaN without one) at lam[i], M[j]; outcome[i, j] an index
    of :data:`OUTCOMES`; P_star_jkr[j] the JKR pull-off (sigma0 = None) of M[j]; theta, gb, alpha_ratio."""

    lam: np.ndarray
    M: np.ndarray
    P_star: np.ndarray
    outcome: np.ndarray
    P_star_jkr: np.ndarray
    theta: float
    gb: float
    alpha_ratio: float = 0.0


def _point(lam, M, theta, gb, ar):
    pb = Problem(M, theta, gb, ar)
    s0 = _scales.zone_strength(lam, pb.m)
    r = _cpo.pull_off_load(pb.m, s0, theta, gb, ar, steps=MAP_STEPS, xtol=1e-6, zero_load=False)
    if r.kind == "touch":        # a shallow fold the long steps jump over (a dip of 1e-4 in P*: an elastic pin in a
        r = _cpo.pull_off_load(pb.m, s0, theta, gb, ar, xtol=1e-6, zero_load=False)    # rigid hole): default steps
    if r.p is not None:
        return r.p / pb.scale, OUTCOMES.index(r.kind)
    kind = 4 if "from first contact" in r.reason else 2 if "no adherence" in r.reason else 3
    return math.nan, kind


def _row(lam, Ms, theta, gb, ar):
    out = [_point(lam, float(M), theta, gb, ar) for M in Ms]
    return np.array([o[0] for o in out]), np.array([o[1] for o in out], dtype=int)


def jkr_pull_off(M, theta, gb, ar=0.0):
    """P* of JKR's load-control pull-off (the model core's walker), NaN where it does not detach."""
    pb = Problem(M, theta, gb, ar)
    r = _po.pull_off(pb, Units.normalised(pb), "load")
    return math.nan if r.P is None else r.P


def pull_off_map(lam, M, theta=1.0, gb=1 / 2.8, alpha_ratio=0.0, workers=2) -> PullOffMap:
    """The map over the 1-D grids lam (> 0) and M (> 0), Dask on ``workers`` local processes (1: in this one)."""
    lam = np.asarray(lam, dtype=float)
    M = np.asarray(M, dtype=float)
    Problem(float(M[0]), theta, gb, alpha_ratio)                # validates theta, gb, alpha_ratio once
    try:
        import dask
    except ImportError as exc:                                    # pragma: no cover - depends on the install
        raise ValueError("workers: the pull-off map needs dask (pip install 'jkrcyl[map]')") from exc
    rows = [dask.delayed(_row)(float(x), M, theta, gb, alpha_ratio) for x in lam]
    if workers > 1:
        done = dask.compute(*rows, scheduler="processes", num_workers=int(workers))
    else:
        done = dask.compute(*rows, scheduler="synchronous")
    jkr = np.array([jkr_pull_off(float(x), theta, gb, alpha_ratio) for x in M])
    return PullOffMap(lam, M, np.vstack([d[0] for d in done]), np.vstack([d[1] for d in done]), jkr, theta, gb,
                      alpha_ratio)
