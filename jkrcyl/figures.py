"""The paper's Figures 2-12, redrawn through the library (matplotlib), each with a CSV of what it plots.

:data:`FIGURES` is the explicit registry: name -> :class:`FigureSpec` (number, builder, the parameters the
figure states).  ``FIGURES[name].build(n, alpha_ratio)`` returns ``(matplotlib Figure, rows)``; rows are
the plotted points, written as CSV with the columns of :data:`CSV_COLUMNS`.

Reading the figures: colour *and* marker tell the curves apart (survives greyscale); solid = gap
inequality h(pi) >= 0 holds, dashed = overclosed (h(pi) < 0), as in the paper; each figure states
vartheta, the compliance ratio gb = (1/G_I)/beta* that delta/Delta depends on, and alpha*/beta*; where
jkrcyl disagrees with the paper (generated/DERIVATION.md, Errata) the figure says so.
"""
import csv
import math
import pathlib
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from . import equilibria as eq
from . import special
from .contact import Contact
from .critical import a_crit
from .materials import Materials

# (1/G_I)/beta* used for delta/Delta: identical bodies with nu = 0.3 at vartheta = 1 (kappa = 1.8,
# gb = 1/(kappa + 1); reproduces eps = 2.41 at delta = 0, M = 1 of section 8.2), a rigid indenter at
# vartheta = 1/2, a rigid cradle with an incompressible cylinder at vartheta = inf.
FIGURE_GB = {1.0: 1 / 2.8, 0.5: 0.0, math.inf: 1.0}
CSV_COLUMNS = ("panel", "series", "x_name", "x", "y_name", "y", "feasible")
M_VALUES = (0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0)
MARKERS = ("o", "s", "^", "v", "D", "P", "X", "*", "<", ">")
FEASIBLE_LS, OVERCLOSED_LS = "-", "--"
# Errata shown on the figures (generated/DERIVATION.md, section "Errata").
ERRATUM_FIG10 = ("erratum (DERIVATION.md 'Fig. 10'): the curves cross; the paper says the\n"
                 "Barquins half plane always under-predicts the adherence force")
ERRATUM_FIG11 = ("erratum (DERIVATION.md 'Fig. 11b'): above $a_{crit}$ stable\nat fixed load where "
                 "$dP^*/da<0$; the paper calls\nthe small-$\\varepsilon$ branch unstable")

LABEL = {"a": "$a$", "a/a_crit": "$a/a_{crit}$", "eps_star": "$\\varepsilon^*$",
         "eps": "$\\varepsilon$ [rad]", "P_star": "$P^*$", "P_R_star": "$P_R^*$",
         "delta_over_Delta": "$\\delta/\\Delta$", "h_pi_over_Delta": "$h(\\pi)/\\Delta$",
         "M": "$M$", "phi": "$\\phi$ [rad]", "N_R_over_absP": "$N(\\phi)R/|P|$",
         "Q_star": "$Q^* = P\\sqrt{A}/\\sqrt{2wR}$", "h_pi_over_zeta_beta": "$h(\\pi)/(\\zeta^*\\beta^*)$"}


def _mpl():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def _theta_text(theta):
    return "$\\vartheta = \\infty$" if math.isinf(theta) else f"$\\vartheta = {theta:g}$"


def _params_text(theta, gb=None, alpha_ratio=0.0):
    parts = [_theta_text(theta)]
    if gb is not None:
        parts.append(f"$(1/G_I)/\\beta^* = {gb:.4g}$")
    parts.append(f"$\\alpha^*/\\beta^* = {alpha_ratio:g}$")
    return ", ".join(parts)


class _Rows(list):
    def add(self, panel, series, x_name, x, y_name, y, feasible=None):
        x, y = np.asarray(x, float), np.asarray(y, float)
        f = np.ones_like(x, dtype=bool) if feasible is None else np.asarray(feasible, bool)
        for xi, yi, fi in zip(x, y, f):
            self.append((panel, series, x_name, repr(float(xi)), y_name, repr(float(yi)), int(fi)))


