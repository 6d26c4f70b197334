"""benchmarks/bench_cohesive.py in smoke mode (two repeats, a few cases) so that the benchmark cannot rot; times
are not checked."""
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.slow         # a whole benchmark script in a subprocess: make test-slow


def test_bench_cohesive_smoke():
    run = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_cohesive.py"), "--repeats", "2", "--quick"],
                         cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout + run.stderr
    for row in ("time per state", "error against the number of nodes", "JKR limit", "half-plane limit",
                "contactless_state", "load-control pull-off", "goals:"):
        assert row in run.stdout, f"missing {row!r} in\n{run.stdout}"
