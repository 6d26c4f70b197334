"""Regime atlas over the (M, vartheta) plane (issue 6 item 3; issue 9 item 3; issue 12 item 4).

classify (numba kernels, one per pair, through jkrcyl.numerics), files (npz, CSV), draw (the map).
"""
from .classify import (CONF_BONDED, CONF_NONE, CONF_TOP, CONF_TOP_FULL, CONF_TOP_TRANSFER, CONF_TRANSFER, CONF_TWO_PATCH,
                       CONF_ZIP, CONFINED, FIELDS_BOOL, FIELDS_FLOAT, FIELDS_INT, FROM_TWOPATCH, classify,
                       classify_parallel, classify_serial, default_grid)
from .draw import draw
from .files import CSV_COLUMNS, NOTE, write_csv, write_npz
