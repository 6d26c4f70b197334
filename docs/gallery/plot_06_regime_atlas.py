"""
The regime atlas
================

What slow pulling under load does to the pin, over the plane of the adhesion parameter M and the material
parameter vartheta (section 6), with a strip for a rigid cradle (vartheta = inf): detachment at a fold and
transfer to the top of the hole, the zip into full contact, the top contact forming first, or a pin bonded from
first touch.  ``make atlas`` draws it on a 1000 x 1000 grid; here a coarse 120 x 60 one (numba kernels, a few
seconds).
"""
import pathlib
import tempfile

import matplotlib.image as mpimg
import matplotlib.pyplot as plt
import numpy as np

from jkrcyl.atlas import CONFINED, classify, default_grid, draw

Ms, thetas = default_grid(n_M=120, n_theta=60)
atlas = classify(Ms, thetas)
codes, counts = np.unique(atlas["confined"], return_counts=True)
for code, count in zip(codes, counts):
    print(f"{count:5d} pairs: {CONFINED[code]}")

# %%
# The map as ``jkrcyl atlas`` draws it (written to a file, shown here).
with tempfile.TemporaryDirectory() as tmp:
    png = [p for p in draw(atlas, pathlib.Path(tmp) / "atlas") if str(p).endswith(".png")][0]
    image = mpimg.imread(png)
fig, ax = plt.subplots(figsize=(9, 7.4))
ax.imshow(image)
ax.set_axis_off()
fig.tight_layout()
