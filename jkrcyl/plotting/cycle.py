"""The plot of a quasi-static cycle (jkrcyl.Contact.cycle): load P against the work-conjugate approach delta_work
(whose loop area is the energy dissipated), every branch the path runs on labelled in words, every jump an arrow
with its kind, arrowheads along the path for the direction of travel, and the parameters in the title (material
pair, R, Delta, w, control and its limits).
"""
from __future__ import annotations

import math

import numpy as np

from ..results import Cycle
from . import style as st

# branch of the path -> (words, colour, marker); colours from viridis at ordered luminance, black for the free pin
BRANCH_WORDS = {"sub-critical": "contact at the bottom", "super-critical": "contact at the bottom",
                "sub-critical-top": "pin on the top", "super-critical-top": "pin on the top",
                "two-patch": "two patches", "full-contact": "full contact", "separated": "free pin"}
FAMILIES = ("contact at the bottom", "pin on the top", "two patches", "full contact", "free pin")
_FAMILY_STYLE = {"contact at the bottom": (0.0, "o"), "pin on the top": (0.3, "s"), "two patches": (0.55, "^"),
                 "full contact": (0.8, "P"), "free pin": (None, "v")}
JUMP_COLOR = "tab:red"
HELD = {"load": ("P", "N/m"), "grip": ("\\delta", "m"), "grip-work": ("\\delta_{work}", "m")}
CONTROL_WORDS = {"load": "load control", "grip": "grip control (the paper's $\\delta$ held)",
                 "grip-work": "grip control ($\\delta_{work}$ held: a machine holding the pin)"}
_PREFIXES = ((1e9, "G"), (1e6, "M"), (1e3, "k"), (1.0, ""), (1e-3, "m"), (1e-6, "\u00b5"), (1e-9, "n"))


def si(value: float, unit: str) -> str:
    """value with an SI prefix and 4 significant digits, e.g. si(2.6e9, 'Pa') = '2.6 GPa'."""
    if not math.isfinite(value) or value == 0:
        return f"{value:g} {unit}"
    for scale, prefix in _PREFIXES:
        if abs(value) >= scale:
            break
    return f"{value / scale:.4g} {prefix}{unit}"


def _body(G, kappa, sub):
    """E and nu of one body in plane strain (nu = (3 - kappa)/4), or G and kappa when nu is outside (-1, 1/2]."""
    if math.isinf(G):
        return "rigid"
    nu = (3 - kappa) / 4
    if -1 < nu <= 0.5:
        return f"$E{sub}$ = {si(2 * G * (1 + nu), 'Pa')}, $\\nu{sub} = {nu:.3g}$"
    return f"$G{sub}$ = {si(G, 'Pa')}, $\\kappa{sub} = {kappa:.4g}$"


def parameters_text(cy, contact) -> str:
    """Material pair, R, Delta, w, control and its limits, in words (two lines)."""
    m = contact.materials
    lo, hi = cy.limits if cy.limits else (math.nan, math.nan)
    sym, unit = HELD[cy.control]
    return (f"hole {_body(m.G, m.kappa, '')}; pin {_body(m.G_I, m.kappa_I, '_I')}; $R$ = {si(contact.R, 'm')}, "
            f"$\\Delta$ = {si(contact.Delta, 'm')}, $w$ = {si(contact.w, 'J/m$^2$')}\n"
            f"{CONTROL_WORDS[cy.control]}: ${sym}$ from 0 up to {si(hi, unit)}, down to {si(lo, unit)} and back")


def _segments(cy):
    """Index lists of the path between jumps (a jump joins two consecutive points: its before and after)."""
    ends = {((j.before.P, j.before.delta), (j.after.P, j.after.delta)) for j in cy.jumps}
    segs, cur = [], [0]
    for i in range(1, len(cy.P)):
        if ((cy.P[i - 1], cy.delta[i - 1]), (cy.P[i], cy.delta[i])) in ends:
            segs.append(cur)
            cur = []
        cur.append(i)
    segs.append(cur)
    return segs


def _unit(Delta):
    """(scale, label) for the approach axis: the largest of m, mm, um, nm not above Delta."""
    for scale, label in ((1.0, "m"), (1e-3, "mm"), (1e-6, "\u00b5m"), (1e-9, "nm")):
        if Delta >= scale:
            return scale, label
    return 1e-9, "nm"


def _direction(ax, x, y, color):
    """An arrowhead along a stretch, pointing the way the path runs: 35 % of its length (in axis fractions) on a
    rising stretch, 65 % on a falling one, so that a branch run both ways shows both heads."""
    if len(x) < 2:
        return
    xr, yr = np.ptp(ax.get_xlim()) or 1.0, np.ptp(ax.get_ylim()) or 1.0
    s = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(x) / xr, np.diff(y) / yr))])
    if s[-1] < 0.03:
        return
    at = 0.35 if y[-1] >= y[0] else 0.65
    k = int(np.clip(np.searchsorted(s, at * s[-1]), 1, len(x) - 1))
    ax.annotate("", xy=(x[k], y[k]), xytext=(x[k - 1], y[k - 1]),
                arrowprops=dict(arrowstyle="-|>", color=color, lw=0, mutation_scale=18), annotation_clip=False)


