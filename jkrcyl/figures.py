"""The paper's Figures 2-12, redrawn from the kernels (matplotlib), each with a CSV of what it plots.

Every figure is ``figNN(n) -> (matplotlib Figure, rows)``; rows are the plotted points, written as
CSV with the columns of :data:`CSV_COLUMNS`.  Dashed lines are equilibria that violate the gap
inequality (h(pi) < 0), as in the paper.  Approaches delta/Delta use the default material family
of :data:`FIGURE_GB`.
"""
import csv
import math
import pathlib

import numpy as np

from . import equilibria as eq
from . import special
from .critical import a_crit
from .generated import load as _load

# (1/G_I)/beta* used for delta/Delta: identical bodies with nu = 0.3 at vartheta = 1 (kappa = 1.8,
# gb = 1/(kappa + 1); reproduces eps = 2.41 at delta = 0, M = 1 of section 8.2), a rigid indenter at
# vartheta = 1/2, a rigid cradle with an incompressible cylinder at vartheta = inf.
FIGURE_GB = {1.0: 1 / 2.8, 0.5: 0.0, math.inf: 1.0}
CSV_COLUMNS = ("panel", "series", "x_name", "x", "y_name", "y", "feasible")
M_VALUES = (0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0)


def _mpl():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


class _Rows(list):
    def add(self, panel, series, x_name, x, y_name, y, feasible=None):
        x, y = np.asarray(x, float), np.asarray(y, float)
        f = np.ones_like(x, dtype=bool) if feasible is None else np.asarray(feasible, bool)
        for xi, yi, fi in zip(x, y, f):
            self.append((panel, series, x_name, repr(float(xi)), y_name, repr(float(yi)), int(fi)))


def _line(ax, x, y, feasible, color, label=None, lw=1.2):
    """Solid where feasible, dashed where not; one legend entry."""
    x, y, f = np.asarray(x), np.asarray(y), np.asarray(feasible, bool)
    first = True
    start = 0
    for i in range(1, len(x) + 1):
        if i == len(x) or f[i] != f[start]:
            j = min(i + 1, len(x))     # overlap one point so that the pieces join
            ax.plot(x[start:j], y[start:j], color=color, lw=lw, ls="-" if f[start] else "--",
                    label=label if first else None)
            first = False
            start = i


def _colors(n):
    plt = _mpl()
    cmap = plt.get_cmap("viridis")
    return [cmap(i / max(n - 1, 1)) for i in range(n)]


def _equilibrium_panels(theta, regime, n, title, Ms=M_VALUES, xlim=None):
    plt = _mpl()
    fig, axs = plt.subplots(2, 2, figsize=(10, 8))
    rows = _Rows()
    is_inf = math.isinf(theta)
    xname = "a" if is_inf else ("a/a_crit" if regime == "sub-critical" else "eps_star")
    for M, col in zip(Ms, _colors(len(Ms))):
        cv = eq.curve(M, theta, regime, n=n, gb=FIGURE_GB[theta])
        if is_inf:
            x = cv.a
        else:
            x = cv.a / a_crit(theta) if regime == "sub-critical" else cv.eps_star
        lab = f"M = {M:g}"
        s = lab
        P = np.clip(cv.P_star, -50, 50)
        _line(axs[0, 0], x, P, cv.feasible, col, lab)
        rows.add("a", s, xname, x, "P_star", cv.P_star, cv.feasible)
        _line(axs[0, 1], cv.delta_over_Delta, x, cv.feasible, col, lab)
        rows.add("b", s, "delta_over_Delta", cv.delta_over_Delta, xname, x, cv.feasible)
        _line(axs[1, 0], cv.delta_over_Delta, P, cv.feasible, col, lab)
        rows.add("c", s, "delta_over_Delta", cv.delta_over_Delta, "P_star", cv.P_star, cv.feasible)
        _line(axs[1, 1], x, cv.h_pi_over_Delta, cv.feasible, col, lab)
        rows.add("d", s, xname, x, "h_pi_over_Delta", cv.h_pi_over_Delta, cv.feasible)
    pl = "P_R*" if is_inf else "P*"
    axs[0, 0].set(xlabel=xname, ylabel=pl, ylim=(-3, 8), title="(a) load")
    axs[0, 1].set(xlabel="delta/Delta", ylabel=xname, xlim=(-6, 6), title="(b) approach")
    axs[1, 0].set(xlabel="delta/Delta", ylabel=pl, xlim=(-6, 6), ylim=(-3, 8), title="(c) load-approach")
    axs[1, 1].set(xlabel=xname, ylabel="h(pi)/Delta", ylim=(-4, 4), title="(d) gap at phi = pi")
    axs[1, 1].axhline(0, color="k", lw=0.6)
    for ax in axs.flat:
        ax.grid(alpha=0.3)
    axs[0, 0].legend(fontsize=7)
    fig.suptitle(title + "  (dashed: gap inequality violated)")
    fig.tight_layout()
    return fig, rows


