"""Issue 20: jkrcyl.fit -- the model adapter against the library's own routes, recovery of known truths, the
intervals against exact results and coverage, the half-plane comparison, bad data and the command line.

References: the superposition/scaling form of jkrcyl/fit/model.py is compared with direct Contact.state calls on
the scaled pair (a number reached two ways); the pole with the solver's own a_crit (numerics.arcs, the unit
approach case's edge coefficient), the mpmath root of 2 vartheta - log(1 + a^2) - 2 a^4 (section 4) and the
plane-strain FE receding limit of a rubber roller (nu_I 0.45) in a rigid cradle, 111.79 deg (issue 18); the
folds with Contact.adherence / Contact.pull_off (derived dG/da kernels, not the fit's splines) and with a dense
sweep of independent states; the profile-likelihood interval with the exact interval of the linear model
P = c - g p2(a) in g = sqrt(w) (weighted linear regression, closed form); the linearised half-plane plot is
reference/halfplane.py (Barquins (7.4)).
"""
import json
import math
import pathlib
import subprocess
import sys
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

import jkrcyl
from jkrcyl.fit import branch, estimate, model, uncertainty
from reference.halfplane import linearised_plot

ROOT = pathlib.Path(__file__).resolve().parents[1]
POLYMER = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
STEEL = jkrcyl.Materials.from_young(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3)          # alpha*/beta* = +0.117
RUBBER = jkrcyl.Materials.from_young(E=math.inf, nu=0.3, E_I=2e6, nu_I=0.45)       # roller in a rigid cradle
CASES = {"polymer": (POLYMER, 0.01, 1e-5), "steel": (STEEL, 0.01, 1e-5), "rubber": (RUBBER, 0.02, 5e-5)}
W = 0.05


@pytest.fixture(autouse=True)
def _quiet():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        yield


def pull_off_width(m, R, D, w=W, control="load"):
    """The contact width at the library's pull-off (Contact.pull_off: the core's path, not the fit's)."""
    return jkrcyl.Contact(R, D, w, m).pull_off(control=control).contact_width


def design(case, n=30, lo=1.05, hi=4.0, w=W):
    """n widths from lo to hi times the pull-off width and the library's loads there (the truth)."""
    m, R, D = CASES[case]
    width = np.linspace(lo, hi, n) * pull_off_width(m, R, D, w)
    pole = jkrcyl.Contact(R, D, w, m).a_crit
    width = np.minimum(width, model.width_of_a(0.9 * pole, R) * np.linspace(0.9, 1, n))  # below the pole
    return width, jkrcyl.Contact(R, D, w, m).state(np.tan(width / (4 * R))).P


# --- the model adapter -------------------------------------------------------------------------------------------
modulus = st.one_of(st.just(math.inf), st.floats(1e6, 1e11))


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(E=modulus, E_I=modulus, nu=st.floats(0.0, 0.5).map(lambda x: round(x, 4)),
       nu_I=st.floats(0.0, 0.5).map(lambda x: round(x, 4)), f=st.floats(0.2, 5.0),
       w=st.floats(1e-3, 1.0), delta=st.floats(1e-5, 1e-2))
def test_superposition_and_scaling_equal_direct_states(E, E_I, nu, nu_I, f, w, delta):
    """The superposed states (unit parts of the unscaled pair, k of the scaled contact's law) equal Contact.state of
    the pair with both moduli times f to 1e-10 of the parts' size, for random pairs (rigid bodies and alpha* != 0
    included): load, work-conjugate approach, gap at the top and the load's slope (against differences of
    Contact.state)."""
    if math.isinf(E) and math.isinf(E_I):
        E = 1e9
    m = jkrcyl.Materials.from_young(E=E, nu=nu, E_I=E_I, nu_I=nu_I)
    R = 0.01
    a = np.array([0.01, 0.1, 0.3, 0.5]) * (1.0 if math.isinf(m.theta) else jkrcyl.a_crit(m.theta))  # below poles
    c = jkrcyl.Contact(R, delta * R, w, model.scaled(m, f))
    fit = model.Superposed.of_inputs(R, delta * R, w, f, m).states(a)        # what the fit evaluates
    direct = c.state(a)
    u = model.unit_slices(m, a)
    k, L = model.edge_coefficient(c), model.load_per_p(c)
    size = lambda field, unit: unit * (np.abs(u.parts[field][0]) + k * np.abs(u.parts[field][1]))
    assert np.all(np.abs(fit.P - direct.P) <= 1e-10 * size("p", L))
    assert np.all(np.abs(fit.delta_work - direct.delta_work) <= 1e-10 * size("dw", c.Delta))
    assert np.all(np.abs(fit.h_pi - direct.h_pi) <= 1e-10 * size("h", c.Delta))
    step = 1e-5 * a
    slope = (c.state(a + step).P - c.state(a - step).P) / (2 * step)
    assert np.all(np.abs(fit.dP_da - slope) <= 1e-5 * size("dp_da", L))


