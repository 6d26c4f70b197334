"""A :class:`jkrcyl.explore.model.Picture` as the columns the explorer's plots draw and the summary it prints
(plain data and HTML: no Bokeh here)."""
from __future__ import annotations

import html
import math
import types

import numpy as np

from .model import CONTROLS

LENGTHS = ((1.0, "m"), (1e-3, "mm"), (1e-6, "\u00b5m"), (1e-9, "nm"))
PRESSURES = ((1e9, "GPa"), (1e6, "MPa"), (1e3, "kPa"), (1.0, "Pa"))
POINT_STYLE = {"first contact": ("circle", "black"), "pull-off (load)": ("inverted_triangle", "#d62728"),
               "pull-off (grip-work)": ("diamond", "#9467bd"), "pull-off (grip)": ("square", "#8c564b"),
               "chosen state": ("star", "#2b7a3d"), "pull-off at the rate": ("triangle", "#e377c2")}


def scale_of(value: float, table) -> tuple:
    """(scale, unit) of the largest unit of ``table`` not above |value| (the smallest for 0 or non-finite)."""
    for scale, unit in table:
        if math.isfinite(value) and abs(value) >= scale:
            return scale, unit
    return table[-1]


def empty() -> dict:
    """The sources' columns before the first picture."""
    return {"stable": {"xs": [], "ys": []}, "unstable": {"xs": [], "ys": []}, "infeasible": {"xs": [], "ys": []},
            "cycle": {"x": [], "y": []}, "jumps": {"x0": [], "y0": [], "x1": [], "y1": []},
            "points": {"x": [], "y": [], "label": [], "marker": [], "color": [], "unit": []},
            "pressure": {"phi": [], "y": []}, "gap": {"phi": [], "y": []}}


def runs(mask: np.ndarray) -> list:
    """Index slices of the runs where mask holds, each extended by one point so that neighbouring runs meet."""
    out, i, n = [], 0, len(mask)
    while i < n:
        if not mask[i]:
            i += 1
            continue
        j = i
        while j < n and mask[j]:
            j += 1
        out.append(slice(max(i - 1, 0), min(j + 1, n)))
        i = j
    return out


def _lines(branches, kind, x_scale):
    """The segments of every branch of one kind: stable (and feasible), unstable (and feasible), infeasible."""
    xs, ys = [], []
    for b in branches:
        mask = {"stable": b.stable & b.feasible, "unstable": ~b.stable & b.feasible, "infeasible": ~b.feasible}[kind]
        for sl in runs(mask):
            xs.append(b.delta_work[sl] / x_scale)
            ys.append(b.P[sl])
    return {"xs": xs, "ys": ys}


def _rate_peak(po):
    """The largest tension of a pull-off at a rate, as a point with P [N/m] and delta_work [m] (None: none)."""
    if po is None or not po.detached:
        return None
    i = int(np.argmin(po.history.P))
    return types.SimpleNamespace(P=float(po.history.P[i]), delta_work=float(po.history.delta_work[i]))


def _points(picture, x_scale, x_unit):
    marks = [("first contact", picture.first_contact)]
    marks += [(f"pull-off ({k})", picture.pull_offs[k].state if picture.pull_offs[k].detached else None)
              for k in CONTROLS]
    marks += [("chosen state", picture.state), ("pull-off at the rate", _rate_peak(picture.rate_pull_off))]
    cols = {k: [] for k in ("x", "y", "label", "marker", "color", "unit")}
    for label, s in marks:
        if s is None:
            continue
        marker, color = POINT_STYLE[label]
        for k, v in zip(cols, (s.delta_work / x_scale, s.P, label, marker, color, x_unit)):
            cols[k].append(v)
    return cols


def picture_data(picture) -> dict:
    """The columns of every source (numpy arrays: Bokeh sends them to the browser as binary buffers), and the units
    chosen: (approach, pressure, gap)."""
    c = picture.contact
    x_scale, x_unit = scale_of(c.Delta, LENGTHS)
    pressure = np.abs(picture.pressure[np.isfinite(picture.pressure) & (picture.pressure != 0)])
    gap = np.abs(picture.gap[np.isfinite(picture.gap)])
    p_scale, p_unit = scale_of(float(np.median(pressure)) if pressure.size else 0.0, PRESSURES)
    g_scale, g_unit = scale_of(float(np.max(gap)) if gap.size else 0.0, LENGTHS)
    cy = picture.cycle
    jumps = {"x0": [j.before.delta_work / x_scale for j in cy.jumps], "y0": [j.before.P for j in cy.jumps],
             "x1": [j.after.delta_work / x_scale for j in cy.jumps], "y1": [j.after.P for j in cy.jumps]}
    phi = np.degrees(picture.phi)
    data = {kind: _lines(picture.branches, kind, x_scale) for kind in ("stable", "unstable", "infeasible")}
    data.update(cycle={"x": np.asarray(cy.delta_work) / x_scale, "y": np.asarray(cy.P, dtype=float)},
                jumps=jumps, points=_points(picture, x_scale, x_unit),
                pressure={"phi": phi, "y": picture.pressure / p_scale},
                gap={"phi": phi, "y": picture.gap / g_scale}, units=(x_unit, p_unit, g_unit))
    data["curve_range"] = curve_range(data, c.Delta / x_scale, c.load_scale)
    return data


def _padded(values, pad=0.08, fallback=(-1.0, 1.0)):
    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    if v.size == 0 or np.ptp(v) == 0:
        return fallback
    lo, hi = v.min(), v.max()
    return float(lo - pad * (hi - lo)), float(hi + pad * (hi - lo))


