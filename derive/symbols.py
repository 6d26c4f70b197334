"""Symbols shared by every derivation, named as in the paper.

Kernels take ``inv_theta`` = 1/vartheta instead of vartheta so that the rigid cradle
(vartheta = infinity, section 7.2) is the ordinary value ``inv_theta = 0``.
"""
import sympy as sp

# contact parameter a = tan(eps/2) (section 2) and the angles of (5.2)-(5.10)
a = sp.Symbol("a", positive=True)
phi = sp.Symbol("phi", real=True)
psi = sp.Symbol("psi", real=True)
eps = sp.Symbol("eps", positive=True)

# geometry and materials (sections 2-4)
R = sp.Symbol("R", positive=True)            # hole radius
Delta = sp.Symbol("Delta", nonnegative=True)  # clearance R - R_D
beta = sp.Symbol("beta", positive=True)       # beta* = (kappa+1)/2G + (kappa_I+1)/2G_I
theta = sp.Symbol("theta", positive=True)     # vartheta = G beta*/(1+kappa) >= 1/2
inv_theta = sp.Symbol("inv_theta", nonnegative=True)
zeta = sp.Symbol("zeta", nonnegative=True)    # zeta* = sqrt(2 w R / A), A = beta*/(2 pi)
kappa_I = sp.Symbol("kappa_I", positive=True)
inv_G_I = sp.Symbol("inv_G_I", nonnegative=True)  # 1/G_I, zero for a rigid indenter

# unknowns of the linear system (4.3) and the constants of (2.6)
B, P, C = sp.symbols("B P C", real=True)
c0, c1 = sp.symbols("c0 c1", real=True)

# dimensionless load problem of section 6
M = sp.Symbol("M", nonnegative=True)          # M = sqrt(w A R)/(sqrt(2) Delta vartheta)

# integration variables of the appendix
s, x, r = sp.symbols("s x r", real=True)

# shorthands used by the paper in section 4: E = sqrt(1 + a^2), L = log(1 + a^2)
E = sp.sqrt(1 + a**2)
L = sp.log(1 + a**2)
