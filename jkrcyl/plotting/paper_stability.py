"""The paper's stability and adherence figures: Fig. 8 (neat fit), Fig. 10 (fixed-load adherence of the cylinder
against Barquins' half plane) and Fig. 11 (fixed-load stability), with the errata of generated/DERIVATION.md.

Fig. 10 draws the cylinder's lowest fixed-load P* minimum as a detachment force only while that minimum is
sub-critical (thick line): a super-critical minimum is a fold where a further pull makes the contact grow round
into full contact (DERIVATION.md, erratum 'Sections 6 and 8.3'), drawn thin and marked 'fold -> full contact'.
The cut, :func:`detachment_limit`, is where the lowest minimum becomes super-critical.
"""
from __future__ import annotations

import math

import numpy as np

from .. import equilibria as eq
from .. import special
from ..critical import a_crit
from ..results import Point
from . import style as st

ERRATUM_FIG10 = ("erratum (DERIVATION.md 'Fig. 10'): the curves cross only where the cylinder's lowest\n"
                 "minimum is super-critical (thin: a fold into full contact, no detachment); wherever the\n"
                 "cylinder detaches, the half plane under-predicts the adherence force, as the paper says")
ERRATUM_FIG11 = ("erratum (DERIVATION.md 'Fig. 11b'): above $a_{crit}$ stable\nat fixed load where "
                 "$dP^*/da<0$; the paper calls\nthe small-$\\varepsilon$ branch unstable")
FIG10_M_RANGE = (0.01, 0.9)
FIG10_THETAS = (0.5, 1.0)
FIG11_M = ((0.3, 0.5), (0.3, 0.5, 0.8))
CUT_TOL = 1e-6            # bisection tolerance in M of the detachment limit
DETACH_LW, FOLD_LW = 1.6, 0.7


def fig08(n=600, alpha_ratio=0.0):
    """The neat fit (Delta = 0, section 7.3) exists in closed form only: drawn at alpha* = 0 for any
    ``alpha_ratio`` (the title says so)."""
    plt = st.mpl()
    fig, axs = plt.subplots(1, 2, figsize=(10.5, 4.6))
    rows = st.Rows()
    ths = (0.5, 1.0)
    styles = st.styles(len(ths))
    for th, sty in zip(ths, styles):
        c = special.neat_fit_curve(th, n)
        lab = f"vartheta = {th:g}"
        stable = c["stable_load"]             # Q* dQ*/da < 0: dQ*/da < 0 above a_crit (erratum 'Fig. 11b')
        st.line(axs[0], c["Q_star"], c["eps"], c["feasible"], sty)
        st.band(axs[0], c["Q_star"], c["eps"], stable, sty.color)
        rows.add("a", lab, "Q_star", c["Q_star"], "eps", c["eps"], c["feasible"])
        rows.add("a", lab + " stable_load flag", "Q_star", c["Q_star"], "stable_load", stable.astype(float),
                 c["feasible"])
        h = special.neat_fit_gap_pi(c["a"], th)
        st.line(axs[1], c["eps"], h, c["feasible"], sty)
        st.band(axs[1], c["eps"], h, stable, sty.color)
        rows.add("b", lab, "eps", c["eps"], "h_pi_over_zeta_beta", h, c["feasible"])
        axs[0].axhline(2 * math.atan(a_crit(th)), color=sty.color, lw=0.8, ls=":")
    axs[0].set(xscale="log", xlabel=st.LABEL["Q_star"], ylabel=st.LABEL["eps"], xlim=(0.1, 1e3),
               title="(a) neat fit ($\\Delta = 0$); dotted: $\\varepsilon_{crit}$")
    axs[1].set(xlabel=st.LABEL["eps"], ylabel=st.LABEL["h_pi_over_zeta_beta"], ylim=(-0.5, 5),
               title="(b) gap at $\\phi = \\pi$")
    axs[1].axhline(0, color="k", lw=0.5)
    for ax in axs:
        ax.grid(alpha=0.3)
    st.legend(axs[0], [(st.theta_text(th), sty) for th, sty in zip(ths, styles)],
              extra=[st.band_handle("stable at fixed load ($dQ^*/da < 0$)")])
    fig.suptitle("Fig. 8: neat fit, super-critical equilibria; $\\alpha^*/\\beta^* = 0$ (a closed form only: "
                 "drawn so whatever $\\alpha^*$ is asked for; no $\\delta$: $(1/G_I)/\\beta^*$ not used)")
    fig.tight_layout()
    return fig, rows


def lowest_minimum(M: float, theta: float, alpha_ratio: float = 0.0) -> "Point | None":
    """The lowest fixed-load P* minimum over both branches (a jkrcyl.results.Point, the figures' pair), or None."""
    pts = eq.adherence(M, theta, "load", gb=st.figure_gb(theta), alpha_ratio=alpha_ratio, confined=False)
    return min(pts, key=lambda q: q.P_star) if pts else None


