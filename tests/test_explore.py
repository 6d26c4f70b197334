"""The explorer (jkrcyl explore): what it computes and prints, how it treats bad input, and the real thing in a
browser.

* Without a browser: every bad field gives the library's own ValueError, attributed to that field; the explorer's
  document keeps its last good picture on bad input; the branches it draws agree with states solved independently
  by Contact.solve at the drawn load; the CLI refuses a bad port in one line (exit status 2).
* In a browser (headless Debian chromium driven by playwright; skipped, with the reason, where either is missing):
  the served page redraws after w and a modulus change, prints the pull-off forces of Contact.pull_off for those
  inputs to 4 significant digits, shows the library's message beside a bad field and keeps the last good picture;
  a screenshot is kept in tests/artefacts/ (ignored by git).
"""
import math
import os
import pathlib
import re
import shutil
import subprocess
import sys
import time

import numpy as np
import pytest

import jkrcyl
from jkrcyl.explore import Inputs, compute, field_of

ROOT = pathlib.Path(__file__).resolve().parents[1]
ARTEFACTS = ROOT / "tests" / "artefacts"
CHROMIUM = os.environ.get("JKRCYL_CHROMIUM", "/usr/bin/chromium")
BROWSER_FLAGS = ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync"]
SERVER_START = 180.0     # s: the server warms the kernels before it prints its URL (numba's cache may be cold)
REDRAW = 120.0           # s: the first alpha* != 0 picture compiles the collocation kernels
# what the page plots: every column of every data source, as BokehJS holds it in the browser
DRAWN = """() => Object.fromEntries(["stable", "unstable", "infeasible", "cycle", "jumps", "points", "pressure", "gap"]
    .map(k => [k, JSON.stringify(Bokeh.documents[0].get_model_by_name(k).data)]))"""


def _pin(kinetics=None, **changes):
    kw = dict(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3, R=0.01, Delta=1e-6, w=0.05)
    kw.update(changes)
    m = jkrcyl.Materials.from_young(kw["E"], kw["nu"], kw["E_I"], kw["nu_I"])
    return jkrcyl.Contact(R=kw["R"], Delta=kw["Delta"], w=kw["w"], materials=m, kinetics=kinetics)


def _library_message(f):
    with pytest.raises(ValueError) as info:
        f()
    return str(info.value)


# --- bad input: the library's message, beside its field --------------------------------------------------------
BAD = [("E", "abc", lambda: jkrcyl.Materials.from_young("abc", 0.3, 2.6e9, 0.3)),
       ("E", "-1", lambda: jkrcyl.Materials.from_young(-1.0, 0.3, 2.6e9, 0.3)),
       ("nu", "0.7", lambda: jkrcyl.Materials.from_young(2.6e9, 0.7, 2.6e9, 0.3)),
       ("E_I", "nan", lambda: jkrcyl.Materials.from_young(2.6e9, 0.3, math.nan, 0.3)),
       ("nu_I", "-1", lambda: jkrcyl.Materials.from_young(2.6e9, 0.3, 2.6e9, -1.0)),
       ("R", "0", lambda: _pin(R=0.0)),
       ("Delta", "0.02", lambda: _pin(Delta=0.02)),
       ("w", "-0.1", lambda: _pin(w=-0.1)),
       ("cycle_max", "x", lambda: _pin().cycle(P_max="x", P_min=-1.0)),
       ("state_P", "1e300", lambda: _pin().solve(P=1e300))]


@pytest.mark.parametrize("name, text, library", BAD, ids=lambda x: str(x)[:12])
def test_bad_field_gives_the_library_message_for_that_field(name, text, library):
    with pytest.raises(ValueError) as info:
        compute(Inputs(**{name: text}))
    assert str(info.value) == _library_message(library)
    assert field_of(str(info.value)) == name


@pytest.mark.parametrize("law, value, message", [("sigma0", "-5", "sigma0 must be in (0, inf]"),
                                                 ("lambda", "zero", "lambda must be a real number"),
                                                 ("kinetic", "-1e-6", "v_star must be in (0, inf]")])
