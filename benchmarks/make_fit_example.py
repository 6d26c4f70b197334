"""Write docs/fit_example.csv: synthetic load-width data of a pin in a conforming hole (the README's fit example).

Truth: R = 10 mm, Delta = 3 um, both bodies E = 2.6 GPa, nu = 0.3 (plane strain), w = 0.05 J/m^2.  30 contact widths
evenly spaced from 6.5 mm (just above the fixed-load pull-off width, 6.19 mm at -888 N/m) to 21 mm; the loads are
the library's equilibrium loads (jkrcyl.Contact.state, (4.4)) at the true widths; then Gaussian noise of 0.1 mm on
each width and 10 N/m on each load is added (seed 20), and those standard deviations are written with the data.

    python benchmarks/make_fit_example.py            # rewrites docs/fit_example.csv (byte-identical on a rerun)
"""
import math
import pathlib

import numpy as np

import jkrcyl

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "docs" / "fit_example.csv"
TRUTH = dict(R=0.01, Delta=3e-6, E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3, w=0.05)
SIGMA_WIDTH, SIGMA_P, SEED, N = 1e-4, 10.0, 20, 30


def make():
    t = TRUTH
    m = jkrcyl.Materials.from_young(E=t["E"], nu=t["nu"], E_I=t["E_I"], nu_I=t["nu_I"])
    c = jkrcyl.Contact(R=t["R"], Delta=t["Delta"], w=t["w"], materials=m)
    width = np.linspace(6.5e-3, 21e-3, N)
    P = c.state(np.tan(width / (4 * t["R"]))).P          # width = 2 R eps, a = tan(eps/2)
    rng = np.random.default_rng(SEED)
    width_measured = width + rng.normal(0.0, SIGMA_WIDTH, N)
    P_measured = P + rng.normal(0.0, SIGMA_P, N)
    lines = ["# Synthetic load-width data of a pin in a conforming hole (benchmarks/make_fit_example.py).",
             f"# Setup: R={t['R']:g} Delta={t['Delta']:g} E={t['E']:g} nu={t['nu']:g} E_I={t['E_I']:g} "
             f"nu_I={t['nu_I']:g} control=load",
             f"# Truth used to generate them (not read by the fit): work of adhesion {t['w']:g} J/m^2, contact "
             f"modulus E* = {4 / m.beta:.6g} Pa; noise sd {SIGMA_WIDTH:g} m on width, {SIGMA_P:g} N/m on P, seed {SEED}",
             "P [N/m],width [m],sigma_P [N/m],sigma_width [m]"]
    lines += [f"{p:.6f},{x:.8e},{SIGMA_P:g},{SIGMA_WIDTH:g}" for p, x in zip(P_measured, width_measured)]
    OUT.write_text("\n".join(lines) + "\n")
    return OUT


if __name__ == "__main__":
    print(f"wrote {make()}")
