"""Command-line front ends of the forward problems (issue 11): ``jkrcyl solve``, ``jkrcyl pull-off``,
``jkrcyl cycle``.  Physical inputs only (SI units); numbers printed with 10 significant digits,
booleans as true/false in every format.
"""
from __future__ import annotations

import json
import math
import sys

PHYSICAL = (("E", "Young's modulus of the body with the hole [Pa] (inf: rigid)"), ("nu", "its Poisson ratio"),
            ("E-I", "Young's modulus of the cylinder [Pa] (inf: rigid)"), ("nu-I", "its Poisson ratio"),
            ("R", "hole radius [m]"), ("Delta", "clearance R - R_D [m], > 0"), ("w", "work of adhesion [J/m^2]"))

UNITS = {"a": "", "a_top": "", "eps": "rad", "eps_top": "rad", "contact_width": "m", "P": "N/m", "delta": "m",
         "h_pi": "m", "K": "Pa m^1/2", "P_star": "", "delta_over_Delta": "", "energy": "J/m"}


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
    if isinstance(x, (bool,)) or type(x).__name__ == "bool_":
        return "true" if x else "false"
    if isinstance(x, str):
        return x
    x = float(x)
    return f"{x:.10g}" if math.isfinite(x) else ("inf" if x > 0 else "-inf" if x < 0 else "nan")


def json_value(x):
    if isinstance(x, str) or x is None:
        return x
    if isinstance(x, bool) or type(x).__name__ == "bool_":
        return bool(x)
    x = float(x)
    return float(f"{x:.10g}") if math.isfinite(x) else None


def header(keys):
    return ",".join(f"{k} [{UNITS[k]}]" if UNITS.get(k) else k for k in keys)


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
    from .forward import BRANCH_SOLVERS
    c = contact_from(args)
    if (args.P is None) == (args.delta is None):
        raise ValueError("P: give exactly one of --P [N/m] and --delta [m]")
    branches = None
    if args.no_two_patch:
        branches = [b for b in BRANCH_SOLVERS if b != "two-patch"]
    states = c.solve(P=args.P, delta=args.delta, branches=branches)
    meta = {"M": c.M, "theta": c.theta, "control": "load" if args.P is not None else "grip"}
    write_rows([s.as_dict() for s in states], args.format, meta=meta)
    return 0


def register(sub, number_type):
    """Add the forward-problem commands to the subparsers of jkrcyl.cli."""
    s = sub.add_parser("solve", help="every equilibrium at a load P [N/m] or an approach delta [m]",
                       description="Every equilibrium at the given load per unit length (--P, fixed-load stability) "
                                   "or approach (--delta, fixed-grip stability) on every branch, sorted by contact "
                                   "size. Physical inputs only.")
    add_physical(s, number_type)
    s.add_argument("--P", type=number_type, help="load per unit length [N/m], positive downward")
    s.add_argument("--delta", type=number_type, help="approach [m], positive downward")
    s.add_argument("--no-two-patch", action="store_true", help="skip the two-patch branches (faster)")
    s.add_argument("--format", choices=("csv", "json"), default="csv", help="output format (default csv)")
    s.set_defaults(func=cmd_solve)