@dataclass(frozen=True)
class Style:
    """How one series is drawn: colour (luminance-ordered) and marker; line style encodes feasibility."""

    color: tuple
    marker: str


def _styles(n):
    """n styles whose greyscale luminance is strictly ordered (viridis, yellow end cut) + distinct markers."""
    plt = _mpl()
    cmap = plt.get_cmap("viridis")
    return [Style(cmap(0.85 * i / max(n - 1, 1)), MARKERS[i % len(MARKERS)]) for i in range(n)]


def _line(ax, x, y, feasible, style, lw=1.2):
    """Solid where feasible, dashed where not, markers spaced along the line; no legend entry (see _legend)."""
    x, y, f = np.asarray(x), np.asarray(y), np.asarray(feasible, bool)
    start = 0
    for i in range(1, len(x) + 1):
        if i == len(x) or f[i] != f[start]:
            j = min(i + 1, len(x))     # overlap one point so that the pieces join
            ax.plot(x[start:j], y[start:j], color=style.color, lw=lw,
                    ls=FEASIBLE_LS if f[start] else OVERCLOSED_LS,
                    marker=style.marker, ms=4, markevery=0.12, mfc="none")
            start = i


def _legend(ax, entries, feasibility=True, extra=(), **kw):
    """Proxy legend: one neutral entry (colour + marker, no line) per series, then the line-style meanings."""
    from matplotlib.lines import Line2D
    handles = [Line2D([], [], color=s.color, marker=s.marker, mfc="none", ls="none", label=lab)
               for lab, s in entries]
    if feasibility:
        handles += [Line2D([], [], color="k", ls=FEASIBLE_LS, label="$h(\\pi) \\geq 0$ (feasible)"),
                    Line2D([], [], color="k", ls=OVERCLOSED_LS, label="$h(\\pi) < 0$ (overclosed)")]
    handles += list(extra)
    return ax.legend(handles=handles, fontsize=7, **kw)


def _a_ratio(cv):
    """a/a_crit from eps* = 2 atan(a/a_crit)/pi (a_crit is the solver's pole when alpha* != 0)."""
    return np.tan(np.pi * cv.eps_star / 2)


