"""Least-squares descents of jkrcyl.fit from several starts, and the check that a descent converged.

A descent (scipy.optimize.least_squares, trust-region reflective) can run away: with errors on the width the
normalised residual of P = f Delta p1 - sqrt(f w) p2 tends to a constant as w -> inf (residual and slope both grow
like sqrt(w)), so the sum of squares has a plateau at infinity, and a start in the wrong basin slides onto it
(w = 1e20 J/m^2 at a cost 1e4 times the truth's).  A descent is refused (:func:`failure`) when it did not
converge, left the finite numbers, moved a positive parameter by more than a factor ABSURD from its start, or ended
where the cost no longer depends on a parameter (its column of the Jacobian below FLAT times the largest).
:func:`best` then restarts from the other starts (and from the backups, also where the best descent leaves the
data far outside their stated errors), and raises ValueError naming what ran away when every descent failed.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.optimize import least_squares

from .params import DESCRIPTION, LINEAR

ABSURD = 1e6         # a positive parameter this many times its start (or 1/this) ran away
FLAT = 1e-8          # Jacobian column norm relative to the largest: the data no longer depend on the parameter
MISFIT_SIGMAS = 10   # a sum of squares this many sd of chi2(dof) above dof (errors stated): try the backups too
MAX_NFEV = 2000
WALL = 1e-6          # a windowed parameter this near its edge (internal coordinate) is at the edge


def solve(problem, u0, loss, f_scale):
    """least_squares from u0: (result, scale); with a robust loss and no stated errors the residuals are first
    scaled by a robust estimate of their spread (1.4826 MAD of a linear fit), so f_scale is in units of it."""
    opts = dict(method="trf", x_scale="jac", xtol=1e-12, ftol=1e-12, gtol=1e-12, max_nfev=MAX_NFEV,
                diff_step=problem.diff_step)
    res = least_squares(problem.residuals, u0, loss="linear", **opts)
    scale = 1.0
    if loss != "linear" and res.success:
        if not problem.sigma_known:
            scale = 1.4826 * float(np.median(np.abs(res.fun - np.median(res.fun)))) or 1.0
        res = least_squares(problem.residuals, res.x, loss=loss, f_scale=f_scale * scale, **opts)
    return res, scale


def failure(spec, res, u0, walls=None):
    """Why the descent from u0 ending at res did not converge (a phrase naming the parameter), or None.  walls:
    {index: (lo, hi)} of parameters held in a window (the cohesive sigma0): flat at its edge by design (the fit
    reports an estimate there as a one-sided bound)."""
    if not res.success:
        return f"no convergence within {res.nfev} evaluations ({res.message})"
    if not (np.all(np.isfinite(res.x)) and np.isfinite(res.cost) and np.all(np.isfinite(res.jac))):
        return "the parameters or the residuals left the finite numbers"
    values = spec.values(res.x)
    for j, n in enumerate(spec.names):
        if n not in LINEAR and abs(res.x[j] - u0[j]) > math.log(ABSURD):
            return (f"{n} ran from {spec.values(u0)[n]:.4g} to {values[n]:.4g} {DESCRIPTION[n][0]} (a factor "
                    f"{math.exp(abs(res.x[j] - u0[j])):.3g})")
    norms = np.linalg.norm(res.jac, axis=0)
    walls = walls or {}
    for j, n in enumerate(spec.names):
        lo, hi = walls.get(j, (-math.inf, math.inf))
        if not lo + WALL < res.x[j] < hi - WALL:
            continue
        if norms.max() > 0 and norms[j] <= FLAT * norms.max():
            return f"{n} ran to {values[n]:.4g} {DESCRIPTION[n][0]}, where the data no longer depend on it"
    return None


def _cost(problem, u):
    with np.errstate(all="ignore"):
        r = problem.residuals(u)
    return float(r @ r) if np.all(np.isfinite(r)) else math.inf


def _misfit(problem, spec, res):
    """Errors stated and the sum of squares far above what they allow (chi2 with the residual degrees of freedom)."""
    dof = max(problem.n_residuals - len(spec.names) - problem.nuisance, 1)
    return problem.sigma_known and 2 * res.cost > dof + MISFIT_SIGMAS * math.sqrt(2 * dof)


def best(problem, spec, starts, loss, f_scale, backups=None, every=False, walls=None):
    """The lowest-cost converged descent: (result, scale, start).  Starts are tried best first; a further start
    only where its own cost is below the best descent's so far (every=True: from each start), then the backups
    (a callable giving more starts) where every descent failed or the best misfits the stated errors.  walls(u):
    the windows of :func:`failure` at u."""
    found, failures = None, []

    def run(candidates):
        nonlocal found
        ranked = sorted(((_cost(problem, u), np.asarray(u, dtype=float)) for u in candidates), key=lambda c: c[0])
        for c0, u0 in ranked:
            if not np.isfinite(c0):
                failures.append("the model cannot be evaluated at the start")
                continue
            if found is not None and not every and c0 >= 2 * found[0].cost:
                continue
            res, scale = solve(problem, u0, loss, f_scale)
            why = failure(spec, res, u0, walls(res.x) if walls else None)
            if why:
                failures.append(why)
            elif found is None or res.cost < found[0].cost:
                found = (res, scale, u0)

    run(starts)
    if backups is not None and (found is None or _misfit(problem, spec, found[0])):
        run(backups())
    if found is None:
        raise ValueError(message(failures))
    return found


def message(failures):
    """The ValueError text when no descent converged, naming the parameter that ran away (else the data, P)."""
    why = failures[0] if failures else "no start"
    first = why.split(" ")[0]
    name = first if first in DESCRIPTION else "P"
    return (f"{name}: the fit did not converge: from every start ({len(failures)}) the least-squares descent "
            f"failed ({why}); check the sign of P (positive pushes the pin into the hole) and the units, or give "
            "starting values (w=, Delta=, materials=) near the expected ones")
