"""
Two patches and the zip to full contact
=======================================

When the pin is pulled the gap at the top of the hole (phi = pi) can close before the contact at the bottom lets
go: a second contact forms at the top.  For a strongly adhesive pin (large M) the fold of the sub-critical branch
is where a further pull makes the contact *grow* (G < w): it zips round into full contact and the pin, bonded all
round, does not detach under load.  The figure is the library's own (``jkrcyl two-patch --figure``): every
equilibrium family for a few M, stability as a band, and the load path of slow pulling.
"""
import jkrcyl
from jkrcyl.plotting import confined_figure

m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
for w in (0.05, 0.08, 0.3):
    pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=w, materials=m)
    ev = pin.confined_events()
    print(f"w = {w:4.2f} J/m^2, M = {pin.M:.3f}: {ev.regime:12s} {ev.summary}")

# %%
# The two-patch branches of the README pin, and the figure over M.
pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
for b in pin.two_patch():
    print(b.ends, f"{int(b.stable_load.sum())} of {len(b.P_star)} states stable under load")
fig = confined_figure()