def cycle_figure(cy: "Cycle", contact: "jkrcyl.Contact", title: str = "") -> "matplotlib.figure.Figure":
    """The figure of a quasi-static cycle: P [N/m] against delta_work, branches in words, jumps as arrows.

    Parameters
    ----------
    cy : jkrcyl.results.Cycle
        The cycle (:meth:`jkrcyl.Contact.cycle`).
    contact : jkrcyl.Contact
        The contact it was computed for (its parameters go in the title).
    title : str
        A first line for the title.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
    >>> fig = cycle_figure(pin.cycle(P_max=2000.0, P_min=-2000.0, n=100), pin)
    >>> fig.axes[0].get_title().splitlines()[0]
    'Quasi-static cycle; dissipated 0.007998 J/m per cycle'
    >>> st.mpl().close(fig)
    """
    plt = st.mpl()
    from matplotlib.lines import Line2D
    cmap = plt.get_cmap("viridis")
    color = {f: ("k" if x is None else cmap(x)) for f, (x, _) in _FAMILY_STYLE.items()}
    scale, unit = _unit(contact.Delta)
    fig, ax = plt.subplots(figsize=(7.6, 5.6))
    x, P = np.asarray(cy.delta_work) / scale, np.asarray(cy.P)
    pieces = []
    for idx in _segments(cy):
        fam = [(BRANCH_WORDS[b], leg) for b, leg in zip(cy.branch[idx], cy.leg[idx])]
        start = 0
        for i in range(1, len(idx) + 1):          # one line per family and leg; neighbours share a point
            if i == len(idx) or fam[i] != fam[start]:
                sel = idx[start:min(i + 1, len(idx))]
                f = fam[start][0]
                ax.plot(x[sel], P[sel], "-", color=color[f], lw=1.6, marker=_FAMILY_STYLE[f][1], ms=4,
                        markevery=0.1, mfc="none")
                pieces.append((x[sel], P[sel], color[f], f))
                start = i
    ax.plot([x[0]], [P[0]], "ko", ms=6, zorder=5)
    for j in cy.jumps:
        a, b = (j.before.delta_work / scale, j.before.P), (j.after.delta_work / scale, j.after.P)
        ax.annotate("", xy=b, xytext=a, arrowprops=dict(arrowstyle="->", color=JUMP_COLOR, lw=1.3, ls="--"))
        ax.annotate(j.kind, ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2), xytext=(4, 4), textcoords="offset points",
                    fontsize=8, color=JUMP_COLOR)
    ax.axhline(0, color="0.8", lw=0.6, zorder=0)
    ax.set_xlabel(f"work-conjugate approach $\\delta_{{work}} = \\delta + P/(8\\pi G_I)$ [{unit}]")
    ax.set_ylabel("load $P$ [N/m]")
    for px, py, c, _ in pieces:                    # after the limits are final
        _direction(ax, px, py, c)
    seen = [f for f in FAMILIES if any(f == g and len(px) > 1 for px, _, _, g in pieces)]
    handles = [Line2D([], [], color=color[f], marker=_FAMILY_STYLE[f][1], mfc="none", lw=1.6, label=f)
               for f in seen]
    handles += [Line2D([], [], color="k", marker="o", ls="none", ms=6, label="first contact (start)"),
                Line2D([], [], color=JUMP_COLOR, ls="--", lw=1.3, label="jump at the held value (kind written)"),
                Line2D([], [], color="0.3", marker=">", ls="none", ms=7, label="direction of travel")]
    ax.legend(handles=handles, fontsize=7.5, loc="best")
    e = ("the loop did not close" + (f": {cy.note}" if cy.note else "")) if cy.dissipated is None else \
        f"dissipated {cy.dissipated:.4g} J/m per cycle"
    ax.set_title((title + "\n" if title else "") + f"Quasi-static cycle; {e}\n{parameters_text(cy, contact)}",
                 fontsize=8)
    fig.tight_layout()
    return fig


def plot(cy: "Cycle", path: str, contact: "jkrcyl.Contact", title: str = "") -> str:
    """Write :func:`cycle_figure` to ``path`` (PNG or PDF by the extension; ``jkrcyl cycle --plot``).

    Parameters
    ----------
    cy, contact, title
        As :func:`cycle_figure`.
    path : str
        The file.

    Returns
    -------
    str
        ``path``.

    Examples
    --------
    >>> import os, tempfile, jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     os.path.basename(plot(pin.cycle(P_max=2000.0, P_min=-2000.0, n=100), os.path.join(folder, "c.png"), pin))
    'c.png'
    """
    fig = cycle_figure(cy, contact, title)
    fig.savefig(path, dpi=120)
    st.mpl().close(fig)
    return path
