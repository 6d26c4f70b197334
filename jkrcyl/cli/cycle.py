"""``jkrcyl cycle``: a quasi-static cycle (jkrcyl.Contact.cycle) -- jumps, dissipated energy, the path as CSV and
its plot (jkrcyl.plotting.cycle); physical inputs only."""
from __future__ import annotations

import math

from . import inputs


def run(args):
    c = inputs.contact_from(args)
    cy = c.cycle(P_max=args.P_max, P_min=args.P_min, control=args.control, n=args.n,
                 delta_max=args.delta_max, delta_min=args.delta_min)
    if args.csv:
        with open(args.csv, "w") as fh:
            t = cy.table()
            inputs.write_rows([dict(zip(t, row)) for row in zip(*t.values())], "csv", out=fh,
                              meta={"control": cy.control, "dissipated_J_per_m": cy.dissipated
                                    if cy.dissipated is not None else math.nan})
    if args.plot:
        from ..plotting.cycle import plot
        plot(cy, args.plot, c)
    n = inputs.number
    print(f"{cy.control} control: {len(cy.P)} path points, {len(cy.jumps)} jumps")
    for j in cy.jumps:
        print(f"  leg {j.leg} {j.kind:11s} {j.before.branch} -> {j.after.branch}: P {n(j.before.P)} -> "
              f"{n(j.after.P)} N/m, delta {n(j.before.delta)} -> {n(j.after.delta)} m")
    if cy.dissipated is None:
        print(f"dissipated energy per cycle: n/a (the loop did not close{': ' + cy.note if cy.note else ''})")
    else:
        print(f"dissipated energy per cycle: {n(cy.dissipated)} J/m")
    return 0


def register(sub):
    c = sub.add_parser("cycle", help="quasi-static load cycle: path, jumps, dissipated energy; plot and CSV",
                       description="From first contact (snap-in) up to the maximum, down to the minimum and up "
                                   "again along the stable branch; jumps listed; energy dissipated per cycle "
                                   "(loop area) [J/m].")
    inputs.add_physical(c)
    c.add_argument("--control", choices=("load", "grip-work", "grip"), default="load",
                   help="driven quantity: load, the work-conjugate approach (grip-work) or the paper's (grip); "
                        "default load")
    c.add_argument("--P-max", type=inputs.number_arg, help="largest load [N/m] (load control)")
    c.add_argument("--P-min", type=inputs.number_arg, help="smallest load [N/m] (load control)")
    c.add_argument("--delta-max", type=inputs.number_arg, help="largest held approach [m] (grip controls)")
    c.add_argument("--delta-min", type=inputs.number_arg, help="smallest held approach [m] (grip controls)")
    c.add_argument("--n", type=int, default=2000, help="path points at most (default 2000)")
    c.add_argument("--plot", default=None,
                   help="P-delta_work plot (PNG or PDF): branches labelled, jumps as arrows with their kind, the "
                        "direction of travel, the parameters in the title")
    c.add_argument("--csv", default=None, help="the path as CSV (physical units)")
    c.set_defaults(func=run)