def _equilibrium_panels(theta, regime, n, title, Ms=M_VALUES, alpha_ratio=0.0):
    plt = _mpl()
    fig, axs = plt.subplots(2, 2, figsize=(10, 8.4))
    rows = _Rows()
    is_inf = math.isinf(theta)
    gb = FIGURE_GB[theta]
    xname = "a" if is_inf else ("a/a_crit" if regime == "sub-critical" else "eps_star")
    pname = "P_R_star" if is_inf else "P_star"
    styles = _styles(len(Ms))
    for M, st in zip(Ms, styles):
        cv = eq.curve(M, theta, regime, n=n, gb=gb, alpha_ratio=alpha_ratio)
        x = cv.a if is_inf else (_a_ratio(cv) if regime == "sub-critical" else cv.eps_star)
        s = f"M = {M:g}"
        P = np.clip(cv.P_star, -50, 50)
        _line(axs[0, 0], x, P, cv.feasible, st)
        rows.add("a", s, xname, x, "P_star", cv.P_star, cv.feasible)
        _line(axs[0, 1], cv.delta_over_Delta, x, cv.feasible, st)
        rows.add("b", s, "delta_over_Delta", cv.delta_over_Delta, xname, x, cv.feasible)
        _line(axs[1, 0], cv.delta_over_Delta, P, cv.feasible, st)
        rows.add("c", s, "delta_over_Delta", cv.delta_over_Delta, "P_star", cv.P_star, cv.feasible)
        _line(axs[1, 1], x, cv.h_pi_over_Delta, cv.feasible, st)
        rows.add("d", s, xname, x, "h_pi_over_Delta", cv.h_pi_over_Delta, cv.feasible)
    mlab = "M_R^*" if is_inf else "M"
    axs[0, 0].set(xlabel=LABEL[xname], ylabel=LABEL[pname], ylim=(-3, 8), title="(a) load")
    axs[0, 1].set(xlabel=LABEL["delta_over_Delta"], ylabel=LABEL[xname], xlim=(-6, 6), title="(b) approach")
    axs[1, 0].set(xlabel=LABEL["delta_over_Delta"], ylabel=LABEL[pname], xlim=(-6, 6), ylim=(-3, 8),
                  title="(c) load-approach")
    axs[1, 1].set(xlabel=LABEL[xname], ylabel=LABEL["h_pi_over_Delta"], ylim=(-4, 4),
                  title="(d) gap at $\\phi = \\pi$")
    axs[1, 1].axhline(0, color="k", lw=0.6)
    for ax in axs.flat:
        ax.grid(alpha=0.3)
    _legend(axs[0, 0], [(f"${mlab} = {M:g}$", st) for M, st in zip(Ms, styles)], ncol=2, loc="best")
    if is_inf:      # the conjugate approach at M_R* = 0 (derive/green.py), drawn next to the paper's
        cv0 = eq.curve(Ms[0], theta, regime, n=n, gb=gb, alpha_ratio=alpha_ratio)
        axs[1, 0].plot(cv0.delta_work_over_Delta, np.clip(cv0.P_star, -50, 50), color="0.55", lw=2.2, ls=":",
                       label=f"$\\delta_{{work}}$, ${mlab} = {Ms[0]:g}$")
        rows.add("c_work", f"M = {Ms[0]:g}", "delta_work_over_Delta", cv0.delta_work_over_Delta, "P_star",
                 cv0.P_star, cv0.feasible)
        axs[1, 0].text(0.98, 0.02, "$P_R^*$ falls with $\\delta$ even at $M_R^* = 0$: the paper's $\\delta$ (5.8)\n"
                       "is not the work conjugate of $P$; grey dotted: the conjugate\n"
                       "$\\delta_{work} = \\delta + P/(8\\pi G_I)$ (pin centroid), stiffness > 0",
                       transform=axs[1, 0].transAxes, ha="right", va="bottom", fontsize=7, color="darkred")
    fig.suptitle(f"{title}\n{_params_text(theta, gb, alpha_ratio)}")
    fig.tight_layout()
    return fig, rows


def fig02(n=600, alpha_ratio=0.0):
    return _equilibrium_panels(1.0, "sub-critical", n, "Fig. 2: sub-critical equilibria", alpha_ratio=alpha_ratio)


def fig03(n=600, alpha_ratio=0.0):
    from matplotlib.lines import Line2D
    plt = _mpl()
    fig, axs = plt.subplots(1, 2, figsize=(11, 4.8))
    rows = _Rows()
    gb = FIGURE_GB[1.0]
    Ms = (0.05, 0.1, 0.2, 0.3)
    styles = _styles(len(Ms))
    for M, st in zip(Ms, styles):
        cv = eq.curve(M, 1.0, "sub-critical", n=n, gb=gb, alpha_ratio=alpha_ratio)
        lab = f"M = {M:g}"
        x = _a_ratio(cv)
        _line(axs[0], x, cv.P_star, cv.feasible, st)
        rows.add("a", lab, "a/a_crit", x, "P_star", cv.P_star, cv.feasible)
        _line(axs[1], cv.delta_over_Delta, cv.P_star, cv.feasible, st)
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
    axs[0].set(xlabel=LABEL["a/a_crit"], ylabel=LABEL["P_star"], xlim=(0, 0.6), ylim=(-0.4, 0.6),
               title="(a) load")
    axs[1].set(xlabel=LABEL["delta_over_Delta"], ylabel=LABEL["P_star"], xlim=(-1.5, 1.5), ylim=(-0.4, 0.6),
               title="(b) load-approach")
    for ax in axs:
        ax.grid(alpha=0.3)
        ax.axhline(0, color="k", lw=0.5)
    marks = [Line2D([], [], color="k", marker="x", ls="none", ms=8, label="adherence, fixed load"),
             Line2D([], [], color="k", marker="o", mfc="none", ls="none", ms=9, label="adherence, fixed grip")]
    _legend(axs[0], [(f"$M = {M:g}$", st) for M, st in zip(Ms, styles)], extra=marks)
    fig.suptitle(f"Fig. 3: close-up of Fig. 2\n{_params_text(1.0, gb, alpha_ratio)}")
    fig.tight_layout()
    return fig, rows


