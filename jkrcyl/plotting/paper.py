"""The paper's equilibrium figures: Figs. 2, 5, 6, 7 (four panels: load, approach, load-approach, gap at pi),
Fig. 3 (close-up of Fig. 2 with the adherence points) and Fig. 9 (cylinder vs half plane).

Each builder ``figNN(n, alpha_ratio) -> (Figure, Rows)`` computes through jkrcyl.equilibria at the figures' pair
(:data:`jkrcyl.plotting.style.FIGURE_GB`) and draws with the shared styles of :mod:`jkrcyl.plotting.style`.
"""
from __future__ import annotations

import math

import numpy as np

from .. import equilibria as eq
from .. import special
from . import style as st

M_VALUES = (0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0)
FIG03_M = (0.05, 0.1, 0.2, 0.3)
FIG09_M = (0.0, 0.1, 0.3, 0.4, 0.6, 1.0)
P_CLIP = 50.0          # P* beyond +-50 is off every axis: clipped so the lines leave the axes cleanly


def _title(text, theta, alpha_ratio):
    gb = st.figure_gb(theta)
    return f"{text}\n{st.params_text(theta, gb, alpha_ratio, st.figure_pair(theta))}"


def _equilibrium_panels(theta, regime, n, title, Ms=M_VALUES, alpha_ratio=0.0):
    plt = st.mpl()
    fig, axs = plt.subplots(2, 2, figsize=(10, 8.4))
    rows = st.Rows()
    is_inf = math.isinf(theta)
    gb = st.figure_gb(theta)
    xname = "a" if is_inf else ("a/a_crit" if regime == "sub-critical" else "eps_star")
    pname = "P_R_star" if is_inf else "P_star"
    styles = st.styles(len(Ms))
    for M, sty in zip(Ms, styles):
        cv = eq.curve(M, theta, regime, n=n, gb=gb, alpha_ratio=alpha_ratio)
        x = cv.a if is_inf else (st.a_ratio(cv) if regime == "sub-critical" else cv.eps_star)
        s = f"M = {M:g}"
        P = np.clip(cv.P_star, -P_CLIP, P_CLIP)
        st.line(axs[0, 0], x, P, cv.feasible, sty)
        rows.add("a", s, xname, x, "P_star", cv.P_star, cv.feasible)
        st.line(axs[0, 1], cv.delta_over_Delta, x, cv.feasible, sty)
        rows.add("b", s, "delta_over_Delta", cv.delta_over_Delta, xname, x, cv.feasible)
        st.line(axs[1, 0], cv.delta_over_Delta, P, cv.feasible, sty)
        rows.add("c", s, "delta_over_Delta", cv.delta_over_Delta, "P_star", cv.P_star, cv.feasible)
        st.line(axs[1, 1], x, cv.h_pi_over_Delta, cv.feasible, sty)
        rows.add("d", s, xname, x, "h_pi_over_Delta", cv.h_pi_over_Delta, cv.feasible)
    mlab = "M_R^*" if is_inf else "M"
    axs[0, 0].set(xlabel=st.LABEL[xname], ylabel=st.LABEL[pname], ylim=(-3, 8), title="(a) load")
    axs[0, 1].set(xlabel=st.LABEL["delta_over_Delta"], ylabel=st.LABEL[xname], xlim=(-6, 6), title="(b) approach")
    axs[1, 0].set(xlabel=st.LABEL["delta_over_Delta"], ylabel=st.LABEL[pname], xlim=(-6, 6), ylim=(-3, 8),
                  title="(c) load-approach")
    axs[1, 1].set(xlabel=st.LABEL[xname], ylabel=st.LABEL["h_pi_over_Delta"], ylim=(-4, 4),
                  title="(d) gap at $\\phi = \\pi$")
    axs[1, 1].axhline(0, color="k", lw=0.6)
    for ax in axs.flat:
        ax.grid(alpha=0.3)
    st.legend(axs[0, 0], [(f"${mlab} = {M:g}$", sty) for M, sty in zip(Ms, styles)], ncol=2, loc="best")
    if is_inf:
        _conjugate_approach(axs[1, 0], rows, Ms[0], theta, regime, n, gb, alpha_ratio, mlab)
    fig.suptitle(_title(title, theta, alpha_ratio))
    fig.tight_layout()
    return fig, rows


def _conjugate_approach(ax, rows, M, theta, regime, n, gb, alpha_ratio, mlab):
    """Fig. 7 (c): the conjugate approach at M_R* = 0 (derive/green.py), drawn next to the paper's."""
    cv0 = eq.curve(M, theta, regime, n=n, gb=gb, alpha_ratio=alpha_ratio)
    ax.plot(cv0.delta_work_over_Delta, np.clip(cv0.P_star, -P_CLIP, P_CLIP), color="0.55", lw=2.2, ls=":",
            label=f"$\\delta_{{work}}$, ${mlab} = {M:g}$")
    rows.add("c_work", f"M = {M:g}", "delta_work_over_Delta", cv0.delta_work_over_Delta, "P_star", cv0.P_star,
             cv0.feasible)
    ax.text(0.98, 0.02, "$P_R^*$ falls with $\\delta$ even at $M_R^* = 0$: the paper's $\\delta$ (5.8)\n"
            "is not the work conjugate of $P$; grey dotted: the conjugate\n"
            "$\\delta_{work} = \\delta + P/(8\\pi G_I)$ (pin centroid), stiffness > 0",
            transform=ax.transAxes, ha="right", va="bottom", fontsize=7, color="darkred")


def fig02(n=600, alpha_ratio=0.0):
    return _equilibrium_panels(1.0, "sub-critical", n, "Fig. 2: sub-critical equilibria", alpha_ratio=alpha_ratio)