def test_pole_against_three_references():
    """mpmath root of the denominator of (4.4); the zero of 1/P without adhesion from the two-arc engine's unit
    cases (not the single-arc solver behind Contact.a_crit); finite elements."""
    import mpmath
    from scipy.optimize import brentq
    from jkrcyl.numerics.arcs import two_patch_linear
    th = POLYMER.theta
    ref = mpmath.findroot(lambda a: 2 * th - mpmath.log(1 + a * a) - 2 * a ** 4, 0.9)
    assert model.pole(POLYMER) == pytest.approx(float(ref), rel=1e-13)
    gb = STEEL.inv_G_I / STEEL.beta

    def inv_P(a):
        lin = two_patch_linear(2 * math.atan(a), 0.0, STEEL.theta, gb, 48, STEEL.alpha_ratio)
        q0, q1 = lin.q0, lin.q1
        return q1[2] / (q0[0] * q1[2] - q0[2] * q1[0])
    ac = model.pole(STEEL)
    assert brentq(inv_P, 0.999 * ac, 1.001 * ac, xtol=1e-15) == pytest.approx(ac, rel=1e-9)
    assert math.degrees(2 * math.atan(model.pole(RUBBER))) == pytest.approx(111.79, abs=0.1)   # FE


@pytest.mark.parametrize("case", CASES)
def test_branch_table_interpolates_the_exact_parts(case):
    """The splines of the table (a search device: located states are then evaluated exactly) against exact
    superposed states, without adhesion and at k = 1."""
    m, R, _ = CASES[case]
    tab = branch.table(m)
    lo = tab.a_min if m.closed_form else tab.a_max * 1e-3     # the solver's adhesionless part is noisy below
    a = np.exp(np.random.default_rng(1).uniform(math.log(lo), math.log(tab.a_max * 0.999), 200))
    tol, tol_slope = (2e-7, 2e-5) if m.closed_form else (2e-6, 1e-3)     # slopes: for Newton steps only
    for k in (0.0, 1.0):
        exact, table = model.superpose(model.unit_slices(m, a), k), tab.interpolate(a, k)
        for f in branch.SPLINE_FIELDS:
            assert np.max(np.abs(table[f][0] / getattr(exact, f) - 1)) < tol, (f, k)
            scale = np.abs(getattr(exact, model.SLOPE_OF[f])) + np.abs(getattr(exact, f)) / a   # d/da ~ value/a
            assert np.max(np.abs(table[f][1] - getattr(exact, model.SLOPE_OF[f])) / scale) < tol_slope, (f, k)


def test_folds_equal_the_library_pull_off():
    """Fixed load: the minimum of P (Contact.adherence, derived dG/da kernels); fixed delta_work: pull_off."""
    R, D = 0.01, 1e-5
    c = jkrcyl.Contact(R, D, W, POLYMER)
    ref = [p for p in c.adherence(control="load", confined=False) if p.regime == "sub-critical"][0]
    po = branch.pull_off(c, POLYMER)
    assert po.P == pytest.approx(ref.P, rel=1e-9) and po.a == pytest.approx(ref.a, rel=1e-5)
    grip = c.pull_off(control="grip-work")
    assert branch.pull_off(c, POLYMER, "grip-work").P == pytest.approx(grip.P, rel=1e-9)


