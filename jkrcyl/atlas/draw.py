"""The atlas map: what slow pulling does to the pin (``confined`` classes) over (M, vartheta), contours of
the load of that event, the zero-load limit M_max(vartheta) of (8.1) and a strip for vartheta = inf."""
from typing import List, Mapping

import numpy as np

from .classify import CONFINED

# one colour per class, distinct in greyscale too (luminance falls with the code)
PALETTE = {0: "#f0f0f0", 1: "#a6cee3", 2: "#fdbf6f", 3: "#fb9a99", 4: "#b2df8a", 5: "#cab2d6", 6: "#6a3d9a",
           7: "#b15928", 8: "#ffff99", 9: "#404040"}         # 8, 9: the law's codes (jkrcyl.atlas.cohesive)
LEVELS = (-5, -3, -2, -1.5, -1, -0.75, -0.5, -0.3, -0.2, -0.1, -0.05, 0.05, 0.1, 0.2, 0.3, 0.5)


def draw(atlas: Mapping[str, np.ndarray], path_stem: str, labels: Mapping[int, str] = CONFINED,
         title: str = "") -> List[str]:
    """Draw the atlas map into path_stem.png and path_stem.pdf (matplotlib, Agg backend).

    One colour per ``confined`` class (distinct in greyscale too), contours of P* of the first event (the fold, or
    where the gap at phi = pi closes), the zero-load limit M_max(vartheta) of (8.1) dashed, and a strip for the
    vartheta = inf row (M_R*, P_R* of (7.6)) when the grid has one.

    Parameters
    ----------
    atlas : mapping of str to ndarray
        What :func:`jkrcyl.atlas.classify` returns (or the arrays of a file of :func:`jkrcyl.atlas.write_npz`).
    path_stem : str
        The path without the extension.
    labels : mapping of int to str
        The legend of each code (default :data:`CONFINED`; the law's atlas: jkrcyl.atlas.cohesive.LAW_CONFINED).
    title : str
        A first title line (e.g. the law and its lambda).

    Returns
    -------
    list of str
        The two paths written.

    Raises
    ------
    KeyError
        Where ``atlas`` lacks a field (M, theta, confined, event_P, zero_load_M_max).

    Examples
    --------
    >>> import os, tempfile
    >>> from jkrcyl import atlas
    >>> result = atlas.classify(*atlas.default_grid(n_M=5, n_theta=3, M_max=1.0, theta_max=2.0), parallel=False)
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     [os.path.basename(p) for p in draw(result, os.path.join(folder, "atlas"))]
    ['atlas.png', 'atlas.pdf']
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import BoundaryNorm, ListedColormap
    from matplotlib.patches import Patch

    Ms, th = atlas["M"], atlas["theta"]
    fin = np.isfinite(th)
    has_inf = (~fin).any()
    code = atlas["confined"]
    present = sorted(set(np.unique(code).tolist()))
    cmap = ListedColormap([PALETTE[c] for c in range(len(PALETTE))])
    norm = BoundaryNorm(np.arange(len(PALETTE) + 1) - 0.5, len(PALETTE))
    fig = plt.figure(figsize=(10, 8.2))
    gs = fig.add_gridspec(2, 1, height_ratios=[12, 1] if has_inf else [1, 0.0001], hspace=0.08)
    ax = fig.add_subplot(gs[0])
    tf = th[fin]
    dM = (Ms[-1] - Ms[0]) / max(len(Ms) - 1, 1)
    dT = (tf[-1] - tf[0]) / max(len(tf) - 1, 1) if tf.size else 1.0
    ext = [Ms[0] - dM / 2, Ms[-1] + dM / 2, tf[0] - dT / 2, tf[-1] + dT / 2] if tf.size else None
    if tf.size:
        ax.imshow(code[fin], origin="lower", aspect="auto", extent=ext, cmap=cmap, norm=norm,
                  interpolation="nearest")
        for c in present:           # per class: P* jumps where the class changes (another branch's event)
            P = np.where(code[fin] == c, atlas["event_P"][fin], np.nan)       # NaN only for plotting
            if c == 0 or np.isfinite(P).sum() <= 4 or len(Ms) <= 2 or tf.size <= 2:
                continue
            lev = [v for v in LEVELS if np.nanmin(P) < v < np.nanmax(P)]
            if lev:
                cs = ax.contour(Ms, tf, P, levels=lev, colors="k", linewidths=0.7, linestyles="solid")
                ax.clabel(cs, fmt="%g", fontsize=7)
        ax.plot(atlas["zero_load_M_max"][fin], tf, color="tab:red", lw=1.6, ls="--")
        ax.set_xlim(ext[0], ext[1])
        ax.set_ylim(ext[2], ext[3])
    ax.set_ylabel(r"$\vartheta$")
    ax.set_title(title + "Slow pulling under load control, starting from the zero-load contact: what happens first;\n"
                 r"contours: $P^*$ of that event (the fold, or where the gap at $\varphi = \pi$ closes)",
                 fontsize=10)
    handles = [Patch(facecolor=PALETTE[c], edgecolor="k", lw=0.3, label=labels[c]) for c in present]
    handles.append(plt.Line2D([], [], color="tab:red", ls="--",
                              label=r"$M_{max}(\vartheta)$: zero-load contact (8.1) for $M < M_{max}$"))
    ax.legend(handles=handles, loc="upper right", fontsize=7, framealpha=0.9)
    if has_inf:
        ax.tick_params(labelbottom=False)
        ax2 = fig.add_subplot(gs[1], sharex=ax)
        ax2.imshow(code[~fin][:1], origin="lower", aspect="auto", extent=[ext[0], ext[1], 0, 1] if ext else None,
                   cmap=cmap, norm=norm, interpolation="nearest")
        ax2.set_yticks([0.5])
        ax2.set_yticklabels([r"$\infty$"])
        ax2.set_xlabel(r"$M$  ($M_R^*$ of (7.6) in the $\vartheta = \infty$ strip)")
    else:
        ax.set_xlabel(r"$M$")
    written = []
    for ext_ in ("png", "pdf"):
        p = f"{path_stem}.{ext_}"
        fig.savefig(p, dpi=110, metadata={"CreationDate": None} if ext_ == "pdf" else None)
        written.append(p)
    plt.close(fig)
    return written
