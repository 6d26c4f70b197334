"""Benchmark (not a test): the S-shaped cohesive branch (jkrcyl.numerics.cohesive_round) and the map's route.

Run: python benchmarks/bench_cohesive_round.py [--sample 6]        (smoke: --sample 2)

Prints, in one run:
  * the S-shaped branch of tests/test_cohesive_s_branch.py (identical bodies, M = 0.45, lambda = 1): the trace
    (cold), Contact.pull_off('load') cold and warm, a load cycle through its jumps;
  * the map's per-point cost two ways over a sample x sample grid of the map's (lambda, M) square: the stand-alone
    continuation the map uses (jkrcyl.analysis.cohesive_map._point) and the model core's walker
    (Contact.pull_off('load'), cold: a fresh contact per point), each projected to the 100 x 100 map on 2 cores.
Goal (issue 26): the 100 x 100 map <= 60 s on 2 cores; the walker route is taken only if its projection meets it.
"""
import argparse
import os
import platform
import time

import numpy as np

import jkrcyl
from jkrcyl.analysis import cohesive_map
from jkrcyl.model.single_patch import solver

PAIR = jkrcyl.Materials(G=1.0, kappa=1.8, G_I=1.0, kappa_I=1.8)


def contact(M, lam):
    probe = jkrcyl.Contact(R=1.0, Delta=0.01, w=1.0, materials=PAIR)
    return jkrcyl.Contact.with_lambda(R=1.0, Delta=0.01, w=(M / probe.M) ** 2, materials=PAIR, lambda_=lam)


def timed(f):
    t = time.perf_counter()
    f()
    return time.perf_counter() - t


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sample", type=int, default=6, help="map sample points per axis")
    args = ap.parse_args()
    print(f"# {platform.processor() or platform.machine()}, python {platform.python_version()}")
    contact(0.2, 3.0).pull_off("load")                 # numba's cached code loaded: not a contact's cost
    c = contact(0.45, 1.0)
    t_trace = timed(lambda: solver(c.problem)._sub)
    c = contact(0.45, 1.0)
    t_cold = timed(lambda: c.pull_off("load"))
    t_warm = min(timed(lambda: c.pull_off("load")) for _ in range(5))
    t_cycle = timed(lambda: c.cycle(P_max=c.load_scale, P_min=-c.load_scale, n=40))
    print(f"S-shaped branch (M 0.45, lambda 1): trace {t_trace * 1e3:.0f} ms; pull-off cold {t_cold * 1e3:.0f} ms, "
          f"warm {t_warm * 1e3:.2f} ms; load cycle {t_cycle * 1e3:.0f} ms")
    lams, Ms = np.geomspace(0.01, 10, args.sample), np.geomspace(0.01, 1.0, args.sample)
    t_map, t_walk = [], []
    for lam in lams:
        for M in Ms:
            pb = contact(float(M), float(lam)).problem
            t_map.append(timed(lambda: cohesive_map._point(float(lam), pb.M, pb.theta, pb.gb, pb.alpha_ratio)))
            fresh = contact(float(M), float(lam))
            t_walk.append(timed(lambda: fresh.pull_off("load")))
    proj = lambda ts: 1e4 * float(np.mean(ts)) / 2
    print(f"per map point, {args.sample}x{args.sample} sample: stand-alone {np.mean(t_map) * 1e3:.0f} ms mean, "
          f"walker (cold) {np.mean(t_walk) * 1e3:.0f} ms mean")
    print(f"\ngoal: issue 26 vs measured (load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores)")
    for name, ts in (("stand-alone (the map's route)", t_map), ("walker", t_walk)):
        print(f"  100 x 100 map <= 60 s on 2 cores, {name}: projected {proj(ts):.0f} s "
              f"({'met' if proj(ts) <= 60 else 'NOT met'})")


if __name__ == "__main__":
    main()
