"""Residuals of the two kinds of measurement, normalised by the stated standard deviations.

Load against width (Chaudhury et al. 1996, Barquins 1988): the state at each width is explicit,
a = tan(width/(4R)), the library's state there (superposed: jkrcyl.fit.model).  An error sigma_width on the width
enters as the effective variance sigma_P^2 + (dP/dwidth sigma_width)^2 + (d2P/dwidth2 sigma_width^2)^2/2 (the
variance of P(width + e) to second order, so that it stays > 0 at the pull-off, where dP/dwidth = 0).

Load against approach delta_work (a testing machine): each point's contact parameter a_i is a nuisance, the point
of the part of the sub-critical branch the path reaches under the stated control (stable, section 8.3, and
feasible; jkrcyl.fit.branch.segment) nearest to the measurement in the metric of the standard deviations
(orthogonal-distance regression, two residuals per point; located on the table's splines, then polished on exact
states).  A variable without a stated error (P under 'load' control when neither is stated, delta_work under
'grip-work') is treated as exact: its standard deviation is set EXACT times the other's (scaled by the data's
slope), so a_i is the root of the model for it to 1e-3 of the noise, while a point beyond the end of the stable
segment (a load below the pull-off force) keeps a smooth, steep penalty instead of a kink.
"""
from __future__ import annotations

import numpy as np

from . import branch, cohesive, model

CONTROLS = ("load", "grip-work")
EXACT = 1e-3          # standard deviation of an 'exact' variable relative to the other one's (see above)
POLISH = 1            # Gauss-Newton steps of each located contact on exact states (the splines hold ~1e-8)


