"""The fit's check of the measured loads against the fitted model's pull-off force (JKR law).

Under any control a single-patch state holds no load below the fixed-load pull-off force of the library's path
(jkrcyl.fit.branch.pull_off: Contact.pull_off's path from first contact, walked on the superposition cache and
refined on exact states).  A row more tensile than it by more than BEYOND_SIGMAS standard errors (of the row's
load as the fit models it, jkrcyl.fit.residuals.Problem.load_sd, and of the fitted force) is refused.

Rows beyond the true pull-off drag the fit: it stiffens or raises w until its own pull-off reaches them, and the
rows then sit on the fitted force instead of beyond it.  So the rows at or below the fitted force (within the same
tolerance and their own misfit, and widths below the pull-off's) are also tried against the model fitted to the
other rows (a deletion diagnostic: one descent from the estimate, screened by its linearisation): where leaving
them out lowers the sum of squares significantly (an outlier test at DRAG_LEVEL) and they lie beyond that model's
pull-off, they are refused.  The standard error of a pull-off force comes from the envelope theorem: at a fold of
P in a, dP_fold/du = dP/du at the fold's fixed a (superposed states).
"""
from __future__ import annotations

import math

import numpy as np
from scipy import stats

from . import branch, model

BEYOND_SIGMAS = 3.0      # a load this many standard errors beyond the fitted pull-off is rejected
FD_STEP = 1e-6           # step in the internal coordinates for the envelope gradient
DRAG_LEVEL = 1e-4        # significance at which rows near the pull-off count as dragging the fit


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


def _tolerance(leg, sd):
    return BEYOND_SIGMAS * np.sqrt(leg.se ** 2 + sd ** 2)


def check(problem, spec, u, cov_u, s2, refit, jac=None):
    """ValueError naming the rows beyond the fitted pull-off, or beyond that of the model fitted to the other rows
    where they drag the fit (``refit(keep)``: (problem, spec, u, cov_u, s2) of the fit to the rows of the mask keep,
    or None); returns {w: pull-off force [N/m] or None} of the estimate."""
    d = problem.data
    sd = problem.load_sd(u, s2)
    misfit = np.abs(problem.residuals(u, normalised=False)[:d.n])     # measured minus model load [N/m]
    found = legs(problem, spec, u, cov_u)
    near = np.zeros(d.n, dtype=bool)
    for leg in found:
        if leg.P is None:
            continue
        tol = _tolerance(leg, sd)
        _refuse(d, leg.rows & (d.P < leg.P - tol), leg.P, "of the fitted model")
        near |= leg.rows & (d.P <= leg.P + tol + misfit)
        if d.kind == "width":                  # smaller contacts than at pull-off: off the path under load
            near |= leg.rows & (d.x < leg.width)
    other = refit(~near) if near.any() and _may_drag(problem, spec, u, jac, near) else None
    if other is not None and _dragged(problem, u, other, near):
        p2, s2_spec, u2, cov2, s2b = other
        sd2 = problem.load_sd(spec.to_internal(s2_spec.values(u2)), s2b) if problem.sigma_known else \
            np.full(d.n, math.sqrt(s2b) * p2.nominal)
        for leg in legs(p2, s2_spec, u2, cov2):
            if leg.P is not None:
                _refuse(d, near & _rows_of(spec, s2_spec, leg) & (d.P < leg.P - _tolerance(leg, sd2)), leg.P,
                        "of the model fitted to the other rows (these rows drag the fit: it reaches them only by "
                        "moving its pull-off)")
    return {float(spec.inputs(u).w[np.nonzero(leg.rows)[0][0]]): leg.P for leg in found}


def _threshold(problem, q, dof):
    """The statistic's quantile at DRAG_LEVEL: chi2(q) (errors stated) or F(q, dof) (variance estimated)."""
    return stats.chi2.isf(DRAG_LEVEL, q) if problem.sigma_known else stats.f.isf(DRAG_LEVEL, q, max(dof, 1))


def _may_drag(problem, spec, u, jac, near):
    """A cheap screen of :func:`_dragged`: the drop of the sum of squares on deleting the rows ``near`` from the
    linearised model (r_D^T (I - H_DD)^-1 r_D, H the hat matrix of the Jacobian; exact for a linear model) against
    a quarter of the threshold.  True (refit) without a Jacobian."""
    if jac is None:
        return True
    d = problem.data
    idx = np.nonzero(near)[0] if problem.n_residuals == d.n else np.concatenate([np.nonzero(near)[0],
                                                                                 d.n + np.nonzero(near)[0]])
    r = problem.residuals(u)
    q, dof = idx.size, problem.n_residuals - len(spec.names) - problem.nuisance
    try:
        Q = np.linalg.qr(jac)[0]
        H = Q[idx] @ Q[idx].T
        drop = float(r[idx] @ np.linalg.solve(np.eye(q) - H, r[idx]))
    except np.linalg.LinAlgError:
        return True
    stat = drop if problem.sigma_known else drop / q / max((float(r @ r) - drop) / max(dof - q, 1), 1e-300)
    return stat > _threshold(problem, q, dof - q) / 4


def _dragged(problem, u, other, near):
    """Whether the rows ``near`` are inconsistent with the model fitted to the others: the drop of the sum of
    squares on leaving them out, in units of the error variance (stated, or the refit's residual variance),
    beyond the chi2 (errors stated) or F quantile (estimated) of its degrees of freedom at DRAG_LEVEL."""
    p2, s2_spec, u2, _, s2b = other
    raw = lambda pr, v: float(np.sum(pr.residuals(v) ** 2)) * pr.nominal ** 2
    drop = raw(problem, u) - raw(p2, u2)
    q = problem.n_residuals - p2.n_residuals
    if problem.sigma_known:
        return drop > _threshold(problem, q, 0)
    dof = p2.n_residuals - len(s2_spec.names) - p2.nuisance
    return dof > 0 and drop / q / (s2b * p2.nominal ** 2) > _threshold(problem, q, dof)


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
