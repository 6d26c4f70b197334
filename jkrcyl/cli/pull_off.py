"""``jkrcyl pull-off``: detachment under load, grip-work and grip (jkrcyl.Contact.pull_off), physical inputs only."""
from __future__ import annotations

import math

from . import inputs

CONTROLS = ("load", "grip-work", "grip")


def _row(c, control):
    po = c.pull_off(control)
    value = (lambda x: x) if po.detached else (lambda x: math.nan)
    return {"control": control, "detached": po.detached, "P": value(po.P), "contact_width": value(po.contact_width),
            "delta": value(po.delta), "delta_work": value(po.delta_work), "reason": po.reason}


def run(args):
    c = inputs.contact_from(args)
    rows = [_row(c, control) for control in CONTROLS]
    if args.format == "json":
        inputs.write_rows(rows, "json")
        return 0
    n = inputs.number
    for r in rows:
        if r["detached"]:
            print(f"{r['control']:9s}: pull-off P = {n(r['P'])} N/m, contact width = {n(r['contact_width'])} m, "
                  f"delta = {n(r['delta'])} m, delta_work = {n(r['delta_work'])} m")
        else:
            print(f"{r['control']:9s}: no detachment -- {r['reason']}")
    return 0


def register(sub):
    p = sub.add_parser("pull-off", help="pull-off force [N/m], contact width and approach (load and grip)",
                       description="Detachment along the stable path from the zero-load contact, under load, "
                                   "under grip on the work-conjugate approach (grip-work: a testing machine "
                                   "holding the pin) and on the paper's approach (grip), or the reason there is "
                                   "none.")
    inputs.add_physical(p)
    p.add_argument("--format", choices=("text", "json"), default="text", help="output format (default text)")
    p.set_defaults(func=run)
