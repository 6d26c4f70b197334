"""Benchmark (not a test): jkrcyl.fit, accuracy, coverage and speed (issue 20).

Run: python benchmarks/bench_fit.py [--replicates 1000] [--halfplane 400] [--workers 2]
     (smoke: --replicates 20 --halfplane 20 --recovery 10)

Prints, in one run:
  * speed: a 50-point fit of (w, E) with profile-likelihood intervals, alpha* = 0 (two equal polymer bodies) and
    alpha* != 0 (steel pin, E 210 GPa nu 0.3, in aluminium, E 70 GPa nu 0.33): warm (median of 5) and cold (one fit
    in a fresh process, numba cache filled); goals <= 1 s and <= 10 s;
  * coverage of the 95 % intervals over --replicates synthetic data sets of the README example design (30 widths
    6.5-21 mm, sd 0.1 mm on the width and 10 N/m on the load, R 10 mm, Delta 3 um, w 0.05, E 2.6 GPa): profile
    likelihood (the library's) and, from the same fits, the log-Wald interval; goal 93-97 %, <= 10 min on 2 cores;
  * half-plane limit (R 10 mm, Delta 30 um: M = 0.011, contacts below 15 deg): RMS relative error of w from the
    direct fit and from the linearised plot P/sqrt(a_h) against a_h^(3/2) (reference/halfplane.py) at 2 % noise
    on the width, --halfplane replicates per design; goal: direct <= half the linear plot's (main design);
  * recovery: Delta fitted (w, Delta from widths with E known; w, E, Delta, offset from delta_work data), and the
    alpha* != 0 pair against the alpha* = 0 pair in the same normalised design.
Every synthetic data set comes from jkrcyl.Contact.state (the library's model), noise from numpy's PCG64 seeded
by the replicate number.
"""
import argparse
import math
import pathlib
import platform
import statistics
import subprocess
import sys
import time
import warnings
from concurrent.futures import ProcessPoolExecutor

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))                    # reference/ (the linearised plot)

import jkrcyl                                    # noqa: E402
from jkrcyl.fit import model                     # noqa: E402
from reference.halfplane import linearised_plot  # noqa: E402

