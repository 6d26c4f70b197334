"""Benchmark (not a test): the full equilibrium state (P, B, C, delta, h(pi)) per contact parameter.

Run: make bench   (or: python benchmarks/bench_state.py [--n 1000000] [--repeats 5]).
Smoke mode for the test suite: --n 1000 --repeats 1 (skips scipy quad if scipy is missing).

Compares, on the same n contact parameters a (identical materials, vartheta = 1, as bench_gap.py):
  * the generated numba kernels load_state + approach + gap_pi, serial (_array) and prange (_parallel);
  * sympy.lambdify(..., "numpy", cse=True) of the same sympy expressions the kernels are emitted from;
  * the paper's printed formulas (jkrcyl.paper) vectorised with numpy;
  * the same printed formulas per point in mpmath (subsample, scaled to per point);
  * a floor: a numba loop over sqrt(a), log1p(a^2), sqrt(1 + a^2), log(a) only;
  * h(pi) alone: scipy.integrate.quad of (5.10) (bench_gap.h_pi_quad, subsample) vs gap_pi;
  * a fresh process importing jkrcyl and computing one state (numba cache warm).
Prints the machine, versions, per-point medians over the repeats and the ratios.
"""
import argparse
import math
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

import mpmath
import numba
import numpy as np
from numba import njit, prange

from jkrcyl import paper

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))    # derive/ (the sympy sources) is not installed
from jkrcyl.generated import approach as _approach
from jkrcyl.generated import gap as _gap
from jkrcyl.generated import load as _load

# identical materials (G = G_I = 1, kappa = kappa_I = 2): beta* = 3, vartheta = 1; constants of bench_gap.py
R, DELTA, BETA, INV_THETA, ZETA = 1.0, 1e-3, 3.0, 1.0, 2e-3
INV_G_I = 1.0
THETA = 1.0 / INV_THETA
KW = dict(Delta=DELTA, beta=BETA, inv_theta=INV_THETA, zeta=ZETA)


# --- the contenders ---------------------------------------------------------------------------------
def kernels_serial(a):
    P, B, C, c0, c1, r0 = _load.load_state_array(R=R, a=a, **KW)
    delta, _ = _approach.approach_array(a=a, inv_G_I=INV_G_I, **KW)
    return P, B, C, delta, _gap.gap_pi_array(a=a, **KW)


def kernels_parallel(a):
    P, B, C, c0, c1, r0 = _load.load_state_parallel(R=R, a=a, **KW)
    delta, _ = _approach.approach_parallel(a=a, inv_G_I=INV_G_I, **KW)
    return P, B, C, delta, _gap.gap_pi_parallel(a=a, **KW)


try:
    from jkrcyl.generated import state as _state
except ImportError:                         # generated/state.py (derive/state.py) not emitted
    _state = None


def fused_kernel():
    """The fused full_state kernel (derive/state.py): array forms, which allocate fresh outputs."""
    if _state is None:
        return None, None
    args = dict(R=R, inv_G_I=INV_G_I, **KW)
    return (lambda a: _state.full_state_array(a=a, **args)), (lambda a: _state.full_state_parallel(a=a, **args))


def _into(parallel):
    """The scalar full_state into preallocated outputs: compute only, no page faults of fresh arrays."""
    full_state = _state.full_state
    loop = prange if parallel else range

    def into(a, out, Delta, R_, beta, inv_G_I, inv_theta, zeta):
        for i in loop(a.shape[0]):
            out[0, i], out[1, i], out[2, i], out[3, i], out[4, i], out[5, i], out[6, i], out[7, i] = \
                full_state(Delta, R_, a[i], beta, inv_G_I, inv_theta, zeta)
    into = njit(parallel=parallel)(into)
    cache = {}

    def run(a):
        out = cache.get(a.size)
        if out is None:
            out = cache[a.size] = np.zeros((8, a.size))
        into(a, out, DELTA, R, BETA, INV_G_I, INV_THETA, ZETA)
        return out
    return run


def state_expressions():
    """(P, B, C, delta, h_pi) as the sympy expressions the kernels are emitted from (cheap accessors)."""
    from derive import approach, gap, load
    sol = load.solution()
    delta = approach.Delta * approach.d_Delta() + approach.zeta * approach.d_zeta()
    h_pi, _ = gap.stable_gap_forms()
    return [sol["P"], sol["B"], sol["C"], delta, h_pi]


def lambdified():
    import sympy as sp
    from derive import symbols as S
    exprs = state_expressions()
    args = [S.Delta, S.R, S.a, S.beta, S.inv_G_I, S.inv_theta, S.zeta]
    f = sp.lambdify(args, exprs, modules="numpy", cse=True)
    return lambda a: f(DELTA, R, a, BETA, INV_G_I, INV_THETA, ZETA)