def test_fold_alpha_pair_against_a_dense_sweep_of_states():
    R, D = 0.01, 1e-5
    c = jkrcyl.Contact(R, D, W, STEEL)
    po = branch.pull_off(c, STEEL)
    a = po.a * np.linspace(0.9, 1.1, 41)
    P = c.state(a).P
    i = int(np.argmin(P))
    c2, c1, c0 = np.polyfit(a[i - 2:i + 3] - a[i], P[i - 2:i + 3], 2)
    assert po.P == pytest.approx(c0 - c1 ** 2 / (4 * c2), rel=1e-7)


def test_stable_segments_match_the_library_flags():
    from jkrcyl import equilibria
    R, D = 0.01, 1e-5
    c = jkrcyl.Contact(R, D, W, POLYMER)
    M, th, gb = equilibria.from_contact(c)
    a = np.geomspace(1e-3, 0.9, 300)
    cv = equilibria.curve(M, th, a=a, gb=gb)
    for control, flags in (("load", cv.stable_load), ("grip-work", cv.stable_grip_work)):
        lo, hi = branch.segment(model.Superposed.of(c, POLYMER), control)
        inside = (a > lo) & (a < hi)
        away = (np.abs(a / lo - 1) > 1e-4) & (np.abs(a / hi - 1) > 1e-4)
        assert np.array_equal(inside[away], (flags & cv.feasible)[away]), control


# --- estimation ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("case", CASES)
@pytest.mark.parametrize("free", [("w", "E"), ("w", "Delta"), ("w_loading", "w_unloading", "E")])
def test_exact_data_give_the_truth(case, free):
    m, R, D = CASES[case]
    width, P = design(case, n=24)
    leg = None
    if "w_loading" in free:             # the unloading half measured with a larger work of adhesion
        leg = np.array(["loading"] * 12 + ["unloading"] * 12)
        P[12:] = jkrcyl.Contact(R, D, 2 * W, m).state(np.tan(width[12:] / (4 * R))).P
    start = dict(Delta=0.7 * D) if "Delta" in free else dict(Delta=D)
    res = jkrcyl.fit(P=P, width=width, R=R, materials=m, free=free, leg=leg, sigma_P=1.0, interval=None, **start)
    truth = dict(w=W, w_loading=W, w_unloading=2 * W, E=4 / m.beta, Delta=D)
    for k in free:
        assert res.values[k] == pytest.approx(truth[k], rel=1e-6), k


@pytest.mark.parametrize("control,sigmas", [("load", ("sigma_delta_work",)), ("grip-work", ("sigma_P",)),
                                            ("load", ("sigma_P", "sigma_delta_work"))])
def test_exact_approach_data_give_the_truth(control, sigmas):
    m, R, D = CASES["polymer"]
    a_fold = np.tan(pull_off_width(m, R, D, W, control) / (4 * R))
    s = jkrcyl.Contact(R, D, W, m).state(np.geomspace(1.05 * a_fold, 5 * a_fold, 30))
    kw = {k: 1.0 if k == "sigma_P" else 1e-9 for k in sigmas}
    res = jkrcyl.fit(P=s.P, delta_work=s.delta_work + 2e-7, R=R, Delta=0.8 * D, materials=m, control=control,
                     free=("w", "E", "Delta", "offset"), interval=None, **kw)
    for k, v in dict(w=W, E=4 / m.beta, Delta=D, offset=2e-7).items():
        assert res.values[k] == pytest.approx(v, rel=1e-5), k


