"""jkrcyl.fit.fit: least squares (scipy.optimize.least_squares), starting values, identifiability and data checks."""
from __future__ import annotations

import math
import warnings

import numpy as np
from scipy.optimize import least_squares

from .._validate import finite_scalar
from ..materials import Materials
from . import cohesive, model, uncertainty
from .start import start as _start
from .data import validate
from .params import Spec
from .residuals import Problem
from .result import FitResult

LOSSES = ("linear", "soft_l1", "huber")
INTERVALS = ("profile", "wald", None)
SINGULAR = 1e-7          # smallest/largest singular value of the column-scaled Jacobian: not identifiable
BEYOND_SIGMAS = 3.0      # a load this many standard errors beyond the fitted pull-off is rejected
MAX_RESTARTS = 3


def fit(P=None, width=None, delta_work=None, *, R, Delta, materials, free=("w", "E"), w=None, offset=0.0,
        sigma0=None, sigma_P=None, sigma_width=None, sigma_delta_work=None, leg=None, control="load", loss="linear",
        f_scale=1.0, interval="profile", confidence=0.95) -> FitResult:
    """Fit the work of adhesion, the moduli, the clearance (and an approach offset) to measured loads.

    Parameters
    ----------
    P : array_like
        Measured loads per unit length [N/m] (positive pushing the pin into the bottom of the hole, section 6).
    width, delta_work : array_like
        Exactly one: contact widths 2 R eps [m] (0 < width < 2 pi R), or work-conjugate approaches [m].
    R, Delta : float
        Hole radius and clearance R - R_D [m] (Delta is the starting value when fitted).
    materials : jkrcyl.Materials
        The material pair; its moduli are the starting values of fitted moduli (and the ratio kept by 'E').
    free : sequence of str
        Fitted parameters: 'w' (or 'w_loading' and 'w_unloading' with leg=), 'E' (contact modulus E* = 4/beta*,
        both moduli scaled by one factor) or 'E_hole'/'E_pin' (one body's Young's modulus), 'Delta', 'offset'
        (delta_work data: measured = model + offset).
    w, offset : float
        Work of adhesion [J/m^2] (required when not fitted; a starting value otherwise) and approach offset [m].
    sigma0 : float, optional
        Cohesive strength [Pa] > 0 of the Maugis-Dugdale law (jkrcyl.Contact(..., sigma0=)); None: JKR.  With
        'sigma0' in free it is fitted (in log, confined to lambda in [0.01, 30]: jkrcyl.fit.cohesive), started
        here or, when None, at the best of lambda = 0.3, 1, 3, 10.  Width data only.
    sigma_P, sigma_width, sigma_delta_work : float or array_like, optional
        Standard deviations of the measurements (absolute; they weight the fit and fix the scale of the
        intervals).  None of them: unit weights, the scale estimated from the residuals.
    leg : array_like of str, optional
        'loading' or 'unloading' per point.
    control : {'load', 'grip-work'}
        What the experiment held: delta_work points are sought on the part of the sub-critical branch stable
        under it (section 8.3); width data fix each state by themselves (any control), and loads below the
        fitted fixed-load pull-off force are rejected for both kinds.
    loss : {'linear', 'soft_l1', 'huber'}
        least_squares loss; f_scale in units of the normalised residual (of the robust residual scale when
        no error is stated).
    interval : {'profile', 'wald', None}
        Profile likelihood (default), estimate +- z standard errors, or none.
    confidence : float
        Coverage of the intervals, in (0, 1).

    Returns
    -------
    FitResult

    Raises
    ------
    ValueError
        Naming the problem: bad data (NaN rows, widths outside (0, 2 pi R), ...), fewer points than parameters,
        parameters the data cannot separate, loads beyond the fitted pull-off force.
    """
    setup = _setup(R, Delta, materials, w, offset, loss, f_scale, interval, confidence)
    R, Delta, w, offset, f_scale, confidence = setup
    strength = _strength(sigma0)
    data = validate(P, width, delta_work, sigma_P, sigma_width, sigma_delta_work, leg, R=R)
    spec = Spec(free, data, R, Delta, materials, w, offset, strength)
    problem = Problem(data, spec, R, control)
    _check_counts(problem, spec)
    starts = _start(problem, spec)
    for attempt in range(MAX_RESTARTS):
        res, scale = _best(problem, starts if attempt == 0 else [u], loss, f_scale)
        try:
            return _finish(problem, spec, res, scale, loss, f_scale, interval, confidence)
        except uncertainty.BetterOptimum as better:
            u = better.u
    raise ValueError("the fit keeps finding better optima while profiling: the least-squares surface is "
                     "multimodal here; give better starting values (w, Delta, materials)")


