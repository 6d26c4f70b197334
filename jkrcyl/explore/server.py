"""The explorer's server: a Bokeh server on 127.0.0.1 (an open port unless one is given), the URL printed, no
browser opened unless asked."""
from __future__ import annotations

import socket
import sys
import threading

from .._validate import count

ADDRESS = "127.0.0.1"


def open_port(address: str = ADDRESS) -> int:
    """A port the system reports free on ``address`` (bound and released: the server binds it a moment later)."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind((address, 0))
        return s.getsockname()[1]


def make_server(port=None, address: str = ADDRESS):
    """The started Bokeh server of the explorer (not yet serving: run its io_loop) and its URL.

    port: None or 0 for an open port, else an integer in [1, 65535] (ValueError naming ``port`` otherwise, or
    when it cannot be listened on)."""
    from bokeh.application import Application
    from bokeh.application.handlers.function import FunctionHandler
    from bokeh.server.server import Server

    from .app import make_document

    port = open_port(address) if port in (None, 0) else count("port", port, low=1, high=65535)
    origins = [f"{address}:{port}", f"localhost:{port}"]
    try:
        server = Server({"/": Application(FunctionHandler(make_document))}, port=port, address=address,
                        allow_websocket_origin=origins)
    except OSError as exc:
        raise ValueError(f"port: cannot listen on {address}:{port} ({exc.strerror or exc})") from None
    server.start()
    return server, f"http://{address}:{port}/"


#: What the first change of each kind computes: a pair with alpha* != 0 and the cohesive law.
WARM_LATER = ({"E": "3e9"}, {"law": "lambda", "law_value": "3"})


def warm_up(later=False):
    """Compile the kernels: the default picture (the first page), or (later=True, in a background thread once the
    server listens) the collocation solver and the cohesive law, so that a first change to them redraws at the
    speed of the next ones rather than after seconds of compilation."""
    from .model import Inputs, compute
    for changes in (WARM_LATER if later else ({},)):
        try:
            compute(Inputs(**changes))
        except Exception:                 # warming only: a failure shows when the user asks for that picture
            pass


def serve(port=None, address: str = ADDRESS, open_browser: bool = False, out=sys.stdout) -> int:
    """Serve until interrupted (Ctrl-C); prints the URL once the server listens and the kernels are warm."""
    server, url = make_server(port, address)
    warm_up()
    threading.Thread(target=warm_up, args=(True,), daemon=True, name="jkrcyl-explore-warm-up").start()
    print(f"jkrcyl explore: {url} (Ctrl-C to stop)", file=out, flush=True)
    if open_browser:
        import webbrowser
        webbrowser.open(url)
    try:
        server.io_loop.start()
    except KeyboardInterrupt:
        pass
    finally:
        server.stop()
    return 0