def curve_range(data, Delta_scaled: float, load_scale: float) -> tuple:
    """(x0, x1, y0, y1) of the load-approach plot: the cycle and the marked points, padded (the branches run far
    beyond; pan and zoom reach them); without a cycle, the approach from the top of the hole to Delta and the
    load scale."""
    xs = list(data["cycle"]["x"]) + list(data["points"]["x"])
    ys = list(data["cycle"]["y"]) + list(data["points"]["y"])
    x0, x1 = _padded(xs, fallback=(-2.5 * Delta_scaled, Delta_scaled))
    y0, y1 = _padded(ys, fallback=(-load_scale, load_scale))
    return x0, x1, y0, y1


def pressure_range(y) -> tuple:
    """The y range of the pressure plot: the JKR pressure is square-root singular at the edges, so the range is
    set by the bulk of the values (2nd to 98th percentile, widened), not by the points next to an edge."""
    y = np.asarray(y, dtype=float)
    y = y[np.isfinite(y)]
    if y.size == 0:
        return -1.0, 1.0
    lo, hi = np.percentile(y, [2, 98])
    lo, hi = min(lo, 0.0), max(hi, 0.0)
    pad = 0.15 * (hi - lo) or 1.0
    return float(lo - pad), float(hi + pad)


def fmt(x, unit="", digits=6) -> str:
    """x to ``digits`` significant digits with its unit; 'none' for None."""
    if x is None:
        return "none"
    return f"{x + 0.0:.{digits}g}" + (f" {unit}" if unit else "")


def _pull_off_rows(picture):
    rows = []
    for k in CONTROLS:
        po = picture.pull_offs[k]
        if po.detached:
            cells = (f"<span class='jkr-pull-off-{k}'>{fmt(po.P, 'N/m')}</span>", fmt(po.contact_width * 1e3, "mm"),
                     fmt(po.delta_work, "m", 4))
        else:
            cells = (f"<span class='jkr-pull-off-{k}'>none</span>", "", html.escape(po.reason))
        rows.append(f"<tr><td>{k}</td>" + "".join(f"<td>{x}</td>" for x in cells) + "</tr>")
    po = picture.rate_pull_off
    if po is not None:
        unit = "N/m/s" if po.control == "load" else "m/s"
        if po.detached:
            cells = (f"<span class='jkr-pull-off-rate'>{fmt(po.P, 'N/m')}</span>", fmt(po.contact_width * 1e3, "mm"),
                     f"{fmt(po.delta_work, 'm', 4)} ({html.escape(po.kind)})")
        else:
            cells = ("<span class='jkr-pull-off-rate'>none</span>", "", html.escape(po.reason))
        rows.append(f"<tr><td>{po.control} at {fmt(po.rate, unit, 4)}</td>" + "".join(f"<td>{x}</td>" for x in cells)
                    + "</tr>")
    return "".join(rows)


def _state_line(name, s, load_scale):
    if s is None:
        return f"{name}: none (not a single patch at the bottom)"
    P = 0.0 if abs(s.P) < 1e-9 * load_scale else s.P        # the zero-load contact's P is zero to round-off
    return (f"{name}: {s.branch}, P = {fmt(P, 'N/m')}, contact width 2R eps = {fmt(s.contact_width * 1e3, 'mm', 4)}"
            f", delta_work = {fmt(s.delta_work, 'm', 4)}, {'stable' if s.stable else 'unstable'} under "
            f"{s.control}, {'feasible' if s.feasible else 'overclosed'}")


def summary_html(picture) -> str:
    """The regime, the three pull-off forces with their widths and approaches, first contact, the chosen state,
    the cycle's jumps and dissipated energy, and the normalised parameters."""
    c, cy = picture.contact, picture.cycle
    lam = c.lambda_
    law = "JKR" if lam is None else f"Maugis-Dugdale, sigma0 = {fmt(c.sigma0, 'Pa', 4)}, lambda = {fmt(lam, '', 4)}"
    if c.kinetics is not None:
        law = f"JKR with crack kinetics, v* = {fmt(c.kinetics.v_star, 'm/s', 4)}, n = {fmt(c.kinetics.n, '', 4)}"
    jumps = ", ".join(f"{j.kind} at P = {fmt(j.before.P, 'N/m', 5)}" for j in cy.jumps) or "none"
    energy = "n/a (the loop did not close)" if cy.dissipated is None else fmt(cy.dissipated, "J/m", 4)
    return (f"<p><b>Regime</b> (slow pulling under load): <span class='jkr-regime'>{html.escape(picture.regime)}"
            f"</span></p><table><tr><th>control</th><th>pull-off P</th><th>contact width</th>"
            f"<th>delta_work / why none</th></tr>{_pull_off_rows(picture)}</table>"
            f"<p>{html.escape(_state_line('first contact', picture.first_contact, c.load_scale))}<br>"
            f"{html.escape(_state_line('chosen state', picture.state, c.load_scale))}<br>"
            f"cycle ({cy.control} control): jumps: {html.escape(jumps)}; dissipated per cycle: {energy}<br>"
            f"M = {fmt(c.M, '', 4)}, vartheta = {fmt(c.theta, '', 4)}, alpha*/beta* = "
            f"{fmt(c.materials.alpha_ratio, '', 3)}, a_crit = {fmt(c.a_crit, '', 4)}; law: {html.escape(law)}</p>")