def _strength(value):
    """The cohesive sigma0 [Pa]: None (JKR) or finite > 0 (ValueError naming sigma0)."""
    return None if value is None else finite_scalar("sigma0", value, low=0.0, low_open=True)


def _setup(R, Delta, materials, w, offset, loss, f_scale, interval, confidence):
    if not isinstance(materials, Materials):
        raise ValueError(f"materials must be a jkrcyl.Materials, got {type(materials).__name__}")
    c = model.contact(R, Delta, 0.0 if w is None else w, materials)      # validates R, Delta, w
    offset = finite_scalar("offset", offset)
    if loss not in LOSSES:
        raise ValueError(f"loss must be one of {', '.join(LOSSES)}, got {loss!r}")
    if interval not in INTERVALS:
        raise ValueError(f"interval must be 'profile', 'wald' or None, got {interval!r}")
    f_scale = finite_scalar("f_scale", f_scale, low=0.0, low_open=True)
    confidence = finite_scalar("confidence", confidence, low=0.0, high=1.0, low_open=True)
    if confidence == 1.0:
        raise ValueError("confidence must be in (0, 1), got 1")
    return c.R, c.Delta, (None if w is None else c.w), offset, f_scale, confidence


def _check_counts(problem, spec):
    d, p = problem.data, len(spec.names)
    need = p if problem.sigma_known else p + 1
    if d.n < need:
        extra = "" if problem.sigma_known else " (one more than the parameters: no error was stated, so the " \
                                               "residual variance is estimated too)"
        raise ValueError(f"P: {d.n} points for {p} free parameters ({', '.join(spec.names)}): fewer points than "
                         f"needed, at least {need}{extra}")
    distinct = np.unique(np.round(d.x / max(np.abs(d.x).max(), 1e-300), 12)).size
    if distinct < min(p, 2) or (d.kind == "width" and distinct < p):
        raise ValueError(f"{d.kind}: the data hold {distinct} distinct value(s) for {p} free parameters "
                         f"({', '.join(spec.names)}): one contact size (e.g. the pull-off point alone) fixes one "
                         "combination of w and the moduli, not both; measure over a range of contact sizes")


# --- solve and finish -------------------------------------------------------------------------------------
def _solve(problem, u0, loss, f_scale):
    """least_squares from u0; with a robust loss and no stated errors the residuals are first scaled by a robust
    estimate of their spread (1.4826 MAD of a linear fit), so f_scale is in units of it."""
    opts = dict(method="trf", x_scale="jac", xtol=1e-12, ftol=1e-12, gtol=1e-12, max_nfev=2000,
                diff_step=problem.diff_step)
    res = least_squares(problem.residuals, u0, loss="linear", **opts)
    scale = 1.0
    if loss != "linear":
        if not problem.sigma_known:
            scale = 1.4826 * float(np.median(np.abs(res.fun - np.median(res.fun)))) or 1.0
        res = least_squares(problem.residuals, res.x, loss=loss, f_scale=f_scale * scale, **opts)
    if not res.success:
        raise ValueError(f"the least-squares fit did not converge ({res.message}); check the data and the "
                         "starting values")
    return res, scale


def _best(problem, starts, loss, f_scale):
    """The lowest-cost descent of those from the starting points."""
    fits = [_solve(problem, u0, loss, f_scale) for u0 in starts]
    return min(fits, key=lambda rs: rs[0].cost)


