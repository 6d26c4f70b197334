"""Benchmark (not a test): the Maugis-Dugdale state solver jkrcyl.numerics.cohesive (issue 19).

Run: python benchmarks/bench_cohesive.py [--repeats 50]        (smoke: --repeats 2 --quick)

Prints, in one run:
  * time per cohesive state (default nodes, best of the repeats) and its error against the same state with twice the nodes (max of
    |dp|, |d delta/Delta|, |dc|), over lambda at alpha* = 0 and for a steel pin in aluminium (alpha* != 0);
  * the error against the number of nodes at lambda = 10 (against n = 256) with the Bernstein-ellipse rate of the
    plain collocation, and with the zone's end layer subtracted (jkrcyl.numerics.cohesive_layer) at lambda = 10
    and 1000;
  * the JKR limit: lambda^2 (X - X_JKR) for p, delta/Delta, h(pi) (the O(lambda^-2) approach);
  * the half-plane limit against Baney-Hui (reference/baney_hui.py, run from the repository root);
  * time per contactless state (closed form) and per touch state;
  * the load-control pull-off: time, and its approach to JKR (lambda^4 times the difference) and to Baney-Hui.
Goals (issue 19): one cohesive state to 1e-8 in <= 1 ms; a pull-off in <= 100 ms.
"""
import argparse
import math
import platform
import sys
import time
from pathlib import Path

import numpy as np

import jkrcyl
from jkrcyl.model.problem import Problem
from jkrcyl.model.single_patch import solver
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_pull_off as po
from jkrcyl.numerics import cohesive_scales as cs
from jkrcyl.numerics import cohesive_zones as cz

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from reference import baney_hui as bh  # noqa: E402  (test reference, for the comparison table only)

THETA, GB, M, EPS = 1.0, 0.5, 0.4, 0.8


def per_call(f, repeats):
    """Best of repeats single calls (the machine is shared: the minimum is the cost, the rest is waiting)."""
    f()                                           # warm: numba cache, node tables (once per node count)
    best = math.inf
    for _ in range(repeats):
        t = time.perf_counter()
        f()
        best = min(best, time.perf_counter() - t)
    return best


def error(s, ref):
    return max(abs(s.p - ref.p), abs(s.delta_over_Delta - ref.delta_over_Delta), abs(s.c - ref.c))


def state_table(repeats, quick):
    print("\n## time per state (default nodes), error against twice the nodes")
    print(f"{'pair':>24} {'lambda':>7} {'n':>5} {'c - eps':>10} {'time':>10} {'error':>9}")
    steel = jkrcyl.Materials.from_young(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3)
    cases = [("alpha* = 0", THETA, GB, 0.0, lam) for lam in ((1, 3, 10, 1000) if quick else
                                                             (0.3, 1, 3, 10, 30, 100, 300, 1000, 3000))]
    cases.append(("steel pin in aluminium", steel.theta, steel.inv_G_I / steel.beta, steel.alpha_ratio, 3.0))
    times = {}
    for name, theta, gb, ar, lam in cases:
        m = M * theta
        s0 = cs.zone_strength(lam, m)
        s = co.cohesive_state(EPS, m, s0, theta, gb, ar)
        ref = co.cohesive_state(EPS, m, s0, theta, gb, ar, n=min(2 * s.n, 1024 if ar == 0 else 256))
        dt = per_call(lambda: co.cohesive_state(EPS, m, s0, theta, gb, ar), repeats)
        times[(name, lam)] = (dt, error(s, ref))
        print(f"{name:>24} {lam:7g} {s.n:5d} {s.c - EPS:10.3g} {dt * 1e3:8.3f}ms {error(s, ref):9.1e}")
    return times


def nodes_table():
    print("\n## error against the number of nodes (eps = 0.8; plain: against n = 256, layered: against n = 192)")
    s0 = cs.zone_strength(10.0, M)
    ref = co.cohesive_state(EPS, M, s0, THETA, GB, n=256, layered=False)
    rho = ref.c / EPS + math.sqrt((ref.c / EPS) ** 2 - 1)
    print(f"lambda = 10, plain collocation: Bernstein ellipse through the zone end rho = {rho:.4f}, rho^-n at "
          f"n = 24, 48, 96: {rho ** -24:.1e}, {rho ** -48:.1e}, {rho ** -96:.1e}")
    refs = {lam: co.cohesive_state(EPS, M, cs.zone_strength(lam, M), THETA, GB, n=192, layered=True)
            for lam in (10.0, 1000.0)}
    print(f"{'n':>5} {'plain, 10':>10} {'layered, 10':>12} {'layered, 1000':>14}")
    for n in (16, 24, 32, 48, 64, 96, 128):
        lay = [error(co.cohesive_state(EPS, M, cs.zone_strength(lam, M), THETA, GB, n=n, layered=True), r)
               for lam, r in refs.items()]
        print(f"{n:5d} {error(co.cohesive_state(EPS, M, s0, THETA, GB, n=n, layered=False), ref):10.2e} "
              f"{lay[0]:12.2e} {lay[1]:14.2e}")


