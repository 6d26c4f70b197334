"""benchmarks/bench_calls.py in smoke mode (one cheap call, one fresh process) so that it cannot rot; times are
not checked (speed is measured, never asserted)."""
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.slow         # a whole benchmark script in a subprocess: make test-slow


def test_bench_calls_smoke():
    run = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_calls.py"), "--pairs", "pin", "--calls",
                          "state", "--repeats", "1"], cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "pin state" in run.stdout and "goals:" in run.stdout, run.stdout