def _is_sub(p):
    return p is not None and p.regime == "sub-critical"


def detachment_limit(theta: float, M_lo: float, M_hi: float, alpha_ratio: float = 0.0,
                     tol: float = CUT_TOL) -> "tuple[float, Point | None, Point | None]":
    """Where Fig. 10's detachment ends: the M at which the lowest fixed-load P* minimum turns super-critical.

    Below it the cylinder detaches at its sub-critical minimum; above it the lowest minimum is a super-critical
    fold that zips into full contact (generated/DERIVATION.md, erratum 'Sections 6 and 8.3').  Bisection in M
    over :func:`lowest_minimum` (the figures' pair, :func:`jkrcyl.plotting.style.figure_gb`).

    Parameters
    ----------
    theta : float
        vartheta >= 1/2 (section 4).
    M_lo, M_hi : float
        A bracket: the lowest minimum sub-critical at M_lo and not at M_hi.
    alpha_ratio : float
        alpha*/beta* in (-1, 1).
    tol : float
        Bisection tolerance in M.

    Returns
    -------
    (float, jkrcyl.results.Point, jkrcyl.results.Point)
        The limit M and the lowest minima just below and just above it.

    Raises
    ------
    ValueError
        Naming theta, M or alpha_ratio outside its range (jkrcyl.equilibria.adherence).

    Examples
    --------
    >>> M, below, above = detachment_limit(1.0, 0.3, 0.6)
    >>> round(M, 4), below.regime, above.regime, above.P_star < below.P_star
    (0.3915, 'sub-critical', 'super-critical', True)
    """
    below, above = lowest_minimum(M_lo, theta, alpha_ratio), lowest_minimum(M_hi, theta, alpha_ratio)
    while M_hi - M_lo > tol:
        mid = 0.5 * (M_lo + M_hi)
        p = lowest_minimum(mid, theta, alpha_ratio)
        if _is_sub(p):
            M_lo, below = mid, p
        else:
            M_hi, above = mid, p
    return 0.5 * (M_lo + M_hi), below, above


def _crossing(Ms, cyl, half):
    d = np.asarray(half) - np.asarray(cyl)
    ok = np.isfinite(d)
    idx = np.nonzero(ok[:-1] & ok[1:] & (np.sign(d[:-1]) != np.sign(d[1:])))[0]
    if not len(idx):
        return None
    i = idx[0]
    return Ms[i] - d[i] * (Ms[i + 1] - Ms[i]) / (d[i + 1] - d[i])


def _fig10_theta(ax, rows, th, sty, n, alpha_ratio):
    """One vartheta of Fig. 10: detachment (thick), fold -> full contact (thin), Barquins (dotted), crossing."""
    Ms = np.linspace(*FIG10_M_RANGE, n)
    pts = [lowest_minimum(M, th, alpha_ratio) for M in Ms]
    cyl = np.array([p.P_star if p and p.P_star < 0 else np.nan for p in pts])
    feas = np.array([bool(p.feasible) if p else False for p in pts])
    sub = np.array([_is_sub(p) for p in pts])
    half = np.array([special.half_plane_adherence(M, th)[1] for M in Ms])
    cut = np.nonzero(sub[:-1] & ~sub[1:])[0]
    x = {True: list(Ms[sub]), False: list(Ms[~sub])}
    y = {True: list(cyl[sub]), False: list(cyl[~sub])}
    f = {True: list(feas[sub]), False: list(feas[~sub])}
    if len(cut):                      # end each part exactly at the detachment limit
        Mc, below, above = detachment_limit(th, Ms[cut[0]], Ms[cut[0] + 1], alpha_ratio)
        k = int(np.searchsorted(x[True], Mc))
        x[True].insert(k, Mc), y[True].insert(k, below.P_star), f[True].insert(k, below.feasible)
        k = int(np.searchsorted(x[False], Mc))
        x[False].insert(k, Mc), y[False].insert(k, above.P_star), f[False].insert(k, above.feasible)
        ax.plot([Mc], [below.P_star], marker=sty.marker, color=sty.color, ms=7)
        ax.annotate(f"detachment ends at $M = {Mc:.4f}$", (Mc, below.P_star), xytext=(-8, -16),
                    textcoords="offset points", fontsize=7, ha="right")
        rows.add("a", f"detachment limit vartheta = {th:g}", "M", [Mc], "P_star_adherence", [below.P_star])
    for key, name, lw in ((True, "detachment", DETACH_LW), (False, "fold to full contact", FOLD_LW)):
        if x[key]:
            st.line(ax, x[key], y[key], f[key], sty, lw=lw, markevery=0.1)
            rows.add("a", f"cylinder {name} vartheta = {th:g}", "M", x[key], "P_star_adherence", y[key], f[key])
    ax.plot(Ms, half, color=sty.color, ls=":", lw=1.6)
    rows.add("a", f"Barquins vartheta = {th:g}", "M", Ms, "P_star_adherence", half)
    mx = _crossing(Ms, cyl, half)
    if mx is not None:
        rows.add("a", f"crossing vartheta = {th:g}", "M", [mx], "P_star_adherence", [np.interp(mx, Ms, half)])
        ax.axvline(mx, color=sty.color, lw=0.8, ls="-.")
        left = th == 1.0
        ax.annotate(f"cross at $M \\approx {mx:.3f}$", (mx, np.interp(mx, Ms, half)), xytext=(-6 if left else 6, 8),
                    textcoords="offset points", fontsize=7, ha="right" if left else "left")


