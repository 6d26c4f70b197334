"""The cohesive (Maugis-Dugdale) law in jkrcyl.fit: direct states, the lambda window, starts and checks.

The superposition surrogate of jkrcyl.fit.model holds for JKR only: with a cohesive zone the state at a fixed
contact is nonlinear in w and Delta (the zone end solves h(c) = h0 = w/sigma0).  So every evaluation asks the
library for the states at the measured contact half-angles eps = width/(2R): ``Contact(R, Delta, w, materials,
sigma0).at_contact(eps)`` (the state of the contact branch joined to the touch, ~1e-10; ~10-40 ms for 50 points
at lambda ~ 1, ~0.1 s at lambda = 10, ~0.3-1 s at lambda = 20).  Parameters the solver refuses (a zone too thin
to resolve) give NaN residuals: least_squares' trust region steps back from them.  A width picks one state of
that branch below the branch's first turn in eps; :func:`check` verifies it on the traced branch
(``Contact.curve``) at the estimate.

Identifiability.  As lambda -> inf the law tends to JKR (states to C/lambda^2, C ~ 3.7 for the README pin) and
the data stop determining sigma0; as lambda -> 0 the zone dominates and w and sigma0 trade off.  A fitted sigma0
is therefore confined to the window LAMBDA_MIN <= lambda <= LAMBDA_MAX (evaluated at the current w and moduli;
outside it the model holds the window's edge, so the fit sees a plateau): an estimate at an edge is reported as
a one-sided bound by profile likelihood (ValueError naming sigma0: the data do not determine it), an interval
reaching an edge is open there (+inf above, 0 below) with a note.
"""
from __future__ import annotations

import math

import numpy as np

from . import model

LAMBDA_MIN = 0.01      # Baney-Hui's tested range starts here (tests/test_cohesive_api.py)
LAMBDA_MAX = 20.0      # the law is JKR's to ~C/lambda^2 ~ 1 % here (C ~ 3.7); a state costs ~5 ms, more beyond
FIXED_MAX = math.inf   # a given, fixed sigma0 is used as it is from LAMBDA_MIN up to what the library resolves (its
#                        own ValueError beyond); below, ValueError naming sigma0 (and a wall mid-fit)
START_LAMBDAS = (0.1, 0.3, 1.0, 3.0)     # starting values of a fitted sigma0 without one given
WIDTH_STEP = 1e-4      # relative step of the central differences dP/dwidth (states to ~1e-10)
TURN_POINTS = 64       # states of the traced branch searched for its first turn in eps (check)


def window(R, Delta, w, materials):
    """(sigma0 at LAMBDA_MIN, at LAMBDA_MAX) [Pa] for this contact (lambda is proportional to sigma0)."""
    return tuple(model.contact_with_lambda(R, Delta, w, materials, lam).sigma0 for lam in (LAMBDA_MIN, LAMBDA_MAX))


def transition(R, Delta, w, materials, strength):
    """lambda of the law (Contact.lambda_)."""
    return model.contact(R, Delta, w, materials, strength).lambda_


class Budget:
    """The work one cohesive fit may do, counted in states weighted by their cost at lambda (a state costs ~0.25 ms
    at lambda <= 1, ~5 times that from lambda ~ 8 on): max(BUDGET, PER_POINT n) units for n points.  Past it,
    :class:`OverBudget` (jkrcyl.fit.fit turns it into a ValueError naming sigma0)."""

    def __init__(self, points):
        self.units = max(BUDGET, PER_POINT * points)
        self.left, self.lam = self.units, None

    def spend(self, lam, states):
        self.lam = lam
        self.left -= states * (1 + min(lam, 8.0) / 2)
        if self.left < 0:
            raise OverBudget(lam, self.units)


BUDGET = 100_000       # fits with profile intervals spend 900-1100 units per point (lambda ~ 1, or sigma0 at the JKR
PER_POINT = 6_000      # edge: tests/test_fit_cohesive.py, the README's): about half a minute for 30 points


