"""Benchmark (not a test): the full equilibrium state per contact parameter, into preallocated outputs.

Run: make bench   (or: python benchmarks/bench_state.py [--n 1000000] [--repeats 5]).
Smoke mode for the test suite: --n 1000 --repeats 1 (skips scipy quad if scipy is missing).

Compares, on the same n contact parameters a (identical materials, vartheta = 1, as bench_gap.py):
  * the generated fused kernel full_state (P, B, C, c0, c1, r0, K, G, delta, h(pi)) written into
    preallocated arrays (full_state_into, serial; full_state_into_parallel, prange) -- what
    jkrcyl.numerics.kernels.full_state calls -- and that layer call itself (it allocates the outputs);
  * a floor: a numba loop over the transcendental functions the state needs and nothing else,
    sqrt(a)        zeta* enters as zeta* sqrt(a) (Griffith condition (3.6b): r0, P, B, C, K, h(pi)),
    sqrt(1 + a^2)  E = sec(eps/2) of section 4 (r0, C, K, delta, h(pi)),
    log1p(a^2)     L = log(1 + a^2), the denominator of (4.4) and every load,
    log1p(1/a^2)   log sin(eps/2) = -log1p(1/a^2)/2 of the approach (5.8),
    asinh(1/a)     h(pi) of (5.10) (a <= 4; a series in 1/a^2 above),
    the list of math.* calls of generated/state.py apart from the constants sqrt(2), sqrt(pi), sqrt(R);
  * sympy.lambdify(..., "numpy", cse=True) of the same sympy expressions the kernel is emitted from;
  * the paper's printed formulas (reference/paper.py) vectorised with numpy, and per point in mpmath;
  * h(pi) alone: scipy.integrate.quad of (5.10) (bench_gap.h_pi_quad, subsample) vs gap_pi;
  * a fresh process importing jkrcyl and computing one state (numba cache warm).
Prints the machine, versions, per-point medians over the repeats and the ratios, serial and prange.
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

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))    # derive/, reference/ are not installed
from reference import paper  # noqa: E402
from jkrcyl.generated import gap as _gap
from jkrcyl.generated import state as _state
from jkrcyl.numerics import kernels as _kernels

# identical materials (G = G_I = 1, kappa = kappa_I = 2): beta* = 3, vartheta = 1; constants of bench_gap.py
R, DELTA, BETA, INV_THETA, ZETA = 1.0, 1e-3, 3.0, 1.0, 2e-3
INV_G_I = 1.0
THETA = 1.0 / INV_THETA
KW = dict(Delta=DELTA, beta=BETA, inv_theta=INV_THETA, zeta=ZETA)
FIELDS = ("P", "B", "C", "delta", "h_pi")        # what every contender computes


# --- the contenders ---------------------------------------------------------------------------------
def _into(parallel):
    """full_state into preallocated outputs (allocated once per size): compute only, no page faults."""
    fill = _state.full_state_into_parallel if parallel else _state.full_state_into
    cache = {}

    def run(a):
        out = cache.get(a.size)
        if out is None:
            out = cache[a.size] = _state.FullState(*(np.zeros(a.size) for _ in _state.FullState._fields))
        fill(out, R=R, a=a, inv_G_I=INV_G_I, **KW)
        return tuple(getattr(out, k) for k in FIELDS)
    return run


kernels_serial, kernels_parallel = _into(False), _into(True)


def layer_call(a):
    """jkrcyl.numerics.kernels.full_state: allocates its outputs (first touch of fresh pages)."""
    out = _kernels.full_state(a, R=R, inv_G_I=INV_G_I, **KW)
    return tuple(getattr(out, k) for k in FIELDS)


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
    """The printed formulas (reference/paper.py): (4.4), (4.5a,b), (5.8), and (5.10) in closed form."""
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


def _floor_body(x):
    return (math.sqrt(x) + math.sqrt(1.0 + x * x) + math.log1p(x * x) + math.log1p(1.0 / (x * x))
            + math.asinh(1.0 / x))


_floor_point = njit(cache=True)(_floor_body)


@njit(cache=True)
def _floor_serial(a, out):
    for i in range(a.shape[0]):
        out[i] = _floor_point(a[i])


@njit(parallel=True, cache=True)
def _floor_parallel(a, out):
    for i in prange(a.shape[0]):
        out[i] = _floor_point(a[i])


def _floor(kernel):
    cache = {}

    def run(a):
        out = cache.setdefault(a.size, np.zeros(a.size))
        kernel(a, out)
        return out
    return run


floor_serial, floor_parallel = _floor(_floor_serial), _floor(_floor_parallel)


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
    rows += [("floor: sqrt(a), sqrt(1+a^2), log1p(a^2), log1p(1/a^2), asinh(1/a), serial", t_floor),
             (f"floor, prange ({opts.threads} threads)", t_floor_par),
             ("generated kernels, serial: full_state_into (preallocated)", t_ser),
             (f"generated kernels, prange ({opts.threads} threads): full_state_into_parallel", t_par),
             ("layer call kernels.full_state (allocates its outputs)", per_point(layer_call, a, opts.repeats))]
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
    print(f"{'contender':76s} {'ns/point':>9s} {'/ floor':>8s} {'/ state':>8s}")
    for label, t in rows:
        print(f"{label:76s} {t * 1e9:9.1f} {t / t_floor:8.2f} {t / best:8.2f}")

    # accuracy sanity: every contender against the kernels (relative to the scale of each output)
    ref = kernels_serial(a)
    ref = tuple(x.copy() for x in ref)
    checks = [("prange", kernels_parallel(a)), ("layer call", layer_call(a)), ("lambdify", lam(a)),
              ("numpy paper", numpy_paper(a))]
    print()
    for label, out in checks:
        err = max(float(np.max(np.abs(o - r)) / np.max(np.abs(r))) for o, r in zip(out, ref))
        print(f"max |{label} - kernels| / max|kernels| = {err:.1e}")

    # h(pi) alone vs the paper's method (quadrature of (5.10))
    print()
    h_out = np.zeros(a.size)
    t_hpi = per_point(lambda x: _gap.gap_pi_into(h_out[: x.size], a=x, **KW), a, opts.repeats)
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
        hk = _kernels.gap_pi(sub, **KW)
        err = np.max(np.abs(hk - hq) / np.maximum(np.abs(hq), DELTA))
        print(f"h(pi) by scipy quad of (5.10) ({sub.size} points): {t_quad * 1e9:.0f} ns/point, "
              f"{t_quad / t_hpi:.0f}x the kernel; max |kernel - quad|/max(|h|, Delta) = {err:.1e}")

    t_proc, t_bare = fresh_process_seconds(max(1, min(opts.repeats, 3)))
    print(f"fresh process, import jkrcyl + one state (cache warm): {t_proc:.2f} s "
          f"(python -c 'import numpy, numba' alone: {t_bare:.2f} s)")
    print(f"lambdify setup (sympy expressions + lambdify): {t_lam_setup:.1f} s")

    print()
    print("goals:")
    goal = [("state within 1.5x floor, serial", best / t_floor, best <= 1.5 * t_floor),
            ("state within 1.5x floor, prange", t_par / t_floor_par, t_par <= 1.5 * t_floor_par),
            (">= 5x faster than lambdify-numpy", t_lam / best, t_lam >= 5 * best),
            (f"prange speed-up >= 1.8x on {opts.threads} threads", t_ser / t_par, t_ser >= 1.8 * t_par),
            ("fresh process < 1 s", t_proc, t_proc < 1.0)]
    if t_quad is not None:
        goal.insert(2, ("h(pi) >= 1000x faster than quad", t_quad / t_hpi, t_quad >= 1000 * t_hpi))
    for label, value, ok in goal:
        print(f"  {label:40s} {value:10.2f}  {'met' if ok else 'NOT met'}")


if __name__ == "__main__":
    main()