def test_profile_interval_equals_the_exact_linear_interval():
    """w alone, noise on P only: P = f Delta p1 - g p2 is linear in g = sqrt(w), so the 95 % interval of g is
    g_hat -+ 1.96 sd(g_hat) exactly (weighted linear regression); the profile interval of w must be its square."""
    m, R, D = CASES["polymer"]
    width, P = design("polymer", n=20)
    rng = np.random.default_rng(3)
    sigma = rng.uniform(5.0, 20.0, P.size)
    y = P + rng.normal(0, sigma, P.size)
    res = jkrcyl.fit(P=y, width=width, R=R, Delta=D, materials=m, free=("w",), sigma_P=sigma)
    a = np.tan(width / (4 * R))
    p1 = jkrcyl.Contact(R, D, 0.0, m).state(a).P                      # f Delta p1 at f = 1
    p2 = -jkrcyl.Contact(R, 0.0, 1.0, m).state(a).P                   # sqrt(w) p2 at w = 1
    wt = 1 / sigma ** 2
    g = np.sum(wt * p2 * (p1 - y)) / np.sum(wt * p2 ** 2)
    sd = 1 / math.sqrt(np.sum(wt * p2 ** 2))
    z = 1.959963984540054
    assert res.values["w"] == pytest.approx(g ** 2, rel=1e-9)
    assert res.intervals["w"] == pytest.approx(((g - z * sd) ** 2, (g + z * sd) ** 2), rel=1e-6)
    assert res.standard_errors["w"] == pytest.approx(2 * g * sd, rel=1e-6)


def test_alpha_pair_recovered_as_well_as_the_closed_form_pair():
    err = {}
    for case in ("polymer", "steel"):
        m, R, D = CASES[case]
        width, P = design(case, n=30, hi=5.0)
        rows = []
        for seed in range(30):
            x = width * (1 + np.random.default_rng(seed).normal(0, 0.01, width.size))
            r = jkrcyl.fit(P=P, width=x, R=R, Delta=D, materials=m, sigma_width=0.01 * x, interval=None)
            rows.append((r.values["w"] / W - 1, r.values["E"] * m.beta / 4 - 1))
        err[case] = np.sqrt(np.mean(np.array(rows) ** 2, axis=0))
    assert np.all(err["steel"] < 1.5 * err["polymer"]) and np.all(err["steel"] > err["polymer"] / 1.5), err
    assert np.all(err["steel"] < 0.01)


def test_delta_recovered_within_two_percent():
    m, R, D = CASES["polymer"]
    width, P = design("polymer", n=40, hi=5.0)
    for seed in range(10):
        x = width * (1 + np.random.default_rng(seed).normal(0, 0.01, width.size))
        r = jkrcyl.fit(P=P, width=x, R=R, Delta=0.7 * D, materials=m, free=("w", "Delta"), sigma_width=0.01 * x)
        assert abs(r.values["Delta"] / D - 1) < 0.02
        assert r.intervals["Delta"][0] < r.values["Delta"] < r.intervals["Delta"][1]


def test_robust_loss_resists_outliers_and_unknown_sigma_is_estimated():
    m, R, D = CASES["polymer"]
    width, P = design("polymer", n=40)
    y = P + np.random.default_rng(4).normal(0, 10.0, P.size)
    clean = jkrcyl.fit(P=y, width=width, R=R, Delta=D, materials=m, interval="wald")
    assert clean.sigma == pytest.approx(10.0, rel=0.3)                 # residual scale ~ the true sd
    y[[5, 20]] += 400.0                                                # two 40-sigma outliers
    plain = jkrcyl.fit(P=y, width=width, R=R, Delta=D, materials=m, interval=None)
    robust = jkrcyl.fit(P=y, width=width, R=R, Delta=D, materials=m, loss="soft_l1", interval=None)
    se = clean.standard_errors["w"]
    assert abs(robust.values["w"] - clean.values["w"]) < 2 * se < abs(plain.values["w"] - clean.values["w"])


def test_open_profile_side_is_reported_as_unbounded():
    class Flat:                                   # residuals depend on u1 only through a bounded function
        def residuals(self, u):
            return np.array([u[0], 0.1 * math.tanh(u[1])])

    class Spec:
        names = ("w", "E")

    prof = uncertainty.Profiler(Flat(), Spec(), np.zeros(2), 0.0, 1.0, 3.84, "linear", 1.0, np.array([1.0, 1.0]))
    assert prof.side(1, +1) == math.inf and prof.side(1, -1) == -math.inf
    assert prof.side(0, +1) == pytest.approx(math.sqrt(3.84), rel=1e-4)


