"""benchmarks/bench_cohesive_two.py run once so that the benchmark cannot rot; times are not checked."""
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.slow         # a whole benchmark script in a subprocess: make test-slow


def test_bench_cohesive_two_smoke():
    run = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_cohesive_two.py"), "--runs", "1", "--quick"],
                         cwd=ROOT, capture_output=True, text=True, timeout=900)
    assert run.returncode == 0, run.stdout + run.stderr
    for row in ("lambda    20: one state", "stable under grip: False", "lambda    10: two_patch (whole branch)",
                "M 0.2, lambda    5: the law's own route"):
        assert row in run.stdout, f"missing {row!r} in\n{run.stdout}"
