"""`make bench` in smoke mode (tiny n, one repeat) so that the benchmark cannot rot; times are not checked."""
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.slow         # a whole benchmark script in a subprocess: make test-slow


def test_bench_state_smoke():
    run = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_state.py"), "--n", "1000", "--repeats", "1"],
                         cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout + run.stderr
    out = run.stdout
    for row in ("floor", "generated kernels, serial", "prange", "lambdify", "numpy-vectorised", "mpmath",
                "h(pi) alone", "fresh process", "goals:"):
        assert row in out, f"missing {row!r} in\n{out}"
    # every contender agrees with the kernels (a broken contender would make the timing meaningless)
    errors = [float(line.rsplit("=", 1)[1]) for line in out.splitlines() if line.startswith("max |")]
    assert errors and max(errors) < 1e-10, out


def test_bench_solver_smoke():
    run = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_solver.py"), "--curve", "300",
                          "--states", "3"], cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stdout + run.stderr
    for row in ("time per state", "ratio", "point curve", "error vs nodes", "goals:"):
        assert row in run.stdout, f"missing {row!r} in\n{run.stdout}"
