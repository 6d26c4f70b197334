"""docs/confined.png (``jkrcyl two-patch --figure docs/confined.png``): the load-approach paths through the confined
regime, P* against delta/Delta for a few M at one vartheta.

Every equilibrium family is drawn -- the single patch at the bottom and (mirrored) at the top of the hole, the
two-patch branches and full contact -- in the line styles of Figs. 2-12 (jkrcyl.plotting.style: solid where the
gap inequality holds, dashed where the gap is overclosed somewhere, h < 0), colour + marker per family;
stability is a band under the line: wide where stable under load, narrow where stable only at fixed delta.
On top, the load path of slow pulling as the library walks it (jkrcyl.analysis.path, as
jkrcyl.equilibria.confined_events): its start (the zero-load contact, or full contact when the pin is bonded
from first touch), its first event (fold or h(pi) = 0) and the jump at fixed load that follows.
"""
from __future__ import annotations

import textwrap
from typing import Sequence

import numpy as np

from .. import equilibria as eq
from .._validate import finite_scalar, theta as _check_theta
from ..analysis import landing as _land
from ..analysis import path as _path
from ..units import Units
from . import style as st

FIGURE_MS = (0.3, 0.4, 0.5, 0.8)
# (label, viridis position, marker): strictly ordered greyscale luminance (0.12, 0.34, 0.50, 0.73) + markers
SERIES = (("single patch, bottom", 0.0, "o"), ("single patch, top (mirror)", 0.3, "s"),
          ("two patches", 0.62, "^"), ("full contact", 0.88, "P"))
# stability bands: (label, line width); the line style stays the feasibility of Figs. 2-12
STABILITY = (("stable under load (and grip)", 8.0), ("stable under fixed $\\delta$ only", 3.5))
X_LIM, Y_LIM = (-2.8, 0.8), (-2.0, 2.0)
CAPTION = ("detachment: the fold (x) comes first; a further pull shrinks the contact away and the pin lands on the "
           "top of the hole (arrow: the jump at fixed load).",
           "zip-full: at the fold a further pull makes the contact grow (G < w): past $h(\\pi) = 0$ it zips round into "
           "full contact (arrow).",
           "bonded: no zero-load contact (8.1): at first touch the pin zips round into full contact, the start (o) "
           "is on that line, and it does not detach under load.",
           "snap-in-*, two-patch: the gap at $\\phi = \\pi$ closes first (diamond) and the top contact forms.")


def _styled(ax, x, y, feasible, load, grip, sty):
    """One family: feasibility line styles (solid / dashed) with markers, stability bands under it."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    feasible, load, grip = (np.asarray(v, bool) for v in (feasible, load, grip))
    (_, w_load), (_, w_grip) = STABILITY
    st.band(ax, x, y, load, sty.color, lw=w_load, alpha=0.25)
    st.band(ax, x, y, grip & ~load, sty.color, lw=w_grip, alpha=0.25)
    st.line(ax, x, y, feasible, sty, lw=1.1, markevery=0.12)


def _load_path(pb):
    """(start, event, end, landing) of slow pulling under load, normalised (P = P*, delta = delta/Delta): the
    walk of jkrcyl.analysis.path from first contact (as confined_events), the jump's landing state or None."""
    un = Units.normalised(pb, K_edge=1.0)
    start, event, end, _ = _path.pull_path(pb, un, "load")
    if event in ("none", "bonded", "elsewhere", "round"):
        return start, None, None, None
    to = None
    if event in ("fold", "end"):
        to, _ = _land.land(pb, un, end, "fold", "load", end.P, False)
    return start, event, end, to


def _families(ax, M, th, gb, ev, series):
    for regime in eq.REGIMES:
        c = eq.curve(M, th, regime, n=1500, gb=gb)
        for sign, sty in ((1, series[0]), (-1, series[1])):
            d = c.delta_over_Delta if sign == 1 else -2 - c.delta_over_Delta
            _styled(ax, d, sign * c.P_star, c.feasible, c.stable_load, c.stable_grip, sty)
    for b in ev.branches:
        _styled(ax, b.delta_over_Delta, b.P_star, b.feasible, b.stable_load, b.stable_grip, series[2])
    fc = [eq.full_contact(th, P_star=p, gb=gb) for p in np.linspace(*Y_LIM, 9)]
    ones = np.ones(len(fc), bool)
    _styled(ax, [f.delta_over_Delta for f in fc], [f.P_star for f in fc], ones, ones, ones, series[3])


def _events(ax, pb, ev):
    """The load path: start (o), onsets h(pi) = 0 (diamonds), the fold (x) and the jump at fixed load (arrow)."""
    for _, P, d, _ in ev.onsets:
        ax.plot([d, -2 - d], [P, -P], "kD", ms=4.5, mfc="w", zorder=5)
    start, event, end, to = _load_path(pb)
    if start is not None:
        ax.plot([start.delta_over_Delta], [start.P_star], "ko", ms=5.5, zorder=6)
    if event == "gap":
        ax.plot([end.delta_over_Delta], [end.P_star], "kD", ms=7, zorder=6)
    elif end is not None:
        ax.plot([end.delta_over_Delta], [end.P_star], "kx", ms=8, mew=1.6, zorder=6)
        if to is not None:
            ax.annotate("", xy=(to.delta_over_Delta, to.P_star), xytext=(end.delta_over_Delta, end.P_star),
                        arrowprops=dict(arrowstyle="->", color="k", lw=1.2), annotation_clip=False)


