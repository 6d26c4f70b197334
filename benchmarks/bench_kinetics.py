"""Benchmark (not a test): rate-dependent adhesion, crack kinetics in time (jkrcyl.kinetics).

Run: python benchmarks/bench_kinetics.py [--repeats 10]          (smoke: --repeats 1 --quick)

Prints, in one run, the best of ``repeats`` warm calls (numba's cached code loaded, the contact's arc table
built: the first call on a contact adds that table, printed as 'cold'):
  * one rate-dependent pull-off at alpha* = 0 (identical nu = 0.3 bodies, R = 10 mm, Delta = 1 um, w = 0.05,
    v* = 1 mm/s, n = 0.6) under load at 100 N/m/s and under grip-work at 1 um/s;
  * the same at alpha* != 0 (steel pin in an aluminium hole, w = 0.1: the collocation states, tabulated);
  * a 30-rate sweep (10 ... 1e6 N/m/s) at alpha* = 0;
  * a load cycle to a steady loop (+-1555 N/m at 300 N/m/s), and the quasi-static limit (v* = 1e12 m/s).
Goals (the issue): a pull-off <= 50 ms (alpha* = 0) and <= 0.5 s (alpha* != 0) warm, the 30-rate sweep <= 2 s.
"""
import argparse
import math
import platform
import time

import numpy as np

import jkrcyl

IDENTICAL = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
STEEL_IN_AL = jkrcyl.Materials.from_young(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3)


def contact(m, w, v_star=1e-3, k=0):
    """A contact never seen before when k is new (the arc tables are cached per problem)."""
    return jkrcyl.Contact(R=10e-3, Delta=1e-6, w=w * (1 + 1e-9 * k), materials=m,
                          kinetics=jkrcyl.CrackKinetics(v_star, 0.6))


def best(f, repeats):
    f()
    out = math.inf
    for _ in range(repeats):
        t = time.perf_counter()
        f()
        out = min(out, time.perf_counter() - t)
    return out


def cold(f):
    t = time.perf_counter()
    f()
    return time.perf_counter() - t


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=10)
    ap.add_argument("--quick", action="store_true", help="skip the quasi-static limit and the cycle")
    args = ap.parse_args()
    print(f"# {platform.processor() or platform.machine()}, python {platform.python_version()}")
    contact(IDENTICAL, 0.05, k=-1).pull_off(rate=100.0)         # numba's cached code loaded: not a contact's cost
    rows = {}
    for label, m, w in (("alpha* = 0", IDENTICAL, 0.05), ("alpha* != 0", STEEL_IN_AL, 0.1)):
        c = contact(m, w, k=1)
        t_cold = cold(lambda: c.pull_off(rate=100.0))
        for control, rate, unit in (("load", 100.0, "N/m/s"), ("grip-work", 1e-6, "m/s")):
            t = best(lambda: c.pull_off(control, rate=rate), args.repeats)
            po = c.pull_off(control, rate=rate)
            rows[(label, control)] = t
            print(f"pull-off {label:11s} {control:9s} at {rate:g} {unit}: {t * 1e3:8.1f} ms warm   "
                  f"(P = {po.P:.6g} N/m, {po.kind}, {len(po.history)} states)")
        print(f"  first call on the contact (arc table built, cold): {t_cold * 1e3:.0f} ms")
    c = contact(IDENTICAL, 0.05, k=2)
    rates = np.geomspace(10.0, 1e6, 30)
    t_sweep = best(lambda: jkrcyl.kinetics.rate_sweep(c, rates), max(1, args.repeats // 5))
    print(f"30-rate sweep alpha* = 0, 10 ... 1e6 N/m/s: {t_sweep:.3f} s warm")
    if not args.quick:
        po = c.pull_off().P
        t_cycle = best(lambda: c.cycle(P_max=-po, P_min=po, rate=300.0), 1)
        cy = c.cycle(P_max=-po, P_min=po, rate=300.0)
        print(f"load cycle +-{-po:.0f} N/m at 300 N/m/s to a steady loop: {t_cycle:.3f} s "
              f"({len(cy.history)} states, dissipated {cy.dissipated:.4g} J/m per cycle)")
        q = contact(IDENTICAL, 0.05, v_star=1e12, k=3)
        qs = q.pull_off()
        t_qs = best(lambda: q.pull_off(rate=0.1 * abs(qs.P)), 1)
        rel = q.pull_off(rate=0.1 * abs(qs.P)).P / qs.P - 1
        print(f"quasi-static limit (v* = 1e12 m/s, load at 0.1 |P_qs| per s): {t_qs:.3f} s, P/P_qs - 1 = {rel:.2e}")
    worst0 = max(rows[("alpha* = 0", c)] for c in ("load", "grip-work"))
    worst1 = max(rows[("alpha* != 0", c)] for c in ("load", "grip-work"))
    print("goals:")
    print(f"  pull-off alpha* = 0   <= 50 ms  : {worst0 * 1e3:7.1f} ms  ({'met' if worst0 <= 0.05 else 'NOT met'})")
    print(f"  pull-off alpha* != 0  <= 500 ms : {worst1 * 1e3:7.1f} ms  ({'met' if worst1 <= 0.5 else 'NOT met'})")
    print(f"  30-rate sweep         <= 2 s    : {t_sweep:7.3f} s   ({'met' if t_sweep <= 2 else 'NOT met'})")


if __name__ == "__main__":
    main()
