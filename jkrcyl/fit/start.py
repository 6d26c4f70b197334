"""Starting values of jkrcyl.fit: a linear least-squares start for width data, a grid scan for delta_work data."""
from __future__ import annotations

import math

import numpy as np

from . import cohesive, model


def start(problem, spec):
    """Internal coordinates to begin the least-squares descent from: a list of one (several for the cohesive law:
    jkrcyl.fit.cohesive.start)."""
    values = dict(spec.fixed)
    if problem.data.kind == "width":
        values.update(_linear_start(problem, spec))
        if not spec.superposes:              # each evaluation is a set of direct states: no grid
            values["sigma0"] = values["sigma0"] or 1.0     # placeholder, set by jkrcyl.fit.cohesive.start
            return cohesive.start(problem, spec, spec.to_internal(values))
        return [_grid_refine(problem, spec, spec.to_internal(values))]
    values.update(_scan_start(problem, spec))
    return [spec.to_internal(values)]


REFINE = np.linspace(-0.6, 0.6, 13)     # log-offsets of the starting grid around the linear start (x 0.55 .. 1.8)


def _grid_refine(problem, spec, u0):
    """The best point of a small grid around the linear start (the first two parameters): the linear start ignores
    the errors on the width, and near the pull-off, where dP/dwidth = 0, the effective variance makes the sum of
    squares non-convex (a far local minimum exists), so the descent must begin in the right basin.  Skipped when
    E_hole or E_pin is free (each evaluation would be a new set of states)."""
    if {"E_hole", "E_pin"} & set(spec.names):
        return u0
    axes = [REFINE if j < 2 and spec.names[j] not in ("offset",) else np.zeros(1) for j in range(u0.size)]
    best, best_cost = u0, math.inf
    for shift in np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, u0.size):
        with np.errstate(all="ignore"):
            r = problem.residuals(u0 + shift)
        cost = float(r @ r)
        if np.isfinite(cost) and cost < best_cost:
            best, best_cost = u0 + shift, cost
    return best


def _w_of_M(spec, M, f=1.0):
    """w [J/m^2] giving the normalised adhesion M (section 6) at the starting pair and clearance."""
    m = spec.materials0
    A = m.beta / f / (2 * math.pi)
    th = 1.0 if math.isinf(m.theta) else m.theta
    return 2 * (M * spec.fixed["Delta"] * th) ** 2 / (A * spec.R) if spec.fixed["Delta"] > 0 else 1e-3


def _linear_start(problem, spec):
    """Width data: P = c1 p1 - g p2 is linear in c1 = f Delta and g = sqrt(f w) (per leg): weighted linear least
    squares, then mapped to the free parameters."""
    d, names = problem.data, set(spec.names)
    p = model.parts(problem.R, spec.materials0, problem.a)
    split = {"w_loading", "w_unloading"} <= names
    legs = [~d.unloading, d.unloading] if split else [np.ones(d.n, bool)]
    cols = [p.p1] + [-p.p2 * sel for sel in legs]
    wgt = np.ones(d.n) if d.sigma_P is None else 1 / d.sigma_P
    coef = np.linalg.lstsq(np.array(cols).T * wgt[:, None], d.P * wgt, rcond=None)[0]
    c1, gs = coef[0], coef[1:]
    out = {}
    f, Delta = 1.0, spec.fixed["Delta"]
    w_fixed = spec.fixed.get("w")
    if c1 > 0 and np.all(gs > 0):
        if names & {"E", "E_hole", "E_pin"}:
            f = c1 / Delta if "Delta" not in names else (gs[0] ** 2 / w_fixed if w_fixed else 1.0)
        if "Delta" in names:
            Delta = c1 / f
        ws = gs ** 2 / f
    else:
        ws = np.full(len(legs), _w_of_M(spec, 0.3))
    out.update(_moduli(spec, names, f))
    if "Delta" in names:
        out["Delta"] = Delta
    if "w" in names:
        out["w"] = float(np.mean(ws))
    if "w_loading" in names:
        out["w_loading"], out["w_unloading"] = (float(ws[0]), float(ws[-1]))
    return out


def _moduli(spec, names, f):
    """The free moduli at the factor f on the starting ones: 'E' (contact modulus E*), 'E_hole', 'E_pin'."""
    out = {"E": f * spec.E_star0} if "E" in names else {}
    out.update({f"E_{b}": f * spec.fixed[f"E_{b}"] for b in ("hole", "pin") if f"E_{b}" in names})
    return out


def _scan_start(problem, spec):
    """delta_work data: the best of a grid in w (normalised adhesion M from 1e-3 to 3) and the modulus factor,
    the offset at each taken as the median misfit of the approach."""
    names = set(spec.names)
    factors = (0.25, 0.5, 1.0, 2.0, 4.0) if names & {"E", "E_hole", "E_pin"} else (1.0,)
    best, best_cost = None, math.inf
    for f in factors:
        for M in np.geomspace(1e-3, 3.0, 16):
            wv = _w_of_M(spec, M, f)
            vals = dict(spec.fixed)
            vals.update({"w": wv, "w_loading": wv, "w_unloading": wv})
            vals.update(_moduli(spec, names, f))
            if "offset" in names:
                vals["offset"] = 0.0
                vals["offset"] = _offset_guess(problem, spec, vals)
            u = spec.to_internal(vals)
            with np.errstate(all="ignore"):
                r = problem.residuals(u)
            cost = float(r @ r) if np.all(np.isfinite(r)) else math.inf
            if cost < best_cost:
                best, best_cost = {k: vals[k] for k in spec.names}, cost
    if best is None:
        raise ValueError("the model cannot be evaluated at any starting value: check R, Delta and the materials")
    return best


def _offset_guess(problem, spec, vals):
    """Median approach misfit with each point's state taken at its measured load (delta_work ignored)."""
    saved = problem.sigma_x
    problem.sigma_x = saved * 1e12
    try:
        r = problem.residuals(spec.to_internal(vals), normalised=False)[problem.data.n:]
    finally:
        problem.sigma_x = saved
    return float(np.median(r))
