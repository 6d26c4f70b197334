"""``jkrcyl rate-sweep``: pull-off against rate with crack kinetics (jkrcyl.kinetics.rate_sweep): a table (CSV or
JSON) and the log-log figure with the quasi-static value, the high-rate power law and the frozen-contact ceiling;
physical inputs only."""
from __future__ import annotations

import numpy as np

from . import inputs

CONTROLS = ("load", "grip-work", "grip")


def run(args):
    c = inputs.contact_from(args)
    if c.kinetics is None:
        raise ValueError("v_star: rate-sweep needs crack kinetics (--v-star and --n)")
    lo, hi = inputs.number_arg(str(args.rate_min)), inputs.number_arg(str(args.rate_max))
    if not (0 < lo < hi and np.isfinite(hi)):
        raise ValueError(f"rate_min must be in (0, rate_max), rate_max finite: got {lo!r}, {hi!r}")
    inputs.positive_count("count", args.count, 2)
    from ..kinetics import rate_sweep
    sw = rate_sweep(c, np.geomspace(lo, hi, args.count), args.control)
    rows = [{"rate": r, "P": P, "event": k, "asymptote": a} for r, P, k, a in zip(sw.rates, sw.P, sw.kind,
                                                                                  sw.asymptote)]
    meta = {"control": args.control, "P_quasi_static": np.nan if sw.P_quasi_static is None else sw.P_quasi_static,
            "P_frozen": np.nan if sw.P_frozen is None else sw.P_frozen, "exponent": sw.exponent}
    if args.figure:
        from ..plotting import rate
        rate.save(rate.sweep_figure(sw, c), args.figure)
    inputs.write_rows(rows, args.format, meta=meta)
    return 0


def register(sub):
    p = sub.add_parser("rate-sweep", help="pull-off against rate with crack kinetics (table, log-log figure)",
                       description="The pull-off (largest tension before the contact vanishes or the top closes) "
                                   "at rates log-spaced from --rate-min to --rate-max, from the zero-load contact "
                                   "at rest; with the quasi-static value, the high-rate power law (load) and the "
                                   "infinite-rate ceiling.")
    inputs.add_physical(p)
    inputs.add_kinetics(p)
    p.add_argument("--control", choices=CONTROLS, default="load",
                   help="the ramped quantity: load [N/m/s], grip-work or grip approach [m/s] (default load)")
    p.add_argument("--rate-min", type=inputs.number_arg, required=True, help="smallest rate")
    p.add_argument("--rate-max", type=inputs.number_arg, required=True, help="largest rate")
    p.add_argument("--count", type=int, default=30, help="rates, log-spaced (default 30)")
    p.add_argument("--figure", default=None, help="the log-log figure (PNG or PDF)")
    p.add_argument("--format", choices=("csv", "json"), default="csv", help="output format (default csv)")
    p.set_defaults(func=run)
