"""``jkrcyl cohesive``: the Maugis-Dugdale figures (jkrcyl.plotting.cohesive) -- the load-control pull-off against
lambda for several M with its JKR and Baney-Hui asymptotes, and the (lambda, M) map of the pull-off showing where
it vanishes (Dask on --workers local processes; the extra 'map': pip install 'jkrcyl[map]')."""
from __future__ import annotations

import csv
import pathlib
import time

import numpy as np

from .._validate import count, finite_scalar
from . import inputs


def run(args):
    from ..analysis.cohesive_map import OUTCOMES, pull_off_map
    from ..plotting import cohesive as fig
    from ..plotting import registry, style
    n = count("n", args.n, 2, 1000)
    workers = count("workers", args.workers, 1, 64)
    lo = finite_scalar("lambda_min", args.lambda_min, low=0.0, low_open=True)
    hi = finite_scalar("lambda_max", args.lambda_max, low=lo, low_open=True)
    m_lo = finite_scalar("M_min", args.M_min, low=0.0, low_open=True)
    m_hi = finite_scalar("M_max", args.M_max, low=m_lo, low_open=True)
    gb = style.figure_gb(args.theta) if args.gb is None else args.gb
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    plt = style.mpl()
    if not args.map_only:
        f, rows = fig.pull_off_figure(theta=args.theta, gb=gb, workers=workers)
        f.savefig(out / "cohesive_pull_off.png", dpi=110)
        plt.close(f)
        registry.write_csv(out / "cohesive_pull_off.csv", rows)
    t = time.perf_counter()
    pm = pull_off_map(np.geomspace(lo, hi, n), np.geomspace(m_lo, m_hi, n), args.theta, gb, workers=workers)
    took = time.perf_counter() - t
    f = fig.map_figure(pm)
    f.savefig(out / "cohesive_map.png", dpi=110)
    plt.close(f)
    with open(out / "cohesive_map.csv", "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["lambda", "M", "P_star", "P_star_jkr", "outcome"])
        for i, lam in enumerate(pm.lam):
            for j, M in enumerate(pm.M):
                w.writerow([inputs.number(lam), inputs.number(M), inputs.number(pm.P_star[i, j]),
                            inputs.number(pm.P_star_jkr[j]), OUTCOMES[pm.outcome[i, j]]])
    print(f"wrote {out}: the {n} x {n} map in {took:.1f} s on {workers} workers "
          f"(theta={inputs.number(args.theta)} gb={inputs.number(gb)})")
    return 0


def register(sub):
    p = sub.add_parser("cohesive", help="Maugis-Dugdale figures: pull-off against lambda, (lambda, M) pull-off map",
                       description="Draws cohesive_pull_off.png (P* of the load-control pull-off against lambda "
                                   "for several M, with JKR's and Baney-Hui's asymptotes) and cohesive_map.png/.csv "
                                   "(the pull-off over (lambda, M), P*/P*_JKR, where it vanishes and why) into OUT.")
    p.add_argument("--out", default="figures", help="output folder (default: figures)")
    p.add_argument("--n", type=int, default=100, help="map points per axis (default 100)")
    p.add_argument("--workers", type=int, default=2, help="Dask worker processes (default 2)")
    p.add_argument("--theta", type=inputs.number_arg, default=1.0, help="vartheta (default 1)")
    p.add_argument("--gb", type=inputs.number_arg, default=None, help="(1/G_I)/beta* (default: the figures' pair)")
    p.add_argument("--lambda-min", type=inputs.number_arg, default=0.01, help="smallest lambda (default 0.01)")
    p.add_argument("--lambda-max", type=inputs.number_arg, default=10.0,
                   help="largest lambda (default 10: beyond, the pull-off is JKR's to ~1e-4, as lambda^-4, and the "
                        "collocation's cost grows as lambda^3)")
    p.add_argument("--M-min", type=inputs.number_arg, default=0.01, help="smallest M (default 0.01)")
    p.add_argument("--M-max", type=inputs.number_arg, default=1.0, help="largest M (default 1)")
    p.add_argument("--map-only", action="store_true", help="skip the pull-off against lambda figure")
    p.set_defaults(func=run)