def _legend_handles(series):
    from matplotlib.lines import Line2D
    handles = st.series_handles([(lab, sty) for (lab, _, _), sty in zip(SERIES, series)])
    handles += st.feasibility_handles()
    handles += [st.band_handle(lab, lw=w, alpha=0.25) for lab, w in STABILITY]
    handles += [Line2D([], [], color="k", marker="o", ls="none", ms=5, label="start: first contact at P = 0"),
                Line2D([], [], color="k", marker="x", ls="none", ms=7, label="fold at fixed load"),
                Line2D([], [], color="k", marker="D", mfc="w", ls="none", ms=5,
                       label="gap closes at $\\phi = \\pi$ (single patch)"),
                Line2D([], [], color="k", marker=r"$\rightarrow$", ls="none", ms=12, label="jump at fixed load")]
    return handles


def confined_figure(Ms: "Sequence[float]" = FIGURE_MS, theta: float = 1.0,
                    gb: "float | None" = None) -> "matplotlib.figure.Figure":
    """The load-approach paths through the confined regime, one panel per M (alpha* = 0).

    Parameters
    ----------
    Ms : sequence of float
        The adhesions M > 0 (section 6), one panel each.
    theta : float
        vartheta >= 1/2, finite (section 4).
    gb : float, optional
        (1/G_I)/beta* in [0, 1] (default: the figures' pair, jkrcyl.plotting.style.figure_gb: identical nu = 0.3
        bodies at vartheta = 1, the README pin).

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    ValueError
        Naming M (none given, or one <= 0), theta or gb outside its range.

    Examples
    --------
    >>> fig = confined_figure(Ms=(0.3,))
    >>> fig.axes[0].get_title()                              # M and the regime of jkrcyl.equilibria.confined_events
    '$M = 0.3$: detachment'
    >>> st.mpl().close(fig)
    """
    plt = st.mpl()
    th = _check_theta(theta)
    pair = st.figure_pair(th) if gb is None else None
    gb = st.figure_gb(th) if gb is None else finite_scalar("gb", gb, low=0.0, high=1.0)
    Ms = [finite_scalar("M", M, low=0.0, low_open=True) for M in Ms]
    if not Ms:
        raise ValueError("M: give at least one M")
    cmap = plt.get_cmap("viridis")
    series = [st.Style(cmap(x), m) for _, x, m in SERIES]
    width = max(3.9 * len(Ms) + 0.4, 10.0)
    fig, axs = plt.subplots(1, len(Ms), figsize=(width, 5.8), sharey=True, squeeze=False)
    for ax, M in zip(axs[0], Ms):
        ev = eq.confined_events(M, th, gb=gb)
        _families(ax, M, th, gb, ev, series)
        _events(ax, eq.problem(M, th, gb), ev)
        ax.set(xlim=X_LIM, ylim=Y_LIM, xlabel=st.LABEL["delta_over_Delta"])
        ax.axhline(0, color="0.9", lw=0.5, zorder=0)
        ax.set_title(f"$M = {M:g}$: {ev.regime}", fontsize=10)
    axs[0, 0].set_ylabel(st.LABEL["P_star"])
    fig.legend(handles=_legend_handles(series), loc="lower center", ncol=5 if width > 12 else 4, fontsize=7.5,
               frameon=False, bbox_to_anchor=(0.5, 0.1))
    caption = "\n".join(textwrap.fill(c, int(18 * width), subsequent_indent="    ") for c in CAPTION)
    fig.text(0.5, 0.005, caption, ha="center", va="bottom", fontsize=7)
    fig.suptitle("Load-approach paths through the confined regime (slow pulling under load)\n"
                 f"{st.params_text(th, gb, 0.0, pair)}", fontsize=10.5)
    fig.tight_layout(rect=(0, 0.19, 1, 1))
    return fig


def draw_confined(path: str, Ms: "Sequence[float]" = FIGURE_MS, theta: float = 1.0,
                  gb: "float | None" = None) -> str:
    """Write :func:`confined_figure` to ``path`` (PNG or PDF by the extension; ``jkrcyl two-patch --figure``).

    Parameters
    ----------
    path : str
        The file.
    Ms, theta, gb
        As :func:`confined_figure`.

    Returns
    -------
    str
        ``path``.

    Raises
    ------
    ValueError
        As :func:`confined_figure`.

    Examples
    --------
    >>> import os, tempfile
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     os.path.basename(draw_confined(os.path.join(folder, "confined.png"), Ms=(0.3,)))
    'confined.png'
    """
    fig = confined_figure(Ms, theta, gb)
    fig.savefig(path, dpi=110)
    st.mpl().close(fig)
    return path
