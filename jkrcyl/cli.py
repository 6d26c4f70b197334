"""``jkrcyl``: equilibrium curves, adherence forces and the paper's figures from the command line.

    jkrcyl figures --out figures            # Figures 2-12 as PNG, PDF and CSV
    jkrcyl curve --M 0.3 --theta 1          # one equilibrium branch as CSV (or --format json)
    jkrcyl curve --E 1e6 --nu 0.45 --E-I inf --nu-I 0.3 --R 0.01 --Delta 1e-4 --w 0.05
    jkrcyl adherence --M 0.3 --theta 1      # fixed-load and fixed-grip adherence, zero-load contact
    jkrcyl two-patch --M 0.4 --theta 1      # two-patch branches (top contact formed) as CSV or JSON
    jkrcyl two-patch --figure docs/confined.png   # load-approach paths through the confined regime
    jkrcyl atlas --out atlas                # regime map over (M, vartheta): atlas.npz, atlas.csv, PNG, PDF

Errors are one line on stderr naming the bad parameter; exit status 2.
"""
import argparse
import json
import math
import re
import sys

import numpy as np

from . import equilibria as eq

EXIT_USAGE = 2


class _Parser(argparse.ArgumentParser):
    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        # "-2e6" and "-inf" are values, not options (argparse alone knows only "-2" and "-.5")
        self._negative_number_matcher = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-inf$")

    def error(self, message):
        sys.stderr.write(f"{self.prog}: error: {message}\n")
        raise SystemExit(EXIT_USAGE)


def _float(text):
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None


def _add_problem(p):
    g = p.add_argument_group("normalised inputs (section 6)")
    g.add_argument("--M", type=_float, help="adhesion parameter M = sqrt(wAR)/(sqrt(2) Delta vartheta) "
                   "(M_R* when --theta inf)")
    g.add_argument("--theta", type=_float, default=1.0, help="vartheta >= 0.5, or inf (default 1)")
    g.add_argument("--gb", type=_float, default=None,
                   help="(1/G_I)/beta*, used by delta/Delta only (default: incompressible pair, 1 - 1/(2 vartheta))")
    h = p.add_argument_group("physical inputs (SI units; replace --M/--theta/--gb)")
    for name, helptext in (("E", "Young's modulus of the body with the hole [Pa] (inf: rigid)"),
                           ("nu", "its Poisson ratio"), ("E-I", "Young's modulus of the cylinder [Pa] (inf: rigid)"),
                           ("nu-I", "its Poisson ratio"), ("R", "hole radius [m]"),
                           ("Delta", "clearance R - R_D [m], > 0"), ("w", "work of adhesion [J/m^2]")):
        h.add_argument(f"--{name}", type=_float, help=helptext)


def _resolve(args):
    """(M, theta, gb) from either input set."""
    phys = [args.E, args.nu, args.E_I, args.nu_I, args.R, args.Delta, args.w]
    if any(v is not None for v in phys):
        names = ("E", "nu", "E-I", "nu-I", "R", "Delta", "w")
        if args.M is not None:
            raise ValueError("M: give either --M (with --theta, --gb) or the physical inputs, not both")
        missing = [n for n, v in zip(names, phys) if v is None]
        if missing:
            raise ValueError(f"--{missing[0]} is required with physical inputs")
        from .contact import Contact
        from .materials import Materials
        mat = Materials.from_young(args.E, args.nu, args.E_I, args.nu_I)
        if args.Delta == 0:
            raise ValueError("Delta must be > 0 here (M and P* divide by Delta; neat fit: see jkrcyl.special)")
        c = Contact(R=args.R, Delta=args.Delta, w=args.w, materials=mat)
        args.contact = c                          # physical columns (P [N/m], delta [m]) in the output
        args.alpha_ratio = mat.alpha_ratio        # alpha* != 0: curve/adherence use the numerical solver
        return eq.from_contact(c)
    if args.M is None:
        raise ValueError("M is required (--M, or the physical inputs --E --nu --E-I --nu-I --R --Delta --w)")
    M, th, gb, *_ = eq._params(args.M, args.theta, args.gb)
    return M, th, gb


