"""Issue 11 item 5: a catalogue of bad and extreme inputs.  Each gives a correct number or a ValueError naming
the parameter (API), or one line on stderr and exit status 2 without a traceback (CLI).

References for the 'correct number' cases: vartheta of a rigid indenter is exactly 1/2 (section 4); the
half-plane limit (7.3b) a = (vartheta M/2)^(2/3) of the fixed-load adherence point for small M; a_crit^4 ->
vartheta for large vartheta (2 vartheta - log(1 + a^2) - 2 a^4 = 0, section 4).
"""
import math
import os
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest
from cli_run import run

import jkrcyl
from jkrcyl import equilibria as eq

ROOT = pathlib.Path(__file__).resolve().parents[1]
MAT = jkrcyl.Materials(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0)
C = jkrcyl.Contact(R=1.0, Delta=0.01, w=1e-4, materials=MAT)
PHYS = ["--E", "2.6e9", "--nu", "0.3", "--E-I", "2.6e9", "--nu-I", "0.3", "--R", "0.01", "--Delta", "1e-5",
        "--w", "0.05"]


# --- correct numbers where the audit found wrong ones -------------------------------------------------------
def test_rigid_pin_in_incompressible_plate_has_theta_one_half():
    m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.5, E_I=math.inf, nu_I=0.5)
    assert m.theta == 0.5
    c = jkrcyl.Contact(R=0.01, Delta=1e-5, w=0.05, materials=m)
    assert math.isfinite(c.M) and jkrcyl.a_crit(c.theta) == jkrcyl.a_crit(0.5)
    assert c.adherence("load")                         # runs through (no "theta must be in [0.5, inf]")


@pytest.mark.parametrize("M", [1e-6, 1e-9, 1e-12])
def test_adherence_found_for_tiny_M(M):
    (p,) = eq.adherence(M, 1.0, "load", regimes=("sub-critical",), gb=eq.incompressible_gb(1.0))
    a_h = (M / 2) ** (2 / 3)                           # half-plane limit (7.3b), vartheta = 1
    assert p.a == pytest.approx(a_h, rel=1e-3) and p.kind == "min"
    assert p.P_star == pytest.approx(-1.5 * (M ** 4 / 2) ** (1 / 3), rel=1e-3)


def test_a_crit_large_theta():
    for th in (1e20, 1e60, 1e100):
        assert jkrcyl.a_crit(th) == pytest.approx(th ** 0.25, rel=1e-12)


@pytest.mark.parametrize("a", [1e-100, 1e-50, 1e4, 1e10, 1e20])
def test_state_finite_at_the_ends_of_the_domain(a):
    s = C.state(a)
    for name in ("P", "B", "C", "K", "delta", "h_pi"):
        assert np.isfinite(getattr(s, name)), name
    assert float(s.G_release) == pytest.approx(C.w, rel=1e-6)      # Griffith (3.6) holds at both ends
    assert np.isfinite(C.gap(a, 3.0))
    if a <= 1e4:                                                   # the pressure's domain (see _validate)
        assert np.all(np.isfinite(C.pressure(a, np.array([0.0, 0.5, 3.0]))))
    else:
        with pytest.raises(ValueError, match="a must be"):
            C.pressure(a, 0.0)


# --- API: ValueError naming the parameter -------------------------------------------------------------------
def materials(**kw):
    args = dict(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0)
    args.update(kw)
    return jkrcyl.Materials(**args)