def fig02(n=600):
    return _equilibrium_panels(1.0, "sub-critical", n, "Fig. 2: sub-critical equilibria, vartheta = 1")


def fig03(n=600):
    plt = _mpl()
    fig, axs = plt.subplots(1, 2, figsize=(11, 4.5))
    rows = _Rows()
    ac = a_crit(1.0)
    for M, col in zip((0.05, 0.1, 0.2, 0.3), _colors(4)):
        cv = eq.curve(M, 1.0, "sub-critical", n=n, gb=FIGURE_GB[1.0])
        lab = f"M = {M:g}"
        _line(axs[0], cv.a / ac, cv.P_star, cv.feasible, col, lab)
        rows.add("a", lab, "a/a_crit", cv.a / ac, "P_star", cv.P_star, cv.feasible)
        _line(axs[1], cv.delta_over_Delta, cv.P_star, cv.feasible, col, lab)
        rows.add("b", lab, "delta_over_Delta", cv.delta_over_Delta, "P_star", cv.P_star, cv.feasible)
        for p in eq.adherence(M, 1.0, "load", gb=FIGURE_GB[1.0], regimes=("sub-critical",)):
            axs[0].plot(p.a / ac, p.P_star, "kx", ms=8)
            axs[1].plot(p.delta_over_Delta, p.P_star, "kx", ms=8)
            rows.add("a", lab + " adherence (load)", "a/a_crit", [p.a / ac], "P_star", [p.P_star], [p.feasible])
        for p in eq.adherence(M, 1.0, "grip", gb=FIGURE_GB[1.0], regimes=("sub-critical",)):
            if p.kind == "min":
                axs[1].plot(p.delta_over_Delta, p.P_star, "ko", mfc="none", ms=7)
                axs[0].plot(p.a / ac, p.P_star, "ko", mfc="none", ms=7)
                rows.add("b", lab + " adherence (grip)", "delta_over_Delta", [p.delta_over_Delta], "P_star",
                         [p.P_star], [p.feasible])
    axs[0].set(xlabel="a/a_crit", ylabel="P*", xlim=(0, 0.6), ylim=(-0.4, 0.6), title="(a) x: fixed-load adherence")
    axs[1].set(xlabel="delta/Delta", ylabel="P*", xlim=(-1.5, 1.5), ylim=(-0.4, 0.6),
               title="(b) o: fixed-grip adherence")
    for ax in axs:
        ax.grid(alpha=0.3)
        ax.axhline(0, color="k", lw=0.5)
    axs[0].legend(fontsize=8)
    fig.suptitle("Fig. 3: close-up, vartheta = 1")
    fig.tight_layout()
    return fig, rows