def paper_state(a, lib):
    """The printed formulas (jkrcyl.paper): (4.4), (4.5a,b), (5.8), and (5.10) in closed form."""
    P = paper.P_44(a, DELTA, BETA, THETA, ZETA, lib)
    B = paper.B_45a(a, DELTA, R, BETA, THETA, ZETA, lib)
    C = paper.C_45b(a, DELTA, R, BETA, THETA, ZETA, lib)
    delta = paper.delta_58(a, DELTA, R, BETA, THETA, 1 / INV_G_I, ZETA, lib)
    c0, c1 = -DELTA - R * BETA * B / (8 * lib.pi * THETA), BETA * P / (2 * lib.pi)
    E = paper.E(a, lib)
    h_pi = -2 * E * c0 + c1 * (lib.asinh(1 / a) - 1 / E)
    return P, B, C, delta, h_pi


def numpy_paper(a):
    return paper_state(a, np)


def mpmath_paper(a):
    return [paper_state(mpmath.mpf(float(x)), mpmath) for x in a]


@njit(cache=True)
def floor_serial(a):
    s = 0.0
    for i in range(a.shape[0]):
        x = a[i]
        s += math.sqrt(x) + math.log1p(x * x) + math.sqrt(1.0 + x * x) + math.log(x)
    return s


@njit(parallel=True, cache=True)
def floor_parallel(a):
    s = 0.0
    for i in prange(a.shape[0]):
        x = a[i]
        s += math.sqrt(x) + math.log1p(x * x) + math.sqrt(1.0 + x * x) + math.log(x)
    return s


@njit(cache=True)
def floor_all_serial(a):
    """The floor plus the two functions the state also needs: log1p(1/a^2) of delta, asinh(1/a) of h(pi)."""
    s = 0.0
    for i in range(a.shape[0]):
        x = a[i]
        s += (math.sqrt(x) + math.log1p(x * x) + math.sqrt(1.0 + x * x) + math.log(x)
              + math.log1p(1.0 / (x * x)) + math.asinh(1.0 / x))
    return s


# --- timing -------------------------------------------------------------------------------------------
def per_point(fn, a, repeats):
    """Median seconds per point over `repeats` calls (after one untimed warm-up call)."""
    fn(a[:8].copy())
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn(a)
        times.append(time.perf_counter() - t0)
    return statistics.median(times) / a.size


def fresh_process_seconds(repeats):
    """Wall time of a new interpreter importing jkrcyl and computing one state (numba cache warm)."""
    code = ("import jkrcyl; m = jkrcyl.Materials(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0); "
            "jkrcyl.Contact(R=1.0, Delta=0.01, w=1e-4, materials=m).state(0.5)")

    def run(src):
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-c", src], check=True)
        return time.perf_counter() - t0

    run(code)                                    # fills the numba cache if it is cold
    bare = statistics.median(run("import numpy, numba") for _ in range(repeats))
    return statistics.median(run(code) for _ in range(repeats)), bare


