"""The regime atlas under the Maugis-Dugdale law (jkrcyl.atlas.cohesive): its confined classes against JKR's atlas
(jkrcyl.atlas.classify, the numba route of the paper's closed forms: no law code) in the limit lambda -> inf, its
event P* against the stand-alone pull-off by continuation (jkrcyl.numerics.cohesive_pull_off, no walker), and the
CLI ``jkrcyl atlas --lambda``.

Measured (lambda = 50 / 100, bisection in M to 1.2e-6 with jkrcyl.atlas.cohesive.classify_pair; JKR's boundaries
from the closed forms: m_sub(vartheta), where the sub-critical P* minimum reaches a_crit, and M_max(vartheta) of
(8.1)):

* zip -> bonded (the zero-load contact vanishes): vartheta 1: JKR 0.64463182, law 0.64463121 at both lambda;
  vartheta 2: JKR 0.48578718, law 0.48578657 -- equal within the bisection's resolution (|shift| < 1.2e-6, so
  C/lambda^2 with C < 3e-3 at lambda 50);
* transfer -> zip (the zero-load contact crosses a_crit): the law's walker finds no first contact ('none') in a
  window of M next to JKR's boundary, vartheta 1: from 0.39149 (lambda 50) / 0.39126 (lambda 100) to past JKR's
  0.39196 (the window does not shrink with lambda: a defect of the law's first contact near the critical contact,
  :func:`test_no_first_contact_window_near_a_crit`); vartheta 2 from 0.26741 (JKR 0.26779);
* the top-closing boundary (h(pi) = h0 under the law, 0 for JKR): absent from the plane under load control -- at
  JKR's first event h(pi)/Delta >= 1.7 on M in [0, 2], vartheta in [0.5, 10] (the fold lifts the pin off the top),
  far above h0/Delta = 4 m^(4/3)/lambda <= 0.31 at lambda 50 there; no pair reaches CONF_TOP;
* the event's P*: within 3e-8 of JKR's on the pairs below at lambda 50 (C/lambda^2 with C = 7.5e-5); on the
  default 24 x 25 grid (benchmarks/bench_atlas.py) all 600 classes equal JKR's and P* within 9.6e-6 (1.1e-6 relative).
"""
import math
import pathlib
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings, strategies as st

from jkrcyl import atlas as A
from jkrcyl.atlas import cohesive as C
from jkrcyl import equilibria as eq
from jkrcyl.critical import a_crit
from jkrcyl.numerics import cohesive_pull_off as standalone
from jkrcyl.numerics import kernels

ROOT = pathlib.Path(__file__).resolve().parents[1]


def m_sub(th):
    """JKR: M where the sub-critical P* minimum runs into a_crit (numerator of P* zero at a_crit; tests/test_atlas)."""
    ac = a_crit(th)
    return 1 / (math.sqrt(ac) * (1 + 2 * ac * ac))


def _away(M, th, margin=0.02):
    """Whether (M, vartheta) lies at least margin in M from JKR's class boundaries (closed forms above)."""
    if math.isinf(th):
        return M >= margin
    return min(abs(M - m_sub(th)), abs(M - eq.zero_load_max_M(th)[0]), M) >= margin


# one pair per class JKR shows on the default plane, away from its boundaries: transfer, zip, bonded, rigid cradle
PAIRS = [(0.2, 1.0), (0.5, 1.0), (0.9, 3.0), (0.5, math.inf)]


def _law_vs_jkr(lam, pairs):
    for M, th in pairs:
        assert _away(M, th)
        jkr = A.classify(np.array([M]), np.array([th]), parallel=False)
        code, a, P, s0, h0, why = C.classify_pair(M, th, lam)
        assert why == ""
        assert code == jkr["confined"][0, 0], (M, th, lam)
        assert abs(P - jkr["event_P"][0, 0]) <= 2.5e-3 / lam ** 2, (M, th, P, jkr["event_P"][0, 0])
        if P:            # the contact of the event: the law's zone moves it by O(h0) (eps differs, P* does not)
            assert abs(a - jkr["event_a"][0, 0]) <= 2 * h0, (M, th, a, jkr["event_a"][0, 0], h0)


@pytest.mark.slow           # 89 s on a 2-core AMD EPYC (the longest of make test there)
def test_classes_equal_jkr_at_lambda_50():
    """Reference: JKR's atlas (closed forms, numba); pairs >= 0.02 in M from JKR's boundaries (measured shifts
    there < 1.2e-6, module docstring, except the first-contact window near a_crit, which these pairs avoid)."""
    _law_vs_jkr(50.0, PAIRS)


@pytest.mark.slow
def test_classes_equal_jkr_at_lambda_100_on_a_grid():
    """As at lambda 50, on a 6 x 4 grid (+ inf) less the pairs within 0.02 of JKR's boundaries."""
    Ms, th = A.default_grid(6, 4, M_max=1.5, theta_max=4.0)
    _law_vs_jkr(100.0, [(M, t) for t in th for M in Ms if M > 0 and _away(M, t)])