def _pressure_panels(cases, regime, title, n):
    plt = _mpl()
    fig, axs = plt.subplots(1, len(cases), figsize=(4.2 * len(cases), 3.8), squeeze=False)
    rows = _Rows()
    for ax, (M, P_target, tag) in zip(axs[0], cases):
        roots = eq.solve_load(M, 1.0, P_target, regime)
        if not roots:
            ax.set_title(f"{tag} M = {M:g}, P* = {P_target:g}: no equilibrium")
            continue
        a = roots[-1] if regime == "sub-critical" else roots[0]
        eps = 2 * math.atan(a)
        phi = np.linspace(-eps, eps, n + 2)[1:-1]
        m = M * 1.0
        nb, nu = _load.pressure_array(Delta=1.0, R=1.0, a=a, beta=1.0, inv_theta=1.0, phi=phi, zeta=4 * math.pi * m)
        P = _load.load_state(1.0, 1.0, a, 1.0, 1.0, 4 * math.pi * m)[0]
        sc = 1.0 / abs(P)
        for y, name, style in ((nb * sc, "bounded", "b-"), (nu * sc, "unbounded", "r-"), ((nb + nu) * sc, "total", "k-")):
            ax.plot(phi, np.clip(y, -20, 20), style, lw=1.2, label=name)
            rows.add(tag, f"{name} (a = {a:.6g})", "phi", phi, "N_R_over_absP", y)
        ax.axhline(0, color="k", lw=0.5)
        ax.set(xlabel="phi [rad]", ylabel="N R/|P|", ylim=(-8, 8), title=f"{tag} M = {M:g}, P* = {P_target:g}, a = {a:.3f}")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle(title)
    fig.tight_layout()
    return fig, rows


def fig04(n=400):
    return _pressure_panels([(0.2, 4.0, "(a)"), (0.2, 2.0, "(b)"), (0.2, 0.1, "(c)"), (0.2, -0.15, "(d)")],
                            "sub-critical", "Fig. 4: pressure at M = 0.2, vartheta = 1 (sub-critical, stable root)", n)


def fig05(n=600):
    return _equilibrium_panels(1.0, "super-critical", n, "Fig. 5: super-critical equilibria, vartheta = 1")


def fig06(n=600):
    return _equilibrium_panels(0.5, "sub-critical", n, "Fig. 6: sub-critical equilibria, vartheta = 0.5")


def fig07(n=600):
    return _equilibrium_panels(math.inf, "sub-critical", n,
                               "Fig. 7: rubbery cylinder in a rigid cradle, vartheta = inf (M_R*, P_R*)")


def fig08(n=600):
    plt = _mpl()
    fig, axs = plt.subplots(1, 2, figsize=(10, 4.2))
    rows = _Rows()
    for th, col in ((0.5, "C0"), (1.0, "C1")):
        c = special.neat_fit_curve(th, n)
        lab = f"vartheta = {th:g}"
        _line(axs[0], c["Q_star"], c["eps"], c["feasible"], col, lab)
        rows.add("a", lab, "Q_star", c["Q_star"], "eps", c["eps"], c["feasible"])
        h = special.neat_fit_gap_pi(c["a"], th)
        _line(axs[1], c["eps"], h, c["feasible"], col, lab)
        rows.add("b", lab, "eps", c["eps"], "h_pi_over_zeta_beta", h, c["feasible"])
        axs[0].axhline(2 * math.atan(a_crit(th)), color=col, lw=0.6, ls=":")
    axs[0].set(xscale="log", xlabel="Q* = P sqrt(A)/sqrt(2wR)", ylabel="eps [rad]", xlim=(0.1, 1e3),
               title="(a) neat fit (Delta = 0); dotted: eps_crit")
    axs[1].set(xlabel="eps [rad]", ylabel="h(pi)/(zeta* beta*)", ylim=(-0.5, 5), title="(b) gap at phi = pi")
    axs[1].axhline(0, color="k", lw=0.5)
    for ax in axs:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Fig. 8: neat fit, super-critical equilibria")
    fig.tight_layout()
    return fig, rows


def fig09(n=600):
    plt = _mpl()
    fig, ax = plt.subplots(figsize=(6.5, 4.8))
    rows = _Rows()
    ac = a_crit(1.0)
    for M, col in zip((0.0, 0.1, 0.3), ("k", "C0", "C3")):
        cv = eq.curve(M, 1.0, "sub-critical", n=n, gb=FIGURE_GB[1.0])
        _line(ax, cv.a / ac, cv.P_star, cv.feasible, col, f"cylinder M = {M:g}")
        rows.add("a", f"cylinder M = {M:g}", "a/a_crit", cv.a / ac, "P_star", cv.P_star, cv.feasible)
        ph = special.half_plane_P_star(cv.a, M, 1.0)
        name = "Hertz half-plane M = 0" if M == 0 else f"Barquins half-plane M = {M:g}"
        ax.plot(cv.a / ac, ph, color=col, ls=":", label=name)
        rows.add("a", name, "a/a_crit", cv.a / ac, "P_star", ph)
    ax.set(xlabel="a/a_crit", ylabel="P*", ylim=(-0.6, 3), title="Fig. 9: cylinder vs half plane, vartheta = 1")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return fig, rows