API_CASES = [
    ("state a = 1e76", lambda: C.state(1e76), "a"),
    ("state a = 1e-155", lambda: C.state(1e-155), "a"),
    ("state a = 1e-200", lambda: C.state(1e-200), "a"),
    ("gap a = 1e-200", lambda: C.gap(1e-200, 1.0), "a"),
    ("pressure a = 1e-200", lambda: C.pressure(1e-200, 0.0), "a"),
    ("state None", lambda: C.state(None), "a"),
    ("state string", lambda: C.state("0.3"), "a"),
    ("state complex", lambda: C.state(0.3 + 1j), "a"),
    ("state empty", lambda: C.state([]), "a"),
    ("pressure phi nan", lambda: C.pressure(0.3, math.nan), "phi"),
    ("a_crit 1e110", lambda: jkrcyl.a_crit(1e110), "theta"),
    ("a_crit 1e160", lambda: jkrcyl.a_crit(1e160), "theta"),
    ("a_crit 0.49", lambda: jkrcyl.a_crit(0.49), "theta"),
    ("adherence M = 1e-200", lambda: eq.adherence(1e-200, 1.0, gb=eq.incompressible_gb(1.0)), "M"),
    ("adherence M = 1e-300", lambda: eq.adherence(1e-300, 1.0, gb=eq.incompressible_gb(1.0)), "M"),
    ("curve M = 1e-300", lambda: eq.curve(1e-300, 1.0, n=10, gb=eq.incompressible_gb(1.0)), "M"),
    ("zero load M = 1e-200", lambda: jkrcyl.zero_load_contact(1e-200, 1.0), "M"),
    ("curve M = -1", lambda: eq.curve(-1.0, 1.0, gb=eq.incompressible_gb(1.0)), "M"),
    ("curve gb = 2", lambda: eq.curve(0.3, 1.0, gb=2.0), "gb"),
    ("curve a bad", lambda: eq.curve(0.3, 1.0, a=[-1, 0, math.nan], gb=eq.incompressible_gb(1.0)), "a"),
    ("curve a off the regime", lambda: eq.curve(0.3, 1.0, regime="super-critical", a=[0.1], gb=eq.incompressible_gb(1.0)), "a"),
    ("curve n = 1e7", lambda: eq.curve(0.3, 1.0, n=1e7, gb=eq.incompressible_gb(1.0)), "n"),
    ("Delta = R", lambda: jkrcyl.Contact(R=1.0, Delta=1.0, w=1e-4, materials=MAT), "Delta"),
    ("Delta > R", lambda: jkrcyl.Contact(R=1.0, Delta=2.0, w=1e-4, materials=MAT), "Delta"),
    ("G = 1e-320", lambda: materials(G=1e-320), "G"),
    ("G_I = 1e-320", lambda: materials(G_I=1e-320), "G_I"),
    ("E = 1e-320", lambda: jkrcyl.Materials.from_young(1e-320, 0.3, 1.0, 0.3), "E"),
    ("G complex", lambda: materials(G=1 + 1j), "G"),
    ("G string", lambda: materials(G="1"), "G"),
    ("G True", lambda: materials(G=True), "G"),
    ("kappa None", lambda: materials(kappa=None), "kappa"),
    ("R True", lambda: jkrcyl.Contact(R=True, Delta=0.01, w=1e-4, materials=MAT), "R"),
    ("w string", lambda: jkrcyl.Contact(R=1.0, Delta=0.01, w="0.1", materials=MAT), "w"),
    ("w = 1e300", lambda: jkrcyl.Contact(R=1.0, Delta=0.01, w=1e300, materials=MAT), "w"),
    ("solve neither", lambda: C.solve(), "P"),
    ("solve both", lambda: C.solve(P=1.0, delta=1e-3), "P"),
    ("solve P inf", lambda: C.solve(P=math.inf), "P"),
    ("solve neat fit", lambda: jkrcyl.Contact(R=1.0, Delta=0.0, w=1e-4, materials=MAT).solve(P=1.0), "Delta"),
    ("pull_off control", lambda: C.pull_off("force"), "control"),
    ("cycle P_min >= P_max", lambda: C.cycle(P_max=0.0, P_min=1.0), "P_min"),
    ("cycle n", lambda: C.cycle(P_max=1.0, P_min=-1.0, n=3), "n"),
    ("method", lambda: C.state(0.3, method="exact"), "method"),
    # more of the same families (issue 11 item 5: "at least the cases above plus your own")
    ("nu = 0.6", lambda: jkrcyl.Materials.from_young(1e9, 0.6, 1e9, 0.3), "nu"),
    ("nu_I = -1", lambda: jkrcyl.Materials.from_young(1e9, 0.3, 1e9, -1.0), "nu_I"),
    ("nu string", lambda: jkrcyl.Materials.from_young(1e9, "0.3", 1e9, 0.3), "nu"),
    ("E_I True", lambda: jkrcyl.Materials.from_young(1e9, 0.3, True, 0.3), "E_I"),
    ("E and E_I rigid", lambda: jkrcyl.Materials.from_young(math.inf, 0.3, math.inf, 0.3), "G"),
    ("kappa < 1", lambda: materials(kappa=0.5), "kappa"),
    ("G_I complex", lambda: materials(G_I=2j), "G_I"),
    ("R nan", lambda: jkrcyl.Contact(R=math.nan, Delta=0.0, w=1e-4, materials=MAT), "R"),
    ("Delta inf", lambda: jkrcyl.Contact(R=1.0, Delta=math.inf, w=1e-4, materials=MAT), "Delta"),
    ("w negative", lambda: jkrcyl.Contact(R=1.0, Delta=0.01, w=-1e-4, materials=MAT), "w"),
    ("materials None", lambda: jkrcyl.Contact(R=1.0, Delta=0.01, w=1e-4, materials=None), "materials"),
    ("state bool", lambda: C.state(True), "a"),
    ("state nested", lambda: C.state([[0.1], [0.2, 0.3]]), "a"),
    ("gap a = 0", lambda: C.gap(0.0, 1.0), "a"),
    ("pressure a = 1e5", lambda: C.pressure(1e5, 0.0), "a"),
    ("solve delta nan", lambda: C.solve(delta=math.nan), "delta"),
    ("solve P string", lambda: C.solve(P="1"), "P"),
    ("solve branches", lambda: C.solve(P=1.0, branches=["nope"]), "branches"),
    ("cycle control", lambda: C.cycle(P_max=1.0, P_min=-1.0, control="force"), "control"),
    ("cycle grip without delta", lambda: C.cycle(control="grip", delta_max=1e-3), "delta_max"),
    ("cycle delta_min >= delta_max", lambda: C.cycle(control="grip", delta_max=0.0, delta_min=1e-3), "delta_min"),
    ("curve regime", lambda: eq.curve(0.3, 1.0, regime="middle", gb=eq.incompressible_gb(1.0)), "regime"),
    ("curve super-critical rigid", lambda: eq.curve(0.3, math.inf, regime="super-critical", gb=eq.incompressible_gb(math.inf)), "regime"),
    ("adherence control", lambda: eq.adherence(0.3, 1.0, control="force", gb=eq.incompressible_gb(1.0)), "control"),
    ("alpha_ratio = 1.5", lambda: eq.curve(0.3, 1.0, alpha_ratio=1.5, gb=eq.incompressible_gb(1.0)), "alpha_ratio"),
    ("closed form refused for alpha* != 0",
     lambda: jkrcyl.Contact(R=0.01, Delta=1e-5, w=0.05, materials=jkrcyl.Materials.from_young(
         2.6e9, 0.3, math.inf, 0.3)).state(0.3, method="closed-form"), "alpha*"),
]