def test_bad_law_value_is_attributed_to_the_law_field(law, value, message):
    with pytest.raises(ValueError, match=re.escape(message)) as info:
        compute(Inputs(law=law, law_value=value))
    assert field_of(str(info.value)) == "law_value"


@pytest.mark.parametrize("changes, name, library", [
    (dict(law="kinetic", law_value="1e-6", kinetic_n="3"), "kinetic_n",
     lambda: jkrcyl.CrackKinetics(v_star=1e-6, n=3.0)),
    (dict(law="kinetic", law_value="1e-6", rate="-5"), "rate",
     lambda: _pin(kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6)).pull_off(rate=-5.0)),
    (dict(rate="1"), "rate", lambda: _pin().pull_off(rate=1.0))])
def test_bad_kinetic_input_is_attributed_to_its_field(changes, name, library):
    with pytest.raises(ValueError) as info:
        compute(Inputs(**changes))
    assert str(info.value) == _library_message(library) and field_of(str(info.value)) == name


def test_printed_rate_pull_off_is_the_library_value():
    """Crack kinetics: the pull-off at the rate, under the chosen control, is Contact.pull_off(control, rate=...)
    for those inputs; it is drawn as a point at the largest tension of the ramp."""
    from jkrcyl.explore.view import picture_data, summary_html
    picture = compute(Inputs(law="kinetic", law_value="1e-6", kinetic_n="0.6", rate="1e-11", control="grip-work"))
    ref = _pin(kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6)).pull_off("grip-work", rate=1e-11)
    shown = float(re.search(r"jkr-pull-off-rate'>([-\d.e+]+) N/m", summary_html(picture)).group(1))
    assert ref.kind == "separation" and shown == pytest.approx(ref.P, rel=5e-6)
    points = picture_data(picture)["points"]
    assert points["y"][points["label"].index("pull-off at the rate")] == pytest.approx(ref.P, rel=1e-12)


def test_field_of_names_general_for_an_unknown_parameter():
    assert field_of("pull_off is undefined for Delta = 0 (neat fit)") == "general"
    assert field_of("") == "general"


# --- what is drawn and printed ----------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def picture():
    return compute(Inputs())


def test_printed_pull_offs_are_the_library_values(picture):
    from jkrcyl.explore.view import summary_html
    text = summary_html(picture)
    c = _pin()
    for control in ("load", "grip-work", "grip"):
        shown = float(re.search(rf"jkr-pull-off-{control}'>([-\d.e+]+) N/m", text).group(1))
        assert shown == pytest.approx(c.pull_off(control).P, rel=5e-6)


def test_drawn_stable_branch_holds_states_solved_at_the_drawn_load(picture):
    """Two routes: the drawn branch (the dense table the walker uses) and Contact.solve at a load read off it
    must give the same approach."""
    from jkrcyl.explore.view import LENGTHS, picture_data, scale_of
    data = picture_data(picture)
    scale = scale_of(picture.contact.Delta, LENGTHS)[0]
    c = _pin()
    checked = 0
    for xs, ys in zip(data["stable"]["xs"], data["stable"]["ys"]):
        for i in np.linspace(1, len(xs) - 2, 3).astype(int):
            states = c.solve(P=ys[i], branches=["sub-critical", "super-critical"])
            assert min(abs(s.delta_work / scale - xs[i]) for s in states) < 1e-6 * max(1.0, abs(xs[i]))
            checked += 1
    assert checked >= 3


def test_runs_split_a_mask_into_touching_segments():
    from jkrcyl.explore.view import runs
    mask = np.array([True, True, False, False, True, False, True, True])
    assert runs(mask) == [slice(0, 3), slice(3, 6), slice(5, 8)]
    assert runs(np.zeros(4, bool)) == []


def html_text(markup):
    """The text a Div shows."""
    import html
    return html.unescape(re.sub(r"<[^>]+>", "", markup))


