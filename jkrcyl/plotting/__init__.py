"""Every jkrcyl figure, in one place (matplotlib, imported only when a figure is drawn).

* :mod:`.style`: the shared look (solid = feasible h(pi) >= 0, dashed = overclosed; colour + marker per series;
  stability bands), the figures' material pairs :data:`FIGURE_GB`, the CSV rows;
* :mod:`.paper`, :mod:`.paper_pressure`, :mod:`.paper_stability`: the paper's Figures 2-12, registered in
  :data:`FIGURES` (:mod:`.registry`: :func:`draw_all`, :func:`write_csv`; ``jkrcyl figures``);
* :mod:`.confined`: docs/confined.png, the load-approach paths through the confined regime
  (``jkrcyl two-patch --figure``);
* :mod:`.cycle`: the plot of a quasi-static cycle (``jkrcyl cycle --plot``).
"""
from .confined import confined_figure, draw_confined
from .cycle import cycle_figure, plot as plot_cycle
from .paper_pressure import FIG04_CASES, FIG12_CASES, PRESSURE_STYLES, figure_contact, pressure_limits
from .paper_stability import detachment_limit
from .registry import FIGURES, FigureSpec, draw_all, write_csv
from .style import CSV_COLUMNS, FIGURE_GB, Style, styles

__all__ = ["CSV_COLUMNS", "FIG04_CASES", "FIG12_CASES", "FIGURES", "FIGURE_GB", "FigureSpec", "PRESSURE_STYLES",
           "Style", "confined_figure", "cycle_figure", "detachment_limit", "draw_all", "draw_confined",
           "figure_contact", "plot_cycle", "pressure_limits", "styles", "write_csv"]
