"""``jkrcyl atlas``: the regime atlas over (M, vartheta) (jkrcyl.atlas): atlas.npz, atlas.csv, PNG and PDF."""
from __future__ import annotations

import pathlib
import time

from . import inputs

GRID_MAX = 10_000        # points per axis: 10^4 x 10^4 pairs is ~1.6 GB of fields and hours on 2 cores


def run(args):
    from .. import atlas
    for name, n in (("n-M", args.n_M), ("n-theta", args.n_theta)):
        if not 2 <= n <= GRID_MAX:
            raise ValueError(f"{name} must be in [2, {GRID_MAX}] (the grid's memory and time grow with "
                             f"n-M x n-theta), got {n}")
    if not args.theta_min < args.theta_max:
        raise ValueError(f"theta-max must be > theta-min, got theta-min = {args.theta_min:g}, "
                         f"theta-max = {args.theta_max:g}")
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    Ms, th = atlas.default_grid(args.n_M, args.n_theta, M_max=args.M_max, theta_min=args.theta_min,
                                theta_max=args.theta_max, with_inf=not args.no_inf)
    t0 = time.perf_counter()
    res = atlas.classify(Ms, th, progress=not args.quiet, two_patch=args.two_patch)
    t1 = time.perf_counter()
    atlas.write_npz(out / "atlas.npz", res)
    if not args.no_csv:
        atlas.write_csv(out / "atlas.csv", res)
    files = atlas.draw(res, str(out / "atlas"))
    t2 = time.perf_counter()
    print(f"classified {Ms.size} x {th.size} pairs in {t1 - t0:.2f} s (output {t2 - t1:.2f} s); "
          f"wrote atlas.npz{'' if args.no_csv else ', atlas.csv'}, {', '.join(pathlib.Path(f).name for f in files)} "
          f"to {out}")
    return 0


def register(sub):
    t = sub.add_parser("atlas", help="regime atlas over (M, vartheta): npz, CSV and a regime map",
                       description="Classify every (M, vartheta) pair of a grid: sub-critical and super-critical "
                                   "fixed-load adherence points (feasible or not), zero-load contact (8.1), "
                                   "adherence force, and what slow pulling does in the hole (the confined "
                                   "classes: detach and land on the top, zip into full contact, or the gap "
                                   "closes first). The last row is vartheta = inf, "
                                   "where M means M_R* and P* means P_R* of (7.6). Writes atlas.npz, atlas.csv, "
                                   "atlas.png and atlas.pdf into OUT (see jkrcyl.atlas for the fields). Every "
                                   "class is a load-control result: none depends on gb.")
    t.add_argument("--out", default="atlas", help="output folder (default: atlas)")
    t.add_argument("--n-M", type=int, default=1000, help="grid points in M (default 1000)")
    t.add_argument("--n-theta", type=int, default=1000, help="grid points in vartheta, plus the inf row (default 1000)")
    t.add_argument("--M-max", type=inputs.number_arg, default=2.0, help="M range [0, M_MAX] (default 2)")
    t.add_argument("--theta-min", type=inputs.number_arg, default=0.5, help="smallest vartheta (default 0.5)")
    t.add_argument("--theta-max", type=inputs.number_arg, default=5.0, help="largest finite vartheta (default 5)")
    t.add_argument("--no-inf", action="store_true", help="leave out the vartheta = inf row")
    t.add_argument("--no-csv", action="store_true", help="skip atlas.csv (the npz holds the same data)")
    t.add_argument("--quiet", action="store_true", help="no progress bar")
    t.add_argument("--two-patch", action="store_true",
                   help="run the two-patch analysis (~1 s per pair) where the gap closes first (none on the default "
                        "grid)")
    t.set_defaults(func=run)
