"""Crack kinetics on the command line (``jkrcyl pull-off --v-star --n --rate``, ``jkrcyl rate-sweep``) and in the
figures (jkrcyl.plotting.rate): the numbers printed are the library's, bad input is one line naming the parameter
with exit status 2, and every figure is written."""
import csv
import io
import json
import os
import subprocess
import sys

import numpy as np
import pytest

import jkrcyl
from jkrcyl.cli import main
from jkrcyl.plotting import rate as rate_plots

PHYS = ["--E", "2.6e9", "--nu", "0.3", "--E-I", "2.6e9", "--nu-I", "0.3", "--R", "0.01", "--Delta", "1e-6",
        "--w", "0.05"]
KIN = ["--v-star", "1e-3", "--n", "0.6"]


def contact():
    m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    return jkrcyl.Contact(R=0.01, Delta=1e-6, w=0.05, materials=m, kinetics=jkrcyl.CrackKinetics(1e-3, 0.6))


def test_pull_off_at_a_rate_is_the_library(capsys):
    assert main(["pull-off", *PHYS, *KIN, "--rate", "1e-6", "--control", "grip-work", "--format", "json"]) == 0
    row = json.loads(capsys.readouterr().out)["rows"][0]
    po = contact().pull_off("grip-work", rate=1e-6)
    assert row["event"] == po.kind and row["P"] == pytest.approx(po.P, rel=1e-9)
    assert row["delta_work"] == pytest.approx(po.delta_work, rel=1e-9)
    assert main(["pull-off", *PHYS, *KIN, "--rate", "100"]) == 0
    assert "load      at 100 N/m/s: pull-off P = " in capsys.readouterr().out


def test_rate_sweep_table_and_figure(capsys, tmp_path):
    fig = tmp_path / "sweep.png"
    assert main(["rate-sweep", *PHYS, *KIN, "--rate-min", "10", "--rate-max", "1000", "--count", "3",
                 "--figure", str(fig)]) == 0
    text = capsys.readouterr().out
    meta, body = text.split("\n", 1)
    assert "P_quasi_static=-1555.09" in meta and "exponent=0.2307692308" in meta
    rows = list(csv.DictReader(io.StringIO(body)))
    sw = jkrcyl.kinetics.rate_sweep(contact(), [10.0, 100.0, 1000.0])
    assert [float(r["P [N/m]"]) for r in rows] == pytest.approx(list(sw.P), rel=1e-9)
    assert fig.stat().st_size > 10_000


@pytest.mark.parametrize("args, name", [
    (["pull-off", *PHYS, "--v-star", "1e-3", "--rate", "1"], "n"),
    (["pull-off", *PHYS, "--n", "0.5", "--rate", "1"], "v_star"),
    (["pull-off", *PHYS, "--v-star", "-1", "--n", "0.5", "--rate", "1"], "v_star"),
    (["pull-off", *PHYS, *KIN[:2], "--n", "2.5", "--rate", "1"], "n"),
    (["pull-off", *PHYS, *KIN, "--rate", "0"], "rate"),
    (["pull-off", *PHYS, *KIN, "--rate", "nan"], "rate"),
    (["pull-off", *PHYS, "--rate", "1"], "rate"),
    (["pull-off", *PHYS, "--control", "grip"], "control"),
    (["rate-sweep", *PHYS, "--rate-min", "1", "--rate-max", "10"], "v_star"),
    (["rate-sweep", *PHYS, *KIN, "--rate-min", "10", "--rate-max", "1"], "rate_min"),
])
def test_bad_input_one_line_exit_2(args, name, capsys):
    assert main(args) == 2
    lines = capsys.readouterr().err.strip().splitlines()
    assert len(lines) == 1 and name in lines[0], lines


def test_bad_input_in_a_subprocess():
    env = dict(os.environ, MPLBACKEND="Agg")
    r = subprocess.run([sys.executable, "-m", "jkrcyl.cli", "pull-off", *PHYS, *KIN, "--rate", "-5"],
                       capture_output=True, text=True, timeout=120, env=env)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1 and "rate" in r.stderr
    assert "Traceback" not in r.stderr


def test_figures_are_written(tmp_path):
    c = contact()
    po = c.pull_off().P
    cycles = [c.cycle(P_max=-po, P_min=0.5 * po, rate=r) for r in (30.0, 300.0)]
    for name, fig in (("loops", rate_plots.loops_figure(cycles, c)),
                      ("width", rate_plots.width_figure(c.pull_off(rate=100.0), c))):
        path = rate_plots.save(fig, tmp_path / f"{name}.png")
        assert path.stat().st_size > 10_000
    assert np.isfinite(cycles[0].dissipated)