class OverBudget(Exception):
    """A cohesive fit ran out of :class:`Budget` (not a ValueError: the residuals turn those into NaN walls)."""

    def __init__(self, lam, units):
        super().__init__(lam)
        self.lam, self.units = lam, units

    def message(self):
        return (f"sigma0: the cohesive fit needs more than {self.units:.0f} state evaluations here (weighted by their "
                f"cost; the last at lambda = {self.lam:.3g}, where the law is near JKR's and each state is costly): "
                "the data barely determine sigma0; fit the JKR law (sigma0=None), fix sigma0, or ask for "
                "interval='wald' or None")


def loads(R, Delta, w, materials, strength, width, slopes=False, clip=False, budget=None):
    """P [N/m] at the contact widths [m] (with clip, a fitted strength, held in the lambda window), and with slopes
    dP/dwidth, d2P/dwidth2 by central differences (relative step WIDTH_STEP); the states are charged to budget."""
    width = np.asarray(width, dtype=float)
    try:
        lo, hi = window(R, Delta, w, materials) if clip else (0.0, math.inf)
        c = model.contact(R, Delta, w, materials, min(max(strength, lo), hi))
        lam = c.lambda_                       # the fit evaluates the law over [LAMBDA_MIN, FIXED_MAX] only
        if not LAMBDA_MIN <= lam <= FIXED_MAX:
            raise ValueError(f"lambda = {lam:.4g} outside [{LAMBDA_MIN:g}, {FIXED_MAX:g}]")
        if budget is not None:
            budget.spend(lam, width.size * (3 if slopes else 1))
        P = c.at_contact(width / (2 * R)).P
        if not slopes:
            return P, None, None
        h = WIDTH_STEP * width
        up, down = (c.at_contact((width + s * h) / (2 * R)).P for s in (1, -1))
    except ValueError:           # parameters the solver refuses (a zone too thin to resolve, Delta >= R): a wall
        nan = np.full(width.shape, np.nan)
        return nan, (nan if slopes else None), (nan if slopes else None)
    return P, (up - down) / (2 * h), (up - 2 * P + down) / (h * h)


def model_loads(R, inp, width, slopes=False, clip=False, budget=None):
    """P (and slopes) at the widths for the model inputs of jkrcyl.fit.params.Inputs (w per point); clip: a fitted
    sigma0, held in the lambda window; budget: the fit's :class:`Budget`."""
    mat = _scaled(inp)
    P, P1, P2 = (np.empty(np.size(width)) for _ in range(3))
    for wv in np.unique(inp.w):
        sel = inp.w == wv
        out = loads(R, inp.Delta, float(wv), mat, inp.strength, np.asarray(width)[sel], slopes, clip, budget)
        for arr, val in zip((P, P1, P2), out):
            arr[sel] = np.nan if val is None else val
    return P, (P1 if slopes else None), (P2 if slopes else None)


def _scaled(inp):
    return inp.pair


# --- the window in internal coordinates, starts --------------------------------------------------------------
def bounds(problem, spec, u):
    """{index of 'sigma0': (lo, hi)} of its internal coordinate (log sigma0) at the window's edges, at u."""
    if "sigma0" not in spec.names:
        return {}
    inp = spec.inputs(u)
    lo, hi = window(problem.R, inp.Delta, float(np.max(inp.w)), _scaled(inp))
    return {spec.names.index("sigma0"): (math.log(lo), math.log(hi))}