class Problem:
    """residuals(u) -> normalised residual vector for the internal coordinates u of a :class:`params.Spec`."""

    def __init__(self, data, spec, R, control):
        if control not in CONTROLS:
            raise ValueError(f"control must be one of {', '.join(CONTROLS)}, got {control!r}")
        self.data, self.spec, self.R, self.control = data, spec, R, control
        # least_squares' relative finite-difference step: the direct states (no superposition) carry ~1e-10
        # rounding, so the default (~1e-8) step would give Jacobian errors of ~1 %; None keeps the default
        self.diff_step = None if spec.superposes else 1e-6
        self.sigma_known = data.sigma_P is not None or data.sigma_x is not None
        self.budget = None if spec.superposes else cohesive.Budget(data.n)     # the work a cohesive fit may do
        self.a = model.a_of_width(data.x, R) if data.kind == "width" else None
        if data.kind == "width":
            self.mode = "width"
        elif data.sigma_P is not None and data.sigma_x is not None:
            self.mode = "both"
        elif data.sigma_P is not None or (data.sigma_x is None and control == "grip-work"):
            self.mode = "approach-exact"     # delta_work exact, residual in P
        else:
            self.mode = "load-exact"         # P exact, residual in delta_work
        # without stated errors the residuals are divided by a nominal 1 % of the measured range, so that they are
        # O(1) whatever the units (least_squares' tolerances are absolute); the scale is estimated from them later
        measured = data.x if self.mode == "load-exact" else data.P
        self.nominal = 1.0 if self.sigma_known else 1e-2 * (float(np.ptp(measured)) or float(np.abs(measured).max())
                                                            or 1.0)
        if data.kind == "delta_work":
            slope = max(np.ptp(data.P), 1e-300) / max(np.ptp(data.x), 1e-300)      # [N/m per m]
            ones = np.full(data.n, self.nominal)
            sP = ones if data.sigma_P is None else data.sigma_P
            sx = ones if data.sigma_x is None else data.sigma_x
            if self.mode == "load-exact":
                sP = EXACT * sx * slope
            elif self.mode == "approach-exact":
                sx = EXACT * sP / slope
            self.sigma_P, self.sigma_x = sP, sx

    @property
    def n_residuals(self):
        return self.data.n if self.mode == "width" else 2 * self.data.n

    @property
    def nuisance(self):
        """Fitted contact parameters (one per point for delta_work data)."""
        return 0 if self.mode == "width" else self.data.n

    def report(self, u):
        """(raw, normalised) residuals of the measured variable(s): P for width data; for delta_work data the
        variable with an error (delta_work under 'load-exact', P under 'approach-exact', both stacked)."""
        raw, norm = self.residuals(u, normalised=False), self.residuals(u)
        n = self.data.n
        pick = {"load-exact": slice(n, 2 * n), "approach-exact": slice(0, n)}.get(self.mode, slice(None))
        return raw[pick], norm[pick]

    def residuals(self, u, normalised=True):
        """Measured minus model, divided by the stated standard deviations (normalised=False: raw); NaN where the
        library refuses the parameters (a wall for least_squares' trust region, never an exception mid-descent)."""
        try:
            inp = self.spec.inputs(u)
            if self.mode == "width":
                return self._width(inp, normalised)
            return self._approach(inp, normalised)
        except (ValueError, OverflowError, ZeroDivisionError, FloatingPointError):
            return np.full(self.n_residuals, np.nan)

    def load_sd(self, u, s2):
        """Standard deviation [N/m] of each measured load as the fit models it at u: the stated sigma_P, the error
        on the width carried through the slope (the effective variance), or the residual scale sqrt(s2) (in the
        nominal unit) when no error is stated; 0 for loads held exactly (delta_work data under load control)."""
        d = self.data
        if not self.sigma_known:
            return np.full(d.n, np.sqrt(s2) * self.nominal)
        if self.mode != "width":
            return np.zeros(d.n) if self.mode == "load-exact" else np.asarray(self.sigma_P, dtype=float)
        var = np.zeros(d.n) if d.sigma_P is None else d.sigma_P ** 2
        if d.sigma_x is not None:
            _, Px, Pxx = self._width_model(self.spec.inputs(u), d.x, slopes=True)
            var = var + (Px * d.sigma_x) ** 2 + 0.5 * (Pxx * d.sigma_x ** 2) ** 2
        return np.sqrt(var)

    # --- load against width -------------------------------------------------------------------------------
    def _width(self, inp, normalised=True):
        d = self.data
        P, Px, Pxx = self._width_model(inp, d.x, slopes=normalised and d.sigma_x is not None)
        r = d.P - P
        if not normalised:
            return r
        if not self.sigma_known:
            return r / self.nominal
        var = np.zeros(d.n) if d.sigma_P is None else d.sigma_P ** 2
        if d.sigma_x is not None:
            var = var + (Px * d.sigma_x) ** 2 + 0.5 * (Pxx * d.sigma_x ** 2) ** 2
        return r / np.sqrt(var)

    def _width_model(self, inp, width, slopes=False):
        """(P, dP/dwidth, d2P/dwidth2) at the widths: superposed library states (JKR) or direct states."""
        if not self.spec.superposes:
            return cohesive.model_loads(self.R, inp, width, slopes, clip="sigma0" in self.spec.names,
                                        budget=self.budget)
        a = model.a_of_width(width, self.R)
        P, P1, P2 = (np.empty(a.size) for _ in range(3))
        for wv, sel in _legs(inp.w):
            sp = inp.superposed(self.R, wv)
            P[sel], P1[sel] = sp.loads(a[sel], slopes)
            if slopes:
                P2[sel] = sp.load_curvature(a[sel])
        if not slopes:
            return P, None, None
        dadx = (1 + a ** 2) / (4 * self.R)              # a = tan(x/(4R))
        d2adx2 = 2 * a * dadx / (4 * self.R)
        return P, P1 * dadx, P2 * dadx ** 2 + P1 * d2adx2

    def curve_width(self, u, width, w=None):
        """Model load [N/m] at contact widths [m] (w: the loading leg's unless given)."""
        inp = self.spec.inputs(u)
        wv = float(inp.w[0] if w is None else w)
        one = type(inp)(materials=inp.materials, f=inp.f, Delta=inp.Delta, w=np.full(np.size(width), wv),
                        offset=inp.offset, strength=inp.strength)
        return self._width_model(one, np.asarray(width, dtype=float))[0]

    # --- load against approach --------------------------------------------------------------------------------
    def states(self, u):
        """Contact parameters a_i of the points (on the stable segment)."""
        return self._located(self.spec.inputs(u))[0]

    def _approach(self, inp, normalised=True):
        _, P, X = self._located(inp)
        d = self.data
        rP, rx = d.P - P, d.x - inp.offset - X
        if normalised:
            rP, rx = rP / self.sigma_P, rx / self.sigma_x
        return np.concatenate([rP, rx])

    def _located(self, inp):
        """(a_i, P(a_i), delta_work(a_i)): located on the table's splines (:meth:`_closest`), then POLISH
        Gauss-Newton steps of the distance on exact library states, whose values the residuals take (so that
        a_i minimises the distance the fit sees)."""
        a, lo, hi, legs = self._closest(inp)
        d = self.data
        P, P1, X, X1 = (np.empty(d.n) for _ in range(4))
        for step in range(POLISH + 1):
            for sp, sel in legs:
                st = sp.states(a[sel], keep=False)
                P[sel], P1[sel], X[sel], X1[sel] = st.P, st.dP_da, st.delta_work, st.ddelta_work_da
            if step == POLISH:
                return a, P, X
            eP, ex = d.P - P, d.x - inp.offset - X
            g = eP * P1 / self.sigma_P ** 2 + ex * X1 / self.sigma_x ** 2
            H = P1 ** 2 / self.sigma_P ** 2 + X1 ** 2 / self.sigma_x ** 2
            with np.errstate(divide="ignore", invalid="ignore"):
                a = np.clip(np.where(H > 0, a + g / H, a), lo, hi)

    def segments(self, inp, legs=None):
        """Per point (lo, hi) of the branch the path reaches under the control (jkrcyl.fit.branch.segment)."""
        lo, hi = np.empty(self.data.n), np.empty(self.data.n)
        legs = legs or [(inp.superposed(self.R, wv), sel) for wv, sel in _legs(inp.w)]
        for sp, sel in legs:
            lo[sel], hi[sel] = branch.segment(sp, self.control)
        return lo, hi

    def _closest(self, inp):
        """a_i minimising ((P_i - P(a))/sP)^2 + ((x_i - off - dw(a))/sx)^2 on the segment [lo_i, hi_i]: the best
        table node (clipped to the segment), then Newton on the derivative between its neighbours, on the
        table's splines (the residuals then take the exact states there: the distance is stationary in a_i)."""
        d, sP, sx = self.data, self.sigma_P, self.sigma_x
        legs = [(inp.superposed(self.R, wv), sel) for wv, sel in _legs(inp.w)]
        lo, hi = self.segments(inp, legs)
        tab = branch.table(inp.materials)
        k, L, D = np.empty(d.n), np.empty(d.n), inp.Delta
        for sp, sel in legs:
            k[sel], L[sel] = sp.k, sp.L
        nodes = tab.a
        cand = np.clip(nodes[None, :], lo[:, None], hi[:, None])          # (points, nodes), inside each segment
        best = np.empty(d.n, dtype=int)
        for wv, sel in _legs(inp.w):
            sel = np.nonzero(sel)[0]
            s = model.superpose(tab.unit, k[sel[0]])
            Pn, Xn = (np.interp(cand[sel], nodes, L[sel[0]] * s.p), np.interp(cand[sel], nodes, D * s.dw))
            dist = (((d.P[sel, None] - Pn) / sP[sel, None]) ** 2
                    + ((d.x[sel, None] - inp.offset - Xn) / sx[sel, None]) ** 2)
            best[sel] = np.argmin(dist, axis=1)
        rows = np.arange(d.n)
        a_lo = cand[rows, np.maximum(best - 1, 0)]
        a_hi = cand[rows, np.minimum(best + 1, nodes.size - 1)]

        def grad(a):
            v = tab.interpolate(a, k, ("p", "dw"))
            (p, p1, p2), (x, x1, x2) = v["p"], v["dw"]
            eP, ex = d.P - L * p, d.x - inp.offset - D * x
            P1, X1, P2, X2 = L * p1, D * x1, L * p2, D * x2
            g = -2 * (eP * P1 / sP ** 2 + ex * X1 / sx ** 2)
            h = 2 * ((P1 ** 2 - eP * P2) / sP ** 2 + (X1 ** 2 - ex * X2) / sx ** 2)
            return g, h

        return _bracketed_root(grad, a_lo, a_hi, grad(a_lo)[0], grad(a_hi)[0]), lo, hi, legs


