"""jkrcyl.fit with the cohesive (Maugis-Dugdale) law (issue 20's sigma0, issue 19's law).

The synthetic data are states of the traced branch (``Contact.curve``: pseudo-arclength continuation projected onto
the curve, jkrcyl.model.cohesive), an independent route from the one the fit evaluates (``Contact.at_contact``:
the zone end's root at each contact half-angle, jkrcyl.numerics.cohesive.cohesive_state).  The two agree to ~1e-10
(test below), so a noise-free fit must return the truth to far better than 1e-6.  The JKR limit is checked by its
rate: the states differ from JKR's by C/lambda^2 (tests/test_cohesive_api.py), so the fitted w and E* at a large
fixed sigma0 must approach the JKR fit's like lambda^-2.
"""
import math
import warnings

import numpy as np
import pytest
from cli_run import run

import jkrcyl
from jkrcyl.fit import cohesive as fit_cohesive

R, DELTA, W = 10e-3, 3e-6, 0.05
PAIR = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
E_STAR = 2.6e9 / (2 * (1 - 0.3 ** 2))          # contact modulus of the pair, E/(2(1 - nu^2)) [Pa]
START = jkrcyl.Materials.from_young(E=2.0e9, nu=0.3, E_I=2.0e9, nu_I=0.3)   # 23 % off: the fit must move


def _branch_data(lam, n=90, eps_range=(0.05, 1.0)):
    """(contact, width [m], P [N/m]) of the traced branch's states at lambda (the README-like pin, Delta = 3 um); n
    uniform in the branch parameter, ~40 % of them below eps = 1e-3 (the branch from the zone-only pin's touch)."""
    c = jkrcyl.Contact.with_lambda(R=R, Delta=DELTA, w=W, materials=PAIR, lambda_=lam)
    cv = c.curve(regime="sub-critical", n=n)
    sel = (cv.eps > eps_range[0]) & (cv.eps < eps_range[1])
    return c, 2 * R * cv.eps[sel], cv.P[sel]


@pytest.fixture(scope="module")
def lambda_one():
    return _branch_data(1.0)


def test_accessor_equals_the_traced_branch(lambda_one):
    """Contact.at_contact (root at a given eps) against the curve's states (continuation + projection)."""
    c, width, P = lambda_one
    s = c.at_contact(width / (2 * R))
    assert np.max(np.abs(s.P - P)) < 1e-8 * np.max(np.abs(P))
    assert width.size >= 15


@pytest.mark.parametrize("bad", [0.0, -0.1, math.pi, math.nan, [0.5, math.inf], "0.5", True, 1j])
def test_accessor_rejects_contacts_outside_the_circle(lambda_one, bad):
    with pytest.raises(ValueError, match=r"eps must be .*in \(0, pi\)"):
        lambda_one[0].at_contact(bad)


def test_noise_free_recovery_of_w_E_sigma0(lambda_one):
    c, width, P = lambda_one
    res = jkrcyl.fit(P=P, width=width, R=R, Delta=DELTA, materials=START, free=("w", "E", "sigma0"),
                     interval=None)
    assert abs(res.values["w"] / W - 1) < 1e-6
    assert abs(res.values["E"] / E_STAR - 1) < 1e-6
    assert abs(res.values["sigma0"] / c.sigma0 - 1) < 1e-6
    assert abs(res.contact().lambda_ - 1.0) < 1e-5


def test_noise_free_recovery_at_a_given_sigma0(lambda_one):
    c, width, P = lambda_one
    res = jkrcyl.fit(P=P, width=width, R=R, Delta=DELTA, materials=START, free=("w", "E"), sigma0=c.sigma0,
                     interval=None)
    assert abs(res.values["w"] / W - 1) < 1e-6 and abs(res.values["E"] / E_STAR - 1) < 1e-6
    assert res.names == ("w", "E") and res.fixed["sigma0"] == c.sigma0


def test_one_free_parameter_and_an_unresolvable_sigma0(lambda_one):
    """E alone at the given w and sigma0 (noise-free); a sigma0 too large for the solver (lambda ~ 1e6, beyond its
    1e4) is refused with a message naming sigma0, not used silently at another lambda."""
    c, width, P = lambda_one
    res = jkrcyl.fit(P=P, width=width, R=R, Delta=DELTA, materials=START, free=("E",), w=W, sigma0=c.sigma0,
                     interval=None)
    assert abs(res.values["E"] / E_STAR - 1) < 1e-6
    with pytest.raises(ValueError, match="sigma0: the cohesive solver cannot resolve"):
        jkrcyl.fit(P=P, width=width, R=R, Delta=DELTA, materials=PAIR, free=("w", "E"), sigma0=1e6 * c.sigma0)


