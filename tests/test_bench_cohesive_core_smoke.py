"""benchmarks/bench_cohesive_core.py in smoke mode (two repeats, no map, lambda 1, 3, 10, 1000) so that the benchmark
cannot rot; times are not checked."""
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.slow         # a whole benchmark script in a subprocess: make test-slow


def test_bench_cohesive_core_smoke():
    run = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_cohesive_core.py"), "--repeats", "2",
                          "--map", "0", "--quick"], cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout + run.stderr
    for row in ("one state", "one table point", "public API, cold", "stand-alone continuation", "cycle", "goals:"):
        assert row in run.stdout, f"missing {row!r} in\n{run.stdout}"