def start(problem, spec, u):
    """Up to STARTS starting points (best first, from different starting w: at small lambda w and sigma0 trade
    off along a curved valley with more than one minimum, so the descent is run from each): u with w (if fitted,
    one for both legs) and sigma0 (if fitted) at the best of a grid: w at the linear JKR start and at the
    normalised adhesions START_M (the JKR start underestimates w where the zone is wide), sigma0 at
    START_LAMBDAS (or at its given value, clipped into the window)."""
    names, u = spec.names, np.array(u, dtype=float)
    fit_w = "w" in names
    inp = spec.inputs(u)
    if "sigma0" not in names:
        _check_fixed(problem, inp)
        if not np.all(np.isfinite(problem.residuals(u))):
            _check_fixed(problem, inp, resolved=False)
    if "sigma0" not in names and not fit_w:
        return [u]
    R, mat = problem.R, _scaled(inp)
    ws = [float(np.max(inp.w))] + ([_w_of_M(problem, inp, M) for M in START_M] if fit_w else [])
    if "sigma0" not in names:         # a given sigma0: no start further towards JKR than the first (costly states)
        top = max(LAMBDA_MAX, transition(R, inp.Delta, ws[0], mat, inp.strength))
        ws = [wv for wv in ws if transition(R, inp.Delta, wv, mat, inp.strength) <= top]
    best = {}                                   # the best start per starting w
    for wv in ws:
        trial = np.array(u, dtype=float)
        if fit_w:
            trial[names.index("w")] = math.log(wv)
        for strength in _strengths(spec, R, inp.Delta, wv, mat):
            if strength is not None:
                trial[names.index("sigma0")] = math.log(strength)
            r = problem.residuals(trial)
            cost = float(r @ r)
            if np.isfinite(cost) and cost < best.get(wv, (math.inf,))[0]:
                best[wv] = (cost, trial.copy())
    ranked = [v for _, v in sorted(best.values(), key=lambda cv: cv[0])]
    return ranked[:STARTS] or [u]


def _check_fixed(problem, inp, resolved=True):
    """ValueError naming sigma0 where a given, fixed sigma0 puts lambda (at the starting w and moduli) outside
    [LAMBDA_MIN, FIXED_MAX], or (resolved=False) where the solver refused its states there."""
    lam = transition(problem.R, inp.Delta, float(np.max(inp.w)), _scaled(inp), inp.strength)
    if lam < LAMBDA_MIN:
        raise ValueError(f"sigma0: lambda = {lam:.4g} at sigma0 = {inp.strength:.6g} Pa and the starting values, "
                         f"below {LAMBDA_MIN:g}, the smallest lambda the fit evaluates the cohesive law at (the zone "
                         "spreads over the contact and w and sigma0 trade off); give a larger sigma0 or fit it")
    if lam > FIXED_MAX or not resolved:
        raise ValueError(f"sigma0: the cohesive solver cannot resolve the zone at sigma0 = {inp.strength:.6g} Pa "
                         f"(lambda = {lam:.4g} at the starting values; the fit evaluates the law up to lambda = "
                         f"{FIXED_MAX:g}: the zone is too thin); the law is JKR's there to O(lambda^-2): fit with "
                         "sigma0=None")


START_M = (0.01, 0.03, 0.1, 0.3, 1.0, 3.0)
STARTS = 3


def _strengths(spec, R, Delta, w, mat):
    """Starting sigma0 values at w: the START_LAMBDAS, or the given one clipped into the window (None: fixed)."""
    if "sigma0" not in spec.names:
        return [None]
    lo, hi = window(R, Delta, w, mat)
    if spec.fixed["sigma0"] is not None:
        return [min(max(spec.fixed["sigma0"], lo * 1.01), hi / 1.01)]
    return [model.contact_with_lambda(R, Delta, w, mat, lam).sigma0 for lam in START_LAMBDAS]


def _w_of_M(problem, inp, M):
    """w [J/m^2] of the normalised adhesion M (section 6) at the current pair and clearance (Contact.M is
    proportional to sqrt(w))."""
    ref = model.contact(problem.R, inp.Delta, 1.0, _scaled(inp))
    return (M / ref.M) ** 2


def window_notes(intervals, confidence):
    """Notes on a sigma0 interval that reaches an edge of the lambda window (one-sided)."""
    lo, hi = intervals.get("sigma0", (1.0, 1.0))
    out = []
    if math.isinf(hi):
        out.append(f"sigma0: one-sided interval: the data do not bound it above within lambda <= {LAMBDA_MAX:g} "
                   f"(towards JKR, lambda -> inf): the {100 * confidence:g} % interval is ({lo:.6g} Pa, inf)")
    if lo == 0.0:
        out.append(f"sigma0: one-sided interval: the data do not bound it below within lambda >= {LAMBDA_MIN:g} "
                   f"(w and sigma0 trade off there): the {100 * confidence:g} % interval is (0, {hi:.6g} Pa)")
    return out