def fig10(n=60):
    plt = _mpl()
    fig, ax = plt.subplots(figsize=(6.5, 4.8))
    rows = _Rows()
    for th, col in ((0.5, "C0"), (1.0, "C1")):
        Ms = np.linspace(0.01, 0.9, n)
        cyl, feas, half = [], [], []
        for M in Ms:
            pts = eq.adherence(M, th, "load")
            p = min(pts, key=lambda q: q.P_star) if pts else None
            cyl.append(p.P_star if p and p.P_star < 0 else np.nan)
            feas.append(bool(p.feasible) if p else False)
            half.append(special.half_plane_adherence(M, th)[1])
        ax.plot(Ms, cyl, color=col, label=f"cylinder, vartheta = {th:g}")
        ax.plot(Ms, half, color=col, ls=":", label=f"Barquins, vartheta = {th:g}")
        rows.add("a", f"cylinder vartheta = {th:g}", "M", Ms, "P_star_adherence", cyl, feas)
        rows.add("a", f"Barquins vartheta = {th:g}", "M", Ms, "P_star_adherence", half)
    ax.set(xlabel="M", ylabel="adherence force P* (fixed load)",
           title="Fig. 10: fixed-load adherence vs M (cylinder: lowest P* minimum < 0)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return fig, rows


def fig11(n=600):
    plt = _mpl()
    fig, axs = plt.subplots(1, 2, figsize=(11, 4.5))
    rows = _Rows()
    for ax, regime, Ms, tag in ((axs[0], "sub-critical", (0.3, 0.5), "a"), (axs[1], "super-critical", (0.3, 0.5, 0.8), "b")):
        for M, col in zip(Ms, ("C0", "C1", "C2")):
            cv = eq.curve(M, 1.0, regime, n=n)
            P = np.clip(cv.P_star, -20, 20)
            _line(ax, cv.eps_star, P, cv.feasible, col, f"M = {M:g}", lw=0.8)
            st = cv.stable_load
            ax.plot(cv.eps_star[st], P[st], ".", color=col, ms=2.5)
            rows.add(tag, f"M = {M:g} stable_load", "eps_star", cv.eps_star, "P_star", cv.P_star, cv.feasible)
            rows.add(tag, f"M = {M:g} stable_load flag", "eps_star", cv.eps_star, "stable_load", st.astype(float),
                     cv.feasible)
        ax.set(xlabel="eps*", ylabel="P*", ylim=(-2, 4), title=f"({tag}) {regime}: dots = stable at fixed load")
        ax.axhline(0, color="k", lw=0.5)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Fig. 11: fixed-load stability (dG/da|_P > 0), vartheta = 1")
    fig.tight_layout()
    return fig, rows


def fig12(n=400):
    return _pressure_panels([(0.4, -0.46, "(a)"), (0.6, -0.08, "(b)")], "super-critical",
                            "Fig. 12: pressure in the super-critical regime, vartheta = 1 (smallest root)", n)


FIGURES = {f"fig{k:02d}": globals()[f"fig{k:02d}"] for k in range(2, 13)}


def write_csv(path, rows):
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(CSV_COLUMNS)
        w.writerows(rows)


def draw_all(out, n=None, only=None, progress=None):
    """Write figNN.png, figNN.pdf, figNN.csv into ``out``; returns the list of paths written."""
    plt = _mpl()
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    names = [k for k in FIGURES if only is None or k in only]
    written = []
    for i, name in enumerate(names):
        if progress:
            progress(i, len(names), name)
        fig, rows = FIGURES[name]() if n is None else FIGURES[name](n)
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
