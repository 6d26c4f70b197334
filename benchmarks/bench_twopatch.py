"""Benchmark (not a test): two-patch equilibria (issue 12).

Run: python benchmarks/bench_twopatch.py [--repeats 5] [--alpha]

Wall and CPU (process) time are both printed: on a shared machine the wall time of a single-threaded run is
inflated by other load, the CPU time is what an idle core gives.

1. One two-patch equilibrium to 1e-10: jkrcyl.twopatch.solve (secant-Newton on the Griffith residual F in the
   bottom half-angle, 24 nodes per arc) against scipy.optimize.brentq on the same F (bracketed), and against
   the 64-node solution for the error.  Goal: <= 5 ms.
2. All branches at one (M, vartheta): continuation (jkrcyl.equilibria.two_patch) against the dense plane grid
   it replaces (F on 80 x 80 half-angle pairs + contouring, matplotlib), which only sketches the curves.
   Goal: <= 2 s.
"""
import argparse
import math
import time

import numpy as np
from scipy.optimize import brentq

from jkrcyl import equilibria as eq
from jkrcyl import twopatch as tp

M, THETA, EPS_TOP, GUESS = 0.4, 1.0, 0.5, 1.0


CPU = {}      # process (CPU) time of the best run per label: the machine is often shared, wall time is not


def best_of(fn, repeats, label=None):
    times = []
    for _ in range(repeats):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        times.append((time.perf_counter() - t0, time.process_time() - c0))
    best = min(times)
    if label:
        CPU[label] = best[1]
    return best[0], out


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--alpha", action="store_true", help="also alpha*/beta* = 0.2 (the arc engine's alpha* path)")
    args = ap.parse_args(argv)
    gb = eq.default_gb(THETA)
    ref = tp.solve(M, THETA, eps_top=EPS_TOP, guess=GUESS, n=64)
    t_newton, s = best_of(lambda: tp.solve(M, THETA, eps_top=EPS_TOP, guess=GUESS), args.repeats, "solve")
    F = lambda e: tp.residual(e, EPS_TOP, M, THETA, gb)
    # same work as solve: the root, then the state (delta, P*, gap check) at it
    t_brent, e_b = best_of(lambda: tp.equilibrium_state(brentq(F, 0.6, 1.3, xtol=1e-13), EPS_TOP, M, THETA, gb).eps,
                           args.repeats)
    print(f"one equilibrium (M = {M}, vartheta = {THETA}, eps_top = {EPS_TOP}):")
    print(f"  twopatch.solve (Newton)  {t_newton * 1e3:8.2f} ms   |eps - eps(64 nodes)| = {abs(s.eps - ref.eps):.2e}"
          f"   |P* - P*(64)| = {abs(s.P_star - ref.P_star):.2e}")
    print(f"  brentq (bracket given)   {t_brent * 1e3:8.2f} ms   |eps - eps(64 nodes)| = {abs(e_b - ref.eps):.2e}"
          f"   ratio {t_brent / t_newton:.2f}")
    print(f"  goal <= 5 ms: {'met' if t_newton <= 5e-3 else 'NOT met'} (CPU time {CPU['solve'] * 1e3:.2f} ms)")

    t_cont, bs = best_of(lambda: eq.two_patch(M, THETA), max(1, args.repeats // 3), "branches")
    npts = sum(b.a.size for b in bs)
    print(f"all branches (continuation): {t_cont:6.2f} s (CPU {CPU['branches']:.2f} s), {len(bs)} branches, "
          f"{npts} points, ends {[b.ends for b in bs]}")
    for m in (0.3, 0.5, 0.8):
        t_m, bm = best_of(lambda: eq.two_patch(m, THETA), 1, f"branches {m}")
        print(f"  M = {m}: {t_m:6.2f} s (CPU {CPU[f'branches {m}']:.2f} s), {len(bm)} branches")

    def grid():
        E = np.linspace(0.02, math.pi - 0.12, 80)
        return np.array([[F2(e, et) for e in E] for et in E])
    F2 = lambda e, et: tp.residual(e, et, M, THETA, gb) if e + et < math.pi - 0.1 else np.nan
    t_grid, _ = best_of(grid, 1)
    print(f"dense 80 x 80 grid of F (sketch only, no states): {t_grid:6.2f} s   ratio grid/continuation "
          f"{t_grid / t_cont:.2f}")
    print(f"  goal <= 2 s for all branches: {'met' if t_cont <= 2 else 'NOT met'}")
    if args.alpha:
        ar = 0.2
        t_a, s_a = best_of(lambda: tp.solve(M, THETA, eps_top=EPS_TOP, guess=GUESS, alpha_ratio=ar), args.repeats,
                           "solve alpha")
        print(f"alpha*/beta* = {ar}: one equilibrium {t_a * 1e3:.2f} ms (CPU {CPU['solve alpha'] * 1e3:.2f} ms, "
              f"{tp._nodes(s_a.eps, EPS_TOP, tp.N_NODES, ar)} nodes per arc)")
        t_b, b_a = best_of(lambda: eq.two_patch(M, THETA, alpha_ratio=ar), 1, "branches alpha")
        print(f"  all branches {t_b:.2f} s (CPU {CPU['branches alpha']:.2f} s, enrichment tables built on the "
              f"way: one per node count), {len(b_a)} branches")


if __name__ == "__main__":
    main()
