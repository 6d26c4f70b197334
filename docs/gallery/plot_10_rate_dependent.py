"""
Rate-dependent adhesion: a rubber roller pulled at a rate
=========================================================

A rubber roller (E_I = 2 MPa, nu_I = 0.49) in a steel cradle (E = 210 GPa, nu = 0.3), R = 20 mm, radial
clearance Delta = 0.2 mm, work of adhesion w = 0.05 J/m^2, with crack kinetics at both contact edges,
G = w [1 + (v/v*)^n] where the contact recedes, v* = 0.1 mm/s and n = 0.6 (illustrative values of the order
reported for rubber on glass).  At rest the law is JKR's G = w, so the quasi-static pull-off is JKR's; pulled at a
rate, the edges must run to let go and the pull-off grows with the rate.
"""
import matplotlib.pyplot as plt
import numpy as np

import jkrcyl
from jkrcyl.plotting import rate as rate_plots

rubber_in_steel = jkrcyl.Materials.from_young(E=210e9, nu=0.3, E_I=2e6, nu_I=0.49)
roller = jkrcyl.Contact(R=20e-3, Delta=0.2e-3, w=0.05, materials=rubber_in_steel,
                        kinetics=jkrcyl.CrackKinetics(v_star=1e-4, n=0.6))
print(f"quasi-static pull-off (fixed load): {roller.pull_off().P:.1f} N/m")
for mm_min in (1, 10, 100):                      # a testing machine holding the pin's approach delta_work
    po = roller.pull_off("grip-work", rate=mm_min * 1e-3 / 60)
    print(f"{mm_min:4d} mm/min: {po.kind}, pull-off {po.P:.1f} N/m, contact width at rest "
          f"{po.history.contact_width[0] * 1e3:.1f} mm")

# %%
# Pull-off against rate
# ---------------------
# ``jkrcyl.kinetics.rate_sweep`` pulls the pin at each rate from the zero-load contact at rest and records the
# largest tension on the way (what the testing machine reads).  The dashed line is the quasi-static value, the
# dash-dotted one the infinite-rate ceiling (the frozen contact pulled until the gap at the top of the hole
# closes).  The crosses are the three crosshead speeds above.
sweep = jkrcyl.kinetics.rate_sweep(roller, np.logspace(-7, -2, 16), control="grip-work")
fig = rate_plots.sweep_figure(sweep, roller, title="rubber roller in a steel cradle, pulled by a testing machine")
ax = fig.axes[0]
speeds = np.array([1, 10, 100]) * 1e-3 / 60                  # 1, 10, 100 mm/min in m/s
forces = [-roller.pull_off("grip-work", rate=r).P for r in speeds]
ax.plot(speeds, forces, "kx", ms=9, mew=1.8, label="1, 10, 100 mm/min")
ax.legend(fontsize=7.5, loc="upper left")

# %%
# Load cycles at three frequencies
# --------------------------------
# The load driven as a triangular wave between +30 and -30 N/m (inside the quasi-static pull-off, so a slow
# enough cycle dissipates nothing) until the loop repeats.  The loop's area is the energy the moving edges
# dissipate per cycle: it is small when the cycle is slow (the edges stay near G = w) and when it is fast (they
# barely move), largest in between.
frequencies = (1e-4, 1e-3, 1e-1)                             # Hz
P_max, P_min = 30.0, -30.0                                   # N/m
cycles = [roller.cycle(P_max=P_max, P_min=P_min, rate=2 * (P_max - P_min) * f) for f in frequencies]
for cy in cycles:
    print(f"{cy.frequency:g} Hz: dissipated {cy.dissipated:.3g} J/m per cycle")
fig = rate_plots.loops_figure(cycles, roller, title="rubber roller in a steel cradle, load cycled at three "
                              "frequencies")
plt.show()
