"""Benchmark (not a test): the numerical arc solver jkrcyl.numerics.arcs (issue 10).

Run: python benchmarks/bench_solver.py [--curve 2000] [--states 200]   (smoke: --curve 20 --states 5)

Prints, in one run:
  * time per equilibrium state (Contact.state, one a per call): closed form vs solver at alpha* = 0, and the
    solver at alpha* != 0 (steel pin in aluminium), with the ratio to the closed form;
  * time per 2000-point equilibrium curve (equilibria.curve: P*, delta/Delta, h(pi) and the slopes);
  * error against the number of nodes n per arc (unit cases P*, B*, edge k, h(pi)) against n = 128,
    at alpha* = 0 and alpha*/beta* = 0.117, 0.375 (the end-enriched basis).
Goals (issue 10): one state to 1e-10 in <= 200 us; a 2000-point curve in <= 0.5 s.
"""
import argparse
import math
import platform
import time

import numpy as np

import jkrcyl
from jkrcyl import equilibria as eq
from jkrcyl.model.collocation import Collocation
from jkrcyl.numerics import arcs


def per_call(f, items):
    for x in items:                               # warm (numba cache, node tables per n: ~0.1 s each, once)
        f(x)
    t = time.perf_counter()
    for x in items:
        f(x)
    return (time.perf_counter() - t) / len(items)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--curve", type=int, default=2000)
    ap.add_argument("--states", type=int, default=200)
    args = ap.parse_args()
    print(f"# {platform.processor() or platform.machine()}, python {platform.python_version()}, "
          f"numpy {np.__version__}")
    same = jkrcyl.Contact(R=1.0, Delta=1e-2, w=1e-4, materials=jkrcyl.Materials(G=1.0, kappa=2.0, G_I=1.0,
                                                                                   kappa_I=2.0))
    alu = jkrcyl.Contact(R=1.0, Delta=1e-2, w=1e-4, materials=jkrcyl.Materials.from_young(70e9, 0.33, 210e9, 0.3))
    a = list(np.geomspace(1e-2, 0.8, args.states))
    t_cf = per_call(lambda x: same.state(x, method="closed-form"), a)
    t_n0 = per_call(lambda x: same.state(x, method="numeric"), a)
    t_na = per_call(lambda x: alu.state(x), a)
    print("time per state (one a per call):")
    print(f"  closed form (alpha* = 0)            {t_cf * 1e6:9.1f} us")
    print(f"  solver, alpha* = 0                  {t_n0 * 1e6:9.1f} us   ratio {t_n0 / t_cf:7.1f} x closed form")
    print(f"  solver, alpha*/beta* = {alu.materials.alpha_ratio:.3f}        {t_na * 1e6:9.1f} us   "
          f"ratio {t_na / t_cf:7.1f} x closed form   (goal <= 200 us)")
    err = np.max(np.abs(same.state(np.array(a), method="numeric").P / same.state(np.array(a)).P - 1))
    print(f"  max |P_solver/P_closed - 1| over these a = {err:.2e}")

    print(f"time per {args.curve}-point curve (equilibria.curve, M = 0.4, vartheta = 1):")
    for ar in (0.0, 0.117):
        eq.curve(0.4, 1.0, n=4, alpha_ratio=ar, gb=0.5)
        t = time.perf_counter()
        eq.curve(0.4, 1.0, n=args.curve, alpha_ratio=ar, gb=0.5)
        dt = time.perf_counter() - t
        label = "closed form" if ar == 0 else f"solver, alpha*/beta* = {ar}"
        print(f"  {label:34s} {dt:9.3f} s   (goal <= 0.5 s)")
    pb = eq.problem(0.4, 1.0, 0.5)
    grid = eq.curve(0.4, 1.0, n=args.curve, gb=0.5).a
    t = time.perf_counter()
    Collocation(pb).states(grid)
    print(f"  {'solver, alpha* = 0':34s} {time.perf_counter() - t:9.3f} s")

    print("error vs nodes per arc (max over unit cases P*, B*, k and h(pi); reference n = 128; eps = 1.5):")
    print("     n " + "".join(f"  alpha*/beta*={ar:<6}" for ar in (0.0, 0.117, 0.375)))
    refs = {ar: arcs.two_patch_linear(1.5, 0.0, 1.0, 0.4, 128, ar) for ar in (0.0, 0.117, 0.375)}
    for n in (8, 12, 16, 24, 32, 48, 64):
        row = []
        for ar, ref in refs.items():
            lin = arcs.two_patch_linear(1.5, 0.0, 1.0, 0.4, n, ar)
            e = max(np.max(np.abs(lin.q0 - ref.q0)), np.max(np.abs(lin.q1 - ref.q1)),
                    abs(lin.gap(math.pi, 0.3)[0] - ref.gap(math.pi, 0.3)[0]))
            row.append(f"  {e:19.2e}")
        print(f"  {n:4d} " + "".join(row))
    print("goals: one state <= 200 us, 2000-point curve <= 0.5 s (see the rows above)")


if __name__ == "__main__":
    main()
