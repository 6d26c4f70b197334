"""Issue 5: the `jkrcyl` command line, end to end: jkrcyl.cli.main in this process (tests/cli_run.py; the
entry points in a subprocess: `python -m jkrcyl` in tests/test_bad_input.py, `python -m jkrcyl.cli` in
tests/test_atlas.py and tests/test_kinetic_cli.py)."""
import csv
import json

import pytest
from cli_run import run


@pytest.mark.parametrize("sub", [[], ["figures"], ["curve"], ["adherence"]])
def test_help_everywhere(sub):
    r = run(*sub, "--help")
    assert r.returncode == 0 and "usage: jkrcyl" in r.stdout


def test_figures_written_with_csv(tmp_path):
    r = run("figures", "--out", str(tmp_path), "--n", "24", "--only", "fig02,fig04,fig10")
    assert r.returncode == 0, r.stderr
    assert "3/3" in r.stderr                      # progress bar
    for name in ("fig02", "fig04", "fig10"):
        for ext in ("png", "pdf", "csv"):
            assert (tmp_path / f"{name}.{ext}").stat().st_size > 0
        with open(tmp_path / f"{name}.csv") as fh:
            rows = list(csv.reader(fh))
        assert rows[0] == ["panel", "series", "x_name", "x", "y_name", "y", "feasible"]
        assert len(rows) > 10 and all(len(row) == 7 for row in rows)
        float(rows[1][3]), float(rows[1][5])
    assert not (tmp_path / "fig03.png").exists()


def test_curve_csv_and_json(tmp_path):
    r = run("curve", "--M", "0.3", "--theta", "1", "--n", "5")
    assert r.returncode == 0, r.stderr
    lines = r.stdout.strip().splitlines()
    assert lines[0].startswith("#")
    header = lines[1].split(",")
    assert header == ["a", "eps", "eps_star", "P_star", "delta_over_Delta", "delta_work_over_Delta",
                      "h_pi_over_Delta", "feasible", "stable_load", "stable_grip", "stable_grip_work"]
    assert len(lines) == 7 and all(len(ln.split(",")) == len(header) for ln in lines[2:])
    out = tmp_path / "c.json"
    r = run("curve", "--M", "0.5", "--regime", "super-critical", "--n", "4", "--format", "json", "-o", str(out))
    assert r.returncode == 0, r.stderr
    data = json.loads(out.read_text())
    assert data["regime"] == "super-critical" and len(data["P_star"]) == 4
    r = run("curve", "--E", "1e6", "--nu", "0.5", "--E-I", "inf", "--nu-I", "0.3", "--R", "0.01",
            "--Delta", "1e-5", "--w", "0.05", "--n", "3")
    assert r.returncode == 0, r.stderr


def test_adherence_text_and_json():
    r = run("adherence", "--M", "0.3")
    assert r.returncode == 0 and "fixed-load adherence" in r.stdout and "a0 = " in r.stdout
    r = run("adherence", "--M", "0.8", "--format", "json")
    data = json.loads(r.stdout)
    assert data["zero_load_a0"] == [] and [p["regime"] for p in data["load"]] == ["super-critical"]


@pytest.mark.parametrize("args, name", [
    (["curve", "--M", "-1"], "M"),
    (["curve", "--M", "0.3", "--theta", "0.2"], "theta"),
    (["curve", "--M", "x"], "--M"),
    (["curve", "--M", "0.3", "--n", "1"], "n"),
    (["curve", "--M", "0.3", "--theta", "inf", "--regime", "super-critical"], "regime"),
    (["curve"], "M"),
    (["curve", "--E", "1e6", "--nu", "0.3"], "--E-I"),
    (["adherence", "--M", "0.3", "--gb", "-2"], "gb"),
    (["figures", "--only", "fig99"], "only"),
    (["bogus"], "command"),
])
def test_bad_input_one_line_exit_2(args, name):
    r = run(*args)
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and name in lines[0], r.stderr


# --- gb: the CLI prints the gb it used (issue 18 item 7) -------------------------------------------------------
@pytest.mark.parametrize("theta, want", [("1", 0.5), ("2", 0.75), ("0.5", 0.0), ("inf", 1.0)])
def test_default_gb_is_printed(theta, want):
    """Without --gb the normalised commands use an incompressible pin, gb = (1/G_I)/beta* = 1 - 1/(2 vartheta)
    (kappa_I = 1 in beta* = (kappa + 1)/(2G) + (kappa_I + 1)/(2G_I) and vartheta = G beta*/(1 + kappa)), and
    say so in the first line (CSV) and in 'gb', 'gb_source' (JSON)."""
    r = run("curve", "--M", "0.3", "--theta", theta, "--n", "3")
    assert r.returncode == 0, r.stderr
    first = r.stdout.splitlines()[0]
    assert f"gb={want:.10g} (default: incompressible pin" in first, first
    data = json.loads(run("curve", "--M", "0.3", "--theta", theta, "--n", "3", "--format", "json").stdout)
    assert data["gb"] == pytest.approx(want, abs=1e-15) and data["gb_source"].startswith("default")


def test_given_gb_is_used_and_printed():
    """--gb reaches the computation: delta/Delta differs from the default's, P* does not (gb enters the approach
    only), and the first line says the gb came from --gb."""
    default = run("curve", "--M", "0.3", "--n", "4", "--format", "json")
    given = run("curve", "--M", "0.3", "--n", "4", "--gb", "0.25", "--format", "json")
    d0, d1 = json.loads(default.stdout), json.loads(given.stdout)
    assert d1["gb"] == 0.25 and d1["gb_source"] == "--gb"
    assert d0["P_star"] == d1["P_star"] and d0["a"] == d1["a"]
    assert all(abs(x - y) > 1e-6 for x, y in zip(d0["delta_over_Delta"], d1["delta_over_Delta"]))
    r = run("curve", "--M", "0.3", "--n", "2", "--gb", "0.25")
    assert "gb=0.25 (--gb)" in r.stdout.splitlines()[0]


def test_gb_printed_by_adherence_two_patch_and_physical_inputs():
    r = run("adherence", "--M", "0.3", "--no-confined")
    assert r.returncode == 0 and "gb = 0.5 (default: incompressible pin" in r.stdout.splitlines()[0]
    r = run("two-patch", "--M", "0.5", "--n", "4", "--gb", "0.3")
    assert r.returncode == 0 and "gb=0.3 (--gb)" in r.stdout.splitlines()[0]
    # physical inputs: the pair's gb = (1/G_I)/beta*, from the moduli (plane strain, identical nu = 0.3 bodies:
    # beta* = 2 (kappa + 1)/(2G), so gb = 1/(kappa + 1) = 1/2.8)
    r = run("curve", "--E", "2.6e9", "--nu", "0.3", "--E-I", "2.6e9", "--nu-I", "0.3", "--R", "0.01",
            "--Delta", "1e-5", "--w", "0.05", "--n", "2")
    assert r.returncode == 0 and f"gb={1 / 2.8:.10g} (physical inputs" in r.stdout.splitlines()[0]


def test_help_documents_the_gb_default():
    r = run("curve", "--help")
    assert "Default: an incompressible pin, 1 - 1/(2 vartheta)" in " ".join(r.stdout.split())