def _cmd_curve(args):
    M, th, gb = _resolve(args)
    from ._validate import count
    from .cli_forward import PHYSICAL_UNITS, header, json_value, number
    n = count("n", args.n, low=2)
    cv = eq.curve(M, th, regime=args.regime, n=n, gb=gb, alpha_ratio=getattr(args, "alpha_ratio", 0.0))
    table = {k: getattr(cv, k) for k in cv.COLUMNS}          # booleans stay booleans (true/false)
    c = getattr(args, "contact", None)
    if c is not None:
        table.update(P=cv.P_star * c.load_scale, delta=cv.delta_over_Delta * c.Delta)
    out = open(args.output, "w") if args.output else sys.stdout
    try:
        if args.format == "json":
            json.dump({"M": json_value(M), "theta": json_value(th), "gb": json_value(gb), "regime": args.regime,
                       **{k: [json_value(x) for x in v] for k, v in table.items()}}, out)
            out.write("\n")
        else:
            out.write(f"# M={number(M)} theta={number(th)} gb={number(gb)} regime={args.regime}\n")
            out.write(header(table, PHYSICAL_UNITS) + "\n")
            for row in zip(*table.values()):
                out.write(",".join(number(x) for x in row) + "\n")
    finally:
        if out is not sys.stdout:
            out.close()
    return 0


def _cmd_two_patch(args):
    from . import twopatch
    if args.figure:
        if args.M is not None or getattr(args, "E", None) is not None:
            raise ValueError("figure: draws the M values of --figure-M (drop --M and the physical inputs)")
        try:
            Ms = [float(x) for x in args.figure_M.split(",") if x.strip()]
        except ValueError:
            raise ValueError(f"figure-M: not a comma-separated list of numbers: {args.figure_M!r}") from None
        if not Ms:
            raise ValueError("figure-M: give at least one M")
        _, th, gb = eq._params(Ms[0], args.theta, args.gb)
        print(f"wrote {twopatch.draw_confined(args.figure, Ms=Ms, theta=th, gb=gb)}")
        return 0
    M, th, gb = _resolve(args)
    if args.n is not None and args.n < 4:
        raise ValueError(f"n must be >= 4, got {args.n}")
    ar = getattr(args, "alpha_ratio", 0.0)           # physical inputs: alpha*/beta* of the pair (any alpha*)
    bs = twopatch.branches(M, th, gb=gb, n=args.n, alpha_ratio=ar)
    clean = lambda v: [None if not math.isfinite(x) else x for x in v.tolist()]
    if args.format == "json":
        json.dump({"M": M, "theta": th, "gb": gb, "alpha_ratio": ar, "branches": [
            {"ends": list(b.ends), **{k: clean(v) for k, v in b.table().items()}} for b in bs]}, sys.stdout)
        sys.stdout.write("\n")
        return 0
    from .cli_forward import number
    print(f"# M={number(M)} theta={number(th)} gb={number(gb)} alpha_ratio={number(ar)} branches={len(bs)}")
    for i, b in enumerate(bs):
        print(f"# branch {i}: ends {b.ends[0]} -> {b.ends[1]}")
    print("branch," + ",".join(twopatch.TwoPatchCurve.COLUMNS))
    for i, b in enumerate(bs):
        t = b.table(raw=True)
        for row in zip(*t.values()):
            print(f"{i}," + ",".join(number(x) for x in row))
    return 0


def _confined_dict(ev):
    nan = lambda x: None if not math.isfinite(x) else x
    return {"regime": ev.regime, "description": ev.description, "summary": ev.summary, "P_fold": nan(ev.P_fold),
            "P_top_contact": nan(ev.P_top_contact), "onsets": [list(o) for o in ev.onsets],
            "grip_detachment": ev.grip_detachment, "two_patch_stable_load": ev.two_patch_stable_load,
            "two_patch_stable_grip": ev.two_patch_stable_grip, "full_contact": ev.full_contact}


