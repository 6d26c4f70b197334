"""The cohesive law on the command line (issue 19, phase 2): --sigma0 [Pa] or --lambda in the one parser, for every
command that takes a problem; the answers are the library's (Contact.with_lambda / Contact(sigma0=...)); bad
input prints one line and exits 2; `jkrcyl cohesive` draws the figures and the map (small smoke run)."""
import json
import pytest
from cli_run import run as run_cli

import jkrcyl

PHYS = ["--E", "2.6e9", "--nu", "0.3", "--E-I", "2.6e9", "--nu-I", "0.3", "--R", "0.01", "--Delta", "1e-6",
        "--w", "0.05"]
PAIR = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)


def cli(*args):
    """``python -m jkrcyl *args`` run in this process (tests/cli_run.py: the same exit status, stdout, stderr)."""
    return run_cli(*args)


def test_pull_off_with_lambda_and_sigma0():
    run = cli("pull-off", *PHYS, "--lambda", "3", "--format", "json")
    assert run.returncode == 0, run.stderr
    rows = {r["control"]: r for r in json.loads(run.stdout)["rows"]}
    c = jkrcyl.Contact.with_lambda(0.01, 1e-6, 0.05, PAIR, 3.0)
    assert rows["load"]["P"] == pytest.approx(c.pull_off("load").P, rel=1e-9)
    run = cli("pull-off", *PHYS, "--sigma0", repr(c.sigma0), "--format", "json")
    assert json.loads(run.stdout)["rows"][0]["P"] == pytest.approx(rows["load"]["P"], rel=1e-9)


def test_solve_cycle_curve_adherence_take_the_law():
    assert "Dugdale" in cli("solve", *PHYS, "--lambda", "3", "--P", "-1000").stdout.splitlines()[0]
    cyc = cli("cycle", *PHYS, "--lambda", "3", "--P-max", "2000", "--P-min", "-2000")
    assert cyc.returncode == 0 and "pull-off" in cyc.stdout
    cur = cli("curve", "--M", "0.3", "--lambda", "3", "--n", "5")
    assert cur.returncode == 0 and "edge=Dugdale" in cur.stdout and ",c,c_top" in cur.stdout
    adh = cli("adherence", "--M", "0.3", "--lambda", "3")
    assert adh.returncode == 0 and "Dugdale" in adh.stdout


@pytest.mark.parametrize("args, name", [
    (["pull-off", *PHYS, "--sigma0", "-1"], "sigma0"), (["pull-off", *PHYS, "--sigma0", "nan"], "sigma0"),
    (["pull-off", *PHYS, "--lambda", "0"], "lambda"), (["pull-off", *PHYS, "--lambda", "1", "--sigma0", "1e5"],
                                                       "sigma0"),
    (["curve", "--M", "0.3", "--sigma0", "1e5"], "sigma0"), (["curve", "--M", "0", "--lambda", "1"], "lambda"),
    (["two-patch", "--M", "0.3", "--lambda", "2000"], "sigma0"),     # (lambda 1: no two-patch state, physical)
    (["pull-off", "--E", "2.6e9", "--nu", "0.3", "--E-I", "2.6e9", "--nu-I", "0.3", "--R", "0.01", "--Delta",
      "1e-6", "--w", "0", "--lambda", "1"], "lambda")])
def test_bad_input_one_line_exit_2(args, name):
    run = cli(*args)
    assert run.returncode == 2 and run.stdout == ""
    assert len(run.stderr.strip().splitlines()) == 1 and f"error: {name}" in run.stderr, run.stderr


def test_cohesive_command_smoke(tmp_path):
    run = cli("cohesive", "--out", str(tmp_path), "--n", "4", "--workers", "1", "--map-only")
    assert run.returncode == 0, run.stderr
    assert (tmp_path / "cohesive_map.png").stat().st_size > 0
    lines = (tmp_path / "cohesive_map.csv").read_text().splitlines()
    assert len(lines) == 1 + 16 and lines[0] == "lambda,M,P_star,P_star_jkr,outcome"
