"""The fit's check of the measured loads against the fitted model's pull-off force (JKR law).

Under any control a single-patch state holds no load below the fixed-load pull-off force of the library's path
(jkrcyl.fit.branch.pull_off: Contact.pull_off's path from first contact, walked on the superposition cache and
refined on exact states).  A row more tensile than it by more than BEYOND_SIGMAS standard errors (of the row's
load as the fit models it, jkrcyl.fit.residuals.Problem.load_sd, and of the fitted force) is refused.

Rows beyond the true pull-off drag the fit: it stiffens or raises w until its own pull-off reaches them, and the
rows then sit on the fitted force instead of beyond it.  So the rows at or below the fitted force (within the same
tolerance and their own misfit, and widths below the pull-off's) are also tried against the model fitted to the
other rows (a deletion diagnostic in a forward search: the most outlying of them, by the linearised deletion, left
out and refitted from the estimate, while that lowers the sum of squares significantly, an outlier test at
DRAG_LEVEL); those beyond the last model's pull-off by DRAG_SIGMAS standard errors are refused.  The standard
error of a pull-off force comes from the envelope theorem: at a fold of P in a, dP_fold/du = dP/du at the fold's
fixed a (superposed states).
"""
from __future__ import annotations

import math

import numpy as np
from scipy import stats

from . import branch, model

BEYOND_SIGMAS = 3.0      # a load this many standard errors beyond the fitted pull-off is rejected
FD_STEP = 1e-6           # step in the internal coordinates for the envelope gradient
DRAG_LEVEL = 1e-6        # significance at which rows near the pull-off count as dragging the fit (small: near a
#                          fold the effective variance of a width error is second order and its residual skewed)
DRAG_SIGMAS = 5.0        # ... and the standard errors they must then lie beyond the refit's pull-off (extrapolated)
ROUNDS = 4               # rounds of the forward search (rows left out in groups, most outlying first)


class Leg:
    """The fitted pull-off of the rows of one work of adhesion: P [N/m] (None: no detachment), its standard error
    [N/m], the contact there (a, width [m]) and the rows (a mask)."""

    def __init__(self, rows, P, se, a, width):
        self.rows, self.P, self.se, self.a, self.width = rows, P, se, a, width


def legs(problem, spec, u, cov_u):
    """The pull-off of each leg at u (jkrcyl.fit.branch.pull_off), with its standard error from cov_u."""
    inp = spec.inputs(u)
    out = []
    for wv in np.unique(inp.w):
        rows = inp.w == wv
        po = branch.pull_off(inp.contact(problem.R, wv), inp.materials)
        se = 0.0 if po.P is None else _standard_error(problem, spec, u, cov_u, rows, po.a, po.P)
        out.append(Leg(rows, po.P, se, po.a, po.width))
    return out


def _standard_error(problem, spec, u, cov_u, rows, a, P):
    """sqrt(g C g) with g = dP/du at the fixed contact parameter a of the fold (envelope theorem)."""
    i = int(np.nonzero(rows)[0][0])
    grad = np.zeros(u.size)
    for k in range(u.size):
        du = np.array(u, dtype=float)
        du[k] += FD_STEP
        ik = spec.inputs(du)
        grad[k] = (model.states(ik.contact(problem.R, ik.w[i]), ik.materials, [a]).P[0] - P) / FD_STEP
    return math.sqrt(max(float(grad @ cov_u @ grad), 0.0))


def _tolerance(leg, sd, sigmas=BEYOND_SIGMAS):
    return sigmas * np.sqrt(leg.se ** 2 + sd ** 2)


class Fit:
    """One fitted problem as the checks read it: problem, spec, estimate u, its covariance, variance scale s2, the
    Jacobian of its normalised residuals, and the rows of the full data set it holds (indices)."""

    def __init__(self, problem, spec, u, cov_u, s2, jac, rows):
        self.problem, self.spec, self.u, self.cov_u, self.s2, self.jac = problem, spec, u, cov_u, s2, jac
        self.rows = rows

    def raw_cost(self):
        """Sum of squared residuals in the unit of the stated errors (or of the data when none is stated)."""
        return float(np.sum(self.problem.residuals(self.u) ** 2)) * self.problem.nominal ** 2


def check(problem, spec, u, cov_u, s2, refit, jac=None):
    """ValueError naming the rows beyond the fitted pull-off, or beyond that of the model fitted to the other rows
    where they drag the fit (``refit(keep)``: (problem, spec, u, cov_u, s2, jac) of the fit to the rows of the mask
    keep, or None); returns {w: pull-off force [N/m] or None} of the estimate."""
    d = problem.data
    fit = Fit(problem, spec, u, cov_u, s2, jac, np.arange(d.n))
    found = legs(problem, spec, u, cov_u)
    near = _near(fit, found, refuse=True)
    left_out = np.zeros(d.n, dtype=bool)
    for _ in range(ROUNDS):                      # a forward search: leave out the most outlying near rows ...
        sub = _most_outlying(fit, near) if near.any() else None
        if sub is None:
            break
        keep = ~left_out
        keep[fit.rows[sub]] = False
        other = refit(keep)
        if other is None:
            break
        other = Fit(*other, np.nonzero(keep)[0])
        if not _dragged(fit, other):             # ... while leaving them out lowers the cost significantly
            break
        left_out, fit = ~keep, other
        near = _near(fit, legs(fit.problem, fit.spec, fit.u, fit.cov_u), refuse=False)
    if left_out.any():
        sd = problem.load_sd(spec.to_internal(fit.spec.values(fit.u)), fit.s2) if problem.sigma_known else \
            np.full(d.n, math.sqrt(fit.s2) * fit.problem.nominal)
        for leg in legs(fit.problem, fit.spec, fit.u, fit.cov_u):
            if leg.P is not None:
                beyond = d.P < leg.P - _tolerance(leg, sd, DRAG_SIGMAS)
                _refuse(d, left_out & _rows_of(spec, fit.spec, leg) & beyond, leg.P,
                        "of the model fitted to the other rows (these rows drag the fit: it reaches them only by "
                        "moving its pull-off)")
    return {float(spec.inputs(u).w[np.nonzero(leg.rows)[0][0]]): leg.P for leg in found}