@pytest.mark.parametrize("what, call, name", API_CASES, ids=[c[0] for c in API_CASES])
def test_api_value_error_names_the_parameter(what, call, name):
    with pytest.raises(ValueError) as info:
        call()
    assert re.search(rf"(^|\W){re.escape(name)}(\W|$)", str(info.value)), str(info.value)


def test_state_none_says_none():
    """The audit found `state(None)` reporting "got nan": the message must show what was given."""
    with pytest.raises(ValueError, match=r"^a must .*None"):
        C.state(None)


# --- CLI: one line, exit 2, no traceback --------------------------------------------------------------------
def subprocess_run(*args):
    """``python -m jkrcyl *args``: the real entry point (the catalogue below runs jkrcyl.cli.main in this process,
    tests/cli_run.py)."""
    env = dict(os.environ, MPLBACKEND="Agg")
    return subprocess.run([sys.executable, "-m", "jkrcyl", *args], cwd=ROOT, env=env, capture_output=True,
                          text=True, timeout=300)


CLI_CASES = [
    (["curve", "--E", "-2e6", *PHYS[2:]], "E"),
    (["curve", "--M", "0.3", *PHYS], "M"),
    (["curve", "--M", "0.3", "--E", "1e9"], "M"),
    (["curve", "--M", "1e-300"], "M"),
    (["adherence", "--M", "1e-300"], "M"),
    (["curve", "--E", "1e-320", *PHYS[2:]], "E"),
    (["curve", "--M", "0.3", "--n", "10000000"], "n"),
    (["curve", "--M", "0.3", "--theta", "1e160"], "theta"),
    (["curve", "--M", "0.3", "--gb", "2"], "gb"),
    (["atlas", "--theta-min", "3", "--theta-max", "2"], "theta-max"),
    (["solve", *PHYS], "P"),
    (["solve", *PHYS, "--P", "1", "--delta", "1e-6"], "P"),
    (["solve", *PHYS[:-2], "--P", "1"], "w"),
    (["solve", *PHYS[:11], "0.01", "--w", "0.05", "--P", "1"], "Delta"),
    (["solve", *PHYS, "--P", "nan"], "P"),
    (["cycle", *PHYS, "--P-max", "-1", "--P-min", "1"], "P_min"),
    (["cycle", *PHYS, "--control", "grip", "--P-max", "1", "--P-min", "-1"], "delta_max"),
    (["pull-off", "--E", "2.6e9"], "nu"),
    (["solve", "--E", "2.6e9", "--nu", "0.6", *PHYS[4:], "--P", "1"], "nu"),
    (["solve", *PHYS[:11], "0.02", "--w", "0.05", "--P", "1"], "Delta"),          # Delta > R
    (["solve", *PHYS[:-1], "-0.05", "--P", "1"], "w"),
    (["solve", *PHYS, "--delta", "nan"], "delta"),
    (["solve", "--E", "nan", *PHYS[2:], "--P", "1"], "E"),
    (["cycle", *PHYS, "--P-max", "1", "--P-min", "-1", "--n", "3"], "n"),
    (["cycle", *PHYS, "--P-max", "1"], "P_max"),
    (["two-patch", "--M", "1e-300"], "M"),
    (["curve", "--M", "0.3", "--theta", "0.4"], "theta"),
    (["curve", "--M", "abc"], "M"),
]