def figure_contact(M, theta=1.0, alpha_ratio=0.0):
    """The Contact behind the pressure figures: R = 2, Delta = 1 (pin radius R - Delta > 0; N R/P depends on
    neither), G = 1, kappa = 1.8 (nu = 0.3) at vartheta = 1.

    alpha_ratio = 0: identical bodies (kappa_I = 1.8, G_I = 1).  Otherwise kappa_I, G_I keep vartheta = 1,
    i.e. (kappa_I + 1)/G_I = kappa + 1, and give (kappa_I - 1)/(kappa_I + 1) = (kappa - 1)/(kappa + 1) - 2
    alpha*/beta*.  w is chosen to give M.
    """
    if theta != 1.0:
        raise ValueError("theta: the pressure figures are drawn at vartheta = 1")
    kappa = 1.8
    q = (kappa - 1) / (kappa + 1) - 2 * alpha_ratio
    if not 0 <= q < 1:
        raise ValueError(f"alpha_ratio: the pressure figures need alpha*/beta* in (-0.36, 0.143], got {alpha_ratio}")
    kappa_I = (1 + q) / (1 - q)
    mat = Materials(G=1.0, kappa=kappa, G_I=(kappa_I + 1) / (kappa + 1), kappa_I=kappa_I)
    probe = Contact(R=2.0, Delta=1.0, w=1.0, materials=mat)
    w = (M / probe.M) ** 2          # M is proportional to sqrt(w)
    return Contact(R=2.0, Delta=1.0, w=w, materials=mat)


def pressure_limits(series, phi, eps, edge=0.97):
    """y-limits from the data: everything on |phi| <= edge * eps plus the whole bounded part, 8 % margin.

    The unbounded part is singular at phi = +-eps; beyond ``edge`` it is clipped (and marked on the plot).
    """
    core = np.abs(phi) <= edge * eps
    vals = np.concatenate([np.concatenate([y[core] for y in series.values()]), series["bounded"]])
    lo, hi = float(min(vals.min(), 0.0)), float(max(vals.max(), 0.0))
    pad = 0.08 * (hi - lo)
    return lo - pad, hi + pad


PRESSURE_STYLES = {"bounded": dict(color="0.55", ls="--", lw=1.4),
                   "unbounded": dict(color="tab:red", ls=":", lw=1.6),
                   "total": dict(color="k", ls="-", lw=1.6)}


