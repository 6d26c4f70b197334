"""The regime atlas: what slow pulling under load control does to the pin, over the (M, vartheta) plane.

:mod:`.classify` classifies every pair of a grid (numba kernels, one per pair, through jkrcyl.numerics; the codes
of :data:`CONFINED`), :mod:`.files` writes the result (npz, CSV) and :mod:`.draw` the map (``jkrcyl atlas``,
``make atlas``).  :mod:`.cohesive` classifies the same way under the Maugis-Dugdale law at a given lambda, each pair
through the model core's load path (``jkrcyl atlas --lambda``).

Examples
--------
>>> from jkrcyl import atlas
>>> Ms, thetas = atlas.default_grid(n_M=5, n_theta=3, M_max=1.0, theta_max=2.0)
>>> result = atlas.classify(Ms, thetas, parallel=False)
>>> [atlas.CONFINED[int(c)].split(":")[0] for c in result["confined"][1, :3]]      # vartheta = 1.25
['no load path (M = 0', 'pull-off at the sub-critical fold', 'fold on the super-critical branch']
"""
from .classify import (CONF_BONDED, CONF_NONE, CONF_TOP, CONF_TOP_FULL, CONF_TOP_TRANSFER, CONF_TRANSFER,
                       CONF_TWO_PATCH, CONF_ZIP, CONFINED, FIELDS_BOOL, FIELDS_FLOAT, FIELDS_INT, FROM_TWOPATCH,
                       classify, classify_parallel, classify_serial, default_grid)
from .draw import draw
from .cohesive import CONF_FLOAT, CONF_REFUSED, LAW_CONFINED, classify_law
from .files import CSV_COLUMNS, NOTE, write_csv, write_law_files, write_npz
