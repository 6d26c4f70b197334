"""Benchmark (not a test): the super-critical branch of the cohesive law (jkrcyl.numerics.cohesive_super).

Run: python benchmarks/bench_cohesive_super.py [--runs 3] [--quick]

Prints, in one run (the README pin's pair, R = 10 mm, Delta = 1 um, M = 0.8 unless said):
  * a cold super-critical curve (Contact.curve(regime='super-critical', n=200) on a contact never seen before:
    trace, then the states; the median of ``runs`` fresh contacts after numba's cached code is loaded) at
    lambda = 1, 10, 100, and the trace alone;
  * a cold load-control pull-off at the same lambda (its landings search the super-critical branch too);
  * the distance to JKR's closed form at lambda = 50 and 100 on 2.0 <= eps <= 2.7 (max |dP*| and lambda^2 times it).
Goal (issue 26, this piece): none stated for a curve; the pull-off's: <= 100 ms at lambda <= 10.  Wall clock and
the process's CPU time; the machine is shared (the load average is printed).
"""
import argparse
import math
import os
import statistics
import time

import numpy as np

import jkrcyl
from jkrcyl import equilibria as eq
from jkrcyl.model.single_patch import solver
from jkrcyl.numerics import cohesive_branch as cb
from jkrcyl.numerics import cohesive_super as csu

PAIR = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
W08 = 0.05 * (0.8 / jkrcyl.Contact(10e-3, 1e-6, 0.05, PAIR).M) ** 2         # M = 0.8


def fresh(lam, k, w=W08):
    """A contact never seen before (the solver cache is per problem): w nudged by k ulps-worth."""
    return jkrcyl.Contact.with_lambda(10e-3, 1e-6, w * (1 + 1e-9 * k), PAIR, lam)


def cold(what, lam, k, runs):
    """(median wall, median CPU) seconds of what(contact) on ``runs`` fresh contacts."""
    wall, cpu = [], []
    for _ in range(runs):
        k[0] += 1
        c = fresh(lam, k[0])
        t, t_cpu = time.perf_counter(), time.process_time()
        what(c)
        wall.append(time.perf_counter() - t)
        cpu.append(time.process_time() - t_cpu)
    return statistics.median(wall), statistics.median(cpu)


def trace_only(c):
    pb = c.problem
    csu.trace(cb.Law(pb.m, pb.edge.s0, pb.theta, pb.gb, pb.alpha_ratio))


def jkr_distance(lam):
    c = fresh(lam, 0)
    cv = c.curve(regime="super-critical", n=60)
    ref = eq.curve(c.M, c.theta, "super-critical", gb=c.problem.gb, a=np.tan(cv.eps / 2))
    window = (cv.eps >= 2.0) & (cv.eps <= 2.7)
    return float(np.abs(cv.P_star - ref.P_star)[window].max())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help="lambda = 10 only, one run (the smoke test)")
    args = ap.parse_args()
    runs = 1 if args.quick else args.runs
    lams = (10.0,) if args.quick else (1.0, 10.0, 100.0)
    k = [0]
    cold(lambda c: c.curve(regime="super-critical", n=20), 10.0, k, 1)          # numba's cache loaded
    print(f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores; M = 0.8, identical bodies")
    print("cold super-critical curve (n = 200), the trace alone, a cold load pull-off [s, wall (cpu)]:")
    for lam in lams:
        curve = cold(lambda c: c.curve(regime="super-critical", n=200), lam, k, runs)
        trace = cold(trace_only, lam, k, runs)
        pull = cold(lambda c: c.pull_off("load"), lam, k, runs)
        print(f"  lambda {lam:6g}: curve {curve[0]:.3f} ({curve[1]:.3f})   trace {trace[0]:.3f} ({trace[1]:.3f})   "
              f"pull-off {pull[0]:.3f} ({pull[1]:.3f})   table points {solver(fresh(lam, k[0]).problem).dense_points}")
    print("JKR limit on 2.0 <= eps <= 2.7 (max |dP*|, lambda^2 times it):")
    for lam in ((50.0,) if args.quick else (50.0, 100.0)):
        d = jkr_distance(lam)
        print(f"  lambda {lam:g}: {d:.3e}   {lam * lam * d:.3f}")
    print("goals: a cold pull-off <= 0.1 s at lambda <= 10 (issue 26); the curve has none")


if __name__ == "__main__":
    main()
