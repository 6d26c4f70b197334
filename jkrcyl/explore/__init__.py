"""``jkrcyl explore``: a local web app (a Bokeh server on 127.0.0.1) to move the inputs of a pin in a hole and watch
the load-approach curves, the pull-offs, a load cycle and the fields around the hole.

* :mod:`.model`: the inputs and what is drawn, computed without a browser (:func:`compute`);
* :mod:`.app`: the Bokeh document (fields, plots, the messages beside the fields);
* :mod:`.server`: the server on an open port of 127.0.0.1.

Needs the ``explore`` extra (``pip install -e '.[explore]'``: bokeh).
"""
from .model import LAWS, Inputs, Picture, compute, field_of

__all__ = ["Inputs", "LAWS", "Picture", "compute", "field_of"]