def machine():
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(line.split(":", 1)[1].strip() for line in f if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    import sympy
    versions = (f"python {platform.python_version()}, numpy {np.__version__}, numba {numba.__version__}, "
                f"sympy {sympy.__version__}, mpmath {mpmath.__version__}")
    try:
        import scipy
        versions += f", scipy {scipy.__version__}"
    except ImportError:
        versions += ", scipy missing (quad skipped)"
    return f"{cpu}, {os.cpu_count()} logical CPUs, numba threads {numba.get_num_threads()}", versions


def contact_parameters(n):
    """n contact parameters a in [1e-3, 1e1], shuffled, away from a_crit (where P is infinite)."""
    a = np.logspace(-3, 1, n + n // 10)
    a = a[np.abs(2 - INV_THETA * (np.log1p(a * a) + 2 * a**4)) > 1e-2][:n]
    return np.random.default_rng(0).permutation(a)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1_000_000, help="contact parameters (default 1e6)")
    parser.add_argument("--repeats", type=int, default=5, help="timed repeats per contender (median)")
    parser.add_argument("--threads", type=int, default=min(2, numba.config.NUMBA_NUM_THREADS))
    opts = parser.parse_args(argv)
    numba.set_num_threads(opts.threads)
    a = contact_parameters(opts.n)
    n_mp = max(20, a.size // 1000)
    n_quad = max(10, a.size // 5000)

    cpu, versions = machine()
    print(f"full equilibrium state (P, B, C, delta, h(pi)), n = {a.size}, a in [1e-3, 1e1], "
          f"vartheta = 1, medians of {opts.repeats}")
    print(f"machine : {cpu}")
    print(f"versions: {versions}")

    rows = []                                         # (label, seconds per point)
    t_floor = per_point(floor_serial, a, opts.repeats)
    t_floor_par = per_point(floor_parallel, a, opts.repeats)
    t_ser = per_point(kernels_serial, a, opts.repeats)
    t_par = per_point(kernels_parallel, a, opts.repeats)
    rows += [("floor: sqrt, log1p, sqrt, log (numba, serial)", t_floor),
             (f"floor (numba prange, {opts.threads} threads)", t_floor_par),
             ("floor + log1p(1/a^2), asinh(1/a) (numba, serial)", per_point(floor_all_serial, a, opts.repeats)),
             ("generated kernels, serial", t_ser),
             (f"generated kernels, prange ({opts.threads} threads)", t_par)]
    fused, fused_par = fused_kernel()
    if fused is not None:
        t_fused = per_point(fused, a, opts.repeats)
        t_fused_par = per_point(fused_par, a, opts.repeats)
        rows += [("fused full_state kernel, serial", t_fused),
                 (f"fused full_state kernel, prange ({opts.threads} threads)", t_fused_par)]
        rows += [("fused full_state, into preallocated outputs, serial", per_point(_into(False), a, opts.repeats)),
                 (f"fused full_state, into preallocated outputs, prange ({opts.threads})",
                  per_point(_into(True), a, opts.repeats))]
        if t_fused < t_ser:
            t_ser, t_par = t_fused, t_fused_par          # the goals below use the faster implementation
    t0 = time.perf_counter()
    lam = lambdified()
    t_lam_setup = time.perf_counter() - t0
    t_lam = per_point(lam, a, opts.repeats)
    t_np = per_point(numpy_paper, a, opts.repeats)
    t_mp = per_point(mpmath_paper, a[:n_mp], 1)
    rows += [("sympy.lambdify numpy, cse=True", t_lam),
             ("paper formulas, numpy-vectorised", t_np),
             (f"paper formulas, mpmath per point ({n_mp} points)", t_mp)]

    best = t_ser
    print()
    print(f"{'contender':58s} {'ns/point':>10s} {'/ floor':>9s} {'/ best serial':>14s}")
    for label, t in rows:
        print(f"{label:58s} {t * 1e9:10.1f} {t / t_floor:9.2f} {t / best:14.2f}")

    # accuracy sanity: every contender against the kernels (relative to the scale of each output)
    ref = kernels_serial(a)
    checks = [("prange", kernels_parallel(a)), ("lambdify", lam(a)), ("numpy paper", numpy_paper(a))]
    if fused is not None:
        out = fused(a)
        checks.append(("fused", tuple(out[k] for k in (0, 1, 2, 6, 7))))      # P, B, C, delta, h_pi
    print()
    for label, out in checks:
        err = max(float(np.max(np.abs(o - r)) / np.max(np.abs(r))) for o, r in zip(out, ref))
        print(f"max |{label} - kernels| / max|kernels| = {err:.1e}")

    # h(pi) alone vs the paper's method (quadrature of (5.10))
    print()
    t_hpi = per_point(lambda x: _gap.gap_pi_array(a=x, **KW), a, opts.repeats)
    print(f"h(pi) alone: gap_pi kernel {t_hpi * 1e9:.1f} ns/point")
    try:
        import bench_gap
    except ImportError as exc:
        print(f"h(pi) by scipy quad skipped ({exc})")
        t_quad = None
    else:
        sub = np.sort(a[:n_quad])
        bench_gap.warnings.simplefilter("ignore", bench_gap.IntegrationWarning)
        t0 = time.perf_counter()
        hq = np.array([bench_gap.h_pi_quad(x) for x in sub])
        t_quad = (time.perf_counter() - t0) / sub.size
        hk = _gap.gap_pi_array(a=sub, **KW)
        err = np.max(np.abs(hk - hq) / np.maximum(np.abs(hq), DELTA))
        print(f"h(pi) by scipy quad of (5.10) ({sub.size} points): {t_quad * 1e9:.0f} ns/point, "
              f"{t_quad / t_hpi:.0f}x the kernel; max |kernel - quad|/max(|h|, Delta) = {err:.1e}")

    t_proc, t_bare = fresh_process_seconds(max(1, min(opts.repeats, 3)))
    print(f"fresh process, import jkrcyl + one state (cache warm): {t_proc:.2f} s "
          f"(python -c 'import numpy, numba' alone: {t_bare:.2f} s)")
    print(f"lambdify setup (sympy expressions + lambdify): {t_lam_setup:.1f} s")

    print()
    print("goals:")
    goal = [("state within 1.5x floor", best / t_floor, best <= 1.5 * t_floor),
            (">= 5x faster than lambdify-numpy", t_lam / best, t_lam >= 5 * best),
            (f"prange speed-up >= 1.8x on {opts.threads} threads", t_ser / t_par, t_ser >= 1.8 * t_par),
            ("fresh process < 1 s", t_proc, t_proc < 1.0)]
    if t_quad is not None:
        goal.insert(2, ("h(pi) >= 1000x faster than quad", t_quad / t_hpi, t_quad >= 1000 * t_hpi))
    for label, value, ok in goal:
        print(f"  {label:40s} {value:10.2f}  {'met' if ok else 'NOT met'}")


if __name__ == "__main__":
    main()
