"""
The cohesive law: from Baney-Hui to JKR
=======================================

JKR assumes adhesion of zero range.  The Maugis-Dugdale law spreads it over a range h0 = w/sigma0 with the
traction sigma0.  The transition parameter lambda runs from the rigid (Bradley/Baney-Hui, small lambda) to the
JKR limit (large lambda).  First the README pin at lambda = 3, then the load-control pull-off against lambda for
a few M with its JKR and half-plane asymptotes, and a coarse (lambda, M) map of where the pin detaches (``jkrcyl
cohesive --n 100`` draws the full one).
"""
import numpy as np

import jkrcyl
from jkrcyl.analysis.cohesive_map import pull_off_map
from jkrcyl.plotting.cohesive import map_figure, pull_off_figure

m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
md = jkrcyl.Contact.with_lambda(R=10e-3, Delta=1e-6, w=0.05, materials=m, lambda_=3.0)
print(f"sigma0 = {md.sigma0 / 1e3:.1f} kPa, h0 = {md.h0 * 1e6:.3f} um")
for control in ("load", "grip-work"):
    print(control, md.pull_off(control))

# %%
# Pull-off against lambda up to 10 (one process: ``workers=1``; beyond lambda = 10 the zone is thin and each
# point costs seconds).
fig, rows = pull_off_figure(lams=np.geomspace(0.02, 10.0, 10), workers=1)

# %%
# The map over (lambda, M), 10 x 10.
pm = pull_off_map(np.geomspace(0.05, 10.0, 10), np.linspace(0.02, 0.6, 10), workers=1)
fig2 = map_figure(pm)
