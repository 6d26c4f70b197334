"""The lazy track (jkrcyl.analysis.tracks: stability and feasibility computed per grid index when a walk reads
them) against the eager one (jkrcyl.analysis.tracks.SingleTrack on the branch's whole table): from the same starts
towards the same targets, a walk passes the same points and ends at the same event and state, on every branch of
the cohesive law, under every control, on either side (the mirror), over random material pairs with rigid bodies
-- and a pull-off's walk computes the flags of fewer points than the table holds."""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

import jkrcyl
from cases import cohesive_contact
from jkrcyl.analysis import tracks as lt
from jkrcyl.analysis import forward as fw
from jkrcyl.analysis import path as _path
from jkrcyl.model.single_patch import solver

modulus = st.one_of(st.just(math.inf), st.floats(1e6, 1e12))
poisson = st.one_of(st.just(0.0), st.floats(0.01, 0.49))


def _same_walks(c, regime, side, control):
    """Walks from the table's ends and a third, down to -inf, up to +inf and to the start's neighbours' mean
    value, on an eager and a lazy track; returns the lazy track's computed flags and the table size."""
    pb, un = c.problem, c.units
    eager = lt.SingleTrack(pb, un, regime, side, control)
    lazy = lt.track(pb, un, regime, side, control)
    assert isinstance(lazy, lt.LazyTrack)
    np.testing.assert_array_equal(lazy.a, eager.a)
    # the held values come from the trace's contacts, the table's from each state: equal to rounding
    np.testing.assert_allclose(lazy.y, eager.y, rtol=1e-9, atol=1e-12 * np.abs(eager.y).max())
    n = eager.a.size
    for i in sorted({0, n // 3, n - 1}):
        mid = 0.5 * (eager.y[max(i - 1, 0)] + eager.y[min(i + 1, n - 1)])
        for target in (-math.inf, math.inf, mid):
            got, want = _path.walk(lazy, i, target), _path.walk(eager, i, target)
            assert got[0] == want[0] and got[1] == want[1], (regime, side, control, i, target, got[:2], want[:2])
            assert got[2].a == want[2].a and got[2].P == want[2].P, (got[2], want[2])
    return lazy.stable.computed + lazy.feasible.computed, n


@pytest.mark.slow
@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(E=modulus, nu=poisson, E_I=modulus, nu_I=poisson, h0=st.floats(0.05, 1.8), lam=st.floats(0.2, 30.0))
@example(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3, h0=0.3, lam=10.0)          # the benchmark's pair (identical)
@example(E=math.inf, nu=0.0, E_I=2e6, nu_I=0.49, h0=1.0, lam=3.0)         # a rigid cradle, a rubber pin
def test_lazy_walks_are_the_tables(E, nu, E_I, nu_I, h0, lam):
    c = cohesive_contact(E, nu, E_I, nu_I, h0, lam)
    sv = solver(c.problem)
    for regime in sv.regimes():
        for control, side in (("load", "bottom"), ("grip", "top"), ("grip-work", "bottom")):
            _same_walks(c, regime, side, control)


def test_a_pull_off_walk_computes_few_flags():
    """The walk of a load-control pull-off from the zero-load contact reads the flags of the points it passes
    only: the README pin at lambda = 10 (identical bodies, R 10 mm, Delta 1 um, w 0.05 J/m^2)."""
    pair = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    c = jkrcyl.Contact.with_lambda(10e-3, 1e-6, 0.05, pair, 10.0)
    pb, un = c.problem, c.units
    start = min([s for s in c.solve(P=0.0, branches=["sub-critical"]) if s.stable_load and s.feasible],
                key=lambda s: s.eps)
    tr = lt.track(pb, un, "sub-critical", "bottom", "load")
    _, event, end = _path.walk(tr, tr.index(start.a), -math.inf)
    eager = lt.SingleTrack(pb, un, "sub-critical", "bottom", "load")
    _, event_eager, end_eager = _path.walk(eager, eager.index(start.a), -math.inf)
    assert (event, end.a, end.P) == (event_eager, end_eager.a, end_eager.P) and event == "fold"
    assert max(tr.stable.computed, tr.feasible.computed) < tr.a.size / 2, (tr.stable.computed, tr.a.size)


# (lambda, h0/Delta) over the map's range and the ranges that nearly reach round; the pairs: identical bodies, a
# rubber pin in a rigid cradle, two rigid bodies (the pin then elastic, E_I 1 GPa: tests/cases.py)
GRID = [(lam, h0) for lam in (0.3, 3.0, 30.0) for h0 in (0.1, 1.0, 1.6)]
PAIRS = [(2.6e9, 0.3, 2.6e9, 0.3), (math.inf, 0.0, 2e6, 0.49), (math.inf, 0.0, math.inf, 0.3)]


@pytest.mark.slow
@pytest.mark.parametrize("pair", PAIRS)
def test_pull_off_on_lazy_tracks_is_the_tables(pair, monkeypatch):
    """Contact.pull_off (load and grip) with the walker's tracks built lazily (path.pull_path's
    tracks.track) against the eager tables': the same P, width and approach (1e-12
    relative: the held values come from the trace's contacts, to rounding) and the same reason, over GRID."""
    for lam, h0 in GRID:
        got = {}
        for lazy in (False, True):
            c = cohesive_contact(*pair, h0, lam)          # a fresh problem: the solver's caches start empty
            with monkeypatch.context() as mp:
                if not lazy:                              # the walker's tracks are lazy: force the tables
                    mp.setattr(lt, "track", lt.SingleTrack)
                got[lazy] = [c.pull_off(ctl) for ctl in ("load", "grip")]
        for eager, lazy in zip(got[False], got[True]):
            assert eager.reason == lazy.reason, (pair, lam, h0, eager.reason, lazy.reason)
            for name in ("P", "contact_width", "delta"):
                x, y = getattr(eager, name), getattr(lazy, name)
                assert (x is None) == (y is None) and (x is None or abs(x - y) <= 1e-12 * abs(x)), (name, x, y)


def test_a_junction_at_a_minimum_of_the_approach_is_a_fold():
    """A rigid cradle round a rubber pin (lambda 3, h0 0.1 Delta) under grip: the contact branch's touch end and the
    zone-only pin's touch are the same state, with delta growing away from it on the contact branch and dipping
    below it between the zone-only table's last two points.  The walk went back and forth between the two ends
    (pull_off never returned); now it ends at that dip: a fold, delta there below the touch's and below the
    zone-only pin's states solved alone on either side of it (forward.single_patch_states, no table)."""
    c = cohesive_contact(math.inf, 0.0, 2e6, 0.49, 0.1, 3.0)
    pb, un = c.problem, c.units
    r = c.pull_off("grip")
    assert r.reason.startswith("detachment: the zone-only pin lets go"), r.reason
    fold = r.state
    assert fold.branch == "contactless" and 0.99 < fold.a < 1.0, fold
    alone = lambda a: fw.single_patch_states(pb, un, "contactless", a, "grip", "bottom")[0].delta
    for a in (fold.a * (1 - 1e-5), min(fold.a * (1 + 1e-5), 1.0), 1.0):
        assert fold.delta < alone(a), (a, fold.delta, alone(a))
