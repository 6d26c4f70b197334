"""``jkrcyl atlas``: the regime atlas over (M, vartheta) (jkrcyl.atlas): atlas.npz, atlas.csv, PNG and PDF."""
from __future__ import annotations

import pathlib
import time

from .._validate import count
from . import inputs

GRID_MAX = 10_000        # points per axis: 10^4 x 10^4 pairs is ~1.6 GB of fields and hours on 2 cores
LAW_GRID_MAX = 200       # the law's atlas: ~0.8 s of CPU per pair (200 x 200: ~4.5 h on 2 cores)


def run(args):
    from .. import atlas
    law = args.lam is not None
    top = LAW_GRID_MAX if law else GRID_MAX
    args.n_M = args.n_M if args.n_M is not None else 24 if law else 1000
    args.n_theta = args.n_theta if args.n_theta is not None else 24 if law else 1000
    for name, n in (("n-M", args.n_M), ("n-theta", args.n_theta)):
        if not 2 <= n <= top:
            raise ValueError(f"{name} must be in [2, {top}] (the grid's memory and time grow with "
                             f"n-M x n-theta{'; the law: ~1 s of CPU per pair' if law else ''}), got {n}")
    if not args.theta_min < args.theta_max:
        raise ValueError(f"theta-max must be > theta-min, got theta-min = {args.theta_min:g}, "
                         f"theta-max = {args.theta_max:g}")
    if law:
        from ..atlas import cohesive
        cohesive.check_lambda(args.lam)
        count("workers", args.workers, 1, cohesive.WORKERS_MAX)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    Ms, th = atlas.default_grid(args.n_M, args.n_theta, M_max=args.M_max, theta_min=args.theta_min,
                                theta_max=args.theta_max, with_inf=not args.no_inf)
    if law:
        return _run_law(args, Ms, th, out)
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


def _run_law(args, Ms, th, out):
    """The Maugis-Dugdale atlas at lambda (jkrcyl.atlas.cohesive)."""
    from .. import atlas
    from ..atlas import cohesive, files
    t0 = time.perf_counter()
    res = cohesive.classify_law(Ms, th, args.lam, workers=args.workers, two_patch=args.two_patch,
                                progress=not args.quiet)
    t1 = time.perf_counter()
    written = files.write_law_files(out, res, csv=not args.no_csv)
    written += atlas.draw(res, str(out / "atlas"), labels=cohesive.LAW_CONFINED,
                          title=f"Maugis-Dugdale law, lambda = {inputs.number(args.lam)}. ")
    t2 = time.perf_counter()
    refused = f"; {len(res['reasons'])} pairs refused by the law's solver (reasons in atlas.npz)" \
        if res["reasons"] else ""
    print(f"classified {Ms.size} x {th.size} pairs under the Maugis-Dugdale law at lambda = "
          f"{inputs.number(args.lam)} in {t1 - t0:.1f} s on {args.workers} workers (output {t2 - t1:.2f} s){refused}; "
          f"wrote {', '.join(pathlib.Path(f).name for f in written)} to {out}")
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
    t.add_argument("--n-M", type=int, default=None, help="grid points in M (default 1000; with --lambda 24)")
    t.add_argument("--n-theta", type=int, default=None,
                   help="grid points in vartheta, plus the inf row (default 1000; with --lambda 24)")
    t.add_argument("--lambda", dest="lam", type=inputs.number_arg, default=None,
                   help="the Maugis-Dugdale law at this transition parameter lambda > 0 (jkrcyl.atlas.cohesive: "
                        "the same classes through the model core's load path, ~1 s of CPU per pair; the top adheres "
                        "where the gap at pi reaches h0). Default: JKR")
    t.add_argument("--workers", type=int, default=2, help="with --lambda: Dask worker processes (default 2)")
    t.add_argument("--M-max", type=inputs.number_arg, default=2.0, help="M range [0, M_MAX] (default 2)")
    t.add_argument("--theta-min", type=inputs.number_arg, default=0.5, help="smallest vartheta (default 0.5)")
    t.add_argument("--theta-max", type=inputs.number_arg, default=5.0, help="largest finite vartheta (default 5)")
    t.add_argument("--no-inf", action="store_true", help="leave out the vartheta = inf row")
    t.add_argument("--no-csv", action="store_true", help="skip atlas.csv (the npz holds the same data)")
    t.add_argument("--quiet", action="store_true", help="no progress bar")
    t.add_argument("--two-patch", action="store_true",
                   help="run the two-patch analysis (~1 s per pair; with --lambda the law's confined_events) where "
                        "the gap closes first (JKR: none on the default grid)")
    t.set_defaults(func=run)
