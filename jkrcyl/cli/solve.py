"""``jkrcyl solve``: every equilibrium at a load P [N/m] or an approach [m] (jkrcyl.Contact.solve), physical inputs
only."""
from __future__ import annotations

from ..analysis.forward import BRANCH_SOLVERS
from ..units import control_of_physical
from . import inputs


def run(args):
    c = inputs.contact_from(args)
    given = {k: getattr(args, k) for k in ("P", "delta", "delta_work") if getattr(args, k) is not None}
    if len(given) != 1:
        raise ValueError("P: give exactly one of --P [N/m], --delta [m] and --delta-work [m]")
    branches = [b for b in BRANCH_SOLVERS if b != "two-patch"] if args.no_two_patch else None
    states = c.solve(**given, branches=branches)
    control = control_of_physical(next(iter(given))).name
    pb = c.problem
    meta = {"M": pb.M, "theta": pb.theta, "gb": pb.gb, "alpha_ratio": pb.alpha_ratio, "control": control,
            "edge": pb.edge.name, "h0": c.h0}
    inputs.write_rows([s.as_dict() for s in states], args.format, meta=meta)
    return 0


def register(sub):
    s = sub.add_parser("solve", help="every equilibrium at a load P [N/m] or an approach delta [m]",
                       description="Every equilibrium at the given load per unit length (--P, fixed-load stability), "
                                   "work-conjugate approach (--delta-work, stability with a testing machine holding "
                                   "the pin) or the paper's approach (--delta, (5.8)) on every branch, sorted by "
                                   "contact size. Physical inputs only.")
    inputs.add_physical(s)
    s.add_argument("--P", type=inputs.number_arg, help="load per unit length [N/m], positive downward")
    s.add_argument("--delta", type=inputs.number_arg, help="the paper's approach (5.8) [m], positive downward")
    s.add_argument("--delta-work", type=inputs.number_arg,
                   help="work-conjugate approach delta + P/(8 pi G_I) [m], positive downward")
    s.add_argument("--no-two-patch", action="store_true", help="skip the two-patch branches (faster)")
    s.add_argument("--format", choices=("csv", "json"), default="csv", help="output format (default csv)")
    s.set_defaults(func=run)
