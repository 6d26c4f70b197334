"""Benchmark (not a test): the regime atlas with the confined classes (issue 9 item 3, issue 12 item 4).

Run: python benchmarks/bench_atlas.py [--n 1000] [--law-n 24] [--law-lambda 50] [--workers 2] [--law-only]

Times, in one run: the classification of the default n x n grid (+ the vartheta = inf row) with all cores
(numba prange) and one core on a slice, the outputs (npz, CSV, map), and the two-patch analysis
(jkrcyl.twopatch.confined_events) that the confined classes stand in for -- per pair, and extrapolated to
the grid, and what ``--two-patch`` (classify(two_patch=True): the two-patch analysis of every pair where the
gap closes first) adds on this grid.  Goal: the default 1000 x 1000 atlas with the confined classes under
60 s on 2 cores.

The law's atlas (jkrcyl.atlas.cohesive.classify_law, ``jkrcyl atlas --lambda``): the default 24 x 24 grid (+ the
vartheta = inf row) at lambda 50 on ``--workers`` Dask processes, per pair, and against JKR's numba atlas of the
same grid (how many classes equal, and where not).  No goal was set for it (each pair walks the law's branch
tables, ~1 s of CPU; --law-sample K: the CPU time of every K-th pair, serial, extrapolated).
"""
import argparse
import os
import sys
import pathlib
import tempfile
import time

import numpy as np

from jkrcyl import atlas
from jkrcyl import equilibria as eq
from jkrcyl.atlas import cohesive


def timed(fn):
    t0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, out


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=1000)
    ap.add_argument("--law-n", type=int, default=24, help="the law's grid per axis (0: skip the law's case)")
    ap.add_argument("--law-lambda", type=float, default=50.0)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--law-only", action="store_true", help="only the law's case")
    ap.add_argument("--law-sample", type=int, default=0,
                    help="instead of the whole law's grid: the CPU time of every K-th pair, serial, extrapolated to "
                         "the grid on --workers idle cores (robust on a loaded machine)")
    args = ap.parse_args(argv)
    if not args.law_only:
        jkr(args)
    if args.law_n:
        law(args)


def law(args):
    Ms, th = atlas.default_grid(args.law_n, args.law_n)
    if args.law_sample:
        return law_sample(args, Ms, th)
    t, res = timed(lambda: cohesive.classify_law(Ms, th, args.law_lambda, workers=args.workers))
    n = res["confined"].size
    same = int((res["confined"] == res["jkr_confined"]).sum())
    codes, counts = np.unique(res["confined"], return_counts=True)
    print(f"law's atlas (Maugis-Dugdale, lambda = {args.law_lambda:g}) {Ms.size} x {th.size} pairs on "
          f"{args.workers} workers: {t:.1f} s ({t / n:.2f} s per pair, {t * args.workers / n:.2f} s per pair per "
          f"worker); classes equal to JKR's on {same} of {n} pairs; refused {len(res['reasons'])}")
    print("  law's classes: " + ", ".join(f"{c}: {k}" for c, k in zip(codes.tolist(), counts.tolist())))
    diff = np.argwhere(res["confined"] != res["jkr_confined"])
    for i, j in diff[:10]:
        print(f"  differs at vartheta {th[i]:g}, M {Ms[j]:.4f}: law {res['confined'][i, j]}, "
              f"JKR {res['jkr_confined'][i, j]}")


def law_sample(args, Ms, th):
    pairs = [(float(M), float(t)) for t in th for M in Ms][::args.law_sample]
    cohesive.classify_pair(0.2, 1.0, args.law_lambda)                     # compile / load the numba caches
    cpu, wall, codes = [], [], []
    for M, t in pairs:
        c0, w0 = time.process_time(), time.perf_counter()
        codes.append(cohesive.classify_pair(M, t, args.law_lambda)[0])
        cpu.append(time.process_time() - c0)
        wall.append(time.perf_counter() - w0)
    n = Ms.size * th.size
    print(f"law's atlas (Maugis-Dugdale, lambda = {args.law_lambda:g}), every {args.law_sample}-th of {n} pairs "
          f"({len(pairs)}): CPU {np.mean(cpu):.2f} s per pair (max {max(cpu):.2f} s, wall {np.mean(wall):.2f} s); "
          f"the {Ms.size} x {th.size} grid on {args.workers} idle cores ~{np.mean(cpu) * n / args.workers / 60:.1f} "
          f"min")
    for code in sorted(set(codes)):
        sel = [c for c, k in zip(cpu, codes) if k == code]
        print(f"  class {code}: {len(sel)} pairs, CPU {np.mean(sel):.2f} s per pair")


def jkr(args):
    atlas.classify(*atlas.default_grid(8, 8))                       # compile / load the numba cache
    Ms, th = atlas.default_grid(args.n, args.n)
    t_par, res = timed(lambda: atlas.classify(Ms, th))
    rows = max(1, args.n // 20)
    t_ser, _ = timed(lambda: atlas.classify(Ms, th[:rows], parallel=False))
    per_pair = t_ser / (rows * Ms.size)
    with tempfile.TemporaryDirectory() as d:
        d = pathlib.Path(d)
        t_npz, _ = timed(lambda: atlas.write_npz(d / "atlas.npz", res))
        t_csv, _ = timed(lambda: atlas.write_csv(d / "atlas.csv", res))
        t_png, _ = timed(lambda: atlas.draw(res, str(d / "atlas")))
    total = t_par + t_npz + t_csv + t_png
    codes, counts = np.unique(res["confined"], return_counts=True)
    print(f"atlas {Ms.size} x {th.size} pairs on {os.cpu_count()} cores:")
    print(f"  classify (prange)      {t_par:7.2f} s   ({t_par / res['confined'].size * 1e6:.2f} us per pair)")
    print(f"  classify (1 core)      {per_pair * 1e6:7.2f} us per pair on {rows} rows; "
          f"speed-up {per_pair * res['confined'].size / t_par:.2f}x")
    print(f"  npz {t_npz:.2f} s, CSV {t_csv:.2f} s, map {t_png:.2f} s; total {total:.2f} s "
          f"(goal <= 60 s: {'met' if total <= 60 else 'NOT met'})")
    print("  confined classes: " + ", ".join(f"{c}: {n}" for c, n in zip(codes.tolist(), counts.tolist())))
    _cl = sys.modules["jkrcyl.atlas.classify"]                  # the module (jkrcyl.atlas.classify is the function)
    n_top = int((res["confined"] == atlas.CONF_TOP).sum())
    t_ref, _ = timed(lambda: _cl._refine_top(res, False))          # what --two-patch adds on this grid
    print(f"  --two-patch: {n_top} pairs where the gap closes first (CONF_TOP) refined in {t_ref:.2f} s; "
          f"total with it {total + t_ref:.2f} s (goal <= 60 s: {'met' if total + t_ref <= 60 else 'NOT met'})")
    t_tp, ev = timed(lambda: eq.confined_events(0.4, 1.0, gb=1 / 2.8))
    print(f"two-patch analysis (confined_events, M = 0.4, vartheta = 1): {t_tp:.2f} s -> {ev.regime}; "
          f"for every pair {t_tp * res['confined'].size / 3600:.0f} h on one core, "
          f"{t_tp / (t_par / res['confined'].size):.0f}x the atlas cost per pair")


if __name__ == "__main__":
    main()
