"""benchmarks/bench_cohesive_super.py in smoke mode (one run, lambda = 10) so that the benchmark cannot rot; times
are not checked."""
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.slow         # a whole benchmark script in a subprocess: make test-slow


def test_bench_cohesive_super_smoke():
    run = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_cohesive_super.py"), "--quick"],
                         cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout + run.stderr
    for row in ("cold super-critical curve", "lambda     10: curve", "JKR limit on 2.0 <= eps <= 2.7", "goals:"):
        assert row in run.stdout, f"missing {row!r} in\n{run.stdout}"
