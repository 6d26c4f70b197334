"""The paper's pressure figures: Fig. 4 (sub-critical) and Fig. 12 (super-critical), N(phi) R/|P| of (5.4) split
into its bounded and unbounded (edge-singular) parts, through :meth:`jkrcyl.Contact.pressure`."""
from __future__ import annotations

import math
import warnings

import numpy as np

from .. import equilibria as eq
from ..contact import Contact
from ..materials import Materials
from ..notices import ValidityWarning
from . import style as st

FIG04_CASES = [(0.2, 4.0, "(a)"), (0.2, 2.0, "(b)"), (0.2, 0.1, "(c)"), (0.2, -0.15, "(d)")]
FIG12_CASES = [(0.4, -0.46, "(a)"), (0.6, -0.08, "(b)")]
PRESSURE_STYLES = {"bounded": dict(color="0.55", ls="--", lw=1.4),
                   "unbounded": dict(color="tab:red", ls=":", lw=1.6),
                   "total": dict(color="k", ls="-", lw=1.6)}


def figure_contact(M: float, theta: float = 1.0, alpha_ratio: float = 0.0) -> Contact:
    """The Contact behind the pressure figures (Figs. 4, 12) at adhesion M.

    R = 2, Delta = 1 (pin radius R - Delta > 0; N R/P depends on neither), G = 1, kappa = 1.8 (nu = 0.3) at
    vartheta = 1.  alpha_ratio = 0: identical bodies (kappa_I = 1.8, G_I = 1).  Otherwise kappa_I, G_I keep
    vartheta = 1, i.e. (kappa_I + 1)/G_I = kappa + 1, and give (kappa_I - 1)/(kappa_I + 1) = (kappa - 1)/(kappa + 1)
    - 2 alpha*/beta*.  w is chosen to give M.

    Parameters
    ----------
    M : float
        The adhesion (section 6).
    theta : float
        vartheta: 1 only.
    alpha_ratio : float
        alpha*/beta* in (-0.36, 0.143].

    Returns
    -------
    jkrcyl.Contact

    Raises
    ------
    ValueError
        Naming theta (not 1) or alpha_ratio outside its range (or w, from the Contact).

    Examples
    --------
    >>> c = figure_contact(0.2)
    >>> round(c.M, 12), c.theta, round(c.materials.alpha_ratio, 12)
    (0.2, 1.0, 0.0)
    """
    if theta != 1.0:
        raise ValueError("theta: the pressure figures are drawn at vartheta = 1")
    kappa = 1.8
    q = (kappa - 1) / (kappa + 1) - 2 * alpha_ratio
    if not 0 <= q < 1:
        raise ValueError(f"alpha_ratio: the pressure figures need alpha*/beta* in (-0.36, 0.143], got {alpha_ratio}")
    kappa_I = (1 + q) / (1 - q)
    mat = Materials(G=1.0, kappa=kappa, G_I=(kappa_I + 1) / (kappa + 1), kappa_I=kappa_I)
    with warnings.catch_warnings():         # the figures are normalised: R = 2, Delta = 1 only fix the units
        warnings.simplefilter("ignore", ValidityWarning)
        probe = Contact(R=2.0, Delta=1.0, w=1.0, materials=mat)
        w = (M / probe.M) ** 2          # M is proportional to sqrt(w)
        return Contact(R=2.0, Delta=1.0, w=w, materials=mat)


def pressure_limits(series: "dict[str, np.ndarray]", phi: np.ndarray, eps: float,
                    edge: float = 0.97) -> "tuple[float, float]":
    """y-limits of a pressure panel from the data: everything on |phi| <= edge * eps plus the whole bounded part.

    The unbounded part is singular at phi = +-eps; beyond ``edge`` it is clipped (and marked on the plot).

    Parameters
    ----------
    series : dict of ndarray
        'bounded', 'unbounded' and 'total' over phi (the keys of :data:`PRESSURE_STYLES`).
    phi : ndarray
        The angles [rad].
    eps : float
        The contact half-angle [rad].
    edge : float
        The fraction of eps inside which every series counts.

    Returns
    -------
    (float, float)
        The limits, with 0 included and an 8 % margin.

    Examples
    --------
    >>> phi = np.linspace(-1.0, 1.0, 5)
    >>> series = {"bounded": np.ones(5), "unbounded": np.array([-10.0, 0, 0, 0, -10.0]), "total": np.ones(5)}
    >>> [round(y, 12) for y in pressure_limits(series, phi, eps=1.0)]          # the ends at +-eps are clipped
    [-0.08, 1.08]
    """
    core = np.abs(phi) <= edge * eps
    vals = np.concatenate([np.concatenate([y[core] for y in series.values()]), series["bounded"]])
    lo, hi = float(min(vals.min(), 0.0)), float(max(vals.max(), 0.0))
    pad = 0.08 * (hi - lo)
    return lo - pad, hi + pad


def _panel(ax, rows, M, P_target, tag, regime, n, alpha_ratio):
    c = figure_contact(M, 1.0, alpha_ratio)
    gb = c.materials.inv_G_I / c.beta
    roots = eq.solve_load(M, 1.0, P_target, regime, gb=gb, alpha_ratio=alpha_ratio)
    if not roots:
        ax.set_title(f"{tag} $M = {M:g}$, $P^* = {P_target:g}$: no equilibrium")
        ax.axis("off")
        return
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
    ax.set(xlabel=st.LABEL["phi"], ylabel=st.LABEL["N_R_over_absP"], ylim=(lo, hi),
           title=f"{tag} $M = {M:g}$, $P^* = {P_target:g}$, $a = {a:.3f}$")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="best")


def _pressure_panels(cases, regime, title, n, alpha_ratio=0.0):
    plt = st.mpl()
    fig, axs = plt.subplots(1, len(cases), figsize=(4.2 * len(cases), 4.2), squeeze=False)
    rows = st.Rows()
    for ax, (M, P_target, tag) in zip(axs[0], cases):
        _panel(ax, rows, M, P_target, tag, regime, n, alpha_ratio)
    fig.suptitle(f"{title}\n{st.params_text(1.0, None, alpha_ratio)} (pressure does not depend on "
                 "$(1/G_I)/\\beta^*$ at $\\alpha^* = 0$)\n"
                 "singular unbounded ends clipped at the axis limits; dash-dot lines: contact edges "
                 "$\\pm\\varepsilon$")
    fig.tight_layout()
    return fig, rows


def fig04(n=400, alpha_ratio=0.0):
    return _pressure_panels(FIG04_CASES, "sub-critical",
                            "Fig. 4: pressure, sub-critical ($a < a_{crit}$, stable root)", n, alpha_ratio)


def fig12(n=400, alpha_ratio=0.0):
    return _pressure_panels(FIG12_CASES, "super-critical",
                            "Fig. 12: pressure, super-critical ($a > a_{crit}$, smallest root)", n, alpha_ratio)