def _columns(ex):
    """Every plotted column of the document, as plain lists."""
    def plain(v):
        return [plain(x) for x in v] if isinstance(v, list) else np.asarray(v).tolist()
    return {k: {c: plain(v) for c, v in s.data.items()} for k, s in ex.sources.items()}


def test_document_keeps_the_last_good_picture_on_bad_input():
    pytest.importorskip("bokeh", reason="the explore extra (bokeh) is not installed")
    from jkrcyl.explore.app import Explorer
    ex = Explorer()
    before = _columns(ex)
    ex.widgets["E"].value = "-1"
    expected = _library_message(lambda: jkrcyl.Materials.from_young(-1.0, 0.3, 2.6e9, 0.3))
    assert html_text(ex.errors["E"].text) == expected
    assert ex.redraws == 1 and "not redrawn" in ex.status.text
    assert _columns(ex) == before
    ex.widgets["E"].value = "2.6e9"
    ex.widgets["w"].value = "0.06"
    assert ex.redraws == 3 and ex.errors["E"].text == ""
    assert float(re.search(r"jkr-pull-off-load'>([-\d.e+]+)", ex.summary.text).group(1)) == pytest.approx(
        _pin(w=0.06).pull_off("load").P, rel=5e-6)


# --- the command line -------------------------------------------------------------------------------------------
@pytest.mark.parametrize("port", ["70000", "abc", "1.5", "-1"])
def test_cli_refuses_a_bad_port(port, capsys):
    """One line naming the port, exit status 2, before anything is served (the CLI's own path, in this process)."""
    from jkrcyl.cli import main
    try:
        code = main(["explore", "--port", port])
    except SystemExit as exc:             # argparse: not a number
        code = exc.code
    err = capsys.readouterr().err
    assert code == 2 and "Traceback" not in err and len(err.strip().splitlines()) == 1 and "port" in err


def test_cli_explore_help_runs():
    from cli_run import run                    # jkrcyl.cli.main in this process
    r = run("explore", "--help")
    assert r.returncode == 0 and "--port" in r.stdout


# --- the browser ------------------------------------------------------------------------------------------------
def _browser_or_skip():
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        pytest.skip("playwright is not installed (pip install -e '.[explore,test]')")
    if not (os.path.exists(CHROMIUM) or shutil.which("chromium")):
        pytest.skip(f"no Chromium at {CHROMIUM} (apt-get install chromium; .ci/run installs it)")
    pytest.importorskip("bokeh", reason="the explore extra (bokeh) is not installed")
    return sync_playwright


@pytest.fixture(scope="module")
def served():
    """The explorer served by the CLI on an open port of 127.0.0.1; its URL."""
    proc = subprocess.Popen([sys.executable, "-m", "jkrcyl", "explore"], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, cwd=ROOT)
    try:
        deadline = time.monotonic() + SERVER_START
        line = ""
        while time.monotonic() < deadline and "http://" not in line:
            line = proc.stdout.readline()
            if not line and proc.poll() is not None:
                pytest.fail(f"jkrcyl explore exited: {proc.stderr.read()[-2000:]}")
        url = re.search(r"http://127\.0\.0\.1:\d+/", line)
        assert url, f"no URL printed: {line!r}"
        yield url.group(0)
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()


def _set(page, name, value):
    field = page.locator(f".jkr-{name} input")
    field.fill(value)
    field.press("Enter")


def _redraws(page):
    return int(page.locator(".jkr-redraws").inner_text())


def _wait_redraw(page, count):
    from playwright.sync_api import expect
    expect(page.locator(".jkr-redraws")).to_have_text(str(count), timeout=REDRAW * 1000)


