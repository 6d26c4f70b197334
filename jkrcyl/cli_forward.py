"""Command-line front ends of the forward problems (issue 11): ``jkrcyl solve``, ``jkrcyl pull-off``,
``jkrcyl cycle``.  Physical inputs only (SI units); numbers printed with 10 significant digits,
booleans as true/false in every format.
"""
from __future__ import annotations

import json
import math
import sys

import numpy as np

PHYSICAL = (("E", "Young's modulus of the body with the hole [Pa] (inf: rigid)"), ("nu", "its Poisson ratio"),
            ("E-I", "Young's modulus of the cylinder [Pa] (inf: rigid)"), ("nu-I", "its Poisson ratio"),
            ("R", "hole radius [m]"), ("Delta", "clearance R - R_D [m], > 0"), ("w", "work of adhesion [J/m^2]"))

UNITS = {"a": "", "a_top": "", "eps": "rad", "eps_top": "rad", "contact_width": "m", "P": "N/m", "delta": "m",
         "delta_work": "m", "h_pi": "m", "K": "Pa m^1/2", "P_star": "", "delta_over_Delta": "", "energy": "J/m"}


def add_physical(p, number):
    g = p.add_argument_group("physical inputs (SI units)")
    for name, helptext in PHYSICAL:
        g.add_argument(f"--{name}", type=number, help=helptext)


def contact_from(args):
    """A jkrcyl.Contact from --E --nu --E-I --nu-I --R --Delta --w (ValueError naming a missing one)."""
    from .contact import Contact
    from .materials import Materials
    values = [getattr(args, n.replace("-", "_")) for n, _ in PHYSICAL]
    for (name, _), v in zip(PHYSICAL, values):
        if v is None:
            raise ValueError(f"{name}: --{name} is required ({', '.join('--' + n for n, _ in PHYSICAL)})")
    E, nu, E_I, nu_I, R, Delta, w = values
    return Contact(R=R, Delta=Delta, w=w, materials=Materials.from_young(E, nu, E_I, nu_I))


def number(x) -> str:
    """10 significant digits, no noise; inf/nan spelled out; booleans true/false."""
    if isinstance(x, (bool, np.bool_)):
        return "true" if x else "false"
    if isinstance(x, str):
        return x
    x = float(x)
    return f"{x:.10g}" if math.isfinite(x) else ("inf" if x > 0 else "-inf" if x < 0 else "nan")


def json_value(x):
    if isinstance(x, str) or x is None:
        return x
    if isinstance(x, (bool, np.bool_)):
        return bool(x)
    x = float(x)
    return float(f"{x:.10g}") if math.isfinite(x) else None


def header(keys, units=None):
    """CSV header with units in brackets (default :data:`UNITS`; pass e.g. PHYSICAL_UNITS for P, delta only)."""
    units = UNITS if units is None else units
    return ",".join(f"{k} [{units[k]}]" if units.get(k) else k for k in keys)


PHYSICAL_UNITS = {"P": "N/m", "delta": "m", "delta_work": "m"}


def write_rows(rows, fmt, out=sys.stdout, meta=None):
    """rows: list of dicts with equal keys; fmt 'csv', 'json' or 'text'."""
    if fmt == "json":
        json.dump({**({k: json_value(v) for k, v in (meta or {}).items()}),
                   "rows": [{k: json_value(v) for k, v in r.items()} for r in rows]}, out)
        out.write("\n")
        return
    if meta:
        out.write("# " + " ".join(f"{k}={number(v)}" for k, v in meta.items()) + "\n")
    if not rows:
        out.write("# no equilibrium\n")
        return
    out.write(header(rows[0]) + "\n")
    for r in rows:
        out.write(",".join(number(v) for v in r.values()) + "\n")


# --- solve ---------------------------------------------------------------------------------------------
def cmd_solve(args):
    from .forward import BRANCH_SOLVERS, CONTROLS
    c = contact_from(args)
    given = {k: getattr(args, k) for k in ("P", "delta", "delta_work") if getattr(args, k) is not None}
    if len(given) != 1:
        raise ValueError("P: give exactly one of --P [N/m], --delta [m] and --delta-work [m]")
    branches = None
    if args.no_two_patch:
        branches = [b for b in BRANCH_SOLVERS if b != "two-patch"]
    states = c.solve(**given, branches=branches)
    control = next(k for k, spec in CONTROLS.items() if spec[3] in given)
    meta = {"M": c.M, "theta": c.theta, "control": control}
    write_rows([s.as_dict() for s in states], args.format, meta=meta)
    return 0