def fig05(n=600, alpha_ratio=0.0):
    return _equilibrium_panels(1.0, "super-critical", n, "Fig. 5: super-critical equilibria",
                               alpha_ratio=alpha_ratio)


def fig06(n=600, alpha_ratio=0.0):
    return _equilibrium_panels(0.5, "sub-critical", n, "Fig. 6: sub-critical equilibria", alpha_ratio=alpha_ratio)


def fig07(n=600, alpha_ratio=0.0):
    return _equilibrium_panels(math.inf, "sub-critical", n,
                               "Fig. 7: rubbery cylinder in a rigid cradle ($M_R^*$, $P_R^*$); "
                               "$\\delta$ is the paper's approach (5.8)", alpha_ratio=alpha_ratio)


def fig03(n=600, alpha_ratio=0.0):
    from matplotlib.lines import Line2D
    plt = st.mpl()
    fig, axs = plt.subplots(1, 2, figsize=(11, 4.8))
    rows = st.Rows()
    gb = st.figure_gb(1.0)
    styles = st.styles(len(FIG03_M))
    for M, sty in zip(FIG03_M, styles):
        cv = eq.curve(M, 1.0, "sub-critical", n=n, gb=gb, alpha_ratio=alpha_ratio)
        lab = f"M = {M:g}"
        x = st.a_ratio(cv)
        st.line(axs[0], x, cv.P_star, cv.feasible, sty)
        rows.add("a", lab, "a/a_crit", x, "P_star", cv.P_star, cv.feasible)
        st.line(axs[1], cv.delta_over_Delta, cv.P_star, cv.feasible, sty)
        rows.add("b", lab, "delta_over_Delta", cv.delta_over_Delta, "P_star", cv.P_star, cv.feasible)
        ac = cv.a[0] / x[0]
        for p in eq.adherence(M, 1.0, "load", gb=gb, regimes=("sub-critical",), alpha_ratio=alpha_ratio,
                              confined=False):
            axs[0].plot(p.a / ac, p.P_star, "kx", ms=8)
            axs[1].plot(p.delta_over_Delta, p.P_star, "kx", ms=8)
            rows.add("a", lab + " adherence (load)", "a/a_crit", [p.a / ac], "P_star", [p.P_star], [p.feasible])
        for p in eq.adherence(M, 1.0, "grip", gb=gb, regimes=("sub-critical",), alpha_ratio=alpha_ratio):
            if p.kind == "min":
                axs[1].plot(p.delta_over_Delta, p.P_star, "ko", mfc="none", ms=9)
                axs[0].plot(p.a / ac, p.P_star, "ko", mfc="none", ms=9)
                rows.add("b", lab + " adherence (grip)", "delta_over_Delta", [p.delta_over_Delta], "P_star",
                         [p.P_star], [p.feasible])
    axs[0].set(xlabel=st.LABEL["a/a_crit"], ylabel=st.LABEL["P_star"], xlim=(0, 0.6), ylim=(-0.4, 0.6),
               title="(a) load")
    axs[1].set(xlabel=st.LABEL["delta_over_Delta"], ylabel=st.LABEL["P_star"], xlim=(-1.5, 1.5), ylim=(-0.4, 0.6),
               title="(b) load-approach")
    for ax in axs:
        ax.grid(alpha=0.3)
        ax.axhline(0, color="k", lw=0.5)
    marks = [Line2D([], [], color="k", marker="x", ls="none", ms=8, label="adherence, fixed load"),
             Line2D([], [], color="k", marker="o", mfc="none", ls="none", ms=9, label="adherence, fixed grip")]
    st.legend(axs[0], [(f"$M = {M:g}$", sty) for M, sty in zip(FIG03_M, styles)], extra=marks)
    fig.suptitle(_title("Fig. 3: close-up of Fig. 2", 1.0, alpha_ratio))
    fig.tight_layout()
    return fig, rows


def fig09(n=600, alpha_ratio=0.0):
    from matplotlib.lines import Line2D
    plt = st.mpl()
    fig, ax = plt.subplots(figsize=(7, 5.4))
    rows = st.Rows()
    gb = st.figure_gb(1.0)
    styles = st.styles(len(FIG09_M))
    for M, sty in zip(FIG09_M, styles):
        cv = eq.curve(M, 1.0, "sub-critical", n=n, gb=gb, alpha_ratio=alpha_ratio)
        x = st.a_ratio(cv)
        st.line(ax, x, cv.P_star, cv.feasible, sty)
        rows.add("a", f"cylinder M = {M:g}", "a/a_crit", x, "P_star", cv.P_star, cv.feasible)
        ph = special.half_plane_P_star(cv.a, M, 1.0)
        name = "Hertz half-plane M = 0" if M == 0 else f"Barquins half-plane M = {M:g}"
        ax.plot(x, ph, color=sty.color, ls=":", lw=1.4, marker=sty.marker, ms=3, markevery=0.15)
        rows.add("a", name, "a/a_crit", x, "P_star", ph)
    ax.set(xlabel=st.LABEL["a/a_crit"], ylabel=st.LABEL["P_star"], ylim=(-1.5, 3))
    ax.grid(alpha=0.3)
    half = Line2D([], [], color="k", ls=":", lw=1.4, label="half plane (Hertz $M=0$, Barquins $M>0$)")
    st.legend(ax, [(f"$M = {M:g}$", sty) for M, sty in zip(FIG09_M, styles)], extra=[half], loc="upper left")
    ax.set_title(_title("Fig. 9: cylinder vs half plane", 1.0, alpha_ratio), fontsize=10)
    fig.tight_layout()
    return fig, rows