def fig10(n=60, alpha_ratio=0.0):
    from matplotlib.lines import Line2D
    plt = st.mpl()
    fig, ax = plt.subplots(figsize=(7.4, 6.4))
    rows = st.Rows()
    styles = st.styles(len(FIG10_THETAS))
    for th, sty in zip(FIG10_THETAS, styles):
        _fig10_theta(ax, rows, th, sty, n, alpha_ratio)
    ax.set(xlabel=st.LABEL["M"], ylabel="adherence force $P^*$ (fixed load)")
    ax.set_title("Fig. 10: fixed-load adherence vs $M$ (cylinder: lowest $P^*$ minimum $< 0$)\n"
                 f"$\\alpha^*/\\beta^* = {alpha_ratio:g}$ (no $\\delta$: $(1/G_I)/\\beta^*$ not used)", fontsize=10)
    ax.text(0.0, -0.13, ERRATUM_FIG10, transform=ax.transAxes, fontsize=7, color="darkred", va="top")
    ax.grid(alpha=0.3)
    extra = [Line2D([], [], color="k", lw=DETACH_LW, label="cylinder: detachment (sub-critical minimum)"),
             Line2D([], [], color="k", lw=FOLD_LW,
                    label="cylinder: fold $\\to$ full contact (super-critical minimum, no detachment)"),
             Line2D([], [], color="k", ls=":", lw=1.6, label="Barquins half plane")]
    st.legend(ax, [(st.theta_text(th), sty) for th, sty in zip(FIG10_THETAS, styles)], extra=extra,
              loc="lower left")
    fig.tight_layout()
    return fig, rows


def fig11(n=600, alpha_ratio=0.0):
    plt = st.mpl()
    fig, axs = plt.subplots(1, 2, figsize=(11.5, 5))
    rows = st.Rows()
    gb = st.figure_gb(1.0)
    for ax, regime, Ms, tag in ((axs[0], "sub-critical", FIG11_M[0], "a"),
                                (axs[1], "super-critical", FIG11_M[1], "b")):
        styles = st.styles(len(Ms))
        for M, sty in zip(Ms, styles):
            cv = eq.curve(M, 1.0, regime, n=n, gb=gb, alpha_ratio=alpha_ratio)
            P = np.clip(cv.P_star, -20, 20)
            st.line(ax, cv.eps_star, P, cv.feasible, sty, lw=0.9)
            st.band(ax, cv.eps_star, P, cv.stable_load, sty.color)
            rows.add(tag, f"M = {M:g} stable_load", "eps_star", cv.eps_star, "P_star", cv.P_star, cv.feasible)
            rows.add(tag, f"M = {M:g} stable_load flag", "eps_star", cv.eps_star, "stable_load",
                     cv.stable_load.astype(float), cv.feasible)
        ax.set(xlabel=st.LABEL["eps_star"], ylabel=st.LABEL["P_star"], ylim=(-2, 4), title=f"({tag}) {regime}")
        ax.axhline(0, color="k", lw=0.5)
        ax.grid(alpha=0.3)
        st.legend(ax, [(f"$M = {M:g}$", sty) for M, sty in zip(Ms, styles)],
                  extra=[st.band_handle("stable at fixed load ($dG/da|_P > 0$)")],
                  loc="upper left" if tag == "a" else "upper center")
    axs[1].text(0.98, 0.03, ERRATUM_FIG11, transform=axs[1].transAxes, fontsize=7, color="darkred", ha="right")
    fig.suptitle("Fig. 11: fixed-load stability (does not depend on $(1/G_I)/\\beta^*$)\n"
                 f"{st.params_text(1.0, gb, alpha_ratio, st.figure_pair(1.0))}")
    fig.tight_layout()
    return fig, rows