def test_noisy_fit_truth_inside_the_intervals(lambda_one, tmp_path):
    """10 N/m noise (about 1 % of the pull-off force), seeded; profile-likelihood intervals."""
    c, width, P = lambda_one
    noisy = P + np.random.default_rng(20).normal(0.0, 10.0, P.size)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = jkrcyl.fit(P=noisy, width=width, R=R, Delta=DELTA, materials=START, free=("w", "E", "sigma0"),
                         sigma_P=10.0)
    truth = {"w": W, "E": E_STAR, "sigma0": c.sigma0}
    for name, value in truth.items():
        lo, hi = res.intervals[name]
        assert lo < value < hi, (name, value, lo, hi)
        assert lo < res.values[name] < hi
        assert abs(res.values[name] - value) < 4 * res.standard_errors[name]
    assert "lambda" in res.table()
    assert res.plot(tmp_path / "fit.png").exists()


@pytest.mark.slow
def test_noise_free_recovery_for_an_alpha_star_pair():
    """A steel pin (E 210 GPa, nu 0.3) in aluminium (70 GPa, 0.33), alpha* != 0: the collocation solver's states of
    the traced branch at lambda = 1, fitted from moduli 14 % off."""
    pair = jkrcyl.Materials.from_young(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3)
    c = jkrcyl.Contact.with_lambda(R=R, Delta=DELTA, w=W, materials=pair, lambda_=1.0)
    cv = c.curve(regime="sub-critical", n=40)
    sel = (cv.eps > 0.05) & (cv.eps < 1.0)
    start = jkrcyl.Materials.from_young(E=60e9, nu=0.33, E_I=180e9, nu_I=0.3)
    res = jkrcyl.fit(P=cv.P[sel], width=2 * R * cv.eps[sel], R=R, Delta=DELTA, materials=start,
                     free=("w", "E", "sigma0"), interval=None)
    assert abs(res.values["w"] / W - 1) < 1e-6 and abs(res.values["sigma0"] / c.sigma0 - 1) < 1e-6
    assert abs(res.values["E"] * pair.beta / 4 - 1) < 1e-6


@pytest.mark.slow
def test_jkr_limit_at_the_rate_of_the_law():
    """JKR data fitted at a fixed large sigma0 (lambda = 10, 20 at the truth): the fitted w and E* approach the
    JKR fit's like C/lambda^2 (the states' rate); C <= 10 stated from C ~ 3.7 of the load at a fixed contact."""
    jkr = jkrcyl.Contact(R=R, Delta=DELTA, w=W, materials=PAIR)
    eps = np.linspace(0.06, 1.0, 12)
    P = jkr.at_contact(eps).P + np.random.default_rng(5).normal(0.0, 10.0, eps.size)
    kw = dict(P=P, width=2 * R * eps, R=R, Delta=DELTA, materials=PAIR, free=("w", "E"), sigma_P=10.0,
              interval=None)
    ref = jkrcyl.fit(**kw)
    gaps = []
    for lam in (10.0, 20.0):
        s0 = jkrcyl.Contact.with_lambda(R=R, Delta=DELTA, w=W, materials=PAIR, lambda_=lam).sigma0
        res = jkrcyl.fit(**kw, sigma0=s0)
        gap = max(abs(res.values[k] / ref.values[k] - 1) for k in ("w", "E"))
        assert gap < 10.0 / lam ** 2
        gaps.append(gap)
    assert 2.5 < gaps[0] / gaps[1] < 6.0          # lambda^-2: 4


@pytest.mark.slow
def test_jkr_data_leave_sigma0_undetermined_with_a_one_sided_bound():
    jkr = jkrcyl.Contact(R=R, Delta=DELTA, w=W, materials=PAIR)
    eps = np.linspace(0.06, 1.0, 12)
    P = jkr.at_contact(eps).P + np.random.default_rng(2).normal(0.0, 10.0, eps.size)
    with pytest.raises(ValueError, match=r"sigma0: the data do not determine .* JKR end .* sigma0 > [0-9.e+]+ Pa"):
        jkrcyl.fit(P=P, width=2 * R * eps, R=R, Delta=DELTA, materials=PAIR, free=("w", "E", "sigma0"),
                   sigma_P=10.0)


