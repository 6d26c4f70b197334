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
from typing import Callable, Collection

from . import paper, paper_pressure, paper_stability
from . import style as st


@dataclass(frozen=True)
class FigureSpec:
    """One registered figure of the paper (:data:`FIGURES`).

    Attributes
    ----------
    number : int
        The paper's figure number.
    builder : callable
        ``(n, alpha_ratio) -> (Figure, rows)`` (jkrcyl.plotting.paper, paper_pressure, paper_stability).
    params : dict
        The parameters the figure states (vartheta, gb, regime, M values, ...).
    closed_form_only : bool
        Drawn at alpha* = 0 whatever alpha_ratio (Fig. 8, the neat fit).

    Examples
    --------
    >>> spec = FIGURES["fig10"]
    >>> spec.number, spec.name, spec.params["theta"]
    (10, 'fig10', (0.5, 1.0))
    """

    number: int
    builder: Callable
    params: dict = field(default_factory=dict)
    closed_form_only: bool = False     # True: drawn at alpha* = 0 whatever alpha_ratio (Fig. 8, the neat fit)

    @property
    def name(self) -> str:
        """'figNN', the key in :data:`FIGURES` and the stem of the files."""
        return f"fig{self.number:02d}"

    def build(self, n: "int | None" = None, alpha_ratio: float = 0.0) -> tuple:
        """Compute and draw the figure.

        Parameters
        ----------
        n : int, optional
            Points per curve (default: the builder's).
        alpha_ratio : float
            alpha*/beta* in (-1, 1): != 0 draws with the numerical solver (not for Fig. 8).

        Returns
        -------
        (matplotlib.figure.Figure, list)
            The figure and its plotted points as CSV rows (:data:`jkrcyl.plotting.style.CSV_COLUMNS`).

        Raises
        ------
        ValueError
            Naming alpha_ratio or n outside its range (from jkrcyl.equilibria).

        Examples
        --------
        >>> fig, rows = FIGURES["fig09"].build(n=20)
        >>> len(fig.axes) > 0, rows[0][:3]
        (True, ('a', 'cylinder M = 0', 'a/a_crit'))
        >>> st.mpl().close(fig)
        """
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


def write_csv(path: "str | pathlib.Path", rows: list) -> None:
    """Write a figure's rows as CSV under the header :data:`jkrcyl.plotting.style.CSV_COLUMNS`.

    Parameters
    ----------
    path : str or pathlib.Path
        The file.
    rows : list of tuple
        (panel, series, x_name, x, y_name, y, feasible), as the builders return them.

    Returns
    -------
    None

    Raises
    ------
    OSError
        Where the file cannot be written.

    Examples
    --------
    >>> import os, tempfile
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     write_csv(os.path.join(folder, "f.csv"), [("a", "M = 0", "a", "0.1", "P_star", "0.2", 1)])
    ...     open(os.path.join(folder, "f.csv")).read().splitlines()
    ['panel,series,x_name,x,y_name,y,feasible', 'a,M = 0,a,0.1,P_star,0.2,1']
    """
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(st.CSV_COLUMNS)
        w.writerows(rows)


def draw_all(out: "str | pathlib.Path", n: "int | None" = None, only: "Collection[str] | None" = None,
             progress: "Callable[[int, int, str], object] | None" = None,
             alpha_ratio: float = 0.0) -> "list[pathlib.Path]":
    """Write figNN.png, figNN.pdf and figNN.csv into ``out`` for the paper's figures (``jkrcyl figures``).

    Parameters
    ----------
    out : str or pathlib.Path
        The folder (made if missing).
    n : int, optional
        Points per curve (default: each builder's).
    only : collection of str, optional
        The names of :data:`FIGURES` to draw (default: all).
    progress : callable, optional
        progress(done, total, next name), called before each figure and at the end.
    alpha_ratio : float
        alpha*/beta* != 0 draws the figures with the numerical solver (Fig. 8, the neat fit, is a closed form:
        drawn at alpha* = 0, as its title says).

    Returns
    -------
    list of pathlib.Path
        The files written.

    Raises
    ------
    ValueError
        Naming alpha_ratio or n outside its range.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     [p.name for p in draw_all(folder, n=20, only=["fig09"])]
    ['fig09.png', 'fig09.pdf', 'fig09.csv']
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
