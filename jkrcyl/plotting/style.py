"""The look every jkrcyl figure shares, so that a reader learns it once.

* Line style = the gap inequality (section 5): solid where h(pi) >= 0 (feasible), dashed where the gap at the top
  of the hole is overclosed (h(pi) < 0), as in the paper.
* Colour *and* marker tell the series apart (viridis at strictly ordered greyscale luminance, distinct markers:
  the figures survive greyscale printing); legends show the series as marker + colour without a line, then
  the meaning of each line style (:func:`legend`).
* Stability is a second channel on top: a wide translucent band in the series' colour (:func:`band`, as Fig. 11).
* Every figure states vartheta, gb = (1/G_I)/beta* (which delta/Delta depends on) and where gb comes from, and
  alpha*/beta* (:func:`params_text`).

The figures' material pairs (:data:`FIGURE_GB`) are fixed here once, with the words the titles use for them.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

# (1/G_I)/beta* of the pair each figure is drawn for: identical bodies with nu = 0.3 at vartheta = 1 (kappa = 1.8,
# gb = 1/(kappa + 1): the README pin; reproduces eps = 2.41 at delta = 0, M = 1 of section 8.2), a rigid pin at
# vartheta = 1/2, a rigid cradle with an incompressible cylinder at vartheta = inf.
FIGURE_GB = {1.0: 1 / 2.8, 0.5: 0.0, math.inf: 1.0}
FIGURE_PAIR = {1.0: "identical bodies, $\\nu = 0.3$", 0.5: "rigid pin",
               math.inf: "rigid cradle, incompressible cylinder"}
CSV_COLUMNS = ("panel", "series", "x_name", "x", "y_name", "y", "feasible")
MARKERS = ("o", "s", "^", "v", "D", "P", "X", "*", "<", ">")
FEASIBLE_LS, OVERCLOSED_LS = "-", "--"
BAND = dict(lw=5, alpha=0.3)          # stability band (wide, translucent, the series' colour)
LABEL = {"a": "$a$", "a/a_crit": "$a/a_{crit}$", "eps_star": "$\\varepsilon^*$",
         "eps": "$\\varepsilon$ [rad]", "P_star": "$P^*$", "P_R_star": "$P_R^*$",
         "delta_over_Delta": "$\\delta/\\Delta$", "h_pi_over_Delta": "$h(\\pi)/\\Delta$",
         "M": "$M$", "phi": "$\\phi$ [rad]", "N_R_over_absP": "$N(\\phi)R/|P|$",
         "Q_star": "$Q^* = P\\sqrt{A}/\\sqrt{2wR}$", "h_pi_over_zeta_beta": "$h(\\pi)/(\\zeta^*\\beta^*)$"}


def mpl():
    """matplotlib.pyplot on the Agg backend (files only, no display needed)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def figure_gb(theta: float) -> float:
    """gb of the figures' pair at vartheta (:data:`FIGURE_GB`; an incompressible pin, 1 - 1/(2 vartheta), at any
    other vartheta)."""
    if theta in FIGURE_GB:
        return FIGURE_GB[theta]
    return 1.0 - 1.0 / (2.0 * theta)


def figure_pair(theta: float, plain: bool = False) -> str:
    """The words for the pair behind :func:`figure_gb` (math text, or plain text for a terminal)."""
    words = FIGURE_PAIR.get(theta, "incompressible pin")
    return words.replace("$", "").replace("\\", "") if plain else words


def theta_text(theta: float) -> str:
    return "$\\vartheta = \\infty$" if math.isinf(theta) else f"$\\vartheta = {theta:g}$"


def params_text(theta: float, gb=None, alpha_ratio: float = 0.0, pair=None) -> str:
    """'vartheta = 1, (1/G_I)/beta* = 0.3571 (pair), alpha*/beta* = 0' in math text."""
    parts = [theta_text(theta)]
    if gb is not None:
        parts.append(f"$(1/G_I)/\\beta^* = {gb:.4g}$" + (f" ({pair})" if pair else ""))
    parts.append(f"$\\alpha^*/\\beta^* = {alpha_ratio:g}$")
    return ", ".join(parts)


