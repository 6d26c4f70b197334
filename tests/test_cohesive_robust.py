"""No input ends the process, and every refusal names the user's parameter (the cohesive law's numerics).

The reproducers that once crashed the interpreter (a segmentation fault inside a numba kernel) or ran for
minutes run in a child process, so that a crash fails its test instead of ending pytest; their answers are
checked against the JKR contact (lambda -> inf: the cohesive pull-off tends to JKR's as lambda^-4).  The
kernels' index arithmetic is exercised with NUMBA_BOUNDSCHECK=1 (a fresh numba cache: every kernel recompiled
with bounds checks, an out-of-bounds index raises IndexError instead of reading memory).
"""
import json
import math
import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import jkrcyl
from jkrcyl.numerics import arcs
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_branch as cb
from jkrcyl.numerics import cohesive_follow as fo
from jkrcyl.model.single_patch import solver

RIGID_PIN_IN_SOFT_HOLE = dict(E=1e6, nu=0.3, E_I=math.inf, nu_I=0.3)
IDENTICAL = dict(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
TIMEOUT = 900          # a hang guard only (never a speed check: benchmarks/bench_cohesive_core.py measures)

_CHILD = textwrap.dedent("""
    import json, math, sys
    import jkrcyl
    out = []
    for pair, R, Delta, w, sigma0 in json.loads(sys.argv[1]):
        mat = jkrcyl.Materials.from_young(**{k: (math.inf if v == "inf" else v) for k, v in pair.items()})
        c = jkrcyl.Contact(R=R, Delta=Delta, w=w, materials=mat, sigma0=sigma0)
        j = jkrcyl.Contact(R=R, Delta=Delta, w=w, materials=mat)
        try:
            po = c.pull_off()
            out.append(dict(lam=c.lambda_, P=po.P, reason=po.reason, jkr=j.pull_off().P))
        except ValueError as err:
            out.append(dict(lam=c.lambda_, error=str(err)))
    print(json.dumps(out))
""")


def _run_child(cases, env=None):
    pairs = [({k: ("inf" if v == math.inf else v) for k, v in pair.items()}, R, D, w, s) for pair, R, D, w, s in cases]
    run = subprocess.run([sys.executable, "-c", _CHILD, json.dumps(pairs)], capture_output=True, text=True,
                         timeout=TIMEOUT, env=env)
    assert run.returncode == 0, f"the child ended with {run.returncode}: {run.stderr[-2000:]}"
    return json.loads(run.stdout.strip().splitlines()[-1])


@pytest.fixture(scope="module")
def reproducers():
    """Issue 24, item 8: lambda ~ 2.6e4 and beyond (a segmentation fault), lambda ~ 150-370 (minutes)."""
    cases = [(RIGID_PIN_IN_SOFT_HOLE, 1e-2, 1e-6, 0.03, 1e7), (RIGID_PIN_IN_SOFT_HOLE, 1e-2, 2e-6, 0.03, 2e7),
             (RIGID_PIN_IN_SOFT_HOLE, 1e-2, 3e-6, 0.03, 3e7),
             (IDENTICAL, 1e-2, 1e-6, 0.05, 1e7), (IDENTICAL, 1e-2, 2e-6, 0.05, 2e7),
             (IDENTICAL, 1e-2, 1e-6, 0.05, 2e7), (IDENTICAL, 1e-2, 2e-6, 0.05, 1e7)]
    return _run_child(cases)


def test_beyond_the_supported_lambda_a_value_error_names_sigma0(reproducers):
    """The rigid pin in a 1 MPa hole at lambda 1.6e4 - 2.6e4 (the segmentation faults): a ValueError naming
    sigma0 and lambda with the supported range, not a crash."""
    for got in reproducers[:3]:
        assert got["lam"] > co.LAMBDA_MAX and "error" in got, got
        assert got["error"].startswith("sigma0") and "lambda" in got["error"] and "at most 10000" in got["error"]


def test_thin_zones_that_ran_for_minutes_give_jkrs_pull_off(reproducers):
    """Identical bodies at lambda 147 - 370 (minutes before, a pull-off now): equal to JKR's to 1e-8
    (measured 1e-11 to 4e-10: the lambda^-4 approach)."""
    for got in reproducers[3:]:
        assert 140 < got["lam"] < 380 and got.get("P") is not None, got
        assert got["P"] == pytest.approx(got["jkr"], rel=1e-8), got


@pytest.mark.parametrize("make, words", [
    (lambda m: jkrcyl.Contact.with_lambda(1e-2, 1e-5, 0.03, m, 1e6), ("sigma0", "lambda", "10000")),
    (lambda m: jkrcyl.Contact(1e-2, 1e-5, 0.03, m, sigma0=1e12), ("sigma0", "lambda", "10000")),
    (lambda m: jkrcyl.Contact(1e-2, 1e-5, 0.03, m, sigma0=1e-99), ("sigma0", "Pa")),
])
def test_messages_name_sigma0_and_its_range(make, words):
    """Issue 24, item 7: lambda 1e6, sigma0 1e12 ('n must be in [8, 1024], got 1032.0' before) and sigma0 1e-99
    ('s0' before): the message starts with sigma0 and gives the allowed range."""
    mat = jkrcyl.Materials.from_young(**RIGID_PIN_IN_SOFT_HOLE)
    with pytest.raises(ValueError) as err:
        make(mat).pull_off()
    msg = str(err.value)
    assert msg.startswith("sigma0") and all(w in msg for w in words), msg
    assert " s0 " not in msg.split("(")[0]


@pytest.mark.parametrize("eps, n, name", [(math.nan, 32, "eps"), (0.0, 32, "eps"), (math.pi, 32, "eps"),
                                          (-0.1, 32, "eps"), (0.5, 4, "n"), (0.5, 2000, "n"), (0.5, 32.5, "n")])
def test_fixed_contact_refuses_what_its_kernels_cannot_index(eps, n, name):
    """The segfault's root: a NaN contact angle made arcs.Arcs drop the arc (an empty collocation system) whose
    LU the unit solutions then read with the nodes' count.  FixedContact checks eps, n and the system before
    any kernel runs."""
    with pytest.raises(ValueError, match=rf"^{name}\b"):
        co.FixedContact(eps, arcs.Kernel(1.0, 0.5), n)


def test_fixed_contact_checks_what_callers_pass():
    """Zones not (k, 2), an unknown vector of the wrong length, a NaN point: a ValueError, not an index."""
    fc = co.FixedContact(0.5, arcs.Kernel(1.0, 0.5), 32, layered=True)
    dn, u = fc.solve(co.zones_of(0.51), 1.0)
    with pytest.raises(ValueError, match="^zones"):
        fc.solve(np.zeros(4), 1.0)
    with pytest.raises(ValueError, match="^u"):
        fc.gap(1.0, dn, u[:-1], co.zones_of(0.51), 1.0)
    with pytest.raises(ValueError, match="^u"):
        fc.load_width(np.zeros(5), co.zones_of(0.51), 1.0)
    with pytest.raises(ValueError, match="^zones"):
        co.zone_displacement(0.3, np.zeros((2, 1)), arcs.Kernel(1.0, 0.5))
    with pytest.raises(ValueError, match="^phi"):
        fc.gap(np.array([0.6, math.nan]), dn, u, co.zones_of(0.51), 1.0)
    assert np.isfinite(fc.gap(np.array([0.6, 3.0]), dn, u, co.zones_of(0.51), 1.0)).all()


def test_a_trace_that_stops_early_says_so(monkeypatch):
    """A branch trace cut short (here: 3 steps) returns its reason; the model core passes it to pull_off and
    cycle instead of a number from a truncated branch."""
    law = cb.Law(0.3, 1.0, 1.0, 0.5, 0.0)
    start = law.state(law.eps_lo)
    x0 = np.array([math.log(law.eps_lo), math.log(start.c - law.eps_lo)])
    pts, why = fo.follow(law, x0, lambda x: True, max_steps=3)
    assert len(pts) == 4 and "could not be followed beyond eps" in why and "3 steps" in why
    real = cb.trace
    monkeypatch.setattr(cb, "trace", lambda lw: (lambda x, kind, _: (x[:5], kind, "stopped: test"))(*real(lw)))
    c = jkrcyl.Contact.with_lambda(1e-2, 1e-6, 0.05 * (1 + 7e-9), jkrcyl.Materials.from_young(**IDENTICAL), 3.0)
    po = c.pull_off()
    assert po.P is None and po.reason == "stopped: test"
    assert solver(c.problem).unmodelled == "stopped: test"


_BOUNDS_CHILD = textwrap.dedent("""
    import math
    import numpy as np
    import jkrcyl
    from jkrcyl.numerics import cohesive as co, cohesive_pull_off as cpo, cohesive_scales as cs
    for theta, gb, ar in ((1.0, 0.5, 0.0), (3.0, 0.3, -0.2)):
        for lam in (3.0, 30.0, 1000.0):
            s0 = cs.zone_strength(lam, 0.4)
            for eps in (1e-3, 0.8, 3.0):
                st = co.cohesive_state(eps, 0.4, s0, theta, gb, ar)
                co.gap_check(st, 60)
                st.fields.pressure(np.linspace(-math.pi, math.pi, 31))
        print(cpo.pull_off_load(0.4, cs.zone_strength(300.0, 0.4), theta, gb, ar).p)
    mat = jkrcyl.Materials.from_young(E=210e9, nu=0.3, E_I=2e6, nu_I=0.49)
    print(jkrcyl.Contact(R=5e-3, Delta=20e-6, w=0.05, materials=mat, sigma0=0.5e6).pull_off().P)
""")


@pytest.mark.slow
def test_kernels_within_bounds(tmp_path):
    """Every cohesive kernel on the paths above -- plain and layered contacts, alpha* = 0 and != 0, tiny and
    near-receding contacts, gaps, fields, a stand-alone pull-off and the roller through the API -- compiled
    with NUMBA_BOUNDSCHECK=1 in a child (its own numba cache) ends normally: no index out of bounds."""
    env = dict(os.environ, NUMBA_BOUNDSCHECK="1", NUMBA_CACHE_DIR=str(tmp_path))
    run = subprocess.run([sys.executable, "-c", _BOUNDS_CHILD], capture_output=True, text=True, timeout=TIMEOUT,
                         env=env)
    assert run.returncode == 0, run.stderr[-3000:]
    assert "IndexError" not in run.stderr and len(run.stdout.split()) == 3