def test_identifiability_check_names_the_parameters():
    jac = np.array([[1.0, 2.0], [2.0, 4.0], [3.0, 6.0000000001]])
    with pytest.raises(ValueError, match="w, E: not separately identifiable"):
        estimate._identifiable(jac, ("w", "E"))
    with pytest.raises(ValueError, match="E: the data do not depend on it"):
        estimate._identifiable(np.array([[1.0, 0.0], [2.0, 0.0]]), ("w", "E"))


@pytest.mark.slow
def test_coverage_small_replicate_study():
    """200 replicates of the README design (benchmarks/bench_fit.py runs 1000): 95 % intervals cover the truth
    in 90-99 % of them (3 binomial sd at n = 200)."""
    sys.path.insert(0, str(ROOT / "benchmarks"))
    import bench_fit
    rows = [bench_fit.coverage_one(seed) for seed in range(200)]
    for k in ("w", "E"):
        assert 0.90 <= np.mean([r[k][0] for r in rows]) <= 0.99, k


@pytest.mark.slow
def test_half_plane_limit_direct_fit_halves_the_linear_plot_error():
    """Delta/R = 3e-3, contacts below 15 deg, 25 widths from 1.05 to 4 times the pull-off width, 2 % noise on
    the width, 400 replicates: RMS error of w from the direct fit <= half that of the linearised plot."""
    m, R, D = POLYMER, 0.01, 3e-5
    width = np.linspace(1.05, 4.0, 25) * pull_off_width(m, R, D)
    P = jkrcyl.Contact(R, D, W, m).state(np.tan(width / (4 * R))).P
    direct, linear = [], []
    for seed in range(400):
        x = width * (1 + np.random.default_rng(seed).normal(0, 0.02, width.size))
        linear.append(linearised_plot(x, P, R, D)[0] / W - 1)
        direct.append(jkrcyl.fit(P=P, width=x, R=R, Delta=D, materials=m, sigma_width=0.02 * x,
                                 interval=None).values["w"] / W - 1)
    rms = lambda e: math.sqrt(np.mean(np.square(e)))
    assert rms(direct) <= 0.5 * rms(linear), (rms(direct), rms(linear))


# --- bad data ------------------------------------------------------------------------------------------------------
def _bad(**change):
    m, R, D = CASES["polymer"]
    width, P = design("polymer", n=10)
    kw = dict(P=P, width=width, R=R, Delta=D, materials=m, sigma_P=5.0)
    kw.update(change)
    return kw


def _with(arr, i, v):
    arr = np.array(arr, dtype=float)
    arr[i] = v
    return arr


BAD = [
    (lambda: _bad(P=_with(_bad()["P"], 3, np.nan)), "P: row 3 is NaN"),
    (lambda: _bad(width=_with(_bad()["width"], 2, np.nan)), "width: row 2 is NaN"),
    (lambda: _bad(width=_with(_bad()["width"], 1, -1e-3)), "width must be > 0.*row 1"),
    (lambda: _bad(width=_with(_bad()["width"], 4, 0.07)), r"width must be < 2 pi R.*row 4"),
    (lambda: _bad(P=_bad()["P"][:1], width=_bad()["width"][:1]), "fewer points"),
    (lambda: _bad(P=_bad()["P"][:2], width=_bad()["width"][:2], sigma_P=None), "at least 3"),
    (lambda: _bad(P=np.full(6, -500.0), width=np.full(6, 3e-3)), "distinct.*pull-off point alone"),
    (lambda: _bad(P=_with(_bad()["P"], 0, 3 * _bad()["P"][0])), "beyond the pull-off force"),
    (lambda: _bad(free=("w", "E", "Delta")), r"E\* Delta and E\* w"),
    (lambda: _bad(free=("w", "G")), "free: unknown parameter 'G'"),
    (lambda: _bad(free=("w", "E", "E_pin")), "E: scales both moduli"),
    (lambda: _bad(free=("w", "offset")), "offset: an approach offset needs delta_work data"),
    (lambda: _bad(free=("w_loading", "w_unloading")), "leg"),
    (lambda: _bad(leg=["up"] * 10), "leg must be 'loading' or 'unloading'"),
    (lambda: _bad(sigma_P=0.0), "sigma_P must be > 0"),
    (lambda: _bad(delta_work=np.ones(10)), "exactly one abscissa"),
    (lambda: _bad(width=_bad()["width"][:5]), "width has 5 values, P has 10"),
    (lambda: _bad(free=("E",)), "w: give the work of adhesion"),
    (lambda: _bad(control="grip"), "control must be one of"),
    (lambda: _bad(loss="cauchy"), "loss must be one of"),
    (lambda: _bad(confidence=1.0), "confidence must be in"),
    (lambda: _bad(materials="steel"), "materials must be a jkrcyl.Materials"),
    (lambda: _bad(Delta=0.02), "Delta must be in"),
    (lambda: _bad(P=["a"] * 10), "P must be an array of real numbers"),
    (lambda: _bad(free=("w", "E_hole"), materials=RUBBER, R=0.02), "E_hole: the hole is rigid"),
]