def jkr_table(quick):
    print("\n## JKR limit: lambda^2 (X - X_JKR) at eps = 0.8 (steady: the O(lambda^-2) approach)")
    sl = solver(Problem(M / THETA, THETA, GB)).states([math.tan(EPS / 2)])
    st = {"p": sl.p, "dn": sl.dn, "h": sl.h}
    for lam in ((12.5, 25, 50, 1000) if quick else (12.5, 25, 50, 100, 200, 400, 1000, 2000)):
        s = co.cohesive_state(EPS, M, cs.zone_strength(lam, M), THETA, GB)
        d = [(getattr(s, a) - st[b][0]) * lam ** 2 for a, b in (("p", "p"), ("delta_over_Delta", "dn"),
                                                                  ("h_pi_over_Delta", "h"))]
        rel = abs(s.p / st["p"][0] - 1)
        print(f"lambda = {lam:6g} (n = {s.n:4d}): p {d[0]:+.5f}  delta {d[1]:+.5f}  h(pi) {d[2]:+.5f}   "
              f"|p/p_JKR - 1| = {rel:.1e}")


def half_plane_table(quick):
    print("\n## half-plane limit (m = 1e-6, Delta/R = 1e-6) against Baney-Hui: Pbar at abar = 1")
    m, dr = 1e-6, 1e-6
    for lam in ((0.1, 1, 10) if quick else (0.01, 0.1, 1, 10, 100)):
        eps = 2 * m ** (2 / 3) * (1 - dr) ** (2 / 3)
        s = co.cohesive_state(eps, m, cs.zone_strength(lam, m, dr), THETA, GB)
        _, Pbar = cs.baney_hui_variables(eps, s.p, m, dr)
        ref = float(bh.load(1.0, lam))
        print(f"lambda = {lam:6g}: Pbar {Pbar:+.9f}  Baney-Hui {ref:+.9f}  relative error {abs(Pbar / ref - 1):.1e}")


def contactless_table(repeats):
    print("\n## contactless states (closed form) and the touch state")
    s0 = cs.zone_strength(3.0, M)
    dt = per_call(lambda: cz.contactless_state(0.2, M, s0, THETA, GB), repeats)
    print(f"contactless_state: {dt * 1e6:.1f} us")
    dt = per_call(lambda: cz.contactless_touch(M, s0, THETA, GB), max(1, repeats // 10))
    print(f"contactless_touch: {dt * 1e3:.2f} ms")


def pull_off_table(quick):
    print("\n## load-control pull-off (M = 0.2, vartheta = 1): time, lambda^4 (p* - p*_JKR); half-plane vs Baney-Hui")
    from scipy.optimize import minimize_scalar
    f = lambda eps: solver(Problem(0.2 / THETA, THETA, GB)).states([math.tan(eps / 2)]).p[0]
    ref = minimize_scalar(f, bracket=(0.3, 0.5, 0.7), options=dict(xtol=1e-12)).fun
    times = []
    for lam in ((1, 3, 100) if quick else (0.3, 1, 3, 10, 25, 100, 300)):
        t = time.perf_counter()
        r = po.pull_off_load(0.2, cs.zone_strength(lam, 0.2), THETA, GB)
        times.append(time.perf_counter() - t)
        print(f"lambda = {lam:5g}: {r.kind:5s} p* = {r.p:+.10f}  lambda^4 (p* - p*_JKR) = {(r.p - ref) * lam ** 4:+.4f}"
              f"  {times[-1] * 1e3:7.1f} ms")
    m = 1e-6
    for lam in ((0.1, 1) if quick else (0.01, 0.1, 0.5, 1, 2, 5)):
        r = po.pull_off_load(m, cs.zone_strength(lam, m), THETA, GB)
        ref_bh = float(bh.pull_off(lam))
        print(f"half-plane lambda = {lam:5g}: -Pbar_c = {-r.p / m ** (4 / 3):.8f}  Baney-Hui {-ref_bh:.8f}  "
              f"relative error {abs(r.p / m ** (4 / 3) / ref_bh - 1):.1e}")
    return min(times)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=50)
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    print(f"# {platform.processor() or platform.machine()}, python {platform.python_version()}, "
          f"numpy {np.__version__}")
    times = state_table(args.repeats, args.quick)
    nodes_table()
    jkr_table(args.quick)
    half_plane_table(args.quick)
    contactless_table(args.repeats)
    t_pull = pull_off_table(args.quick)
    dt, err = times[("alpha* = 0", 3)]
    print(f"\ngoals: one cohesive state to 1e-8 in <= 1 ms -- lambda = 3, alpha* = 0: {dt * 1e3:.2f} ms, "
          f"error {err:.0e}; a pull-off in <= 100 ms -- fastest above {t_pull * 1e3:.0f} ms")


if __name__ == "__main__":
    main()