def _pressure_panels(cases, regime, title, n, alpha_ratio=0.0):
    plt = _mpl()
    fig, axs = plt.subplots(1, len(cases), figsize=(4.2 * len(cases), 4.2), squeeze=False)
    rows = _Rows()
    for ax, (M, P_target, tag) in zip(axs[0], cases):
        c = figure_contact(M, 1.0, alpha_ratio)
        gb = c.materials.inv_G_I / c.beta
        roots = eq.solve_load(M, 1.0, P_target, regime, gb=gb, alpha_ratio=alpha_ratio)
        if not roots:
            ax.set_title(f"{tag} $M = {M:g}$, $P^* = {P_target:g}$: no equilibrium")
            ax.axis("off")
            continue
        a = roots[-1] if regime == "sub-critical" else roots[0]
        eps = 2 * math.atan(a)
        phi = -eps * np.cos(np.pi * (np.arange(n) + 0.5) / n)   # Chebyshev nodes: resolve the edge patches
        nb, nu = c.pressure(a, phi, parts=True)
        sc = c.R / abs(P_target * c.load_scale)
        ys = {"bounded": nb * sc, "unbounded": nu * sc, "total": (nb + nu) * sc}
        lo, hi = pressure_limits(ys, phi, eps)
        for name, y in ys.items():
            ax.plot(phi, np.clip(y, lo, hi), label=name, **PRESSURE_STYLES[name])
            rows.add(tag, f"{name} (a = {a:.6g})", "phi", phi, "N_R_over_absP", y)
        for sgn in (-1, 1):
            ax.axvline(sgn * eps, color="k", lw=0.5, ls="-.")
        ax.axhline(0, color="k", lw=0.5)
        ax.set(xlabel=LABEL["phi"], ylabel=LABEL["N_R_over_absP"], ylim=(lo, hi),
               title=f"{tag} $M = {M:g}$, $P^* = {P_target:g}$, $a = {a:.3f}$")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="best")
    fig.suptitle(f"{title}\n{_params_text(1.0, None, alpha_ratio)} (pressure does not depend on "
                 "$(1/G_I)/\\beta^*$ at $\\alpha^* = 0$)\n"
                 "singular unbounded ends clipped at the axis limits; dash-dot lines: contact edges "
                 "$\\pm\\varepsilon$")
    fig.tight_layout()
    return fig, rows


FIG04_CASES = [(0.2, 4.0, "(a)"), (0.2, 2.0, "(b)"), (0.2, 0.1, "(c)"), (0.2, -0.15, "(d)")]
FIG12_CASES = [(0.4, -0.46, "(a)"), (0.6, -0.08, "(b)")]


def fig04(n=400, alpha_ratio=0.0):
    return _pressure_panels(FIG04_CASES, "sub-critical",
                            "Fig. 4: pressure, sub-critical ($a < a_{crit}$, stable root)", n, alpha_ratio)


def fig05(n=600, alpha_ratio=0.0):
    return _equilibrium_panels(1.0, "super-critical", n, "Fig. 5: super-critical equilibria", alpha_ratio=alpha_ratio)


def fig06(n=600, alpha_ratio=0.0):
    return _equilibrium_panels(0.5, "sub-critical", n, "Fig. 6: sub-critical equilibria", alpha_ratio=alpha_ratio)


def fig07(n=600, alpha_ratio=0.0):
    return _equilibrium_panels(math.inf, "sub-critical", n,
                               "Fig. 7: rubbery cylinder in a rigid cradle ($M_R^*$, $P_R^*$); "
                               "$\\delta$ is the paper's approach (5.8)", alpha_ratio=alpha_ratio)


def neat_fit_stable(c):
    """Fixed-load stability of the (super-critical) neat fit: dQ*/da < 0 above a_crit (erratum 'Fig. 11b')."""
    return np.gradient(c["Q_star"], c["a"]) < 0


