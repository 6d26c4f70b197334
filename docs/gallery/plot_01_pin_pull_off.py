"""
The README pin: pull-off under load and under grip
==================================================

A pin in a hole of radius 10 mm with 1 um radial clearance, both bodies E = 2.6 GPa, nu = 0.3, work of adhesion
0.05 J/m^2.  The single-patch branches of equilibria on the plane of the load P and the work-conjugate approach
delta_work, with the pull-off under each of the three controls: the load held (a dead weight), delta_work held
(a testing machine holding the pin) and the paper's approach delta held.
"""
import matplotlib.pyplot as plt
import numpy as np

import jkrcyl

m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
for control in ("load", "grip-work", "grip"):
    po = pin.pull_off(control=control)
    print(f"{control:9s}: P = {po.P:8.1f} N/m, contact width = {po.contact_width * 1e3:5.2f} mm, "
          f"delta_work = {po.delta_work * 1e6:6.3f} um")

# %%
# The branches: solid where the state is stable under load, dashed where it is not; the sub-critical branch
# (contact smaller than the receding contact a_crit) carries the path of a pin pulled from first contact.
fig, ax = plt.subplots(figsize=(7, 4.5))
for regime, color in (("sub-critical", "C0"), ("super-critical", "C1")):
    cv = pin.curve(regime, n=1500)
    x, P = cv.delta_work * 1e6, cv.P
    ax.plot(x, np.where(cv.stable_load, P, np.nan), color=color, lw=2, label=f"{regime}, stable under load")
    ax.plot(x, np.where(cv.stable_load, np.nan, P), color=color, lw=1, ls="--", label=f"{regime}, unstable")
for control, marker in (("load", "v"), ("grip-work", "D"), ("grip", "s")):
    po = pin.pull_off(control)
    ax.plot(po.delta_work * 1e6, po.P, marker, ms=9, label=f"pull-off ({control})")
ax.set(xlim=(-1.5, 1.5), ylim=(-2500, 2500), xlabel="delta_work [um]", ylabel="P [N/m]",
       title="README pin: branches and pull-offs")
ax.axhline(0, color="0.8", lw=0.6)
ax.legend(fontsize=7, loc="lower right")
fig.tight_layout()
