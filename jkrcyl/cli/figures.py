"""``jkrcyl figures``: the paper's Figures 2-12 as PNG, PDF and CSV (jkrcyl.plotting.draw_all), with a progress
bar on stderr."""
from __future__ import annotations

import sys

from . import inputs


def _progress_bar():
    """A callback (done, total, next figure) driving one tqdm bar on stderr."""
    from tqdm import tqdm
    shown = []

    def bar(i, n, name):
        if not shown:
            shown.append(tqdm(total=n, unit="figures", file=sys.stderr))
        shown[0].set_postfix_str(name)
        shown[0].update(i - shown[0].n)
        if i == n:
            shown[0].close()
    return bar


def run(args):
    from .. import plotting
    only = None
    if args.only:
        only = [s.strip() for s in args.only.split(",") if s.strip()]
        bad = [s for s in only if s not in plotting.FIGURES]
        if bad:
            raise ValueError(f"only: unknown figure {bad[0]!r} (choose from {', '.join(plotting.FIGURES)})")
    inputs.positive_count("n", args.n, 4)
    written = plotting.draw_all(args.out, n=args.n, only=only, progress=None if args.quiet else _progress_bar(),
                                alpha_ratio=args.alpha_ratio)
    print(f"wrote {len(written)} files to {args.out}")
    return 0


def register(sub):
    f = sub.add_parser("figures", help="draw the paper's Figures 2-12 (PNG, PDF, CSV)",
                       description="Draw Figures 2-12 into OUT as figNN.png, figNN.pdf and figNN.csv "
                                   "(CSV columns: panel, series, x_name, x, y_name, y, feasible). Each figure "
                                   "states vartheta, the gb of its material pair and alpha*/beta*.")
    f.add_argument("--out", default="figures", help="output folder (default: figures)")
    f.add_argument("--n", type=int, default=None, help="points per curve (default: per figure, 400-600)")
    f.add_argument("--only", default=None, help="comma-separated subset, e.g. fig02,fig11")
    f.add_argument("--quiet", action="store_true", help="no progress bar")
    f.add_argument("--alpha-ratio", type=inputs.number_arg, default=0.0,
                   help="alpha*/beta* (default 0: the paper's closed forms; otherwise the solver, no Fig. 8)")
    f.set_defaults(func=run)