def _point_dict(p):
    return {k: getattr(p, k) for k in ("control", "regime", "kind", "a", "eps", "eps_star", "P_star",
                                        "delta_over_Delta", "h_pi_over_Delta", "feasible", "outcome")}


def _cmd_adherence(args):
    M, th, gb = _resolve(args)
    ar = getattr(args, "alpha_ratio", 0.0)
    want_confined = not math.isinf(th) and M > 0 and not args.no_confined
    load = eq.adherence(M, th, "load", gb=gb, alpha_ratio=ar, confined=want_confined)
    grip = eq.adherence(M, th, "grip", gb=gb, alpha_ratio=ar)
    if ar:   # (8.1) is an alpha* = 0 result: the zero-load contact from the solver
        a0 = eq.solve_load(M, th, 0.0, gb=gb, alpha_ratio=ar)
        Mmax = math.inf
    else:
        from .numerics.zero_load import zero_load_contact, zero_load_max_M
        a0 = zero_load_contact(M, th)
        Mmax = zero_load_max_M(th)[0]
    confined = None
    if want_confined:
        from . import twopatch           # any alpha* (the arc engine); ~2 s at alpha* = 0, ~30-60 s otherwise
        confined = _confined_dict(twopatch.confined_events(M, th, gb=gb, alpha_ratio=ar))
    if args.format == "json":
        json.dump({"M": M, "theta": th, "gb": gb, "confined": confined, "load": [_point_dict(p) for p in load],
                   "grip": [_point_dict(p) for p in grip], "zero_load_a0": a0,
                   "zero_load_M_max": None if math.isinf(Mmax) else Mmax}, sys.stdout)
        sys.stdout.write("\n")
        return 0
    print(f"M = {M:.10g}, theta = {th:g}, gb = {gb:.10g}" + (f", alpha*/beta* = {ar:.6g} (numerical solver)"
                                                              if ar else ""))
    print("fixed-load adherence (minimum of P* per branch):")
    for p in load or []:
        print(f"  {p.regime:14s} a = {p.a:.10g}  eps = {p.eps:.10g}  P* = {p.P_star:.10g}  "
              f"delta/Delta = {p.delta_over_Delta:.10g}  feasible = {p.feasible}"
              + (f"  outcome = {p.outcome}" if p.outcome else ""))
    if not load:
        print("  none (no minimum of P* on any branch)")
    print("fixed-grip stationary points (d delta/da = 0):")
    for p in grip:
        print(f"  {p.regime:14s} {p.kind} a = {p.a:.10g}  P* = {p.P_star:.10g}  "
              f"delta/Delta = {p.delta_over_Delta:.10g}  feasible = {p.feasible}")
    if not grip:
        print("  none")
    print(f"zero-load contact ({'solver, P* = 0' if ar else '8.1'}): "
          + (", ".join(f"a0 = {x:.10g}" for x in a0) if a0 else "none"))
    if not math.isinf(Mmax):
        print(f"  (8.1) has roots for M <= {Mmax:.10g}")
    if confined:
        print(f"confined regime (slow upward loading, jkrcyl.twopatch): {confined['regime']}")
        print(f"  {confined['summary']}")
        for key in ("P_fold", "P_top_contact"):
            if confined[key] is not None:
                print(f"  {key} = {confined[key]:.12g}")
        for e, P, d, st in confined["onsets"]:
            print(f"  gap closes at pi (single patch): eps = {e:.12g}  P* = {P:.12g}  delta/Delta = {d:.12g}"
                  f"  stable under load = {st}")
        print(f"  two-patch states stable under load: {confined['two_patch_stable_load']}, under grip: "
              f"{confined['two_patch_stable_grip']}; pin can be held free (grip): {confined['grip_detachment']}")
    return 0


