"""``jkrcyl explore``: the interactive explorer (jkrcyl.explore), served on 127.0.0.1; needs the explore extra."""
from __future__ import annotations

from . import inputs


def run(args):
    try:
        from ..explore.server import serve
    except ImportError as exc:            # bokeh missing: one line, exit status 2
        raise ValueError(f"explore: needs the explore extra (pip install -e '.[explore]'): {exc}") from None
    return serve(args.port, open_browser=args.open)


def register(sub):
    p = sub.add_parser("explore", help="interactive explorer in the browser (local Bokeh server)",
                       description="Serve the explorer on 127.0.0.1 and print its URL: inputs for both materials, "
                                   "R, Delta, w, the edge law and the control; the load-approach branches, first "
                                   "contact, the three pull-offs, a load cycle, the pressure and the gap around the "
                                   "hole. Stop with Ctrl-C.")
    p.add_argument("--port", type=inputs.number_arg, default=None,
                   help="port on 127.0.0.1 (default: an open port chosen by the system)")
    p.add_argument("--open", action="store_true", help="also open the URL in the default browser")
    p.set_defaults(func=run)
