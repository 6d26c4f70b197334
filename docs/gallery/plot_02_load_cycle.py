"""
A load cycle: snap-in, pull-off, landing on the top
===================================================

The README pin driven from first contact up to 2000 N/m, down to -2000 N/m and back.  Pulled past the pull-off
force the contact at the bottom lets go and the pin lands on the top of the hole; pushed back it returns.  The loop
on the (delta_work, P) plane encloses the energy dissipated per cycle, which the library also sums from the jumps'
energy drops.
"""
import jkrcyl
from jkrcyl.plotting import cycle_figure

m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
cy = pin.cycle(P_max=2000.0, P_min=-2000.0, control="load", n=400)
for j in cy.jumps:
    print(f"{j.kind:9s} at P = {j.before.P:8.1f} N/m: {j.before.branch} -> {j.after.branch}")
print(f"dissipated per cycle: {cy.dissipated:.5f} J/m")

# %%
# The same under grip: the machine holds delta_work between 0.3 um and -2.3 um.
grip = pin.cycle(delta_max=0.3e-6, delta_min=-2.3e-6, control="grip-work", n=300)
print([j.kind for j in grip.jumps], f"dissipated per cycle: {grip.dissipated:.5f} J/m")
fig = cycle_figure(cy, pin)
fig2 = cycle_figure(grip, pin)
