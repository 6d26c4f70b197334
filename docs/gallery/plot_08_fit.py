"""
Fitting measurements: w and the contact modulus
===============================================

``docs/fit_example.csv`` holds 30 synthetic points of a pin in a hole (R = 10 mm, Delta = 3 um, E = 2.6 GPa,
nu = 0.3 for both bodies, w = 0.05 J/m^2; 0.1 mm noise on the width, 10 N/m on the load).  ``jkrcyl.fit``
estimates the work of adhesion and the contact modulus with 95 % profile-likelihood intervals; the plot shows the
data, the fitted curve and the normalised residuals.
"""
import pathlib
import tempfile

import matplotlib.image as mpimg
import matplotlib.pyplot as plt

import jkrcyl

csv = pathlib.Path(jkrcyl.__file__).resolve().parents[1] / "docs" / "fit_example.csv"
data = jkrcyl.fit.read_csv(csv)
m0 = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)   # starting moduli; "E" keeps their ratio
res = jkrcyl.fit(**data.columns, R=0.01, Delta=3e-6, materials=m0, free=("w", "E"))
print(res.table())
print("truth: w = 0.05 J/m^2, E* = E/(2(1 - nu^2)) =", f"{2.6e9 / (2 * (1 - 0.3 ** 2)):.5g} Pa")

# %%
# The library's plot of the fit (written to a file, shown here).
with tempfile.TemporaryDirectory() as tmp:
    image = mpimg.imread(res.plot(pathlib.Path(tmp) / "fit.png"))
fig, ax = plt.subplots(figsize=(6.4, 6.4))
ax.imshow(image)
ax.set_axis_off()
fig.tight_layout()
