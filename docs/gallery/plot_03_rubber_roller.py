"""
A rubber roller in a rigid cradle
=================================

A rubber roller (E = 2 MPa, nu = 0.45) in a rigid steel cradle (``E = math.inf``) of radius 10 mm with 50 um
clearance.  A rigid cradle with a compressible roller still has a receding contact a_crit (the pole of the
load without adhesion), found by the collocation solver because alpha* != 0 for this pair.  The pressure and the
gap around the hole show the square-root adhesive edges of JKR.
"""
import math

import matplotlib.pyplot as plt
import numpy as np

import jkrcyl

m = jkrcyl.Materials.from_young(E=math.inf, nu=0.3, E_I=2e6, nu_I=0.45)
roller = jkrcyl.Contact(R=10e-3, Delta=50e-6, w=0.05, materials=m)
print(f"alpha*/beta* = {m.alpha_ratio:.3f}, M = {roller.M:.3f}, "
      f"a_crit = {roller.a_crit:.4f} (eps_crit = {math.degrees(2 * math.atan(roller.a_crit)):.2f} deg)")
po = roller.pull_off("load")
print(po)

# %%
# The pressure and the gap at three loads on the stable branch.
phi = np.linspace(-math.pi, math.pi, 1441)
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.8))
for P in (0.0, 20.0, 60.0):
    s = next(s for s in roller.solve(P=P, branches=["sub-critical"]) if s.stable)
    ax1.plot(np.degrees(phi), roller.pressure(s.a, phi) / 1e3, label=f"P = {P:g} N/m")
    ax2.plot(np.degrees(phi), roller.gap(s.a, phi) * 1e6, label=f"P = {P:g} N/m")
ax1.set(ylim=(-60, 60), xlabel="phi [deg]", ylabel="pressure N [kPa]", title="pressure (compressive > 0)")
ax2.set(xlabel="phi [deg]", ylabel="gap h [um]", title="gap")
ax1.legend(fontsize=8)
fig.tight_layout()