def test_no_top_closing_boundary_on_the_plane():
    """At JKR's first event h(pi)/Delta (closed form) stays far above the law's range h0/Delta = 4 m^(4/3)/lambda
    (zone_range of zone_strength) at lambda 50: the law's earlier top adhesion cannot change a class here."""
    Ms, th = A.default_grid(41, 20, theta_max=10.0, with_inf=False)
    res = A.classify(Ms, th, parallel=False)
    assert not (res["confined"] == A.CONF_TOP).any()
    worst = math.inf
    for i, t in enumerate(th):
        for j, M in enumerate(Ms):
            if res["confined"][i, j] in (A.CONF_TRANSFER, A.CONF_ZIP):
                h = kernels.h_pi_nb(res["event_a"][i, j], 1 / t, M * t)
                h0 = 4 * (M * t) ** (4 / 3) / 50.0
                worst = min(worst, h - h0)
    assert worst > 1.0


@settings(max_examples=3, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(M=st.floats(0.05, 0.3), th=st.sampled_from([0.5, 0.8, 1.0, 2.0, 4.0, math.inf]), lam=st.floats(20.0, 100.0))
def test_event_P_equals_the_standalone_pull_off(M, th, lam):
    """The atlas cell's P* (the walker on the law's branch tables) equals the stand-alone load-control pull-off by
    continuation (jkrcyl.numerics.cohesive_pull_off, the route of the (lambda, M) map) for transfer pairs:
    measured 7e-11 at most on four pairs; asserted 1e-8."""
    assume(_away(M, th) and (math.isinf(th) or M < m_sub(th)))
    pb = C.law_problem(M, th, lam)
    code, _, P, _, _, _ = C.classify_pair(M, th, lam)
    ref = standalone.pull_off_load(pb.m, pb.edge.s0, th, pb.gb, 0.0)
    assert code == C.CONF_TRANSFER and ref.kind == "fold"
    assert abs(P - ref.p / pb.scale) <= 1e-8


def test_grid_fields_and_no_adhesion_column():
    """classify_law: M = 0 is JKR's 'no load path' without building a law (none exists at w = 0); shapes; the
    jkr_* fields are classify's."""
    r = C.classify_law([0.0, 0.2], [math.inf], 50.0, workers=1)
    assert r["confined"].tolist() == [[C.CONF_NONE, C.CONF_TRANSFER]]
    assert r["jkr_confined"].tolist() == [[A.CONF_NONE, A.CONF_TRANSFER]]
    assert r["s0"][0, 0] == 0 and r["s0"][0, 1] == pytest.approx(50.0 * 0.2 ** (2 / 3) / 4, rel=1e-12)
    assert r["reasons"] == []


@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan, math.inf, "x"])
def test_bad_lambda(bad):
    with pytest.raises(ValueError, match="lambda"):
        C.classify_law([0.2], [1.0], bad, workers=1)


@pytest.mark.slow
def test_first_contact_next_to_a_crit():
    """JKR (closed forms): at M 0.392, vartheta 1 the zero-load contact a0 = 0.91365 is next to a_crit = 0.91357
    and the pin zips (CONF_ZIP).  The law at lambda 50 has its zero-load contact on the part of its branch that
    crosses eps_crit with a finite load and folds ~3.6e-4 below it (jkrcyl.numerics.cohesive_crossing; its
    first contact was 'none' on M in ~[0.3915, 0.3927] while the table stopped 1e-3 short of eps_crit): the
    same class as JKR's."""
    assert C.classify_pair(0.392, 1.0, 50.0)[0] == A.classify(np.array([0.392]), np.array([1.0]))["confined"][0, 0]


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "jkrcyl", "atlas", *args], capture_output=True, text=True,
                          cwd=ROOT, timeout=600)


def test_cli_law_atlas(tmp_path):
    """End to end on 2 x 2 pairs (M 0 and 0.1, vartheta 0.5 and 5): files written, classes as JKR's."""
    r = _cli("--lambda", "50", "--n-M", "2", "--n-theta", "2", "--M-max", "0.1", "--no-inf", "--workers", "1",
             "--quiet", "--out", str(tmp_path))
    assert r.returncode == 0, r.stderr
    assert "Maugis-Dugdale law at lambda = 50" in r.stdout
    for f in ("atlas.npz", "atlas.csv", "atlas.png", "atlas.pdf"):
        assert (tmp_path / f).stat().st_size > 0
    saved = np.load(tmp_path / "atlas.npz")
    assert saved["confined"].tolist() == saved["jkr_confined"].tolist() == [[0, 1], [0, 1]]
    rows = (tmp_path / "atlas.csv").read_text().splitlines()
    assert rows[0].startswith("# Maugis-Dugdale law at lambda = 50") and len(rows) == 2 + 4


@pytest.mark.parametrize("value", ["0", "-3", "nan", "abc"])
def test_cli_bad_lambda_one_line(tmp_path, value):
    r = _cli("--lambda", value, "--out", str(tmp_path))
    assert r.returncode == 2 and "lambda" in r.stderr and len(r.stderr.strip().splitlines()) == 1
