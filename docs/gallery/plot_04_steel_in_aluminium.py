"""
Steel in aluminium: any pair of materials
=========================================

A steel pin (E = 210 GPa, nu = 0.3) in an aluminium plate (E = 70 GPa, nu = 0.33), R = 5 mm, Delta = 2 um,
w = 0.1 J/m^2.  The second Dundurs parameter alpha* is not zero, so the paper's closed forms do not hold: jkrcyl
solves (2.1) by collocation.  Here the true branch against the closed form evaluated as if alpha* were zero
with the same beta*, vartheta and gb: the loads move by a few per cent, the approach by much more.
"""
import matplotlib.pyplot as plt

import jkrcyl
from jkrcyl import equilibria

m = jkrcyl.Materials.from_young(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3)
c = jkrcyl.Contact(R=5e-3, Delta=2e-6, w=0.1, materials=m)
print(f"alpha*/beta* = {m.alpha_ratio:+.3f}, vartheta = {c.theta:.3f}, M = {c.M:.4f}")
print("a_crit:", c.a_crit, "(the closed form as if alpha* = 0:", jkrcyl.a_crit(c.theta), ")")
print(c.pull_off("load"))

# %%
true = c.curve("sub-critical", n=300)
M, theta, gb = equilibria.from_contact(c)
as_if = equilibria.curve(M, theta, "sub-critical", 300, gb=gb)         # alpha* = 0
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.8))
ax1.plot(true.eps_star, true.P_star, label="alpha* of the pair (collocation)")
ax1.plot(as_if.eps_star, as_if.P_star, "--", label="as if alpha* = 0 (closed form)")
ax2.plot(true.eps_star, true.delta_over_Delta)
ax2.plot(as_if.eps_star, as_if.delta_over_Delta, "--")
ax1.set(xlabel="eps*", ylabel="P*", title="load")
ax2.set(xlabel="eps*", ylabel="delta / Delta", title="approach")
ax1.legend(fontsize=8)
fig.tight_layout()
