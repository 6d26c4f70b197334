"""``jkrcyl fit data.csv``: fit w and the moduli (and Delta, an approach offset) to measurements.

    jkrcyl fit data.csv --fix R=0.01 --fix Delta=1e-5 --fix E=2.6e9 --fix nu=0.3 --fix E_I=inf --fix nu_I=0.3
    jkrcyl fit docs/fit_example.csv --free w,E --plot fit.png        # setup from the file's '# key=value' lines
    jkrcyl fit data.csv --free w,E,sigma0 --sigma0 1e5               # the Maugis-Dugdale law, sigma0 fitted

The CSV has a header (P, width or delta_work, optional sigma_P, sigma_width, sigma_delta_work, leg; units in
brackets allowed) and may carry the setup in comment lines (``# R=0.01 Delta=1e-5 E=2.6e9 nu=0.3 E_I=2.6e9
nu_I=0.3``); ``--fix NAME=VALUE`` overrides or completes it.  Prints a table (or CSV/JSON); errors: one line,
exit status 2 (jkrcyl.cli.main).

"""
from __future__ import annotations

import json
import math
import sys
import warnings

from ..materials import Materials
from . import inputs
from .inputs import json_value, number

ALIASES = {"E_hole": "E", "nu_hole": "nu", "E_pin": "E_I", "nu_pin": "nu_I"}
MATERIAL_KEYS = ("E", "nu", "E_I", "nu_I")
SETUP_KEYS = ("R", "Delta", "w", "offset") + MATERIAL_KEYS


def _pairs(items, option, number):
    """NAME=VALUE strings -> dict (ValueError naming the option and the bad item)."""
    out = {}
    for item in items or ():
        name, sep, value = item.partition("=")
        name = ALIASES.get(name.strip(), name.strip())
        if not sep or name not in SETUP_KEYS:
            raise ValueError(f"{option}: expected NAME=VALUE with NAME in {', '.join(SETUP_KEYS)} "
                             f"(or E_hole, nu_hole, E_pin, nu_pin), got {item!r}")
        try:
            out[name] = number(value)
        except Exception:
            raise ValueError(f"{option}: {name}: not a number: {value!r}") from None
    return out


def _setup(args, table, free, number):
    """(R, Delta, materials, w, offset) from the CSV's meta, --fix and --start."""
    setup = {k: v for k, v in table.meta.items() if k in SETUP_KEYS}
    fixed = _pairs(args.fix, "--fix", number)
    start = _pairs(args.start, "--start", number)
    for name in sorted(set(fixed) & set(free) - set(MATERIAL_KEYS)):
        raise ValueError(f"{name}: given by --fix and listed in --free (use --start NAME=VALUE for a starting value)")
    bad_start = [n for n in start if n in MATERIAL_KEYS or n == "R"]
    if bad_start:
        raise ValueError(f"--start: {bad_start[0]}: the moduli start from --fix E, E_I (R is not fitted)")
    setup.update(fixed)
    setup.update(start)
    missing = [k for k in ("R", "Delta") + MATERIAL_KEYS if k not in setup]
    if missing:
        raise ValueError(f"{missing[0]}: not given (--fix {missing[0]}=VALUE, or a '# {missing[0]}=...' line in the CSV)")
    w_free = any(n.startswith("w") for n in free)
    if not w_free and "w" not in setup:
        raise ValueError("w: not fitted and not given (--fix w=VALUE or --free w,...)")
    mat = Materials.from_young(setup["E"], setup["nu"], setup["E_I"], setup["nu_I"])
    return setup["R"], setup["Delta"], mat, setup.get("w"), setup.get("offset", 0.0)


def cmd_fit(args):
    from .. import fit as fitting
    try:
        table = fitting.read_csv(args.data)
    except OSError as exc:
        raise ValueError(f"data: cannot read {args.data}: {exc.strerror or exc}") from None
    free = _free(args.free)
    R, Delta, mat, w, offset = _setup(args, table, free, args.number)
    cols = dict(table.columns)
    have = [k for k in ("width", "delta_work") if k in cols]
    x = args.x or (have[0] if len(have) == 1 else None)
    if x is None:
        raise ValueError("x: the file has " + ("both width and delta_work columns: choose one with --x" if have
                                               else "neither a width nor a delta_work column"))
    if x not in cols:
        raise ValueError(f"x: the file has no {x!r} column (columns: {', '.join(cols)})")
    other = "delta_work" if x == "width" else "width"
    cols.pop(other, None)
    cols.pop(f"sigma_{other}", None)
    control = args.control or table.meta.get("control", "load")
    interval = None if args.interval == "none" else args.interval
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")          # the notes are printed with the table
        res = fitting(**cols, R=R, Delta=Delta, materials=mat, free=free, w=w, offset=offset, control=control,
                      sigma0=_strength(args.sigma0), loss=args.loss, f_scale=args.f_scale, interval=interval,
                      confidence=args.confidence)
    _write(res, args.format)
    if args.plot:
        res.plot(args.plot)
    return 0


