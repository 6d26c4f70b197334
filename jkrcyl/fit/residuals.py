"""Residuals of the two kinds of measurement, normalised by the stated standard deviations.

Load against width (Chaudhury et al. 1996, Barquins 1988): the state at each width is explicit,
a = tan(width/(4R)), P = f Delta p1(a) - sqrt(f w) p2(a) (jkrcyl.fit.model).  An error sigma_width on the width
enters as the effective variance sigma_P^2 + (dP/dwidth sigma_width)^2 + (d2P/dwidth2 sigma_width^2)^2/2 (the
variance of P(width + e) to second order, so that it stays > 0 at the pull-off, where dP/dwidth = 0).

Load against approach delta_work (a testing machine): each point's contact parameter is a nuisance, found on the
part of the sub-critical branch that is stable under the stated control (section 8.3; jkrcyl.fit.model.segment):
the variable without a stated error is exact (P under 'load' control when neither is stated, delta_work under
'grip-work'), and a_i solves the model for it (a monotone 1-D root); with both errors stated a_i minimises the
weighted distance of the point from the curve (orthogonal-distance regression, two residuals per point).
"""
from __future__ import annotations

import numpy as np

from . import model

CONTROLS = ("load", "grip-work")


class Problem:
    """residuals(u) -> normalised residual vector for the internal coordinates u of a :class:`params.Spec`."""

    def __init__(self, data, spec, R, control):
        if control not in CONTROLS:
            raise ValueError(f"control must be one of {', '.join(CONTROLS)}, got {control!r}")
        self.data, self.spec, self.R, self.control = data, spec, R, control
        self.sigma_known = data.sigma_P is not None or data.sigma_x is not None
        self.a = model.a_of_width(data.x, R) if data.kind == "width" else None
        self.clamped = np.zeros(data.n, dtype=bool)     # delta_work: points beyond the stable segment
        if data.kind == "width":
            self.mode = "width"
        elif data.sigma_P is not None and data.sigma_x is not None:
            self.mode = "both"
        elif data.sigma_P is not None or (data.sigma_x is None and control == "grip-work"):
            self.mode = "approach-exact"     # delta_work exact, residual in P
        else:
            self.mode = "load-exact"         # P exact, residual in delta_work

    @property
    def n_residuals(self):
        return 2 * self.data.n if self.mode == "both" else self.data.n

    def residuals(self, u, normalised=True):
        """Measured minus model, divided by the stated standard deviations (normalised=False: raw)."""
        inp = self.spec.inputs(u)
        if self.mode == "width":
            return self._width(inp, normalised)
        return self._approach(inp, normalised)

    # --- load against width -------------------------------------------------------------------------------
    def _width(self, inp, normalised=True):
        d = self.data
        p = model.parts(self.R, inp.materials, self.a, slopes=d.sigma_x is not None)
        r = d.P - p.load(inp.f, inp.Delta, inp.w)
        if not self.sigma_known or not normalised:
            return r
        var = np.zeros(d.n) if d.sigma_P is None else d.sigma_P ** 2
        if d.sigma_x is not None:
            dadx = (1 + self.a ** 2) / (4 * self.R)              # a = tan(x/(4R))
            d2adx2 = 2 * self.a * dadx / (4 * self.R)
            P1, P2 = p.load(inp.f, inp.Delta, inp.w, 1), p.load(inp.f, inp.Delta, inp.w, 2)
            Px, Pxx = P1 * dadx, P2 * dadx ** 2 + P1 * d2adx2
            var = var + (Px * d.sigma_x) ** 2 + 0.5 * (Pxx * d.sigma_x ** 2) ** 2
        return r / np.sqrt(var)

    def curve_width(self, u, width):
        """Model load [N/m] at contact widths [m] (one w: the loading leg's)."""
        inp = self.spec.inputs(u)
        a = model.a_of_width(width, self.R)
        return model.parts(self.R, inp.materials, a).load(inp.f, inp.Delta, inp.w[0] if np.ndim(inp.w) else inp.w)

    # --- load against approach --------------------------------------------------------------------------------
    def states(self, u):
        """Contact parameters a_i of the points on the stable segment, and the flags of clamped points."""
        inp = self.spec.inputs(u)
        return self._solve_points(inp)

    def _approach(self, inp, normalised=True):
        a = self._solve_points(inp)
        p = model.branch(self.R, inp.materials).parts(a)
        d = self.data
        rP = d.P - p.load(inp.f, inp.Delta, inp.w)
        rx = d.x - inp.offset - p.approach(inp.f, inp.Delta, inp.w)
        sP = 1.0 if d.sigma_P is None or not normalised else d.sigma_P
        sx = 1.0 if d.sigma_x is None or not normalised else d.sigma_x
        if self.mode == "both":
            return np.concatenate([rP / sP, rx / sx])
        return rP / sP if self.mode == "approach-exact" else rx / sx

    def segments(self, inp):
        """Per point (lo, hi) of the stable segment under the control."""
        quantity = "load" if self.control == "load" else "approach"
        lo, hi = np.empty(self.data.n), np.empty(self.data.n)
        br = model.branch(self.R, inp.materials)
        for wv in np.unique(inp.w):
            seg = model.segment(self.R, inp.materials, inp.f, inp.Delta, wv, quantity)
            sel = inp.w == wv
            lo[sel], hi[sel] = (br.a_min, br.a_max) if seg is None else seg
        return lo, hi

    def _solve_points(self, inp):
        d = self.data
        br = model.branch(self.R, inp.materials)
        lo, hi = self.segments(inp)
        f, D, w = inp.f, inp.Delta, inp.w
        if self.mode == "load-exact":
            g = lambda p, k=0: p.load(f, D, w, k)
            target = d.P
        elif self.mode == "approach-exact":
            g = lambda p, k=0: p.approach(f, D, w, k)
            target = d.x - inp.offset
        else:
            return self._closest(br, inp, lo, hi)
        vlo, vhi = g(br.parts(lo)), g(br.parts(hi))
        self.clamped = (target < vlo) | (target > vhi)

        def fun(a):
            p = br.parts(a)
            return g(p) - target, g(p, 1)
        return _bracketed_root(fun, lo.copy(), hi.copy(), vlo - target, vhi - target)

    def _closest(self, br, inp, lo, hi):
        """a_i minimising ((P_i - P(a))/sP)^2 + ((x_i - off - dw(a))/sx)^2 on [lo_i, hi_i] (2-D distance)."""
        d, f, D = self.data, inp.f, inp.Delta
        nodes = br.nodes()
        inside = (nodes[None, :] >= lo[:, None]) & (nodes[None, :] <= hi[:, None])
        pn = br.parts(nodes)
        # per distinct w: the curve on the nodes
        best = np.empty(d.n)
        for wv in np.unique(inp.w):
            sel = np.nonzero(inp.w == wv)[0]
            Pn, Xn = pn.load(f, D, wv), pn.approach(f, D, wv)
            dist = (((d.P[sel, None] - Pn[None, :]) / d.sigma_P[sel, None]) ** 2
                    + ((d.x[sel, None] - inp.offset - Xn[None, :]) / d.sigma_x[sel, None]) ** 2)
            dist = np.where(inside[sel], dist, np.inf)
            best[sel] = nodes[np.argmin(dist, axis=1)]
        k = np.searchsorted(nodes, best)
        a_lo = np.maximum(lo, nodes[np.maximum(k - 1, 0)])
        a_hi = np.minimum(hi, nodes[np.minimum(k + 1, nodes.size - 1)])

        def grad(a):
            p = br.parts(a)
            eP = d.P - p.load(f, D, inp.w)
            ex = d.x - inp.offset - p.approach(f, D, inp.w)
            P1, X1 = p.load(f, D, inp.w, 1), p.approach(f, D, inp.w, 1)
            P2, X2 = p.load(f, D, inp.w, 2), p.approach(f, D, inp.w, 2)
            g = -2 * (eP * P1 / d.sigma_P ** 2 + ex * X1 / d.sigma_x ** 2)
            h = 2 * ((P1 ** 2 - eP * P2) / d.sigma_P ** 2 + (X1 ** 2 - ex * X2) / d.sigma_x ** 2)
            return g, h

        glo, _ = grad(a_lo)
        ghi, _ = grad(a_hi)
        self.clamped = np.zeros(d.n, dtype=bool)
        return _bracketed_root(grad, a_lo, a_hi, glo, ghi)


def _bracketed_root(fun, lo, hi, flo, fhi, tol=1e-11, iterations=100):
    """Vectorised safeguarded Newton for increasing functions on [lo, hi] (fun(a) -> (value, slope)); where the
    bracket holds no sign change the nearer end is returned (the point is clamped to the segment)."""
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