def register(sub, number_type):
    """Add the forward-problem commands to the subparsers of jkrcyl.cli."""
    s = sub.add_parser("solve", help="every equilibrium at a load P [N/m] or an approach delta [m]",
                       description="Every equilibrium at the given load per unit length (--P, fixed-load stability), "
                                   "work-conjugate approach (--delta-work, stability with a testing machine holding "
                                   "the pin) or the paper's approach (--delta, (5.8)) on every branch, sorted by "
                                   "contact size. Physical inputs only.")
    add_physical(s, number_type)
    s.add_argument("--P", type=number_type, help="load per unit length [N/m], positive downward")
    s.add_argument("--delta", type=number_type, help="the paper's approach (5.8) [m], positive downward")
    s.add_argument("--delta-work", type=number_type,
                   help="work-conjugate approach delta + P/(8 pi G_I) [m], positive downward")
    s.add_argument("--no-two-patch", action="store_true", help="skip the two-patch branches (faster)")
    s.add_argument("--format", choices=("csv", "json"), default="csv", help="output format (default csv)")
    s.set_defaults(func=cmd_solve)
    register_more(sub, number_type)


# --- pull-off and cycle ----------------------------------------------------------------------------------
def cmd_pull_off(args):
    c = contact_from(args)
    rows = []
    for control in ("load", "grip-work", "grip"):
        po = c.pull_off(control)
        rows.append({"control": control, "detached": po.detached, "P": po.P if po.detached else math.nan,
                     "contact_width": po.contact_width if po.detached else math.nan,
                     "delta": po.delta if po.detached else math.nan,
                     "delta_work": po.delta_work if po.detached else math.nan, "reason": po.reason})
    if args.format == "json":
        write_rows(rows, "json")
        return 0
    for r in rows:
        if r["detached"]:
            print(f"{r['control']:9s}: pull-off P = {number(r['P'])} N/m, contact width = "
                  f"{number(r['contact_width'])} m, delta = {number(r['delta'])} m, delta_work = "
                  f"{number(r['delta_work'])} m")
        else:
            print(f"{r['control']:9s}: no detachment -- {r['reason']}")
    return 0


def cmd_cycle(args):
    from .cycle import plot
    c = contact_from(args)
    cy = c.cycle(P_max=args.P_max, P_min=args.P_min, control=args.control, n=args.n,
                 delta_max=args.delta_max, delta_min=args.delta_min)
    if args.csv:
        with open(args.csv, "w") as fh:
            t = cy.table()
            write_rows([dict(zip(t, row)) for row in zip(*t.values())], "csv", out=fh,
                       meta={"control": cy.control, "dissipated_J_per_m": cy.dissipated if cy.dissipated is not None
                             else math.nan})
    if args.plot:
        plot(cy, args.plot)
    print(f"{cy.control} control: {len(cy.P)} path points, {len(cy.jumps)} jumps")
    for j in cy.jumps:
        print(f"  leg {j.leg} {j.kind:11s} {j.before.branch} -> {j.after.branch}: P {number(j.before.P)} -> "
              f"{number(j.after.P)} N/m, delta {number(j.before.delta)} -> {number(j.after.delta)} m")
    if cy.dissipated is None:
        print(f"dissipated energy per cycle: n/a (the loop did not close{': ' + cy.note if cy.note else ''})")
    else:
        print(f"dissipated energy per cycle: {number(cy.dissipated)} J/m")
    return 0


def register_more(sub, number_type):
    p = sub.add_parser("pull-off", help="pull-off force [N/m], contact width and approach (load and grip)",
                       description="Detachment along the stable path from the zero-load contact, under load, "
                                   "under grip on the work-conjugate approach (grip-work: a testing machine "
                                   "holding the pin) and on the paper's approach (grip), or the reason there is "
                                   "none.")
    add_physical(p, number_type)
    p.add_argument("--format", choices=("text", "json"), default="text", help="output format (default text)")
    p.set_defaults(func=cmd_pull_off)
    c = sub.add_parser("cycle", help="quasi-static load cycle: path, jumps, dissipated energy; plot and CSV",
                       description="From first contact (snap-in) up to the maximum, down to the minimum and up "
                                   "again along the stable branch; jumps listed; energy dissipated per cycle "
                                   "(loop area) [J/m].")
    add_physical(c, number_type)
    c.add_argument("--control", choices=("load", "grip-work", "grip"), default="load",
                   help="driven quantity: load, the work-conjugate approach (grip-work) or the paper's (grip); "
                        "default load")
    c.add_argument("--P-max", type=number_type, help="largest load [N/m] (load control)")
    c.add_argument("--P-min", type=number_type, help="smallest load [N/m] (load control)")
    c.add_argument("--delta-max", type=number_type, help="largest held approach [m] (grip controls)")
    c.add_argument("--delta-min", type=number_type, help="smallest held approach [m] (grip controls)")
    c.add_argument("--n", type=int, default=2000, help="path points at most (default 2000)")
    c.add_argument("--plot", default=None, help="P-delta_work plot with the jumps as arrows (PNG or PDF)")
    c.add_argument("--csv", default=None, help="the path as CSV (physical units)")
    c.set_defaults(func=cmd_cycle)
