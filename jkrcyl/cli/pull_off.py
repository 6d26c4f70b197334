"""``jkrcyl pull-off``: detachment under load, grip-work and grip (jkrcyl.Contact.pull_off), physical inputs only;
with crack kinetics (--v-star --n) and --rate, the pull-off at that rate under one --control."""
from __future__ import annotations

import math

from . import inputs

CONTROLS = ("load", "grip-work", "grip")


def _row(c, control):
    po = c.pull_off(control)
    value = (lambda x: x) if po.detached else (lambda x: math.nan)
    return {"control": control, "detached": po.detached, "P": value(po.P), "contact_width": value(po.contact_width),
            "delta": value(po.delta), "delta_work": value(po.delta_work), "reason": po.reason}


def _rate_row(c, control, rate):
    po = c.pull_off(control, rate=rate)
    value = (lambda x: x) if po.detached else (lambda x: math.nan)
    return {"control": control, "rate": rate, "detached": po.detached, "event": po.kind, "P": value(po.P),
            "delta": value(po.delta), "delta_work": value(po.delta_work), "reason": po.reason}


def run(args):
    c = inputs.contact_from(args)
    if args.rate is not None:
        r = _rate_row(c, args.control or "load", args.rate)
        if args.format == "json":
            inputs.write_rows([r], "json")
        elif r["detached"]:
            n, unit = inputs.number, "N/m/s" if r["control"] == "load" else "m/s"
            print(f"{r['control']:9s} at {n(r['rate'])} {unit}: pull-off P = {n(r['P'])} N/m (largest tension), "
                  f"{r['event']} at delta = {n(r['delta'])} m, delta_work = {n(r['delta_work'])} m")
        else:
            print(f"{r['control']:9s}: no detachment -- {r['reason']}")
        return 0
    if args.control is not None:
        raise ValueError("control: --control selects the ramp of --rate (without it every control is shown)")
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
    inputs.add_kinetics(p)
    p.add_argument("--rate", type=inputs.number_arg, default=None,
                   help="with crack kinetics: ramp rate, N/m/s for --control load, m/s for grip-work and grip")
    p.add_argument("--control", choices=CONTROLS, default=None, help="the ramp of --rate (default load)")
    p.add_argument("--format", choices=("text", "json"), default="text", help="output format (default text)")
    p.set_defaults(func=run)