@pytest.mark.parametrize("make,message", BAD, ids=[m for _, m in BAD])
def test_bad_data_raise_value_error_naming_the_problem(make, message):
    with pytest.raises(ValueError, match=message):
        jkrcyl.fit(**make())


# --- CSV, plot, command line -------------------------------------------------------------------------------
def test_read_csv(tmp_path):
    f = tmp_path / "d.csv"
    f.write_text("# R=0.01 Delta=3e-6 E=inf nu=0.3 control=grip-work\n# E* = 5 is prose\n"
                 "P [N/m],width [m],leg\n1.5,0.002,loading\n-2,0.003,unloading\n")
    t = jkrcyl.fit.read_csv(f)
    assert t.meta == dict(R=0.01, Delta=3e-6, E=math.inf, nu=0.3, control="grip-work")
    assert list(t.columns) == ["P", "width", "leg"] and t.columns["P"].tolist() == [1.5, -2.0]
    f.write_text("P,widht\n1,2\n")
    with pytest.raises(ValueError, match="unknown column 'widht'"):
        jkrcyl.fit.read_csv(f)
    f.write_text("P,width\n1,x\n")
    with pytest.raises(ValueError, match=r"width \(data row 1\): not a number"):
        jkrcyl.fit.read_csv(f)


def test_plots_are_written(tmp_path):
    m, R, D = CASES["polymer"]
    width, P = design("polymer", n=12)
    res = jkrcyl.fit(P=P + 1.0, width=width, R=R, Delta=D, materials=m)
    assert res.plot(tmp_path / "w.png").stat().st_size > 1000
    s = jkrcyl.Contact(R, D, W, m).state(np.geomspace(0.07, 0.3, 12))
    res = jkrcyl.fit(P=s.P, delta_work=s.delta_work * 1.001, R=R, Delta=D, materials=m)
    res.plot(tmp_path / "d.png")
    assert (tmp_path / "d.png").stat().st_size > 1000 and "w" in res.table()


def _cli(*args, cwd=ROOT):
    return subprocess.run([sys.executable, "-m", "jkrcyl", "fit", *args], cwd=cwd, capture_output=True, text=True,
                          timeout=300)


def _main(capsys, monkeypatch, *args, cwd=ROOT):
    """jkrcyl.cli.main in this process (the subprocess route is tested once): (exit status, stdout, stderr)."""
    from jkrcyl import cli
    monkeypatch.chdir(cwd)
    code = cli.main(["fit", *args])
    out = capsys.readouterr()
    return code, out.out, out.err


def test_cli_fits_the_example_like_the_api(tmp_path):
    r = _cli("docs/fit_example.csv", "--format", "json", "--plot", str(tmp_path / "f.png"))
    assert r.returncode == 0, r.stderr
    out = {p["parameter"]: p for p in json.loads(r.stdout)["parameters"]}
    t = jkrcyl.fit.read_csv(ROOT / "docs" / "fit_example.csv")
    api = jkrcyl.fit(**t.columns, R=0.01, Delta=3e-6, materials=POLYMER)
    for k in ("w", "E"):
        assert out[k]["value"] == pytest.approx(api.values[k], rel=1e-8)
        assert (out[k]["lower"], out[k]["upper"]) == pytest.approx(api.intervals[k], rel=1e-8)
    assert (tmp_path / "f.png").stat().st_size > 1000


