"""benchmarks/bench_kinetics.py in smoke mode (one repeat, no cycle, no quasi-static limit) so that the benchmark
cannot rot; times are not checked.  The script runs as __main__ in this process (runpy: what `python script.py`
runs, without a fresh interpreter's import and kernel load)."""
import pathlib
import runpy
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]


def test_bench_kinetics_smoke(monkeypatch, capsys):
    script = ROOT / "benchmarks" / "bench_kinetics.py"
    monkeypatch.setattr(sys, "argv", [str(script), "--repeats", "1", "--quick"])
    monkeypatch.chdir(ROOT)
    try:
        runpy.run_path(str(script), run_name="__main__")
    except SystemExit as exc:
        assert exc.code in (None, 0), exc.code
    out = capsys.readouterr().out
    for row in ("pull-off alpha* = 0", "pull-off alpha* != 0", "30-rate sweep", "goals:"):
        assert row in out, f"missing {row!r} in\n{out}"