# --- checks at the estimate --------------------------------------------------------------------------------
def edge(problem, spec, u, rel=1e-6):
    """'above'/'below' when the fitted sigma0 sits at the window's edge (the plateau), else None."""
    b = bounds(problem, spec, u)
    if not b:
        return None
    (j, (lo, hi)), = b.items()
    return "above" if u[j] >= hi - rel else ("below" if u[j] <= lo + rel else None)


def edge_message(side, bound, confidence):
    """The ValueError text for an estimate at the window's edge, with the one-sided profile bound [Pa]."""
    if side == "above":
        return (f"sigma0: the data do not determine the cohesive strength: the best fit lies at the JKR end of the "
                f"window (lambda >= {LAMBDA_MAX:g}, where the law is JKR's to ~C/lambda^2); one-sided "
                f"{100 * confidence:g} % profile-likelihood bound: sigma0 > {bound:.6g} Pa; fit the JKR law "
                "(sigma0=None) for w and the moduli, or fix sigma0")
    return (f"sigma0: the data do not determine the cohesive strength: the best fit lies at the small-lambda end of "
            f"the window (lambda <= {LAMBDA_MIN:g}, where w and sigma0 trade off); one-sided {100 * confidence:g} % "
            f"profile-likelihood bound: sigma0 < {bound:.6g} Pa; fix sigma0 or w")


def check(problem, spec, u, cov_u, s2, beyond_sigmas):
    """At the estimate: every width below the traced branch's first turn in eps (a width picks one state there),
    and no load beyond the fixed-load pull-off force (Contact.pull_off) by more than beyond_sigmas standard errors
    (of the point's load as the fit models it, and of the pull-off force: at a fold by the envelope theorem, dP/du
    at the fold's fixed contact; else by finite differences of pull-offs in u).  ValueError naming the rows
    otherwise; returns {w: pull-off force [N/m] or None}."""
    d, R = problem.data, problem.R
    inp = spec.inputs(u)
    out = {}
    for wv in np.unique(inp.w):
        sel = inp.w == wv
        c = inp.contact(R, wv)
        eps = c.curve(regime="sub-critical", n=TURN_POINTS).eps
        turn = np.nonzero(np.diff(eps) < 0)[0]
        if turn.size:
            far = sel & (d.x / (2 * R) > eps[turn[0]])
            if far.any():
                rows = np.nonzero(far)[0]
                raise ValueError(f"width: rows {', '.join(str(int(i)) for i in rows[:5])} lie beyond the contact "
                                 f"width {2 * R * eps[turn[0]]:.6g} m where the fitted cohesive branch turns back: "
                                 "a width picks no unique state there; fit smaller contacts or the JKR law")
        po = c.pull_off(control="load")
        fo = out[float(wv)] = po.P
        if fo is None:
            continue
        grad = np.zeros(u.size)
        fold = "shrinks away" in po.reason          # a fold of P: dP/du at its fixed contact (envelope theorem)
        for k in range(u.size):
            du = np.array(u, dtype=float)
            du[k] += 1e-5
            ik = spec.inputs(du)
            ck = ik.contact(R, ik.w[np.nonzero(sel)[0][0]])
            fk = float(ck.at_contact(np.array([po.state.eps])).P[0]) if fold else _pull_off(ck)
            grad[k] = 0.0 if fk is None else (fk - fo) / 1e-5
        se_fold = math.sqrt(max(float(grad @ cov_u @ grad), 0.0))
        sP = problem.load_sd(u, s2)[sel]
        beyond = d.P[sel] < fo - beyond_sigmas * np.sqrt(se_fold ** 2 + sP ** 2)
        if beyond.any():
            rows = np.nonzero(sel)[0][beyond]
            raise ValueError(f"P: row{'s' if rows.size > 1 else ''} {', '.join(str(int(i)) for i in rows[:5])} "
                             f"({d.P[rows[0]]:.6g} N/m) lie beyond the pull-off force {fo:.6g} N/m of the fitted "
                             "cohesive model (no stable equilibrium holds such a load; P < 0 pulls)")
    return out


def _pull_off(c):
    po = c.pull_off(control="load")
    return po.P