def test_browser_redraws_prints_the_pull_off_and_shows_bad_input(served):
    sync_playwright = _browser_or_skip()
    from playwright.sync_api import expect
    ARTEFACTS.mkdir(exist_ok=True)
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=BROWSER_FLAGS, headless=True)
        try:
            page = browser.new_page(viewport={"width": 1400, "height": 1100})
            page.goto(served)
            _wait_redraw(page, 1)
            _set(page, "w", "0.07")
            _wait_redraw(page, 2)
            _set(page, "E", "3e9")                          # alpha* != 0: the collocation solver
            _wait_redraw(page, 3)
            c = _pin(w=0.07, E=3e9)
            for control in ("load", "grip-work", "grip"):
                ref = c.pull_off(control).P
                shown = float(page.locator(f".jkr-pull-off-{control}").inner_text().split()[0])
                assert f"{shown:.4g}" == f"{ref:.4g}" and shown == pytest.approx(ref, rel=5e-5), control
            page.screenshot(path=str(ARTEFACTS / "explore.png"), full_page=True)
            drawn = page.evaluate(DRAWN)
            assert "pull-off (load)" in drawn["points"] and len(drawn["stable"]) > 1000
            printed = page.locator(".jkr-pull-off-load").inner_text()

            _set(page, "nu", "0.7")                         # bad input: the library's message beside the field
            expected = _library_message(lambda: jkrcyl.Materials.from_young(3e9, 0.7, 2.6e9, 0.3))
            expect(page.locator(".jkr-error-nu .jkr-message")).to_have_text(expected, timeout=REDRAW * 1000)
            expect(page.locator(".jkr-not-redrawn")).to_be_visible()
            page.screenshot(path=str(ARTEFACTS / "explore_bad_input.png"), full_page=True)
            assert page.locator(".jkr-pull-off-load").inner_text() == printed
            assert page.evaluate(DRAWN) == drawn           # the last good picture: every plotted column as it was
            assert "Traceback" not in page.content()
        finally:
            browser.close()


def test_browser_prints_the_rate_pull_off_of_the_kinetic_law(served):
    """The kinetic law chosen in the page, v* and a rate typed, the control switched to grip-work: the printed
    pull-off at the rate is Contact(..., kinetics=...).pull_off("grip-work", rate=...) to 4 significant digits,
    beside the quasi-static ones."""
    sync_playwright = _browser_or_skip()
    ARTEFACTS.mkdir(exist_ok=True)
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=BROWSER_FLAGS, headless=True)
        try:
            page = browser.new_page(viewport={"width": 1400, "height": 1100})
            page.goto(served)
            _wait_redraw(page, 1)
            from jkrcyl.explore.model import LAWS
            page.locator(".jkr-law select").select_option(label=LAWS["kinetic"][0])   # v* still empty: no redraw
            _set(page, "law_value", "1e-6")
            _wait_redraw(page, 2)
            page.locator(".jkr-control select").select_option("grip-work")
            _wait_redraw(page, 3)
            _set(page, "rate", "1e-11")
            _wait_redraw(page, 4)
            c = _pin(kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6))
            ref = c.pull_off("grip-work", rate=1e-11).P
            shown = float(page.locator(".jkr-pull-off-rate").inner_text().split()[0])
            assert f"{shown:.4g}" == f"{ref:.4g}" and shown == pytest.approx(ref, rel=5e-5)
            quasi_static = float(page.locator(".jkr-pull-off-grip-work").inner_text().split()[0])
            assert quasi_static == pytest.approx(c.pull_off("grip-work").P, rel=5e-5) and shown < quasi_static
            page.screenshot(path=str(ARTEFACTS / "explore_kinetic.png"), full_page=True)
        finally:
            browser.close()


# --- the benchmark ----------------------------------------------------------------------------------------------
def test_bench_explore_smoke():
    """benchmarks/bench_explore.py in smoke mode (one change, the README pin only, no browser) so that it cannot rot;
    times are not checked.  The script runs as __main__ in this process (tests/cli_run.run_script)."""
    from cli_run import run_script
    out = run_script(ROOT / "benchmarks" / "bench_explore.py", "--repeats", "1", "--no-browser", "--quick")
    for row in ("alpha* = 0 (README pin)", "compute", "document", "goals:"):
        assert row in out, f"missing {row!r} in\n{out}"