@pytest.mark.parametrize("bad", [0.0, -1e5, math.nan, math.inf, "1e5", True])
def test_bad_sigma0_names_the_parameter(lambda_one, bad):
    _, width, P = lambda_one
    with pytest.raises(ValueError, match="sigma0"):
        jkrcyl.fit(P=P, width=width, R=R, Delta=DELTA, materials=PAIR, free=("w", "E"), sigma0=bad)


def test_cohesive_law_with_approach_data_is_refused():
    with pytest.raises(ValueError, match="sigma0: .*width only"):
        jkrcyl.fit(P=[-100.0, 0.0, 100.0, 200.0], delta_work=[-1e-7, 0.0, 1e-7, 2e-7], R=R, Delta=DELTA,
                   materials=PAIR, free=("w", "sigma0"))


def test_window_edges_are_the_stated_lambdas():
    lo, hi = fit_cohesive.window(R, DELTA, W, PAIR)
    for s0, lam in ((lo, fit_cohesive.LAMBDA_MIN), (hi, fit_cohesive.LAMBDA_MAX)):
        assert abs(jkrcyl.Contact(R=R, Delta=DELTA, w=W, materials=PAIR, sigma0=s0).lambda_ / lam - 1) < 1e-12


def _cli(*args):
    return run("fit", *args)            # jkrcyl.cli.main in this process (tests/cli_run.py)


def test_cli_sigma0(lambda_one, tmp_path):
    c, width, P = lambda_one
    path = tmp_path / "md.csv"
    rows = "\n".join(f"{float(p)!r},{float(x)!r}" for p, x in zip(P, width))
    path.write_text(f"# R={R} Delta={DELTA} E=2.6e9 nu=0.3 E_I=2.6e9 nu_I=0.3\nP [N/m],width [m]\n{rows}\n")
    out = _cli(str(path), "--free", "w,E", "--sigma0", repr(c.sigma0), "--interval", "none", "--format", "csv")
    assert out.returncode == 0, out.stderr
    values = {line.split(",")[0]: float(line.split(",")[1]) for line in out.stdout.splitlines()[2:]}
    assert abs(values["w"] / W - 1) < 1e-6 and abs(values["E"] / E_STAR - 1) < 1e-6
    for bad in ("-1", "nan", "0"):
        out = _cli(str(path), "--free", "w,E", "--sigma0", bad)
        assert out.returncode == 2 and len(out.stderr.strip().splitlines()) == 1 and "sigma0" in out.stderr


@pytest.mark.slow
def test_readme_cohesive_fit_as_stated():
    """The user guide's fitting page (docs/guide/fitting.md), the cohesive example: its block run as the page runs it
    (jkrcyl, np and the starting pair m0 of the earlier block), the numbers in its comments are what the fit
    returns (to the digits stated: the text cannot go stale), and the truth (w = 0.05, the contact's sigma0) lies
    inside the intervals."""
    import pathlib
    import re
    section = (pathlib.Path(__file__).resolve().parents[1] / "docs" / "guide" / "fitting.md").read_text()
    block = next(b for b in re.findall(r"```python\n(.*?)```", section, re.S) if "res_md" in b)
    ns = {"jkrcyl": jkrcyl, "np": np, "m0": PAIR}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        exec(compile(block, "guide cohesive fit", "exec"), ns)
    res, pin = ns["res_md"], ns["md_pin"]
    assert "sigma0 = 77.87 kPa" in block and pin.sigma0 == pytest.approx(77.87e3, abs=5)
    s0, s_lo, s_hi = map(float, re.search(r"# (\d+) Pa, \((\d+), (\d+)\) Pa at 95 %", block).groups())
    assert res.values["sigma0"] == pytest.approx(s0, abs=0.5)
    assert res.intervals["sigma0"] == pytest.approx((s_lo, s_hi), abs=0.5)
    w, w_lo, w_hi = map(float, re.search(r"# ([\d.]+) J/m\^2, \(([\d.]+), ([\d.]+)\)", block).groups())
    assert res.values["w"] == pytest.approx(w, abs=0.5e-5)
    assert res.intervals["w"] == pytest.approx((w_lo, w_hi), abs=0.5e-5)
    lam, corr = map(float, re.search(r"# ([\d.]+); correlation of w and sigma0 ([-\d.]+)", block).groups())
    assert res.contact().lambda_ == pytest.approx(lam, abs=5e-4)
    assert res.correlation[0, 2] == pytest.approx(corr, abs=5e-3)
    assert res.intervals["w"][0] < 0.05 < res.intervals["w"][1]
    assert res.intervals["sigma0"][0] < pin.sigma0 < res.intervals["sigma0"][1]
