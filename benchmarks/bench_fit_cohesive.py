"""Benchmark (not a test): jkrcyl.fit with the cohesive (Maugis-Dugdale) law, coverage and speed (issue 20).

Run: python benchmarks/bench_fit_cohesive.py [--replicates 200] [--workers 2] [--lam 1]
     (smoke: --replicates 4)

Prints, in one run:
  * speed: a 50-point fit of (w, E, sigma0) at lambda = 1 (widths 1.2-20 mm, README pair, R 10 mm, Delta 3 um,
    w 0.05) without intervals and with profile-likelihood intervals (warm: the numba cache filled);
  * coverage of the 95 % profile-likelihood intervals of w, E* and sigma0 over --replicates synthetic data sets
    (30 widths, eps = 0.06-1.0 rad, 10 N/m normal noise on the load, about 1.2 % of the pull-off force), with the
    RMS relative errors, the fits that failed (ValueError) and the open (one-sided) intervals.
The data sets are Contact.at_contact states (the route the fit evaluates; tests/test_fit_cohesive.py recovers the
truth from the traced branch's states, an independent route), noise from numpy's PCG64 seeded by the replicate.
"""
import argparse
import math
import statistics
import time
import warnings
from concurrent.futures import ProcessPoolExecutor

import numpy as np

import jkrcyl

R, DELTA, W, SIGMA_P = 10e-3, 3e-6, 0.05, 10.0
PAIR = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
E_STAR = 4 / PAIR.beta
FREE = ("w", "E", "sigma0")


def design(lam, n):
    c = jkrcyl.Contact.with_lambda(R=R, Delta=DELTA, w=W, materials=PAIR, lambda_=lam)
    eps = np.linspace(0.06, 1.0, n)
    return c, 2 * R * eps, c.at_contact(eps).P


def speed(lam):
    c, width, P = design(lam, 50)
    noisy = P + np.random.default_rng(0).normal(0.0, SIGMA_P, P.size)
    kw = dict(P=noisy, width=width, R=R, Delta=DELTA, materials=PAIR, free=FREE, sigma_P=SIGMA_P)
    out = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        jkrcyl.fit(**kw, interval=None)                   # warm-up (numba, tables)
        for name, interval in (("no intervals", None), ("profile intervals", "profile")):
            t = time.perf_counter()
            res = jkrcyl.fit(**kw, interval=interval)
            out[name] = (time.perf_counter() - t, res.nfev)
    return out


def coverage_one(args):
    seed, lam = args
    c, width, P = design(lam, 30)
    noisy = P + np.random.default_rng(seed).normal(0.0, SIGMA_P, P.size)
    truth = {"w": W, "E": E_STAR, "sigma0": c.sigma0}
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            res = jkrcyl.fit(P=noisy, width=width, R=R, Delta=DELTA, materials=PAIR, free=FREE, sigma_P=SIGMA_P)
    except ValueError as exc:
        return {"error": str(exc)[:120]}
    return {n: (res.values[n] / truth[n] - 1, res.intervals[n][0] < truth[n] < res.intervals[n][1],
                math.isinf(res.intervals[n][1]) or res.intervals[n][0] == 0.0) for n in FREE}


def coverage(replicates, workers, lam):
    t = time.perf_counter()
    with ProcessPoolExecutor(workers) as ex:
        rows = list(ex.map(coverage_one, [(s, lam) for s in range(replicates)]))
    elapsed = time.perf_counter() - t
    ok = [r for r in rows if "error" not in r]
    errors = [r["error"] for r in rows if "error" in r]
    print(f"coverage at lambda = {lam:g}: {replicates} replicates, {len(ok)} fitted, {len(errors)} ValueError "
          f"({elapsed:.0f} s on {workers} workers)")
    for n in FREE:
        cov = sum(r[n][1] for r in ok) / max(len(ok), 1)
        rms = math.sqrt(statistics.fmean(r[n][0] ** 2 for r in ok)) if ok else math.nan
        bias = statistics.fmean(r[n][0] for r in ok) if ok else math.nan
        sd = math.sqrt(cov * (1 - cov) / max(len(ok), 1))
        print(f"  {n:7s} coverage {100 * cov:5.1f} % (binomial sd {100 * sd:.1f} %), RMS error {100 * rms:.2f} %, "
              f"mean error {100 * bias:+.2f} %, open intervals {sum(r[n][2] for r in ok)}")
    for e in sorted(set(errors))[:5]:
        print(f"  error: {e}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--replicates", type=int, default=200)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--lam", type=float, default=1.0)
    args = ap.parse_args()
    for name, (dt, nfev) in speed(args.lam).items():
        print(f"speed: 50-point fit of (w, E, sigma0) at lambda = {args.lam:g}, {name}: {dt:.2f} s "
              f"({nfev} evaluations in the main descent)")
    coverage(args.replicates, args.workers, args.lam)


if __name__ == "__main__":
    main()