@pytest.mark.parametrize("args, name", CLI_CASES, ids=[" ".join(a[:3]) + f" [{n}]" for a, n in CLI_CASES])
def test_cli_one_line_exit_2(args, name):
    r = run(*args)
    assert r.returncode == 2, (r.stdout, r.stderr)
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in r.stderr and name in lines[0], r.stderr


def test_cli_version_and_module_entry():
    r = subprocess_run("--version")
    assert r.returncode == 0 and r.stdout.strip() == f"jkrcyl {jkrcyl.__version__}"
    r = subprocess_run(*CLI_CASES[0][0])            # bad input through the real entry point: one line, exit 2
    lines = r.stderr.strip().splitlines()
    assert r.returncode == 2 and len(lines) == 1 and "Traceback" not in r.stderr and CLI_CASES[0][1] in lines[0]


def test_cli_broken_pipe_is_quiet():
    """`jkrcyl curve ... | head -1`: no BrokenPipe message."""
    p = subprocess.Popen([sys.executable, "-m", "jkrcyl", "curve", "--M", "0.3", "--n", "200000"], cwd=ROOT,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    p.stdout.readline()
    p.stdout.close()
    err = p.stderr.read().decode()
    p.wait(timeout=120)
    assert "Traceback" not in err and "BrokenPipe" not in err


def test_cli_numbers_and_booleans():
    """10 significant digits (no 17-digit noise); booleans true/false in CSV and JSON alike."""
    import json
    r = run("curve", "--M", "0.3", "--n", "3")
    head = r.stdout.splitlines()[1].split(",")
    rows = [dict(zip(head, ln.split(","))) for ln in r.stdout.splitlines()[2:]]
    digits = lambda x: len(x.lstrip("-").split("e")[0].replace(".", "").lstrip("0"))
    flags = [k for k in head if k == "feasible" or k.startswith("stable")]
    assert rows and len(flags) >= 3
    assert all(digits(v) <= 10 for row in rows for k, v in row.items() if k not in flags)
    assert {row[k] for row in rows for k in flags} <= {"true", "false"}
    data = json.loads(run("curve", "--M", "0.3", "--n", "3", "--format", "json").stdout)
    assert all(isinstance(v, bool) for v in data["feasible"])


def test_cli_two_patch_numbers_and_booleans():
    """Was: repr(float) (17 digits) and booleans as 1.0/0.0, unlike every other command (issue 11)."""
    r = run("two-patch", "--M", "0.4", "--theta", "1", "--n", "4")
    assert r.returncode == 0, r.stderr
    lines = [ln for ln in r.stdout.splitlines() if not ln.startswith("#")]
    head = lines[0].split(",")
    rows = [dict(zip(head, ln.split(","))) for ln in lines[1:]]
    digits = lambda x: len(x.lstrip("-").split("e")[0].replace(".", "").lstrip("0"))
    flags = [k for k in head if k == "feasible" or k.startswith("stable")]
    assert all(digits(v) <= 10 for row in rows for k, v in row.items() if k not in flags and k != "branch")
    assert {row[k] for row in rows for k in flags} <= {"true", "false"}


def test_counts_alpha_ratio_and_huge_theta():
    """Found by the property tests: fractional counts were truncated, alpha*/beta* = 1 accepted (|alpha*| < beta*
    for every elastic pair), and a curve at huge vartheta complained about an 'a' the caller never gave."""
    from jkrcyl import equilibria as eq
    with pytest.raises(ValueError, match="n must be an integer"):
        eq.curve(0.3, 1.0, n=5.5, gb=eq.incompressible_gb(1.0))
    with pytest.raises(ValueError, match="alpha_ratio"):
        eq.curve(0.3, 1.0, n=5, alpha_ratio=1.0, gb=eq.incompressible_gb(1.0))
    with pytest.raises(ValueError, match="theta"):
        eq.curve(0.3, 1e100, regime="super-critical", n=5, gb=eq.incompressible_gb(1e100))
    c = jkrcyl.Contact(R=1.0, Delta=0.01, w=1e-4, materials=jkrcyl.Materials(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0))
    with pytest.raises(ValueError, match="n must be an integer"):
        c.cycle(P_max=1.0, P_min=-1.0, n=10.5)
