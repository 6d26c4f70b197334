"""What the paper's alpha* = 0 restriction costs (issue 10, item 5): a Markdown table for the user guide
(docs/guide/materials.md).

For each material pair: the true alpha* (solver, jkrcyl.numerics.arcs) against the closed form evaluated as if
alpha* = 0 with the same beta*, vartheta and gb = (1/G_I)/beta*, at M = 0.4 and a = 0.5 (sub-critical), and the
fixed-load adherence force (minimum of P* on the sub-critical branch).
Run: python benchmarks/alpha_table.py
"""
import math

import numpy as np

import jkrcyl
from jkrcyl import equilibria as eq

PAIRS = [("steel pin in aluminium plate", 70e9, 0.33, 210e9, 0.30),
         ("aluminium pin in steel plate", 210e9, 0.30, 70e9, 0.33),
         ("steel roller in polymer cradle", 3e9, 0.40, 210e9, 0.30),
         ("rigid pin in plate, nu = 0.2", 210e9, 0.20, math.inf, 0.30),
         ("rigid pin in plate, nu = 0.3", 210e9, 0.30, math.inf, 0.30)]
M, A = 0.4, 0.5


def row(name, E, nu, E_I, nu_I):
    mat = jkrcyl.Materials.from_young(E, nu, E_I, nu_I)
    th, gb, ar = mat.theta, mat.inv_G_I / mat.beta, mat.alpha_ratio
    true = eq.curve(M, th, gb=gb, a=np.array([A]), alpha_ratio=ar)
    cf = eq.curve(M, th, gb=gb, a=np.array([A]))
    adh_t = eq.adherence(M, th, "load", gb=gb, regimes=("sub-critical",), alpha_ratio=ar, confined=False)
    adh_c = eq.adherence(M, th, "load", gb=gb, regimes=("sub-critical",), confined=False)
    f = lambda pts: pts[0].P_star if pts else math.nan
    cells = [f"{true.P_star[0]:.4f} / {cf.P_star[0]:.4f}",
             f"{true.delta_over_Delta[0]:.4f} / {cf.delta_over_Delta[0]:.4f}",
             f"{true.h_pi_over_Delta[0]:.4f} / {cf.h_pi_over_Delta[0]:.4f}",
             f"{f(adh_t):.4f} / {f(adh_c):.4f}"]
    return f"| {name} | {ar:+.3f} | {th:.3f} | " + " | ".join(cells) + " |"


def main():
    print(f"M = {M}, a = {A} (sub-critical); each cell: true alpha* / closed form as if alpha* = 0")
    print("| pair | alpha*/beta* | vartheta | P* | delta/Delta | h(pi)/Delta | adherence P* (fixed load) |")
    print("|---|---|---|---|---|---|---|")
    for p in PAIRS:
        print(row(*p), flush=True)


if __name__ == "__main__":
    main()