def _legs(w):
    """(w, mask) per distinct work of adhesion of the points (one, or one per leg)."""
    return [(wv, w == wv) for wv in np.unique(w)]


def _bracketed_root(fun, lo, hi, flo, fhi, tol=1e-11, iterations=100):
    """Vectorised safeguarded Newton for increasing functions on [lo, hi] (fun(a) -> (value, slope)); where the
    bracket holds no sign change, the end where the function is nearer to its zero side is returned."""
    out = np.where(flo >= 0, lo, hi)
    todo = (flo < 0) & (fhi > 0)
    if not todo.any():
        return out
    lo, hi = lo[todo], hi[todo]
    x = np.sqrt(lo * hi)
    active = np.ones(x.size, dtype=bool)
    sub = _Subset(fun, todo)
    for _ in range(iterations):
        v, s = sub(x)
        neg = v < 0
        lo = np.where(neg, x, lo)
        hi = np.where(neg, hi, x)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = x - v / s
        bad = ~((step >= lo) & (step <= hi)) | ~np.isfinite(step)
        x_new = np.where(bad, np.sqrt(lo * hi), step)
        converged = (np.abs(x_new - x) <= tol * x) | (hi - lo <= tol * lo) | (v == 0)
        x = np.where(active, np.where(v == 0, x, x_new), x)
        active &= ~converged
        if not active.any():
            break
    out[todo] = x
    return out


class _Subset:
    """fun restricted to the points of a mask (fun works on all points at once: pad the others)."""

    def __init__(self, fun, mask):
        self.fun, self.mask = fun, mask
        self.full = None

    def __call__(self, x):
        if self.full is None:
            self.full = np.ones(self.mask.size)
        a = self.full.copy()
        a[self.mask] = x
        a[~self.mask] = x[0]
        v, s = self.fun(a)
        return v[self.mask], s[self.mask]