def fig08(n=600, alpha_ratio=0.0):
    from matplotlib.lines import Line2D
    if alpha_ratio != 0.0:
        raise ValueError("alpha_ratio: Fig. 8 (neat fit, section 7.3) exists only in closed form, alpha* = 0")
    plt = _mpl()
    fig, axs = plt.subplots(1, 2, figsize=(10.5, 4.6))
    rows = _Rows()
    ths = (0.5, 1.0)
    styles = _styles(len(ths))
    for th, st in zip(ths, styles):
        c = special.neat_fit_curve(th, n)
        lab = f"vartheta = {th:g}"
        stable = neat_fit_stable(c)
        _line(axs[0], c["Q_star"], c["eps"], c["feasible"], st)
        axs[0].plot(np.where(stable, c["Q_star"], np.nan), c["eps"], color=st.color, lw=5, alpha=0.3)
        rows.add("a", lab, "Q_star", c["Q_star"], "eps", c["eps"], c["feasible"])
        rows.add("a", lab + " stable_load flag", "Q_star", c["Q_star"], "stable_load", stable.astype(float),
                 c["feasible"])
        h = special.neat_fit_gap_pi(c["a"], th)
        _line(axs[1], c["eps"], h, c["feasible"], st)
        axs[1].plot(c["eps"], np.where(stable, h, np.nan), color=st.color, lw=5, alpha=0.3)
        rows.add("b", lab, "eps", c["eps"], "h_pi_over_zeta_beta", h, c["feasible"])
        axs[0].axhline(2 * math.atan(a_crit(th)), color=st.color, lw=0.8, ls=":")
    axs[0].set(xscale="log", xlabel=LABEL["Q_star"], ylabel=LABEL["eps"], xlim=(0.1, 1e3),
               title="(a) neat fit ($\\Delta = 0$); dotted: $\\varepsilon_{crit}$")
    axs[1].set(xlabel=LABEL["eps"], ylabel=LABEL["h_pi_over_zeta_beta"], ylim=(-0.5, 5),
               title="(b) gap at $\\phi = \\pi$")
    axs[1].axhline(0, color="k", lw=0.5)
    band = Line2D([], [], color="0.5", lw=5, alpha=0.3, label="stable at fixed load ($dQ^*/da < 0$)")
    for ax in axs:
        ax.grid(alpha=0.3)
    _legend(axs[0], [(_theta_text(th), st) for th, st in zip(ths, styles)], extra=[band])
    fig.suptitle("Fig. 8: neat fit, super-critical equilibria; $\\alpha^*/\\beta^* = 0$ "
                 "(no $\\delta$: $(1/G_I)/\\beta^*$ not used)")
    fig.tight_layout()
    return fig, rows


def fig09(n=600, alpha_ratio=0.0):
    from matplotlib.lines import Line2D
    plt = _mpl()
    fig, ax = plt.subplots(figsize=(7, 5.4))
    rows = _Rows()
    gb = FIGURE_GB[1.0]
    Ms = (0.0, 0.1, 0.3, 0.4, 0.6, 1.0)
    styles = _styles(len(Ms))
    for M, st in zip(Ms, styles):
        cv = eq.curve(M, 1.0, "sub-critical", n=n, gb=gb, alpha_ratio=alpha_ratio)
        x = _a_ratio(cv)
        _line(ax, x, cv.P_star, cv.feasible, st)
        rows.add("a", f"cylinder M = {M:g}", "a/a_crit", x, "P_star", cv.P_star, cv.feasible)
        ph = special.half_plane_P_star(cv.a, M, 1.0)
        name = "Hertz half-plane M = 0" if M == 0 else f"Barquins half-plane M = {M:g}"
        ax.plot(x, ph, color=st.color, ls=":", lw=1.4, marker=st.marker, ms=3, markevery=0.15)
        rows.add("a", name, "a/a_crit", x, "P_star", ph)
    ax.set(xlabel=LABEL["a/a_crit"], ylabel=LABEL["P_star"], ylim=(-1.5, 3))
    ax.grid(alpha=0.3)
    half = Line2D([], [], color="k", ls=":", lw=1.4, label="half plane (Hertz $M=0$, Barquins $M>0$)")
    _legend(ax, [(f"$M = {M:g}$", st) for M, st in zip(Ms, styles)], extra=[half], loc="upper left")
    ax.set_title(f"Fig. 9: cylinder vs half plane\n{_params_text(1.0, gb, alpha_ratio)}", fontsize=10)
    fig.tight_layout()
    return fig, rows


def _crossing(Ms, cyl, half):
    d = np.asarray(half) - np.asarray(cyl)
    ok = np.isfinite(d)
    idx = np.nonzero(ok[:-1] & ok[1:] & (np.sign(d[:-1]) != np.sign(d[1:])))[0]
    if not len(idx):
        return None
    i = idx[0]
    return Ms[i] - d[i] * (Ms[i + 1] - Ms[i]) / (d[i + 1] - d[i])