def _identifiable(jac, names):
    norms = np.linalg.norm(jac, axis=0)
    if norms.max() == 0:
        raise ValueError(f"{', '.join(names)}: the data do not depend on the free parameters")
    flat = [n for n, v in zip(names, norms) if v <= 1e-12 * norms.max()]
    if flat:
        raise ValueError(f"{flat[0]}: the data do not depend on it (fix it)")
    _, s, vt = np.linalg.svd(jac / norms, full_matrices=False)
    if s[-1] < SINGULAR * s[0]:
        null = vt[-1]
        involved = [n for n, v in zip(names, null) if abs(v) > 0.2]
        raise ValueError(f"{', '.join(involved)}: not separately identifiable from these data (the fit depends only "
                         f"on a combination of them; condition number {s[0] / s[-1]:.3g}); fix one of them")


def _finish(problem, spec, res, scale, loss, f_scale, interval, confidence):
    names, u = spec.names, res.x
    _at_edge(problem, spec, res, scale, loss, f_scale, confidence)
    _identifiable(res.jac, names)
    dof = problem.n_residuals - len(names) - problem.nuisance
    S = 2.0 * res.cost
    s2 = 1.0 if problem.sigma_known else (S / dof if dof > 0 else math.nan)
    if loss != "linear" and not problem.sigma_known:
        s2 = S / dof
    cov, cov_u = uncertainty.covariance(res.jac, u, spec, s2)
    values = spec.values(u)
    se = {n: float(math.sqrt(max(cov[i, i], 0.0))) for i, n in enumerate(names)}
    se_u = np.sqrt(np.maximum(np.diag(cov_u), 0.0))
    notes = []
    if spec.superposes:
        _check_pull_off(problem, spec, u, cov_u, s2)
    else:
        cohesive.check(problem, spec, u, cov_u, s2, BEYOND_SIGMAS)
    intervals, method = {}, "none"
    q = uncertainty.threshold(confidence, dof, problem.sigma_known)
    if interval == "profile":
        prof = uncertainty.Profiler(problem, spec, u, S, s2, q, loss, f_scale * scale, se_u,
                                    cohesive.bounds(problem, spec, u))
        method = f"profile likelihood ({'chi2(1)' if problem.sigma_known else f'F(1, {dof})'} threshold {q:.4g})"
        for j, (lo, hi) in enumerate(prof.intervals()):
            intervals[names[j]] = _to_values(spec, u, j, lo, hi)
    elif interval == "wald":
        z = math.sqrt(q)
        method = f"Wald (estimate +- {z:.4g} standard errors in log coordinates)"
        for j, n in enumerate(names):
            intervals[n] = _to_values(spec, u, j, u[j] - z * se_u[j], u[j] + z * se_u[j])
    for n, (lo, hi) in intervals.items():
        for side, v in (("below", lo), ("above", hi)):
            if v in (0.0, math.inf, -math.inf):
                notes.append(f"the data do not bound {n} {side} at {100 * confidence:g} % (profile stays under "
                             "the threshold): the interval is open there")
    notes += cohesive.window_notes(intervals, confidence)
    corr = uncertainty.correlation(cov)
    for i in range(len(names)):
        for j in range(i + 1, len(names)):
            if abs(corr[i, j]) > 0.99:
                notes.append(f"{names[i]} and {names[j]} are strongly correlated ({corr[i, j]:+.4f}): the data "
                             "determine mainly a combination of them")
    if loss != "linear":
        notes.append(f"robust loss {loss}: intervals treat the robust cost as a log-likelihood (approximate)")
    for t in notes:
        warnings.warn(t, stacklevel=3)
    r = res.fun
    raw, normalised = problem.report(u)
    return FitResult(names=names, values={n: values[n] for n in names}, intervals=intervals, standard_errors=se,
                     covariance=cov, correlation=corr, residuals=raw, normalised_residuals=normalised,
                     cost=(float(r @ r) if loss == "linear" else S) * problem.nominal ** 2, dof=dof,
                     sigma=1.0 if problem.sigma_known else math.sqrt(s2) * problem.nominal, confidence=confidence,
                     interval_method=method, loss=loss, control=problem.control, kind=problem.data.kind,
                     n=problem.data.n, materials=spec.fitted_materials(u), Delta=values["Delta"], R=problem.R,
                     nfev=res.nfev, notes=notes, fixed={k: v for k, v in values.items() if k not in names},
                     _problem=problem, _u=u)


