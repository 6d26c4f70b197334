"""``jkrcyl two-patch``: every two-patch branch (jkrcyl.equilibria.two_patch, or Contact.two_patch with physical
columns), or with ``--figure`` the load-approach paths through the confined regime (jkrcyl.plotting.confined)."""
from __future__ import annotations

import json
import math
import sys

from .. import equilibria as eq
from ..results import TwoPatchCurve
from . import inputs

FIGURE_M = "0.3,0.4,0.5,0.8"


def _figure(args):
    from .. import plotting
    from ..plotting import style
    if args.M is not None or inputs.physical_given(args):
        raise ValueError("figure: draws the M values of --figure-M (drop --M and the physical inputs)")
    try:
        Ms = [float(x) for x in args.figure_M.split(",") if x.strip()]
    except ValueError:
        raise ValueError(f"figure-M: not a comma-separated list of numbers: {args.figure_M!r}") from None
    if not Ms:
        raise ValueError("figure-M: give at least one M")
    th = eq.problem(Ms[0], args.theta, 0.0).theta
    gb, source = ((args.gb, "--gb") if args.gb is not None else
                  (style.figure_gb(th), f"default: {style.figure_pair(th, plain=True)}; pass --gb"))
    path = plotting.draw_confined(args.figure, Ms=Ms, theta=th, gb=args.gb)     # None: the figures' pair, named
    print(f"wrote {path} (theta={inputs.number(th)} gb={inputs.number(gb)} ({source}))")
    return 0


def run(args):
    if args.figure:
        return _figure(args)
    pi = inputs.resolve(args)
    param = "lambda" if getattr(args, "lambda_", None) is not None else ""        # the name the user gave the law
    eq.problem(pi.M, pi.theta, pi.gb, pi.alpha_ratio, s0=pi.s0).require("two-patch-branches", "two-patch states are",
                                                                         param)
    n = inputs.positive_count("n", args.n, 4)
    try:
        if pi.contact is not None:               # physical columns P [N/m], delta, delta_work [m] too
            bs = pi.contact.two_patch(n)
        else:
            bs = eq.two_patch(pi.M, pi.theta, n, gb=pi.gb, alpha_ratio=pi.alpha_ratio, s0=pi.s0)
    except ValueError as why:                # the law's message names sigma0: say the name the user gave
        raise ValueError(str(why).replace("sigma0:", f"{param}:", 1) if param else str(why)) from None
    if args.format == "json":
        clean = lambda v: [None if not math.isfinite(x) else x for x in v.tolist()]
        json.dump({**pi.meta(), "branches": [{"ends": list(b.ends), **{k: clean(v) for k, v in b.table().items()}}
                                             for b in bs]}, sys.stdout)
        sys.stdout.write("\n")
        return 0
    print(f"# M={inputs.number(pi.M)} theta={inputs.number(pi.theta)} {pi.gb_text} "
          f"alpha_ratio={inputs.number(pi.alpha_ratio)} branches={len(bs)}")
    for i, b in enumerate(bs):
        print(f"# branch {i}: ends {b.ends[0]} -> {b.ends[1]}")
    if not bs:
        return 0
    table0 = bs[0].table(raw=True)
    print("branch," + inputs.header(table0, inputs.PHYSICAL_UNITS))
    for i, b in enumerate(bs):
        t = b.table(raw=True)
        for row in zip(*t.values()):
            print(f"{i}," + ",".join(inputs.number(x) for x in row))
    return 0


def register(sub):
    tw = sub.add_parser("two-patch", help="two-patch equilibria (second contact at the top of the hole)",
                        description="Every branch of two-patch equilibria (bottom arc a, top arc a_top) at (M, "
                                    "vartheta), for any material pair (physical inputs: the pair's alpha*, and "
                                    "the columns P [N/m], delta, delta_work [m] too): CSV rows per branch (column "
                                    "'branch') or JSON; with --figure FILE the load-approach paths through the "
                                    "confined regime instead; columns " + ", ".join(TwoPatchCurve.COLUMNS) + ".")
    inputs.add_problem(tw)
    tw.add_argument("--n", type=int, default=None, help="points per branch (default: continuation steps)")
    tw.add_argument("--format", choices=("csv", "json"), default="csv", help="output format (default csv)")
    tw.add_argument("--figure", default=None, metavar="FILE",
                    help="instead: draw the load-approach paths through the confined regime (docs/confined.png) "
                         "for the M values of --figure-M at --theta (alpha* = 0) and --gb (default: the figures' "
                         "pair, identical nu = 0.3 bodies at vartheta = 1 -- the README pin, gb = 1/2.8; an "
                         "incompressible pin at other vartheta)")
    tw.add_argument("--figure-M", default=FIGURE_M, help=f"comma-separated M values of --figure (default {FIGURE_M})")
    tw.set_defaults(func=run)