def test_cli_text_table(capsys, monkeypatch):
    code, text, _ = _main(capsys, monkeypatch, "docs/fit_example.csv")
    assert code == 0 and text.splitlines()[0].split()[:2] == ["parameter", "value"] and "profile likelihood" in text


def test_cli_fix_rigid_pin(tmp_path, capsys, monkeypatch):
    m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=math.inf, nu_I=0.3)
    R, D = 0.01, 1e-5
    width = np.linspace(1.1, 4, 15) * pull_off_width(m, R, D)
    P = jkrcyl.Contact(R, D, W, m).state(np.tan(width / (4 * R))).P
    f = tmp_path / "rigid.csv"
    f.write_text("P,width,sigma_P\n" + "".join(f"{float(p)!r},{float(x)!r},1\n" for p, x in zip(P, width)))
    code, out, err = _main(capsys, monkeypatch, str(f), "--x", "width", "--fix", "R=0.01", "--fix", "Delta=1e-5",
                           "--fix", "E=2.6e9", "--fix", "nu=0.3", "--fix", "E_I=inf", "--fix", "nu_I=0.3",
                           "--format", "csv", cwd=tmp_path)
    assert code == 0, err
    rows = {ln.split(",")[0]: ln.split(",") for ln in out.splitlines()[2:]}
    assert float(rows["w"][1]) == pytest.approx(W, rel=1e-6)
    assert float(rows["E"][1]) == pytest.approx(4 / m.beta, rel=1e-6)


@pytest.mark.parametrize("args,name", [
    (("missing.csv",), "data: cannot read"),
    (("docs/fit_example.csv", "--fix", "R"), "--fix: expected NAME=VALUE"),
    (("docs/fit_example.csv", "--fix", "w=0.05", "--free", "w,E"), "w: given by --fix and listed in --free"),
    (("docs/fit_example.csv", "--free", "w,E,Delta"), "Delta, E, w"),
    (("docs/fit_example.csv", "--x", "delta_work"), "x: the file has no 'delta_work' column"),
])
def test_cli_errors_are_one_line_exit_2(args, name, capsys, monkeypatch):
    code, _, err = _main(capsys, monkeypatch, *args)
    lines = err.strip().splitlines()
    assert code == 2 and len(lines) == 1 and name in lines[0], err


def test_cli_nan_row_names_it(tmp_path):
    """One line on stderr, exit status 2, no traceback (jkrcyl.cli.main in this process, tests/cli_run.py; a bad fit
    through the entry point itself: tests/test_fit_converge.py::test_cli_diverging_fit_exits_2)."""
    from cli_run import run
    f = tmp_path / "nan.csv"
    f.write_text("# R=0.01 Delta=1e-5 E=2.6e9 nu=0.3 E_I=2.6e9 nu_I=0.3\nP,width\n1,0.003\n,0.004\n2,0.005\n3,0.006\n")
    r = run("fit", f)
    lines = r.stderr.strip().splitlines()
    assert r.returncode == 2 and len(lines) == 1 and "P: row 1 is NaN" in lines[0] and "Traceback" not in r.stderr


@pytest.mark.slow
def test_benchmark_smoke():
    """benchmarks/bench_fit.py in smoke mode (tiny counts, one worker) so that it cannot rot; numbers not checked."""
    run = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_fit.py"), "--replicates", "6",
                          "--halfplane", "4", "--recovery", "2", "--workers", "1"], cwd=ROOT, capture_output=True,
                         text=True, timeout=600)
    assert run.returncode == 0, run.stdout + run.stderr
    for row in ("speed:", "coverage of 95 % intervals", "half-plane limit", "recovery", "steel in aluminium"):
        assert row in run.stdout, f"missing {row!r} in\n{run.stdout}"
