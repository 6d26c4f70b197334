"""
The paper's Figures 2-12
========================

Every figure of the paper redrawn from the re-derived kernels, as ``make figures`` writes them (PNG, PDF and the
plotted points as CSV): equilibrium curves (Figs. 2, 3, 5, 6, 7), pressure distributions (Figs. 4, 12), the neat
fit (Fig. 8), the Barquins comparison (Figs. 9, 10) and the stability (Fig. 11).  Solid lines: the gap inequality
holds; dashed: the gap is overclosed somewhere (h(pi) < 0).
"""
from jkrcyl.plotting import FIGURES

for name, spec in FIGURES.items():
    fig, rows = spec.build()
    print(f"{name}: Figure {spec.number}, {len(rows)} plotted points")
