"""The explicit registry of the paper's figures and the writer of their files.

:data:`FIGURES` maps name -> :class:`FigureSpec` (paper number, builder, the parameters the figure states).
``FIGURES[name].build(n, alpha_ratio)`` returns ``(matplotlib Figure, rows)``; the rows are the plotted points,
written as CSV with the columns of :data:`jkrcyl.plotting.style.CSV_COLUMNS`.
"""
from __future__ import annotations

import csv
import math
import pathlib
from dataclasses import dataclass, field
from typing import Callable

from . import paper, paper_pressure, paper_stability
from . import style as st


@dataclass(frozen=True)
class FigureSpec:
    """One registered figure: paper number, builder ``(n, alpha_ratio) -> (Figure, rows)``, stated parameters."""

    number: int
    builder: Callable
    params: dict = field(default_factory=dict)
    closed_form_only: bool = False     # True: drawn at alpha* = 0 whatever alpha_ratio (Fig. 8, the neat fit)

    @property
    def name(self):
        return f"fig{self.number:02d}"

    def build(self, n=None, alpha_ratio=0.0):
        return self.builder(alpha_ratio=alpha_ratio) if n is None else self.builder(n, alpha_ratio=alpha_ratio)


_GB1 = st.figure_gb(1.0)
_REGISTRY = [
    FigureSpec(2, paper.fig02, dict(theta=1.0, gb=_GB1, regime="sub-critical", M=paper.M_VALUES)),
    FigureSpec(3, paper.fig03, dict(theta=1.0, gb=_GB1, regime="sub-critical", M=paper.FIG03_M)),
    FigureSpec(4, paper_pressure.fig04, dict(theta=1.0, regime="sub-critical", cases=paper_pressure.FIG04_CASES)),
    FigureSpec(5, paper.fig05, dict(theta=1.0, gb=_GB1, regime="super-critical", M=paper.M_VALUES)),
    FigureSpec(6, paper.fig06, dict(theta=0.5, gb=st.figure_gb(0.5), regime="sub-critical", M=paper.M_VALUES)),
    FigureSpec(7, paper.fig07, dict(theta=math.inf, gb=st.figure_gb(math.inf), regime="sub-critical",
                                    M=paper.M_VALUES)),
    FigureSpec(8, paper_stability.fig08, dict(theta=(0.5, 1.0), Delta=0.0), closed_form_only=True),
    FigureSpec(9, paper.fig09, dict(theta=1.0, gb=_GB1, M=paper.FIG09_M)),
    FigureSpec(10, paper_stability.fig10, dict(theta=paper_stability.FIG10_THETAS, control="load")),
    FigureSpec(11, paper_stability.fig11, dict(theta=1.0, gb=_GB1, M=paper_stability.FIG11_M)),
    FigureSpec(12, paper_pressure.fig12, dict(theta=1.0, regime="super-critical", cases=paper_pressure.FIG12_CASES)),
]
FIGURES = {spec.name: spec for spec in _REGISTRY}


def write_csv(path, rows):
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(st.CSV_COLUMNS)
        w.writerows(rows)


def draw_all(out, n=None, only=None, progress=None, alpha_ratio=0.0):
    """Write figNN.png, figNN.pdf, figNN.csv into ``out``; returns the list of paths written.

    alpha_ratio = alpha*/beta* != 0 draws the figures with the numerical solver (Fig. 8, the neat fit, is a closed
    form: drawn at alpha* = 0, as its title says).  progress(done, total, next name) is called before each figure
    and at the end.
    """
    plt = st.mpl()
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    names = [k for k in FIGURES if only is None or k in only]
    written = []
    for i, name in enumerate(names):
        if progress:
            progress(i, len(names), name)
        fig, rows = FIGURES[name].build(n, alpha_ratio=alpha_ratio)
        for ext in ("png", "pdf"):
            p = out / f"{name}.{ext}"
            fig.savefig(p, dpi=110, metadata={"CreationDate": None} if ext == "pdf" else None)
            written.append(p)
        plt.close(fig)
        write_csv(out / f"{name}.csv", rows)
        written.append(out / f"{name}.csv")
    if progress:
        progress(len(names), len(names), "done")
    return written
