"""Benchmark (not a test): wall time of every README call, cold and warm (issue 18, "Speed").

Run: python benchmarks/bench_calls.py [--pairs pin steel] [--calls state curve ...] [--repeats 3]
                                      [--baseline DIR]    (DIR: another checkout, timed in turn)

For each pair and call, ``--repeats`` fresh Python processes (``python bench_calls.py --one PAIR CALL``) each
import jkrcyl (numba's on-disk cache filled by a warm-up process first), build the Contact, then time
  cold: the first call in that process (node tables, lru caches, numba dispatch all empty or loaded from disk),
  warm: the same call once more in the same process (what a second question on the same contact costs).
The medians over the processes are printed (seconds), with the process's total wall time (import included).

Pairs: the README pin (E 2.6 GPa, nu 0.3 both, R 10 mm, Delta 1 um, w 0.05: alpha* = 0, closed forms) and
steel in aluminium (steel pin E 210 GPa nu 0.3 in aluminium E 70 GPa nu 0.33, R 5 mm, Delta 2 um, w 0.1:
alpha* != 0, every state a collocation solve).  Calls (arguments as in the README; the steel loads scaled to
its own pull-off of about -3.4e3 N/m): state (one a), curve (2000 points), solve (P = -2000 N/m, no
two-patch branch), pull_off under the three controls, cycle (load control, n 400, P_max = -P_min = 2000 N/m
for the pin, 4000 N/m for steel), two_patch, confined_events.
A call that raises is timed up to the exception and marked with its type.
Goals (issue 18): every README call <= 1 s warm; the first alpha* != 0 answer in a fresh process <= 3 s;
two_patch / confined_events <= 5 s for any pair.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

CALLS = ("state", "curve", "solve", "pull_off-load", "pull_off-grip-work", "pull_off-grip", "cycle",
         "two_patch", "confined_events")
PAIRS = ("pin", "steel")
NO_TWO_PATCH = ["sub-critical", "super-critical", "sub-critical-top", "super-critical-top", "full-contact",
                "separated"]


def _contact(pair):
    import jkrcyl
    if pair == "pin":
        m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        return jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m), 2000.0
    m = jkrcyl.Materials.from_young(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3)
    return jkrcyl.Contact(R=5e-3, Delta=2e-6, w=0.1, materials=m), 4000.0


def _call(contact, load, name):
    """The README call ``name`` on ``contact`` (load: the cycle's limits)."""
    if name == "state":
        return contact.state(0.5)
    if name == "curve":
        return contact.curve("sub-critical", n=2000)
    if name == "solve":
        return contact.solve(P=-2000.0, branches=NO_TWO_PATCH)
    if name.startswith("pull_off-"):
        return contact.pull_off(control=name[len("pull_off-"):])
    if name == "cycle":
        return contact.cycle(P_max=load, P_min=-load, control="load", n=400)
    if name == "two_patch":
        return contact.two_patch()
    if name == "confined_events":
        return contact.confined_events()
    raise ValueError(f"call must be one of {CALLS}, got {name!r}")


def _timed(fn):
    """(wall, cpu) seconds of fn() and the exception's type name if it raised."""
    t, c = time.perf_counter(), time.process_time()
    try:
        fn()
        err = None
    except Exception as exc:            # timed to the exception: a crash is a result too (issue 18, item 5)
        err = type(exc).__name__
    return time.perf_counter() - t, time.process_time() - c, err


def one(pair, name):
    """In this (fresh) process: cold and warm time of one call; prints one JSON line."""
    t0 = time.perf_counter()
    import jkrcyl  # noqa: F401  (timed apart: the import is the same for every call)
    t1 = time.perf_counter()
    contact, load = _contact(pair)
    cold, cold_cpu, err = _timed(lambda: _call(contact, load, name))
    warm, warm_cpu, err2 = _timed(lambda: _call(contact, load, name))
    print(json.dumps({"cold": cold, "warm": warm, "cold_cpu": cold_cpu, "warm_cpu": warm_cpu,
                      "total": time.perf_counter() - t0, "import": t1 - t0, "error": err or err2}))


def _fresh(pair, name, tree=None):
    """One fresh process; tree: another checkout of the project to time instead (put first on sys.path)."""
    env = dict(os.environ, PYTHONHASHSEED="0")
    if tree:
        env["PYTHONPATH"] = tree
    run = subprocess.run([sys.executable, os.path.abspath(__file__), "--one", pair, name], capture_output=True,
                         text=True, env=env, timeout=1800, cwd=tree or None)
    if run.returncode != 0:
        raise RuntimeError(run.stderr[-2000:])
    return json.loads(run.stdout.strip().splitlines()[-1])


def _medians(runs):
    med = {k: statistics.median(r[k] for r in runs) for k in ("cold", "warm", "cold_cpu", "warm_cpu", "total")}
    med["note"] = ", ".join(sorted({r["error"] for r in runs if r["error"]}))
    return med


def _row(label, m):
    return (f"{label:26s} {m['cold']:8.3f} {m['warm']:8.3f} {m['cold_cpu']:8.3f} {m['warm_cpu']:8.3f} "
            f"{m['total']:8.3f}  {m['note']}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--pairs", nargs="+", default=list(PAIRS), choices=PAIRS)
    ap.add_argument("--calls", nargs="+", default=list(CALLS), choices=CALLS)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--baseline", metavar="DIR", help="another checkout (e.g. of main, with jkrcyl/generated "
                    "linking to its generated/) timed in turn with this one: before/after under the same load")
    ap.add_argument("--one", nargs=2, metavar=("PAIR", "CALL"), help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.one:
        return one(*args.one)
    trees = [None] + ([args.baseline] if args.baseline else [])
    for tree in trees:                         # fill numba's on-disk cache (and compile) before timing
        for pair in args.pairs:
            _fresh(pair, "state", tree)
    print(f"# median of {args.repeats} fresh processes, seconds; cold = first call after import, warm = the "
          f"same call again; cpu = process time; process = import + both calls")
    print(f"{'pair call':26s} {'cold':>8s} {'warm':>8s} {'cold cpu':>8s} {'warm cpu':>8s} {'process':>8s}")
    for pair in args.pairs:
        for name in args.calls:
            runs = {tree: [] for tree in trees}
            for _ in range(args.repeats):     # in turn: a change in the machine's load hits both alike
                for tree in trees:
                    runs[tree].append(_fresh(pair, name, tree))
            print(_row(f"{pair} {name}", _medians(runs[None])), flush=True)
            if args.baseline:
                print(_row("  baseline", _medians(runs[args.baseline])), flush=True)
    print("goals: every README call <= 1 s warm; first alpha* != 0 answer in a fresh process <= 3 s; "
          "two_patch / confined_events <= 5 s")


if __name__ == "__main__":
    main()
