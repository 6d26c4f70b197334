"""Starting values of jkrcyl.fit: a linear least-squares start for width data, a grid scan for delta_work data."""
from __future__ import annotations

import math

import numpy as np

from . import cohesive, model


def start(problem, spec):
    """Internal coordinates to begin the least-squares descent from: a list (best first) of one (several for the
    cohesive law: jkrcyl.fit.cohesive.start; the best points of the scan for delta_work data)."""
    values = dict(spec.fixed)
    if problem.data.kind == "width":
        values.update(_linear_start(problem, spec))
        if not spec.superposes:              # each evaluation is a set of direct states: no grid
            values["sigma0"] = values["sigma0"] or 1.0     # placeholder, set by jkrcyl.fit.cohesive.start
            return cohesive.start(problem, spec, spec.to_internal(values))
        return [_grid_refine(problem, spec, spec.to_internal(values))]
    return scan(problem, spec)


def backups(problem, spec):
    """Further starts where the descents from :func:`start` diverged or stopped far above them: the best points
    of :func:`scan` (JKR width data; the cohesive law and delta_work data start from several points already)."""
    if problem.data.kind != "width" or not spec.superposes:
        return []
    return scan(problem, spec)


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
    """w [J/m^2] giving the normalised adhesion M (section 6) at the starting pair (moduli times f) and clearance:
    M is proportional to sqrt(w)."""
    ref = model.contact(spec.R, spec.fixed["Delta"], 1.0, model.scaled(spec.materials0, f), law=spec.law)
    return (M / ref.M) ** 2


def _linear_start(problem, spec):
    """Width data: P = x1 c1 + x2 c2 is linear in x1 = f Delta/Delta_0 and x2 = sqrt(f w) (per leg;
    jkrcyl.fit.model.linear_columns): least squares weighted by the effective variance of each point (the fit's own,
    jkrcyl.fit.residuals, re-evaluated at the previous solution: an error on the width weighs points by their slope,
    which unweighted would let the steep points near the pole decide), then mapped to the free parameters."""
    d, names = problem.data, set(spec.names)
    Delta = spec.fixed["Delta"]
    (c1, c2), slopes, curvatures = model.linear_columns(problem.R, Delta, spec.materials0, problem.a)
    split = {"w_loading", "w_unloading"} <= names
    legs = [~d.unloading, d.unloading] if split else [np.ones(d.n, bool)]
    columns = lambda cols: np.array([cols[0]] + [cols[1] * sel for sel in legs]).T
    X, X1, X2 = columns((c1, c2)), columns(slopes), columns(curvatures)
    coef = _weighted_lstsq(X, d.P, np.ones(d.n) if d.sigma_P is None else d.sigma_P)
    if d.sigma_x is not None:                 # iteratively reweighted: the effective variance at the last solution
        dadx = (1 + problem.a ** 2) / (4 * problem.R)
        for _ in range(REWEIGHTS):
            var = (X1 @ coef * dadx * d.sigma_x) ** 2 + 0.5 * (X2 @ coef * dadx ** 2 * d.sigma_x ** 2) ** 2
            var = var + (0.0 if d.sigma_P is None else d.sigma_P ** 2)
            new = _weighted_lstsq(X, d.P, np.sqrt(np.maximum(var, 1e-30 * var.max())))
            done = np.allclose(new, coef, rtol=1e-8, atol=0)
            coef = new
            if done:
                break
    x1, gs = coef[0], coef[1:]
    out = {}
    f = 1.0
    w_fixed = spec.fixed.get("w")
    if x1 > 0 and np.all(gs > 0):
        if names & {"E", "E_hole", "E_pin"}:
            f = x1 if "Delta" not in names else (gs[0] ** 2 / w_fixed if w_fixed else 1.0)
        if "Delta" in names:
            Delta = Delta * x1 / f
        ws = model.amplitude_w(gs, f)
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


REWEIGHTS = 20      # passes of the effective-variance reweighting (they converge in a few)


def _weighted_lstsq(X, y, sd):
    return np.linalg.lstsq(X / sd[:, None], y / sd, rcond=None)[0]


def _moduli(spec, names, f):
    """The free moduli at the factor f on the starting ones: 'E' (contact modulus E*), 'E_hole', 'E_pin'."""
    out = {"E": f * spec.E_star0} if "E" in names else {}
    out.update({f"E_{b}": f * spec.fixed[f"E_{b}"] for b in ("hole", "pin") if f"E_{b}" in names})
    return out


SCAN_M = np.geomspace(1e-3, 3.0, 16)     # normalised adhesions of the scan
SCAN_FACTORS = (0.25, 0.5, 1.0, 2.0, 4.0)  # modulus factors of the scan (free moduli)
SCAN_KEEP = 3                             # starts kept from the scan: the best, each from another w or factor


def scan(problem, spec):
    """The best SCAN_KEEP points of a grid in w (normalised adhesion M from 1e-3 to 3) and the modulus factor,
    the offset at each taken as the median misfit of the approach (ValueError where none can be evaluated)."""
    names = set(spec.names)
    factors = SCAN_FACTORS if names & {"E", "E_hole", "E_pin"} else (1.0,)
    found = []
    for f in factors:
        for M in SCAN_M:
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
            if np.all(np.isfinite(r)):
                found.append((float(r @ r), u))
    if not found:
        raise ValueError("the model cannot be evaluated at any starting value: check R, Delta and the materials")
    return [u for _, u in sorted(found, key=lambda cu: cu[0])[:SCAN_KEEP]]


def _offset_guess(problem, spec, vals):
    """Median approach misfit with each point's state taken at its measured load (delta_work ignored)."""
    saved = problem.sigma_x
    problem.sigma_x = saved * 1e12
    try:
        r = problem.residuals(spec.to_internal(vals), normalised=False)[problem.data.n:]
    finally:
        problem.sigma_x = saved
    return float(np.median(r))