def _cmd_figures(args):
    from . import figures

    from tqdm import tqdm
    shown = []

    def bar(i, n, name):                      # figures.draw_all reports (done, total, next figure)
        if not shown:
            shown.append(tqdm(total=n, unit="figures", file=sys.stderr))
        shown[0].set_postfix_str(name)
        shown[0].update(i - shown[0].n)
        if i == n:
            shown[0].close()

    only = None
    if args.only:
        only = [s.strip() for s in args.only.split(",") if s.strip()]
        bad = [s for s in only if s not in figures.FIGURES]
        if bad:
            raise ValueError(f"only: unknown figure {bad[0]!r} (choose from {', '.join(figures.FIGURES)})")
    if args.n is not None and args.n < 4:
        raise ValueError(f"n must be >= 4, got {args.n}")
    written = figures.draw_all(args.out, n=args.n, only=only, progress=None if args.quiet else bar,
                               alpha_ratio=args.alpha_ratio)
    print(f"wrote {len(written)} files to {args.out}")
    return 0


def _cmd_atlas(args):
    import time
    from . import atlas
    if args.n_M < 2 or args.n_theta < 2:
        raise ValueError(f"n-M and n-theta must be >= 2, got {args.n_M} and {args.n_theta}")
    if not args.theta_min < args.theta_max:
        raise ValueError(f"theta-max must be > theta-min, got theta-min = {args.theta_min:g}, "
                         f"theta-max = {args.theta_max:g}")
    import pathlib
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