def fig10(n=60, alpha_ratio=0.0):
    from matplotlib.lines import Line2D
    plt = _mpl()
    fig, ax = plt.subplots(figsize=(7, 5.4))
    rows = _Rows()
    ths = (0.5, 1.0)
    styles = _styles(len(ths))
    for th, st in zip(ths, styles):
        Ms = np.linspace(0.01, 0.9, n)
        cyl, feas, half = [], [], []
        for M in Ms:
            pts = eq.adherence(M, th, "load", alpha_ratio=alpha_ratio, confined=False)
            p = min(pts, key=lambda q: q.P_star) if pts else None
            cyl.append(p.P_star if p and p.P_star < 0 else np.nan)
            feas.append(bool(p.feasible) if p else False)
            half.append(special.half_plane_adherence(M, th)[1])
        ax.plot(Ms, cyl, color=st.color, ls="-", marker=st.marker, mfc="none", ms=4, markevery=0.1)
        ax.plot(Ms, half, color=st.color, ls=":", lw=1.6)
        rows.add("a", f"cylinder vartheta = {th:g}", "M", Ms, "P_star_adherence", cyl, feas)
        rows.add("a", f"Barquins vartheta = {th:g}", "M", Ms, "P_star_adherence", half)
        mx = _crossing(Ms, cyl, half)
        if mx is not None:
            ax.axvline(mx, color=st.color, lw=0.8, ls="-.")
            ax.annotate(f"cross at $M \\approx {mx:.3f}$", (mx, np.interp(mx, Ms, half)),
                        xytext=(6, -14 if th == 1.0 else 10), textcoords="offset points", fontsize=7)
    ax.set(xlabel=LABEL["M"], ylabel="adherence force $P^*$ (fixed load)")
    ax.set_title(f"Fig. 10: fixed-load adherence vs $M$ (cylinder: lowest $P^*$ minimum $< 0$)\n"
                 f"$\\alpha^*/\\beta^* = {alpha_ratio:g}$", fontsize=10)
    ax.text(0.02, 0.02, ERRATUM_FIG10, transform=ax.transAxes, fontsize=7, color="darkred")
    ax.grid(alpha=0.3)
    extra = [Line2D([], [], color="k", ls="-", label="conforming cylinder"),
             Line2D([], [], color="k", ls=":", lw=1.6, label="Barquins half plane")]
    _legend(ax, [(_theta_text(th), st) for th, st in zip(ths, styles)], feasibility=False, extra=extra)
    fig.tight_layout()
    return fig, rows


def fig11(n=600, alpha_ratio=0.0):
    from matplotlib.lines import Line2D
    plt = _mpl()
    fig, axs = plt.subplots(1, 2, figsize=(11.5, 5))
    rows = _Rows()
    gb = eq.default_gb(1.0)
    for ax, regime, Ms, tag in ((axs[0], "sub-critical", (0.3, 0.5), "a"),
                                (axs[1], "super-critical", (0.3, 0.5, 0.8), "b")):
        styles = _styles(len(Ms))
        for M, st in zip(Ms, styles):
            cv = eq.curve(M, 1.0, regime, n=n, gb=gb, alpha_ratio=alpha_ratio)
            P = np.clip(cv.P_star, -20, 20)
            _line(ax, cv.eps_star, P, cv.feasible, st, lw=0.9)
            stab = cv.stable_load
            ax.plot(cv.eps_star, np.where(stab, P, np.nan), color=st.color, lw=5, alpha=0.3)
            rows.add(tag, f"M = {M:g} stable_load", "eps_star", cv.eps_star, "P_star", cv.P_star, cv.feasible)
            rows.add(tag, f"M = {M:g} stable_load flag", "eps_star", cv.eps_star, "stable_load",
                     stab.astype(float), cv.feasible)
        ax.set(xlabel=LABEL["eps_star"], ylabel=LABEL["P_star"], ylim=(-2, 4), title=f"({tag}) {regime}")
        ax.axhline(0, color="k", lw=0.5)
        ax.grid(alpha=0.3)
        band = Line2D([], [], color="0.5", lw=5, alpha=0.3, label="stable at fixed load ($dG/da|_P > 0$)")
        _legend(ax, [(f"$M = {M:g}$", st) for M, st in zip(Ms, styles)], extra=[band],
                loc="upper left" if tag == "a" else "upper center")
    axs[1].text(0.98, 0.03, ERRATUM_FIG11, transform=axs[1].transAxes, fontsize=7, color="darkred", ha="right")
    fig.suptitle(f"Fig. 11: fixed-load stability\n{_params_text(1.0, gb, alpha_ratio)}")
    fig.tight_layout()
    return fig, rows


