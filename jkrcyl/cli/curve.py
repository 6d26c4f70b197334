"""``jkrcyl curve``: one equilibrium branch (jkrcyl.equilibria.curve) as CSV or JSON."""
from __future__ import annotations

import json
import sys

from .. import equilibria as eq
from .._validate import count
from ..results import Curve
from . import inputs


def run(args):
    pi = inputs.resolve(args)
    n = count("n", args.n, low=2)
    cv = eq.curve(pi.M, pi.theta, regime=args.regime, n=n, gb=pi.gb, alpha_ratio=pi.alpha_ratio, s0=pi.s0)
    table = {k: getattr(cv, k) for k in cv.COLUMNS}          # booleans stay booleans (true/false)
    table.update({k: getattr(cv, k) for k in ("c", "c_top") if getattr(cv, k) is not None})   # cohesive zone ends
    c = pi.contact
    if c is not None:
        dimensional = cv.with_units(c.units)
        table.update({k: getattr(dimensional, k) for k in ("P", "delta", "delta_work")})
    out = open(args.output, "w") if args.output else sys.stdout
    try:
        if args.format == "json":
            ends = {"ends": list(cv.ends)} if cv.ends is not None else {}
            json.dump({**pi.meta(), "regime": args.regime, **ends,
                       **{k: [inputs.json_value(x) for x in v] for k, v in table.items()}}, out)
            out.write("\n")
        else:
            out.write(f"# M={inputs.number(pi.M)} theta={inputs.number(pi.theta)} {pi.gb_text} "
                      f"alpha_ratio={inputs.number(pi.alpha_ratio)} regime={args.regime} edge={pi.law_text}\n")
            if cv.ends is not None:
                out.write("".join(f"# family {j}: {end}\n" for j, end in enumerate(cv.ends)))
            out.write(inputs.header(table, inputs.PHYSICAL_UNITS) + "\n")
            for row in zip(*table.values()):
                out.write(",".join(inputs.number(x) for x in row) + "\n")
    finally:
        if out is not sys.stdout:
            out.close()
    return 0


def register(sub):
    c = sub.add_parser("curve", help="one equilibrium branch as CSV or JSON",
                       description="Equilibrium branch: columns " + ", ".join(Curve.COLUMNS) +
                                   " (feasible, stable_* as true/false; with physical inputs also P [N/m], "
                                   "delta, delta_work [m]). The first line names the problem, with the gb used.")
    inputs.add_problem(c)
    c.add_argument("--regime", choices=eq.REGIMES + ("contactless", "top-bridge"), default="sub-critical",
                   help="branch (default sub-critical; contactless: the cohesive law's zone-only pin; top-bridge: "
                        "its zone at the top held by its own traction, as traced, the families' ends on a comment "
                        "line)")
    c.add_argument("--n", type=int, default=200, help="number of points (default 200)")
    c.add_argument("--format", choices=("csv", "json"), default="csv", help="output format (default csv)")
    c.add_argument("--output", "-o", default=None, help="file to write (default: stdout)")
    c.set_defaults(func=run)
