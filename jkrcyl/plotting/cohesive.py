"""Figures of the Maugis-Dugdale pin: the load-control pull-off against lambda for several M with its
JKR and Baney-Hui asymptotes, and the map of the pull-off over (lambda, M) showing where it vanishes
(``jkrcyl cohesive``).

* Pull-off: P* (section 6) of the stand-alone continuation (jkrcyl.analysis.cohesive_map, one point per lambda,
  Dask); JKR's (sigma0 = None, the model core's walker) as a horizontal line per M; Baney and Hui's half-plane
  pull-off m^(4/3) Pbar_c(lambda)/vartheta (jkrcyl.numerics.cohesive_half_plane: the derived half-plane limit),
  the small-M asymptote; lambda from the lead's convention (R_eff = R R_D/Delta, Delta/R -> 0).
* Map: the pull-off over JKR's, P*/P*_JKR, in colour where the pin detaches (pink where JKR's does not: its
  fold is infeasible or grows into full contact); grey where there is no adherence force (the range reaches
  round: h0 > 2 Delta less the uniform pull); light blue where the sub-critical contact branch has no zero-load
  contact (no detachment path from P = 0 on it; JKR's is super-critical there or missing, and the super-critical
  side is not modelled for the law); sand where the pin floats at first touch on a round zone that jumps when
  pushed (an S-shaped branch, narrow or not: jkrcyl.numerics.cohesive_branch.top_opens; no adherence force from
  first contact); the black line: where the pull-off vanishes.
"""
from __future__ import annotations

import math

import numpy as np

from ..analysis import cohesive_map as _map
from ..numerics.cohesive_half_plane import half_plane_pull_off
from . import style as st

PULL_OFF_M = (0.02, 0.1, 0.3)


def pull_off_figure(Ms=PULL_OFF_M, lams=None, theta=1.0, gb=None, workers=2):
    """(Figure, CSV rows): P* of the load-control pull-off against lambda for each M, with the asymptotes."""
    plt = st.mpl()
    gb = st.figure_gb(theta) if gb is None else gb
    lams = np.geomspace(0.01, 30.0, 36) if lams is None else np.asarray(lams, dtype=float)
    pm = _map.pull_off_map(lams, np.asarray(Ms, dtype=float), theta, gb, workers=workers)
    bh = np.array([half_plane_pull_off(x) for x in lams])
    scale = 1.0 if math.isinf(theta) else theta
    fig, ax = plt.subplots(figsize=(7.5, 5))
    rows = []
    for j, (M, s) in enumerate(zip(Ms, st.styles(len(Ms)))):
        m = M * scale
        y, asym = pm.P_star[:, j], (m ** (4 / 3)) * bh / scale
        ax.plot(lams, y, color=s.color, marker=s.marker, ms=4, lw=1.5, label=f"$M = {M:g}$")
        ax.axhline(pm.P_star_jkr[j], color=s.color, ls="--", lw=1)
        ax.plot(lams, asym, color=s.color, ls=":", lw=1.2)
        rows += [("pull-off", f"M={M:g}", "lambda", x, "P_star", v, True) for x, v in zip(lams, y)]
        rows += [("Baney-Hui", f"M={M:g}", "lambda", x, "P_star", v, True) for x, v in zip(lams, asym)]
        rows.append(("JKR", f"M={M:g}", "lambda", math.inf, "P_star", pm.P_star_jkr[j], True))
    ax.plot([], [], "k--", lw=1, label="JKR ($\\sigma_0$ = None)")
    ax.plot([], [], "k:", lw=1.2, label="Baney-Hui half plane, $m^{4/3}\\bar P_c(\\lambda)/\\vartheta$")
    ax.set_xscale("log")
    ax.set_xlabel("transition parameter $\\lambda$")
    ax.set_ylabel("load-control pull-off $P^*$")
    ax.set_title(f"Maugis-Dugdale pin in a hole: pull-off against $\\lambda$ "
                 f"({st.params_text(theta, gb, 0.0)})", fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    return fig, rows


def map_figure(pm: _map.PullOffMap):
    """Figure of a jkrcyl.analysis.cohesive_map.PullOffMap (module docstring)."""
    plt = st.mpl()
    from matplotlib.colors import ListedColormap
    fig, ax = plt.subplots(figsize=(7.5, 5.5))
    ratio = pm.P_star / pm.P_star_jkr[None, :]
    X, Y = np.meshgrid(pm.lam, pm.M, indexing="ij")
    mesh = ax.pcolormesh(X, Y, np.ma.masked_invalid(ratio), shading="nearest", cmap="viridis", vmin=0, vmax=1)
    fig.colorbar(mesh, ax=ax, label="pull-off $P^*/P^*_{JKR}$")
    none = np.where(pm.outcome == 2, 1.0, np.nan)
    ax.pcolormesh(X, Y, np.ma.masked_invalid(none), shading="nearest", cmap=ListedColormap(["0.75"]))
    only = np.where(np.isfinite(pm.P_star) & ~np.isfinite(ratio), 1.0, np.nan)     # JKR does not detach there
    ax.pcolormesh(X, Y, np.ma.masked_invalid(only), shading="nearest", cmap=ListedColormap(["#f4a6a6"]))
    drawn = np.where(pm.outcome == 3, 1.0, np.nan)
    ax.pcolormesh(X, Y, np.ma.masked_invalid(drawn), shading="nearest", cmap=ListedColormap(["#bcd4ea"]))
    s_shaped = np.where(pm.outcome == 4, 1.0, np.nan)
    ax.pcolormesh(X, Y, np.ma.masked_invalid(s_shaped), shading="nearest", cmap=ListedColormap(["#e8d8a8"]))
    ax.contour(X, Y, np.isfinite(pm.P_star).astype(float), levels=[0.5], colors="k", linewidths=1.2)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("transition parameter $\\lambda$")
    ax.set_ylabel("$M$" if not math.isinf(pm.theta) else "$M_R^*$")
    ax.plot([], [], "s", color="0.75", label="no adherence force (range reaches round)")
    ax.plot([], [], "s", color="#bcd4ea", label="no zero-load contact on the sub-critical branch")
    ax.plot([], [], "s", color="#e8d8a8",
            label="no adherence force from first contact (a round zone that jumps when pushed)")
    ax.plot([], [], "s", color="#f4a6a6", label="detaches; JKR does not (its fold is confined)")
    ax.plot([], [], "k-", lw=1.2, label="where the pull-off vanishes")
    ax.legend(fontsize=8, loc="lower right")
    ax.set_title(f"Load-control pull-off over $(\\lambda, M)$, {len(pm.lam)} x {len(pm.M)} "
                 f"({st.params_text(pm.theta, pm.gb, pm.alpha_ratio)})", fontsize=9)
    fig.tight_layout()
    return fig