def fig12(n=400, alpha_ratio=0.0):
    return _pressure_panels(FIG12_CASES, "super-critical",
                            "Fig. 12: pressure, super-critical ($a > a_{crit}$, smallest root)", n, alpha_ratio)


@dataclass(frozen=True)
class FigureSpec:
    """One registered figure: paper number, builder ``(n, alpha_ratio) -> (Figure, rows)``, stated parameters."""

    number: int
    builder: Callable
    params: dict = field(default_factory=dict)
    any_alpha: bool = True      # False: the figure exists only at alpha* = 0 (Fig. 8, the neat fit)

    @property
    def name(self):
        return f"fig{self.number:02d}"

    def build(self, n=None, alpha_ratio=0.0):
        return self.builder(alpha_ratio=alpha_ratio) if n is None else self.builder(n, alpha_ratio=alpha_ratio)


_REGISTRY = [
    FigureSpec(2, fig02, dict(theta=1.0, gb=FIGURE_GB[1.0], regime="sub-critical", M=M_VALUES)),
    FigureSpec(3, fig03, dict(theta=1.0, gb=FIGURE_GB[1.0], regime="sub-critical", M=(0.05, 0.1, 0.2, 0.3))),
    FigureSpec(4, fig04, dict(theta=1.0, regime="sub-critical", cases=FIG04_CASES)),
    FigureSpec(5, fig05, dict(theta=1.0, gb=FIGURE_GB[1.0], regime="super-critical", M=M_VALUES)),
    FigureSpec(6, fig06, dict(theta=0.5, gb=FIGURE_GB[0.5], regime="sub-critical", M=M_VALUES)),
    FigureSpec(7, fig07, dict(theta=math.inf, gb=FIGURE_GB[math.inf], regime="sub-critical", M=M_VALUES)),
    FigureSpec(8, fig08, dict(theta=(0.5, 1.0), Delta=0.0), any_alpha=False),
    FigureSpec(9, fig09, dict(theta=1.0, gb=FIGURE_GB[1.0], M=(0.0, 0.1, 0.3, 0.4, 0.6, 1.0))),
    FigureSpec(10, fig10, dict(theta=(0.5, 1.0), control="load")),
    FigureSpec(11, fig11, dict(theta=1.0, gb=eq.default_gb(1.0), M=((0.3, 0.5), (0.3, 0.5, 0.8)))),
    FigureSpec(12, fig12, dict(theta=1.0, regime="super-critical", cases=FIG12_CASES)),
]
FIGURES = {spec.name: spec for spec in _REGISTRY}


def write_csv(path, rows):
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(CSV_COLUMNS)
        w.writerows(rows)


def draw_all(out, n=None, only=None, progress=None, alpha_ratio=0.0):
    """Write figNN.png, figNN.pdf, figNN.csv into ``out``; returns the list of paths written.

    alpha_ratio = alpha*/beta* != 0 draws the figures that exist for any alpha* (not Fig. 8) with the
    numerical solver.
    """
    plt = _mpl()
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    names = [k for k in FIGURES if (only is None or k in only) and (alpha_ratio == 0 or FIGURES[k].any_alpha)]
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