def _near(fit, found, refuse):
    """Rows of a fit (a mask over its own rows) at or below its pull-off within the tolerance and their own
    misfit, or (width data) smaller than the pull-off's contact; refuse=True: ValueError for rows beyond it."""
    pr, d = fit.problem, fit.problem.data
    sd = pr.load_sd(fit.u, fit.s2)
    misfit = np.abs(pr.residuals(fit.u, normalised=False)[:d.n])     # measured minus model load [N/m]
    near = np.zeros(d.n, dtype=bool)
    for leg in found:
        if leg.P is None:
            continue
        tol = _tolerance(leg, sd)
        if refuse:
            _refuse(d, leg.rows & (d.P < leg.P - tol), leg.P, "of the fitted model")
        near |= leg.rows & (d.P <= leg.P + tol + misfit)
        if d.kind == "width":                  # smaller contacts than at pull-off: off the path under load
            near |= leg.rows & (d.x < leg.width)
    return near


def _threshold(problem, q, dof):
    """The statistic's quantile at DRAG_LEVEL: chi2(q) (errors stated) or F(q, dof) (variance estimated)."""
    return stats.chi2.isf(DRAG_LEVEL, q) if problem.sigma_known else stats.f.isf(DRAG_LEVEL, q, max(dof, 1))


def _residual_index(problem, mask):
    rows = np.nonzero(mask)[0]
    return rows if problem.n_residuals == problem.data.n else np.concatenate([rows, problem.data.n + rows])


def _most_outlying(fit, near):
    """The rows to leave out (a mask over the fit's rows): of the nested sets of the ``near`` rows taken most
    tensile first, the one whose deletion from the linearised model (drop of the sum of squares
    r_D^T (I - H_DD)^-1 r_D, H the hat matrix of the Jacobian; exact for a linear model) is the most significant;
    None where even that one stays above DRAG_LEVEL at four times its drop (no refit).  All of them without a
    Jacobian."""
    pr, d = fit.problem, fit.problem.data
    if fit.jac is None:
        return near
    r = pr.residuals(fit.u)
    dof = pr.n_residuals - len(fit.spec.names) - pr.nuisance
    Q = np.linalg.qr(fit.jac)[0]
    best, mask = (math.inf, None), np.zeros(d.n, dtype=bool)
    for i in np.nonzero(near)[0][np.argsort(d.P[near], kind="stable")]:
        mask[i] = True
        idx = _residual_index(pr, mask)
        q = idx.size
        if q >= dof:
            break
        try:
            drop = float(r[idx] @ np.linalg.solve(np.eye(q) - Q[idx] @ Q[idx].T, r[idx]))
        except np.linalg.LinAlgError:
            continue
        if pr.sigma_known:
            level = stats.chi2.sf(4 * drop, q)
        else:
            level = stats.f.sf(4 * drop / q / max((float(r @ r) - drop) / (dof - q), 1e-300), q, dof - q)
        if level < best[0]:
            best = (level, mask.copy())
    return best[1] if best[0] < DRAG_LEVEL else None


def _dragged(fit, other):
    """Whether the rows the fit ``other`` leaves out of ``fit`` are inconsistent with the model fitted to the
    others: the drop of the sum of squares, in units of the error variance (stated, or the refit's residual
    variance), beyond the chi2 (errors stated) or F quantile (estimated) of its degrees of freedom at DRAG_LEVEL."""
    drop = fit.raw_cost() - other.raw_cost()
    q = fit.problem.n_residuals - other.problem.n_residuals
    if fit.problem.sigma_known:
        return drop > _threshold(fit.problem, q, 0)
    dof = other.problem.n_residuals - len(other.spec.names) - other.problem.nuisance
    return dof > 0 and drop / q / (other.s2 * other.problem.nominal ** 2) > _threshold(fit.problem, q, dof)


def _rows_of(spec, other_spec, leg):
    """Rows of the full data set on a leg of the refit (one work of adhesion for all, or per loading leg)."""
    sub = other_spec.data.unloading
    if leg.rows.all() or sub is None:
        return np.ones(spec.data.n, dtype=bool)
    return spec.data.unloading == sub[np.nonzero(leg.rows)[0][0]]


def _refuse(data, beyond, P_pull, whose):
    if not beyond.any():
        return
    rows = np.nonzero(beyond)[0]
    raise ValueError(f"P: row{'s' if rows.size > 1 else ''} {', '.join(str(int(i)) for i in rows[:5])}"
                     f"{', ...' if rows.size > 5 else ''} ({data.P[rows[0]]:.6g} N/m) lie beyond the pull-off force "
                     f"{P_pull:.6g} N/m {whose} (no stable equilibrium holds such a load; P < 0 pulls); remove "
                     "them or check the units and the sign")
