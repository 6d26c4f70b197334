"""benchmarks/bench_kinetics.py in smoke mode (one repeat, no cycle, no quasi-static limit) so that the benchmark
cannot rot; times are not checked.  The script runs as __main__ in this process (tests/cli_run.run_script: what
`python script.py` runs, without a fresh interpreter's import and kernel load)."""
import pathlib

from cli_run import run_script

ROOT = pathlib.Path(__file__).resolve().parents[1]


def test_bench_kinetics_smoke():
    out = run_script(ROOT / "benchmarks" / "bench_kinetics.py", "--repeats", "1", "--quick")
    for row in ("pull-off alpha* = 0", "pull-off alpha* != 0", "30-rate sweep", "goals:"):
        assert row in out, f"missing {row!r} in\n{out}"