def _at_edge(problem, spec, res, scale, loss, f_scale, confidence):
    """A fitted sigma0 at an edge of its lambda window (jkrcyl.fit.cohesive): ValueError with the one-sided
    profile-likelihood bound."""
    side = cohesive.edge(problem, spec, res.x)
    if side is None:
        return
    j = spec.names.index("sigma0")
    dof = problem.n_residuals - len(spec.names) - problem.nuisance
    S = 2.0 * res.cost
    s2 = 1.0 if problem.sigma_known else S / dof
    q = uncertainty.threshold(2 * confidence - 1, dof, problem.sigma_known)      # one-sided
    se = np.full(res.x.size, 0.1)
    prof = uncertainty.Profiler(problem, spec, res.x, S, s2, q, loss, f_scale * scale, se,
                                cohesive.bounds(problem, spec, res.x))
    t = prof.side(j, -1 if side == "above" else +1)
    bound = math.exp(t) if math.isfinite(t) else (0.0 if side == "above" else math.inf)
    raise ValueError(cohesive.edge_message(side, bound, confidence))


def _to_values(spec, u, j, lo, hi):
    out = []
    for t in (lo, hi):
        v = np.array(u, dtype=float)
        if math.isinf(t):
            out.append(t if spec.names[j] == "offset" else (0.0 if t < 0 else math.inf))
            continue
        v[j] = t
        out.append(spec.values(v)[spec.names[j]])
    return tuple(out)


def _check_pull_off(problem, spec, u, cov_u, s2):
    """Loads more tensile than the fitted fixed-load pull-off (the minimum of P on the sub-critical branch) by more
    than BEYOND_SIGMAS standard errors (of the point and of the fitted pull-off force) cannot be equilibria."""
    d = problem.data
    inp = spec.inputs(u)
    if problem.mode == "load-exact":
        sP = np.zeros(d.n)                                   # the loads were held: exact
    elif d.sigma_P is not None:
        sP = d.sigma_P
    else:                                                    # no error stated on P: the residual scale, if any
        sP = np.full(d.n, 0.0 if problem.sigma_known else math.sqrt(s2) * problem.nominal)
    for wv in np.unique(inp.w):
        sel = inp.w == wv
        fo = model.fold(problem.R, inp.materials, inp.f, inp.Delta, wv, "load")
        if fo is None:
            continue
        grad = np.zeros(u.size)
        for k in range(u.size):
            h = 1e-6
            du = np.array(u, dtype=float)
            du[k] += h
            ik = spec.inputs(du)
            wk = ik.w[np.nonzero(sel)[0][0]]
            fk = model.fold(problem.R, ik.materials, ik.f, ik.Delta, wk, "load")
            grad[k] = 0.0 if fk is None else (fk[1] - fo[1]) / h
        se_fold = math.sqrt(max(float(grad @ cov_u @ grad), 0.0))
        tol = BEYOND_SIGMAS * np.sqrt(se_fold ** 2 + sP[sel] ** 2)
        beyond = d.P[sel] < fo[1] - tol
        if beyond.any():
            rows = np.nonzero(sel)[0][beyond]
            raise ValueError(f"P: row{'s' if rows.size > 1 else ''} {', '.join(str(int(i)) for i in rows[:5])} "
                             f"({d.P[rows[0]]:.6g} N/m) lie beyond the pull-off force {fo[1]:.6g} N/m of the "
                             "fitted model (no stable equilibrium holds such a load; P < 0 pulls); remove "
                             "them or check the units and the sign")
