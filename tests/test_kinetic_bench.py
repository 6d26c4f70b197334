"""benchmarks/bench_kinetics.py in smoke mode (one repeat, no cycle, no quasi-static limit) so that the benchmark
cannot rot; times are not checked."""
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]


def test_bench_kinetics_smoke():
    run = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_kinetics.py"), "--repeats", "1",
                          "--quick"], cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout + run.stderr
    for row in ("pull-off alpha* = 0", "pull-off alpha* != 0", "30-rate sweep", "goals:"):
        assert row in run.stdout, f"missing {row!r} in\n{run.stdout}"