def build_parser():
    p = _Parser(prog="jkrcyl", description=__doc__.split("\n\n")[0])
    from . import __version__
    p.add_argument("--version", action="version", version=f"jkrcyl {__version__}")
    sub = p.add_subparsers(dest="command", metavar="command", title="commands (figures, curve, adherence, two-patch, atlas)", parser_class=_Parser)
    sub.required = True
    f = sub.add_parser("figures", help="draw the paper's Figures 2-12 (PNG, PDF, CSV)",
                       description="Draw Figures 2-12 into OUT as figNN.png, figNN.pdf and figNN.csv "
                                   "(CSV columns: panel, series, x_name, x, y_name, y, feasible).")
    f.add_argument("--out", default="figures", help="output folder (default: figures)")
    f.add_argument("--n", type=int, default=None, help="points per curve (default: per figure, 400-600)")
    f.add_argument("--only", default=None, help="comma-separated subset, e.g. fig02,fig11")
    f.add_argument("--quiet", action="store_true", help="no progress bar")
    f.add_argument("--alpha-ratio", type=float, default=0.0,
                   help="alpha*/beta* (default 0: the paper's closed forms; otherwise the solver, no Fig. 8)")
    f.set_defaults(func=_cmd_figures)
    c = sub.add_parser("curve", help="one equilibrium branch as CSV or JSON",
                       description="Equilibrium branch: columns " + ", ".join(eq.Curve.COLUMNS) +
                                   " (feasible, stable_* as 0/1).")
    _add_problem(c)
    c.add_argument("--regime", choices=eq.REGIMES, default="sub-critical", help="branch (default sub-critical)")
    c.add_argument("--n", type=int, default=200, help="number of points (default 200)")
    c.add_argument("--format", choices=("csv", "json"), default="csv", help="output format (default csv)")
    c.add_argument("--output", "-o", default=None, help="file to write (default: stdout)")
    c.set_defaults(func=_cmd_curve)
    a = sub.add_parser("adherence", help="adherence forces and the zero-load contact",
                       description="Fixed-load adherence (P* minima), fixed-grip points (d delta/da = 0), "
                                   "the zero-load contact parameters of (8.1) (the solver's P* = 0 roots when "
                                   "alpha* != 0) and what slow pulling does in the hole (the confined regime: "
                                   "detachment and transfer to the top, zipping into full contact, or the top "
                                   "contact forming first; jkrcyl.twopatch.REGIMES), for any material pair.")
    _add_problem(a)
    a.add_argument("--format", choices=("text", "json"), default="text", help="output format (default text)")
    a.add_argument("--no-confined", action="store_true",
                   help="skip the confined-regime analysis (jkrcyl.twopatch.confined_events: ~2 s at alpha* = 0, "
                        "30-60 s for a pair with alpha* != 0)")
    a.set_defaults(func=_cmd_adherence)
    tw = sub.add_parser("two-patch", help="two-patch equilibria (second contact at the top of the hole)",
                        description="Every branch of two-patch equilibria (bottom arc a, top arc a_top) at (M, "
                                    "vartheta), for any material pair (physical inputs: the pair's alpha*): "
                                    "CSV rows per branch (column 'branch') or JSON; with --figure FILE the "
                                    "load-approach paths through the confined regime instead; columns "
                                    + ", ".join(("a", "a_top", "eps", "eps_top", "eps_star", "eps_top_star",
                                                 "P_star", "delta_over_Delta", "gap_min", "feasible",
                                                 "stable_load", "stable_grip")) + ".")
    _add_problem(tw)
    tw.add_argument("--n", type=int, default=None, help="points per branch (default: continuation steps)")
    tw.add_argument("--format", choices=("csv", "json"), default="csv", help="output format (default csv)")
    tw.add_argument("--figure", default=None, metavar="FILE",
                    help="instead: draw the load-approach paths through the confined regime (docs/confined.png) "
                         "for the M values of --figure-M at --theta, --gb (alpha* = 0)")
    tw.add_argument("--figure-M", default=",".join(f"{m:g}" for m in (0.3, 0.4, 0.5, 0.8)),
                    help="comma-separated M values of --figure (default 0.3,0.4,0.5,0.8)")
    tw.set_defaults(func=_cmd_two_patch)
    from . import cli_forward
    cli_forward.register(sub, _float)
    from . import cli_fit
    cli_fit.register(sub, _float)
    t = sub.add_parser("atlas", help="regime atlas over (M, vartheta): npz, CSV and a regime map",
                       description="Classify every (M, vartheta) pair of a grid: sub-critical and super-critical "
                                   "fixed-load adherence points (feasible or not), zero-load contact (8.1), "
                                   "adherence force, and what slow pulling does in the hole (the confined "
                                   "classes: detach and land on the top, zip into full contact, or the gap "
                                   "closes first). The last row is vartheta = inf, "
                                   "where M means M_R* and P* means P_R* of (7.6). Writes atlas.npz, atlas.csv, "
                                   "atlas.png and atlas.pdf into OUT (see jkrcyl.atlas for the fields).")
    t.add_argument("--out", default="atlas", help="output folder (default: atlas)")
    t.add_argument("--n-M", type=int, default=1000, help="grid points in M (default 1000)")
    t.add_argument("--n-theta", type=int, default=1000, help="grid points in vartheta, plus the inf row (default 1000)")
    t.add_argument("--M-max", type=_float, default=2.0, help="M range [0, M_MAX] (default 2)")
    t.add_argument("--theta-min", type=_float, default=0.5, help="smallest vartheta (default 0.5)")
    t.add_argument("--theta-max", type=_float, default=5.0, help="largest finite vartheta (default 5)")
    t.add_argument("--no-inf", action="store_true", help="leave out the vartheta = inf row")
    t.add_argument("--no-csv", action="store_true", help="skip atlas.csv (the npz holds the same data)")
    t.add_argument("--quiet", action="store_true", help="no progress bar")
    t.add_argument("--two-patch", action="store_true",
                   help="run the two-patch analysis (~1 s per pair) where the gap closes first (none on the default grid)")
    t.set_defaults(func=_cmd_atlas)
    return p


def main(argv=None):
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return args.func(args)
    except BrokenPipeError:                       # `jkrcyl curve ... | head`: the reader left; no traceback
        import os
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except (ValueError, ArithmeticError) as exc:  # ArithmeticError: outside the domain the checks know
        msg = str(exc).splitlines()[0] if str(exc) else "invalid input"
        sys.stderr.write(f"jkrcyl {args.command}: error: {msg}\n")
        return EXIT_USAGE
    except OSError as exc:
        sys.stderr.write(f"jkrcyl {args.command}: error: out: {exc}\n")
        return EXIT_USAGE


if __name__ == "__main__":
    sys.exit(main())
