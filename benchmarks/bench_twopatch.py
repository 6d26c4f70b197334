"""Benchmark (not a test): two-patch equilibria (issue 12).

Run: python benchmarks/bench_twopatch.py [--repeats 5]

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


def best_of(fn, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return min(times), out


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=5)
    args = ap.parse_args(argv)
    gb = eq.default_gb(THETA)
    ref = tp.solve(M, THETA, eps_top=EPS_TOP, guess=GUESS, n=64)
    t_newton, s = best_of(lambda: tp.solve(M, THETA, eps_top=EPS_TOP, guess=GUESS), args.repeats)
    F = lambda e: tp.residual(e, EPS_TOP, M, THETA, gb)
    # same work as solve: the root, then the state (delta, P*, gap check) at it
    t_brent, e_b = best_of(lambda: tp.equilibrium_state(brentq(F, 0.6, 1.3, xtol=1e-13), EPS_TOP, M, THETA, gb).eps,
                           args.repeats)
    print(f"one equilibrium (M = {M}, vartheta = {THETA}, eps_top = {EPS_TOP}):")
    print(f"  twopatch.solve (Newton)  {t_newton * 1e3:8.2f} ms   |eps - eps(64 nodes)| = {abs(s.eps - ref.eps):.2e}"
          f"   |P* - P*(64)| = {abs(s.P_star - ref.P_star):.2e}")
    print(f"  brentq (bracket given)   {t_brent * 1e3:8.2f} ms   |eps - eps(64 nodes)| = {abs(e_b - ref.eps):.2e}"
          f"   ratio {t_brent / t_newton:.2f}")
    print(f"  goal <= 5 ms: {'met' if t_newton <= 5e-3 else 'NOT met'}")

    t_cont, bs = best_of(lambda: eq.two_patch(M, THETA), max(1, args.repeats // 3))
    npts = sum(b.a.size for b in bs)
    print(f"all branches (continuation): {t_cont:6.2f} s, {len(bs)} branches, {npts} points, "
          f"ends {[b.ends for b in bs]}")

    def grid():
        E = np.linspace(0.02, math.pi - 0.12, 80)
        return np.array([[F2(e, et) for e in E] for et in E])
    F2 = lambda e, et: tp.residual(e, et, M, THETA, gb) if e + et < math.pi - 0.1 else np.nan
    t_grid, _ = best_of(grid, 1)
    print(f"dense 80 x 80 grid of F (sketch only, no states): {t_grid:6.2f} s   ratio grid/continuation "
          f"{t_grid / t_cont:.2f}")
    print(f"  goal <= 2 s for all branches: {'met' if t_cont <= 2 else 'NOT met'}")


if __name__ == "__main__":
    main()