class Rows(list):
    """The plotted points, for the CSV next to each figure (columns :data:`CSV_COLUMNS`)."""

    def add(self, panel, series, x_name, x, y_name, y, feasible=None):
        x, y = np.asarray(x, float), np.asarray(y, float)
        f = np.ones_like(x, dtype=bool) if feasible is None else np.asarray(feasible, bool)
        for xi, yi, fi in zip(x, y, f):
            self.append((panel, series, x_name, repr(float(xi)), y_name, repr(float(yi)), int(fi)))


@dataclass(frozen=True)
class Style:
    """How one series is drawn: colour (luminance-ordered) and marker; the line style encodes feasibility.

    Attributes
    ----------
    color : tuple
        An RGBA colour.
    marker : str
        A matplotlib marker.

    Examples
    --------
    >>> Style(color=(0.0, 0.0, 0.0, 1.0), marker="o").marker
    'o'
    """

    color: tuple
    marker: str


def styles(n: int, top: float = 0.85) -> "list[Style]":
    """n styles whose greyscale luminance is strictly ordered (viridis up to ``top``, yellow end cut), with distinct
    markers.

    Parameters
    ----------
    n : int
        The number of series.
    top : float
        The viridis position of the last series, in (0, 1].

    Returns
    -------
    list of Style

    Examples
    --------
    >>> [s.marker for s in styles(3)]
    ['o', 's', '^']
    >>> lum = [0.299 * r + 0.587 * g + 0.114 * b for r, g, b, _ in (s.color for s in styles(5))]
    >>> all(x < y for x, y in zip(lum, lum[1:]))                  # greyscale order
    True
    """
    cmap = mpl().get_cmap("viridis")
    return [Style(cmap(top * i / max(n - 1, 1)), MARKERS[i % len(MARKERS)]) for i in range(n)]


def line(ax, x, y, feasible, style: Style, lw=1.2, markevery=0.12):
    """Solid where feasible, dashed where not, markers spaced along the line; no legend entry (see :func:`legend`).
    Returns the Line2D pieces."""
    x, y, f = np.asarray(x), np.asarray(y), np.asarray(feasible, bool)
    out, start = [], 0
    for i in range(1, len(x) + 1):
        if i == len(x) or f[i] != f[start]:
            j = min(i + 1, len(x))     # overlap one point so that the pieces join
            out += ax.plot(x[start:j], y[start:j], color=style.color, lw=lw,
                           ls=FEASIBLE_LS if f[start] else OVERCLOSED_LS,
                           marker=style.marker, ms=4, markevery=markevery, mfc="none")
            start = i
    return out


def band(ax, x, y, mask, color, **kw):
    """A translucent band under the states where ``mask`` holds (stability), no markers; returns the Line2D."""
    y = np.where(np.asarray(mask, bool), np.asarray(y, float), np.nan)
    return ax.plot(x, y, color=color, solid_capstyle="butt", **{**BAND, **kw})[0]


def band_handle(label, color="0.5", **kw):
    from matplotlib.lines import Line2D
    return Line2D([], [], color=color, label=label, **{**BAND, **kw})


def feasibility_handles():
    from matplotlib.lines import Line2D
    return [Line2D([], [], color="k", ls=FEASIBLE_LS, label="$h(\\pi) \\geq 0$ (feasible)"),
            Line2D([], [], color="k", ls=OVERCLOSED_LS, label="$h(\\pi) < 0$ (overclosed)")]


def series_handles(entries):
    """One neutral legend entry (colour + marker, no line) per (label, Style)."""
    from matplotlib.lines import Line2D
    return [Line2D([], [], color=s.color, marker=s.marker, mfc="none", ls="none", label=lab) for lab, s in entries]


def legend(ax, entries, feasibility=True, extra=(), **kw):
    """Proxy legend: the series (:func:`series_handles`), then the line-style meanings, then ``extra``."""
    handles = series_handles(entries) + (feasibility_handles() if feasibility else []) + list(extra)
    return ax.legend(handles=handles, fontsize=7, **kw)


def a_ratio(cv):
    """a/a_crit from eps* = 2 atan(a/a_crit)/pi (a_crit is the solver's pole when alpha* != 0)."""
    return np.tan(np.pi * cv.eps_star / 2)
