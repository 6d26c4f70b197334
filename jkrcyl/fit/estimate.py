"""jkrcyl.fit.fit: least squares (scipy.optimize.least_squares), starting values, identifiability and data checks."""
from __future__ import annotations

import math
import warnings

import numpy as np

from .._validate import finite_scalar
from ..materials import Materials
from . import checks, cohesive, descent, model, uncertainty
from .data import Data, validate
from .params import Spec, names as _names
from .residuals import Problem
from .result import FitResult
from .start import backups as _backups, start as _start

LOSSES = ("linear", "soft_l1", "huber")
INTERVALS = ("profile", "wald", None)
SINGULAR = 1e-7          # smallest/largest singular value of the column-scaled Jacobian: not identifiable
BEYOND_SIGMAS = checks.BEYOND_SIGMAS
MAX_RESTARTS = 3


def fit(P=None, width=None, delta_work=None, *, R, Delta, materials, free=("w", "E"), w=None, offset=0.0,
        sigma0=None, law=None, sigma_P=None, sigma_width=None, sigma_delta_work=None, leg=None, control="load", loss="linear",
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
    law : jkrcyl.laws.EdgeLaw, optional
        The edge law (jkrcyl.laws; None: JKR's Griffith); ``laws.Dugdale(s)`` is ``sigma0=s``.  A law of the
        Griffith family (its edge a crack: e.g. a subclass of laws.Griffith) is fitted on the superposed states.
    sigma_P, sigma_width, sigma_delta_work : float or array_like, optional
        Standard deviations of the measurements (absolute; they weight the fit and fix the scale of the
        intervals).  None of them: unit weights, the scale estimated from the residuals.
    leg : array_like of str, optional
        'loading' or 'unloading' per point.
    control : {'load', 'grip-work'}
        What the experiment held: delta_work points are sought on the part of the sub-critical branch the path
        from first contact reaches under it (stable, section 8.3, and feasible); width data fix each state by
        themselves (any control), and loads below the fixed-load pull-off force (Contact.pull_off's path) of the
        fitted model, or of the model fitted to the other rows where they drag the fit, are rejected for both
        kinds (jkrcyl.fit.checks).
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
        parameters the data cannot separate, loads beyond the fitted pull-off force, a descent that did not
        converge from any start (a parameter run off to absurd values, jkrcyl.fit.descent: never returned as an
        estimate), a cohesive fit beyond its work budget or a given sigma0 outside the lambda range the fit
        evaluates the law over (jkrcyl.fit.cohesive).

    Examples
    --------
    >>> import jkrcyl, numpy as np
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> c = jkrcyl.Contact(R=0.01, Delta=3e-6, w=0.05, materials=m)
    >>> width = np.linspace(7e-3, 20e-3, 12)
    >>> res = jkrcyl.fit(P=c.state(np.tan(width / 0.04)).P, width=width, R=0.01, Delta=3e-6, materials=m,
    ...                  free=("w",), sigma_P=1.0, interval=None)
    >>> round(res.values["w"], 6)
    0.05
    """
    setup = _setup(R, Delta, materials, w, offset, loss, f_scale, interval, confidence)
    R, Delta, w, offset, f_scale, confidence = setup
    strength, law = _law(R, Delta, materials, sigma0, law)
    free = _names(free)
    data = validate(P, width, delta_work, sigma_P, sigma_width, sigma_delta_work, leg, R=R)
    spec = Spec(free, data, R, Delta, materials, w, offset, strength, law)
    problem = Problem(data, spec, R, control)
    _check_counts(problem, spec)
    try:
        return _fit(problem, spec, loss, f_scale, interval, confidence)
    except cohesive.OverBudget as over:
        raise ValueError(over.message()) from None


def _fit(problem, spec, loss, f_scale, interval, confidence):
    """Descents from the starts, restarted where the profile finds a better optimum; the result."""
    starts = _start(problem, spec)
    more = lambda: _backups(problem, spec)
    u = None
    for attempt in range(MAX_RESTARTS):
        res, scale, _ = descent.best(problem, spec, starts if attempt == 0 else [u], loss, f_scale, more,
                                     walls=lambda x: cohesive.bounds(problem, spec, x))
        try:
            return _finish(problem, spec, res, scale, loss, f_scale, interval, confidence)
        except uncertainty.BetterOptimum as better:
            u = better.u
    raise ValueError("w: the fit keeps finding better optima while profiling: the least-squares surface is "
                     "multimodal here; give better starting values (w, Delta, materials)")


def _law(R, Delta, materials, sigma0, law):
    """(sigma0, law): the cohesive strength of the Maugis-Dugdale path (None: the superposed path) and the law of the
    superposed path (None: JKR), resolved once as jkrcyl.Contact resolves them (sigma0 is laws.Dugdale's shorthand)."""
    resolved = model.contact(R, Delta, 1.0, materials, _strength(sigma0), law)     # law: an EdgeLaw, given once
    arguments = resolved.law.arguments()
    return _strength(arguments.get("sigma0")), arguments.get("law")


def _strength(value):
    """The cohesive sigma0 [Pa]: None (JKR) or finite > 0 (ValueError naming sigma0)."""
    return None if value is None else finite_scalar("sigma0", value, low=0.0, low_open=True)


def _setup(R, Delta, materials, w, offset, loss, f_scale, interval, confidence):
    if not isinstance(materials, Materials):
        raise ValueError(f"materials must be a jkrcyl.Materials, got {type(materials).__name__}")
    c = model.contact(R, Delta, 0.0 if w is None else w, materials)      # validates R, Delta, w
    if c.Delta == 0:
        raise ValueError("Delta must be > 0 in a fit (got 0: a neat fit, section 7.3, has no normalised adhesion M "
                         "and no pull-off path in the model); give the clearance R - R_D, or a start when fitted")
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


# --- finish ------------------------------------------------------------------------------------------------
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
        pull_offs = checks.check(problem, spec, u, cov_u, s2, lambda keep: _refit(problem, spec, u, keep, loss,
                                                                                    f_scale), res.jac)
    else:
        pull_offs = cohesive.check(problem, spec, u, cov_u, s2, BEYOND_SIGMAS)
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
                     nfev=res.nfev, notes=notes, law=spec.law, fixed={k: v for k, v in values.items() if k not in names},
                     pull_off=pull_offs, _problem=problem, _u=u)


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


def _refit(problem, spec, u, keep, loss, f_scale):
    """(problem, spec, u, cov_u, s2, jac) of the fit to the rows of the mask keep, descending from u; None where too
    few rows remain or the descent fails (the deletion diagnostic of jkrcyl.fit.checks)."""
    d = problem.data
    pick = lambda v: None if v is None else v[keep]
    sub = Data(P=d.P[keep], x=d.x[keep], kind=d.kind, sigma_P=pick(d.sigma_P), sigma_x=pick(d.sigma_x),
               unloading=pick(d.unloading))
    v = spec.values(u)
    try:
        other = Spec(spec.names, sub, spec.R, v["Delta"], spec.materials0, v["w"], v["offset"], v["sigma0"])
        p2 = Problem(sub, other, problem.R, problem.control)
        _check_counts(p2, other)
        res, _, _ = descent.best(p2, other, [other.to_internal(v)], loss, f_scale)
    except ValueError:
        return None
    dof = p2.n_residuals - len(other.names) - p2.nuisance
    s2 = 1.0 if p2.sigma_known else (2 * res.cost / dof if dof > 0 else math.nan)
    try:
        _, cov_u = uncertainty.covariance(res.jac, res.x, other, s2)
    except np.linalg.LinAlgError:
        return None
    return p2, other, res.x, cov_u, s2, res.jac
