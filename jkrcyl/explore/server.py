"""The explorer's server: a Bokeh server on 127.0.0.1 (an open port unless one is given), the URL printed, no
browser opened unless asked."""
from __future__ import annotations

import socket
import sys

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


def warm_up():
    """Compile the kernels on the default picture, so that the first page comes at the speed of later ones."""
    from .model import Inputs, compute
    compute(Inputs())


def serve(port=None, address: str = ADDRESS, open_browser: bool = False, out=sys.stdout) -> int:
    """Serve until interrupted (Ctrl-C); prints the URL once the server listens and the kernels are warm."""
    server, url = make_server(port, address)
    warm_up()
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
