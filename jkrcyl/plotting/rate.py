"""The figures of rate-dependent adhesion (crack kinetics, jkrcyl.kinetics), each stating its parameters:

* :func:`sweep_figure`: pull-off against rate on log-log axes -- the rate-dependent pull-off (marker by the event
  that ended the single patch: separation, or the gap at the top closing first), the quasi-static value, the
  high-rate power law (load control) and the infinite-rate ceiling of the frozen contact;
* :func:`loops_figure`: the load against the work-conjugate approach round the steady loop at several
  frequencies (its area the energy dissipated per cycle);
* :func:`width_figure`: the contact width against time in a ramp, the held quantity beside it.
"""
from __future__ import annotations

import numpy as np

from . import style as st
from .cycle import _body, _unit, si

RATE_UNIT = {"load": "N/m/s", "grip": "m/s", "grip-work": "m/s"}
CONTROL = {"load": "load ramped down", "grip": "the paper's approach $\\delta$ pulled",
           "grip-work": "the approach $\\delta_{work}$ pulled (a testing machine)"}


def parameters_text(contact) -> str:
    """The pair, R, Delta, w and the crack law, in words (two lines): what every figure of this module states.

    Parameters
    ----------
    contact : jkrcyl.Contact
        A contact with crack kinetics.

    Returns
    -------
    str
        Two lines of matplotlib mathtext.
    """
    m, law = contact.materials, contact.law
    phi = f"$(v/v^*)^{{{law.n:g}}}$" if law.phi is None else "a user $\\phi(v)$"
    shift = "" if law.shift == 1 else f", $a_T$ = {law.shift:.4g}"
    return (f"hole {_body(m.G, m.kappa, '')}; pin {_body(m.G_I, m.kappa_I, '_I')}; $R$ = {si(contact.R, 'm')}, "
            f"$\\Delta$ = {si(contact.Delta, 'm')}, $w$ = {si(contact.w, 'J/m$^2$')}\n"
            f"crack kinetics $G = w[1 + \\phi(v)]$ opening, $w = G[1 + \\phi(v)]$ closing, $\\phi$ = {phi}, "
            f"$v^*$ = {si(law.v_star, 'm/s')}{shift}")


def sweep_figure(sw, contact, title: str = ""):
    """Pull-off against rate on log-log axes, with the quasi-static value, the power law and the ceiling.

    Parameters
    ----------
    sw : jkrcyl.kinetics.RateSweep
        What :func:`jkrcyl.kinetics.rate_sweep` returned for ``contact``.
    contact : jkrcyl.Contact
        The contact (its parameters are stated on the figure).
    title : str, optional
        A first line of the title.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> import jkrcyl
    >>> from jkrcyl.plotting import rate
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m,
    ...                      kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6))
    >>> sw = jkrcyl.kinetics.rate_sweep(pin, [1e-12, 1e-11, 1e-10], control="grip-work")
    >>> fig = rate.sweep_figure(sw, pin)
    >>> fig.axes[0].get_xscale(), fig.axes[0].get_yscale()
    ('log', 'log')
    >>> rate.st.mpl().close(fig)
    """
    plt = st.mpl()
    fig, ax = plt.subplots(figsize=(7.2, 5.4))
    cmap = plt.get_cmap("viridis")
    r, P = sw.rates, -np.asarray(sw.P, dtype=float)
    for kind, marker, color, label in (("separation", "o", cmap(0.0), "the contact vanished (separation)"),
                                       ("top-contact", "s", cmap(0.6), "the gap at the top closed first")):
        sel = (sw.kind == kind) & np.isfinite(P)
        if sel.any():                                  # a legend entry only for an event the sweep met
            ax.plot(r[sel], P[sel], marker, color=color, mfc="none", ms=6, label=label)
    ok = np.isfinite(P)
    ax.plot(r[ok], P[ok], "-", color="0.5", lw=0.8, zorder=0)
    if sw.P_quasi_static is not None:
        ax.axhline(-sw.P_quasi_static, color="k", ls="--", lw=1.0, label="quasi-static pull-off")
    if np.any(np.isfinite(sw.asymptote)):
        ax.plot(r, -sw.asymptote, ":", color=cmap(0.3), lw=1.4,
                label=f"high-rate power law, $|P| \\propto$ rate$^{{{sw.exponent:.3g}}}$ (n/(n+2))")
    if sw.P_frozen is not None:
        ax.axhline(-sw.P_frozen, color=cmap(0.85), ls="-.", lw=1.0, label="infinite rate: the frozen contact "
                   "pulled until $h(\\pi) = 0$")
    top = r[sw.kind == "top-contact"]
    if top.size:
        ax.axvspan(top.min(), r.max(), color=cmap(0.6), alpha=0.08, lw=0)
    ax.set_xscale("log")
    ax.set_yscale("log")
    levels = [v for v in (*P[ok], -(sw.P_quasi_static or np.nan), -(sw.P_frozen or np.nan)) if np.isfinite(v)]
    ax.set_ylim(0.5 * min(levels), 2.0 * max(levels))          # the power law drawn up to the ceiling's decade
    ax.set_xlabel(f"rate [{RATE_UNIT[sw.control]}] ({CONTROL[sw.control]})")
    ax.set_ylabel("pull-off: largest tension $|P|$ [N/m]")
    ax.legend(fontsize=7.5, loc="upper left")
    ax.set_title((title + "\n" if title else "") + f"Pull-off against rate\n{parameters_text(contact)}",
                 fontsize=8)
    fig.tight_layout()
    return fig


def _last_loop(cy):
    """The rows of the last loop (top to top) of a RateCycle, or all rows."""
    h = cy.history
    held = {"load": h.P, "grip": h.delta, "grip-work": h.delta_work}[cy.control]
    tops = np.nonzero(np.abs(held - cy.limits[1]) <= 1e-9 * abs(cy.limits[1]))[0]
    return slice(tops[-2], tops[-1] + 1) if tops.size >= 2 else slice(None)