def _free(text):
    """--free: comma-separated parameter names, each known (ValueError naming the first unknown one)."""
    from ..fit.params import names
    free = tuple(n.strip() for n in text.split(",") if n.strip())
    try:
        return names(free)
    except ValueError as exc:
        why = str(exc).removeprefix("free: ").removeprefix("free ")
        raise ValueError(f"--free: {why}") from None


def _strength(value):
    """--sigma0 [Pa]: None (JKR) or a finite number > 0 (ValueError naming sigma0 otherwise)."""
    if value is None:
        return None
    if not (math.isfinite(value) and value > 0):
        raise ValueError(f"sigma0 must be a finite cohesive strength > 0 [Pa], got {value!r}")
    return value


def _write(res, fmt, out=None):
    from ..fit import PARAMETERS
    out = sys.stdout if out is None else out
    rows = [dict(parameter=n, value=res.values[n], std_error=res.standard_errors[n],
                 lower=res.intervals.get(n, (math.nan, math.nan))[0],
                 upper=res.intervals.get(n, (math.nan, math.nan))[1], unit=PARAMETERS[n][0]) for n in res.names]
    if fmt == "text":
        out.write(res.table() + "\n")
    elif fmt == "csv":
        out.write(f"# {res.n} points, loss {res.loss}, control {res.control}, sum of squares {res.cost:.10g} on "
                  f"{res.dof} dof, intervals {res.interval_method}, confidence {res.confidence:g}\n")
        out.write(",".join(rows[0]) + "\n")
        for r in rows:
            out.write(",".join(number(v) for v in r.values()) + "\n")
    else:
        json.dump({"parameters": [{k: json_value(v) for k, v in r.items()} for r in rows],
                   "correlation": [[json_value(x) for x in row] for row in res.correlation],
                   "n": res.n, "dof": res.dof, "sum_of_squares": json_value(res.cost), "loss": res.loss,
                   "control": res.control, "interval_method": res.interval_method, "notes": res.notes}, out)
        out.write("\n")


def register(sub, number_type=inputs.number_arg):
    """Add ``jkrcyl fit`` to the subparsers of jkrcyl.cli."""
    p = sub.add_parser(
        "fit", help="fit w and the moduli (Delta, an approach offset) to measured load against width or approach",
        description="Least-squares fit of the work of adhesion and the moduli (and optionally the clearance Delta "
                    "and an approach offset) to a CSV of measured load P [N/m] against contact width [m] or "
                    "delta_work [m], with 95 % profile-likelihood intervals (jkrcyl.fit). The setup (R, Delta, E, "
                    "nu, E_I, nu_I, w) comes from '# key=value' comment lines of the file and --fix; inf = rigid.")
    p.add_argument("data", help="CSV file: header P, width or delta_work [, sigma_P, sigma_width, "
                                "sigma_delta_work, leg]")
    p.add_argument("--x", choices=("width", "delta_work"), default=None,
                   help="abscissa column (default: the one present)")
    p.add_argument("--free", default="w,E",
                   help="comma-separated fitted parameters: w (or w_loading,w_unloading), E (contact modulus, both "
                        "moduli scaled) or E_hole/E_pin, Delta, offset, sigma0 (cohesive law; default w,E)")
    p.add_argument("--fix", action="append", metavar="NAME=VALUE",
                   help="known quantity: R, Delta, w, offset [SI]; materials E, nu, E_I, nu_I (aliases E_hole, "
                        "nu_hole, E_pin, nu_pin; the starting moduli when E is fitted); repeatable")
    p.add_argument("--sigma0", type=number_type, default=None, metavar="PA",
                   help="cohesive strength [Pa] of the Maugis-Dugdale law (fixed, or the start when sigma0 is in "
                        "--free; without --sigma0 and not fitted: JKR)")
    p.add_argument("--start", action="append", metavar="NAME=VALUE",
                   help="starting value of a fitted w, Delta or offset; repeatable")
    p.add_argument("--control", choices=("load", "grip-work"), default=None,
                   help="what the experiment held (default: the file's '# control=' or load)")
    p.add_argument("--loss", choices=("linear", "soft_l1", "huber"), default="linear",
                   help="least-squares loss (default linear)")
    p.add_argument("--f-scale", type=number_type, default=1.0, help="robust loss scale, in standard deviations")
    p.add_argument("--interval", choices=("profile", "wald", "none"), default="profile",
                   help="confidence intervals (default profile likelihood)")
    p.add_argument("--confidence", type=number_type, default=0.95, help="interval coverage (default 0.95)")
    p.add_argument("--format", choices=("text", "csv", "json"), default="text", help="output (default text)")
    p.add_argument("--plot", default=None, metavar="FILE", help="write data, fitted curve and residuals (PNG, PDF)")
    p.set_defaults(func=cmd_fit, number=number_type)