POLYMER = dict(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
STEEL_IN_ALUMINIUM = dict(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3)


def materials(pair):
    return jkrcyl.Materials.from_young(**pair)


def widths_loads(pair, R, Delta, w, n, lo, hi):
    """n widths from lo to hi times the fixed-load pull-off width, and the model's loads there."""
    m = materials(pair)
    width = np.linspace(lo, hi, n) * jkrcyl.Contact(R, Delta, w, m).pull_off().contact_width
    return width, jkrcyl.Contact(R, Delta, w, m).state(np.tan(width / (4 * R))).P


# --- speed ---------------------------------------------------------------------------------------------------
SPEED_CASE = dict(R=0.01, Delta=1e-5, w=0.05, n=50, lo=1.05, hi=5.0)


def speed_fit(pair_name):
    pair = POLYMER if pair_name == "polymer" else STEEL_IN_ALUMINIUM
    c = SPEED_CASE
    width, P = widths_loads(pair, c["R"], c["Delta"], c["w"], c["n"], c["lo"], c["hi"])
    rng = np.random.default_rng(0)
    x = width * (1 + rng.normal(0, 0.01, width.size))
    t = time.perf_counter()
    jkrcyl.fit(P=P, width=x, R=c["R"], Delta=c["Delta"], materials=materials(pair), sigma_width=0.01 * x)
    return time.perf_counter() - t


def speed():
    print("speed: 50-point fit of (w, E), profile-likelihood intervals")
    for name, goal in (("polymer", 1.0), ("steel-in-aluminium", 10.0)):
        code = (f"import sys, time; sys.path.insert(0, {str(ROOT / 'benchmarks')!r}); t = time.perf_counter(); "
                f"import bench_fit as b; t1 = time.perf_counter(); f = b.speed_fit({name!r}); "
                "print(t1 - t, f)")
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split()
        speed_fit(name)                                              # warm this process
        warm = statistics.median(speed_fit(name) for _ in range(5))
        print(f"  {name:<20} warm {warm:7.3f} s   cold (fresh process: fit {float(out[1]):.2f} s after "
              f"{float(out[0]):.2f} s of imports)   goal <= {goal:g} s")


# --- coverage ------------------------------------------------------------------------------------------------
COVERAGE_CASE = dict(R=0.01, Delta=3e-6, w=0.05, n=30, sigma_width=1e-4, sigma_P=10.0)


def coverage_one(seed):
    c = COVERAGE_CASE
    m = materials(POLYMER)
    width = np.linspace(6.5e-3, 21e-3, c["n"])
    P = jkrcyl.Contact(c["R"], c["Delta"], c["w"], m).state(np.tan(width / (4 * c["R"]))).P
    rng = np.random.default_rng(seed)
    x, y = width + rng.normal(0, c["sigma_width"], c["n"]), P + rng.normal(0, c["sigma_P"], c["n"])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = jkrcyl.fit(P=y, width=x, R=c["R"], Delta=c["Delta"], materials=m, sigma_P=c["sigma_P"],
                       sigma_width=c["sigma_width"])
    truth = {"w": c["w"], "E": 4 / m.beta}
    out = {}
    for k, v in truth.items():
        lo, hi = r.intervals[k]
        z = 1.959963984540054 * r.standard_errors[k] / r.values[k]       # log-Wald from the same fit
        out[k] = (lo <= v <= hi, r.values[k] * math.exp(-z) <= v <= r.values[k] * math.exp(z), r.values[k] / v - 1)
    return out


def coverage(replicates, workers):
    t = time.perf_counter()
    with ProcessPoolExecutor(workers) as ex:
        rows = list(ex.map(coverage_one, range(replicates), chunksize=10))
    dt = time.perf_counter() - t
    print(f"coverage of 95 % intervals, {replicates} replicates, {workers} workers: {dt:.1f} s "
          f"({dt / 60:.2f} min; goal <= 10 min)")
    for k in ("w", "E"):
        prof = np.mean([r[k][0] for r in rows])
        wald = np.mean([r[k][1] for r in rows])
        err = np.array([r[k][2] for r in rows])
        se = math.sqrt(0.95 * 0.05 / replicates)
        print(f"  {k}: profile likelihood {100 * prof:.1f} %, log-Wald {100 * wald:.1f} % (binomial sd "
              f"{100 * se:.1f} %); bias {100 * err.mean():+.3f} %, sd {100 * err.std():.3f} %   goal 93-97 %")


# --- half-plane limit ------------------------------------------------------------------------------------------
HALFPLANE = dict(R=0.01, Delta=3e-5, w=0.05, noise=0.02)
DESIGNS = (("main: 25 widths, 1.05-4 x pull-off width", 25, 1.05, 4.0, ("w", "E")),
           ("10 widths, 1.05-3 x", 10, 1.05, 3.0, ("w", "E")),
           ("20 widths, 1.6-4 x (no points near pull-off)", 20, 1.6, 4.0, ("w", "E")),
           ("15 widths, 1.05-2 x (narrow)", 15, 1.05, 2.0, ("w", "E")),
           ("10 widths, 1.05-3 x, E known", 10, 1.05, 3.0, ("w",)))


def halfplane_one(args):
    seed, n, lo, hi, free = args
    h = HALFPLANE
    m = materials(POLYMER)
    width, P = widths_loads(POLYMER, h["R"], h["Delta"], h["w"], n, lo, hi)
    x = width * (1 + np.random.default_rng(seed).normal(0, h["noise"], n))
    A = None if "E" in free else m.beta / (2 * math.pi)
    w_lin, _ = linearised_plot(x, P, h["R"], h["Delta"], A=A)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = jkrcyl.fit(P=P, width=x, R=h["R"], Delta=h["Delta"], materials=m, free=free,
                       sigma_width=h["noise"] * x, interval=None)
    return r.values["w"] / h["w"] - 1, w_lin / h["w"] - 1


def halfplane(replicates, workers):
    h = HALFPLANE
    c = jkrcyl.Contact(h["R"], h["Delta"], h["w"], materials(POLYMER))
    print(f"half-plane limit: Delta/R = {h['Delta'] / h['R']:g}, M = {c.M:.4f}, {100 * h['noise']:g} % noise on "
          f"the width, {replicates} replicates; RMS relative error of w")
    with ProcessPoolExecutor(workers) as ex:
        for name, n, lo, hi, free in DESIGNS:
            rows = np.array(list(ex.map(halfplane_one, [(s, n, lo, hi, free) for s in range(replicates)],
                                        chunksize=20)))
            rms = np.sqrt(np.mean(rows ** 2, axis=0))
            print(f"  {name:<46} direct fit {100 * rms[0]:5.2f} %  linearised plot {100 * rms[1]:5.2f} %  "
                  f"ratio {rms[0] / rms[1]:.2f}" + ("   goal <= 0.5" if name.startswith("main") else ""))


# --- recovery ----------------------------------------------------------------------------------------------------
def recovery_one(args):
    seed, kind = args
    R, Delta, w = 0.01, 1e-5, 0.05
    pair = STEEL_IN_ALUMINIUM if kind == "steel" else POLYMER
    m = materials(pair)
    rng = np.random.default_rng(seed)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        if kind.startswith("approach"):
            a_fold = np.tan(jkrcyl.Contact(R, Delta, w, m).pull_off().contact_width / (4 * R))
            a = np.geomspace(1.02 * a_fold, 5 * a_fold, 40)
            s = jkrcyl.Contact(R, Delta, w, m).state(a)
            sP, sd = 0.005 * np.ptp(s.P), 0.005 * np.ptp(s.delta_work)
            r = jkrcyl.fit(P=s.P + rng.normal(0, sP, a.size), delta_work=s.delta_work + 2e-7 +
                           rng.normal(0, sd, a.size), R=R, Delta=0.7 * Delta, materials=m, sigma_P=sP,
                           sigma_delta_work=sd, interval=None,
                           free=("w", "E", "Delta", "offset") if kind == "approach-all" else ("w", "Delta", "offset"))
            return r.values["Delta"] / Delta - 1, r.values["w"] / w - 1
        width, P = widths_loads(pair, R, Delta, w, 50, 1.05, 5.0)
        x = width * (1 + rng.normal(0, 0.01, width.size))
        free = ("w", "Delta") if kind == "Delta" else ("w", "E")
        r = jkrcyl.fit(P=P, width=x, R=R, Delta=0.7 * Delta if kind == "Delta" else Delta, materials=m,
                       sigma_width=0.01 * x, free=free, interval=None)
        second = r.values["Delta"] / Delta - 1 if kind == "Delta" else r.values["E"] * m.beta / 4 - 1
        return r.values["w"] / w - 1, second


def recovery(replicates, workers):
    print(f"recovery ({replicates} replicates each; R 10 mm, Delta 10 um, w 0.05; RMS and max relative errors)")
    rows = {}
    with ProcessPoolExecutor(workers) as ex:
        for kind in ("polymer", "steel", "Delta", "approach", "approach-all"):
            rows[kind] = np.array(list(ex.map(recovery_one, [(s, kind) for s in range(replicates)])))
    label = {"polymer": ("w", "E", "alpha* = 0 pair, widths, 1 % noise, fit (w, E)"),
             "steel": ("w", "E", "steel in aluminium (alpha*/beta* = 0.117), same design"),
             "Delta": ("w", "Delta", "widths, fit (w, Delta), E known, start Delta 0.7 x truth"),
             "approach": ("Delta", "w", "delta_work data, 0.5 % noise on both, fit (w, Delta, offset), E known"),
             "approach-all": ("Delta", "w", "the same, fit (w, E, Delta, offset): E, Delta, offset nearly degenerate")}
    for kind, v in rows.items():
        a, b, text = label[kind]
        rms, mx = np.sqrt(np.mean(v ** 2, axis=0)), np.abs(v).max(axis=0)
        print(f"  {text:<74} {a}: RMS {100 * rms[0]:.3f} % max {100 * mx[0]:.3f} %; "
              f"{b}: RMS {100 * rms[1]:.3f} % max {100 * mx[1]:.3f} %")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--replicates", type=int, default=1000)
    ap.add_argument("--halfplane", type=int, default=400)
    ap.add_argument("--recovery", type=int, default=100)
    ap.add_argument("--workers", type=int, default=2)
    args = ap.parse_args()
    print(f"# {platform.processor() or platform.machine()}, python {platform.python_version()}, "
          f"numpy {np.__version__}, {args.workers} worker processes")
    speed()
    coverage(args.replicates, args.workers)
    halfplane(args.halfplane, args.workers)
    recovery(args.recovery, args.workers)


if __name__ == "__main__":
    main()