def loops_figure(cycles, contact, title: str = ""):
    """The last loop of each cycle at a rate (one per frequency): P against delta_work sheared by the chord of the
    first loop (delta_work - P/k: a shear keeps the loop's area, the energy dissipated, and makes a thin loop
    visible).

    Parameters
    ----------
    cycles : sequence of jkrcyl.kinetics.RateCycle
        The cycles of ``contact`` (same control and limits), the slowest first.
    contact : jkrcyl.Contact
        The contact (its parameters are stated on the figure).
    title : str, optional
        A first line of the title.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> import jkrcyl
    >>> from jkrcyl.plotting import rate
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m,
    ...                      kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6))
    >>> cycles = [pin.cycle(P_max=1000.0, P_min=-1000.0, rate=r) for r in (0.04, 0.4)]   # 1e-5, 1e-4 Hz
    >>> fig = rate.loops_figure(cycles, pin)
    >>> len(fig.axes[0].get_lines())             # two loops and the axis line P = 0
    3
    >>> rate.st.mpl().close(fig)
    """
    plt = st.mpl()
    fig, ax = plt.subplots(figsize=(7.2, 5.4))
    scale, unit = _unit(contact.Delta)
    h0, sel0 = cycles[0].history, _last_loop(cycles[0])
    P0, d0 = h0.P[sel0], h0.delta_work[sel0]
    i, j = int(np.argmin(P0)), int(np.argmax(P0))
    k = (P0[j] - P0[i]) / (d0[j] - d0[i])                       # the chord stiffness [N/m per m]
    for cy, s in zip(cycles, st.styles(len(cycles))):
        h, sel = cy.history, _last_loop(cy)
        e = "n/a" if cy.dissipated is None else f"{cy.dissipated:.3g} J/m"
        ax.plot((h.delta_work[sel] - h.P[sel] / k) / scale, h.P[sel], "-", color=s.color, marker=s.marker,
                markevery=0.08, mfc="none", ms=4, lw=1.4, label=f"{cy.frequency:.3g} Hz: dissipated {e} per cycle")
    ax.axhline(0, color="0.8", lw=0.6, zorder=0)
    ax.set_xlabel(f"$\\delta_{{work}} - P/k$ [{unit}] (sheared by the chord stiffness k = {k:.4g} N/m per m: "
                  "the loop's area is kept)", fontsize=8)
    ax.set_ylabel("load $P$ [N/m]")
    ax.legend(fontsize=7.5, loc="best")
    c0 = cycles[0]
    sym = {"load": "P", "grip": "\\delta", "grip-work": "\\delta_{work}"}[c0.control]
    lim = {"load": "N/m", "grip": "m", "grip-work": "m"}[c0.control]
    ax.set_title((title + "\n" if title else "") + f"Steady loops: ${sym}$ between {si(c0.limits[0], lim)} and "
                 f"{si(c0.limits[1], lim)}, triangular wave\n{parameters_text(contact)}", fontsize=8)
    fig.tight_layout()
    return fig


def width_figure(po, contact, title: str = ""):
    """Contact width against time in the ramp of a pull-off at a rate, the load beside it (a second axis).

    Parameters
    ----------
    po : jkrcyl.kinetics.RatePullOff
        What ``contact.pull_off(control, rate=...)`` returned.
    contact : jkrcyl.Contact
        The contact (its parameters are stated on the figure).
    title : str, optional
        A first line of the title.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> import jkrcyl
    >>> from jkrcyl.plotting import rate
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m,
    ...                      kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6))
    >>> fig = rate.width_figure(pin.pull_off("grip-work", rate=1e-11), pin)
    >>> fig.axes[0].get_ylabel()
    'contact width [mm]'
    >>> rate.st.mpl().close(fig)
    """
    plt = st.mpl()
    h = po.history
    fig, ax = plt.subplots(figsize=(7.2, 5.0))
    cmap = plt.get_cmap("viridis")
    ax.plot(h.t, h.contact_width * 1e3, "-", color=cmap(0.0), lw=1.6, label="contact width $2R\\varepsilon$")
    ax.set_xlabel("time $t$ [s]")
    ax.set_ylabel("contact width [mm]", color=cmap(0.0))
    ax2 = ax.twinx()
    ax2.plot(h.t, h.P, "--", color=cmap(0.6), lw=1.2, label="load $P$")
    ax2.set_ylabel("load $P$ [N/m]", color=cmap(0.6))
    for e in h.events:
        ax.axvline(e.t, color="0.6", lw=0.7, ls=":")
        ax.annotate(e.kind, (e.t, ax.get_ylim()[1]), fontsize=7, rotation=90, va="top", ha="right")
    ax.set_title((title + "\n" if title else "") + f"Contact width in a ramp: {CONTROL[po.control]} at "
                 f"{po.rate:.4g} {RATE_UNIT[po.control]}; pull-off {po.P:.4g} N/m ({po.kind})\n"
                 f"{parameters_text(contact)}", fontsize=8)
    fig.tight_layout()
    return fig


def save(fig, path):
    """Write a figure (PNG or PDF by the extension) and close it.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        One of this module's figures.
    path : str or pathlib.Path
        The file.

    Returns
    -------
    str or pathlib.Path
        ``path``.

    Examples
    --------
    >>> import os, tempfile
    >>> from jkrcyl.plotting import rate
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     os.path.basename(rate.save(rate.st.mpl().figure(), os.path.join(folder, "f.png")))
    'f.png'
    """
    fig.savefig(path, dpi=120)
    st.mpl().close(fig)
    return path
