"""Standard errors from the Jacobian and confidence intervals by profile likelihood.

Covariance: s^2 (J^T J)^-1 in the internal coordinates u (log of the positive parameters) at the optimum, mapped to
the parameters by the diagonal Jacobian of the coordinate change; s^2 = 1 when the measurement errors are stated
(absolute), else the residual variance S_min/(m - p) (m residuals, p parameters, nuisance contact parameters
counted for orthogonal-distance fits).

Intervals: profile likelihood with re-optimisation of the other parameters (Venzon and Moolgavkar 1988): the
interval of parameter j holds every value t with [S_j(t) - S_min]/s^2 <= q, S_j(t) the least sum of squares
with u_j = t, q = chi2_1 quantile (errors stated) or the F(1, m - p) quantile (variance estimated from the
residuals).  It is invariant under reparametrisation and follows the curvature of the model, which the Wald
interval (estimate +- 1.96 standard errors) does not; tests/test_fit.py and benchmarks/bench_fit.py measure
its coverage.  With a robust loss S is 2 x the robust cost (an approximate likelihood).
"""
from __future__ import annotations

import math

import numpy as np
from scipy import stats
from scipy.optimize import least_squares

from ..numerics import roots as _roots

LOG_RANGE = 30.0       # a log-parameter profile that stays below the threshold over e^30: open on that side
LINEAR_RANGE = 1e3     # likewise for the offset, in units of its length scale
MAX_DOUBLINGS = 40
PROFILE_TOL = 1e-9     # least_squares tolerances of a profile's re-optimisation: S to ~1e-9 relative, far below
#                        the threshold's resolution (the crossing is sought to 1e-4 standard errors)


class BetterOptimum(Exception):
    """The profile found a lower sum of squares: the fit stopped in a local minimum (u holds the better point)."""

    def __init__(self, u):
        super().__init__("better optimum")
        self.u = u


def covariance(jac, u, spec, s2):
    """(covariance of the parameters, of u) from the Jacobian of the normalised residuals at the optimum."""
    jtj = jac.T @ jac
    cov_u = s2 * np.linalg.pinv(jtj, rcond=1e-15)
    D = spec.derivative(u)
    return D[:, None] * cov_u * D[None, :], cov_u


def correlation(cov):
    sd = np.sqrt(np.diag(cov))
    with np.errstate(invalid="ignore", divide="ignore"):
        return cov / np.outer(sd, sd)


def threshold(confidence, dof, sigma_known):
    """q of the profile-likelihood interval."""
    if sigma_known:
        return float(stats.chi2.ppf(confidence, 1))
    return float(stats.f.ppf(confidence, 1, dof))


class Profiler:
    """Profile intervals of every free parameter of a fitted problem.

    cost(u) = 2 x the least_squares cost (= S for the linear loss); s2: the variance scale; q: the threshold;
    edges: {index: (lo, hi)} of parameters confined to a window (jkrcyl.fit.cohesive: sigma0 within a lambda
    range): the profile is evaluated at the edge last and the side is open (+-inf) if it stays below q there."""

    def __init__(self, problem, spec, u_hat, S_hat, s2, q, loss, f_scale, se_u, edges=None):
        self.problem, self.spec, self.u_hat, self.S_hat = problem, spec, np.asarray(u_hat, float), S_hat
        self.s2, self.q, self.loss, self.f_scale, self.se_u = s2, q, loss, f_scale, se_u
        self.edges = edges or {}

    def S(self, r):
        if self.loss == "linear":
            return float(r @ r)
        z = (r / self.f_scale) ** 2
        rho = 2 * (np.sqrt(1 + z) - 1) if self.loss == "soft_l1" else np.where(z <= 1, z, 2 * np.sqrt(z) - 1)
        return float(self.f_scale ** 2 * rho.sum())

    def excess(self, j, t, warm):
        """([S_j(t) - S_min]/s2, re-optimised others) with u_j = t."""
        others = [k for k in range(self.u_hat.size) if k != j]

        def full(v):
            u = self.u_hat.copy()
            u[j] = t
            u[others] = v
            return u

        if not others:
            u = full([])
            return (self.S(self.problem.residuals(u)) - self.S_hat) / self.s2, warm
        res = least_squares(lambda v: self.problem.residuals(full(v)), warm, loss=self.loss, f_scale=self.f_scale,
                            x_scale="jac", method="trf", xtol=PROFILE_TOL, ftol=PROFILE_TOL, gtol=PROFILE_TOL,
                            diff_step=getattr(self.problem, "diff_step", None))
        S = self.S(res.fun)
        if S < self.S_hat - 1e-7 * max(self.S_hat, self.s2):
            raise BetterOptimum(full(res.x))
        return (S - self.S_hat) / self.s2, res.x

    def side(self, j, sign):
        """(u_j at the crossing, or +-inf when the profile stays below q over the whole range)."""
        others0 = np.delete(self.u_hat, j)
        t0 = self.u_hat[j]
        linear = self.spec.names[j] in ("offset",)
        limit = LINEAR_RANGE if linear else LOG_RANGE
        step = self.se_u[j] if np.isfinite(self.se_u[j]) and self.se_u[j] > 0 else 0.1
        step = min(step, limit / 4)
        t_prev, warm_prev = t0, others0
        wall = self.edges.get(j, (-math.inf, math.inf))[sign > 0]
        if (t0 - wall) * sign >= 0:
            return sign * math.inf
        if math.isfinite(wall) and (t0 + sign * math.sqrt(self.q) * step - wall) * sign >= 0:
            e, warm = self.excess(j, wall, others0)      # the Wald crossing lies beyond the wall: try the wall first
            if e < self.q:
                return sign * math.inf
        for _ in range(MAX_DOUBLINGS):
            t = t0 + sign * step
            if (t - wall) * sign >= 0:
                t = wall
            elif abs(t - t0) > limit:
                return sign * math.inf
            e, warm = self.excess(j, t, warm_prev)
            if t == wall and e < self.q:
                return sign * math.inf
            if e >= self.q:
                cache = {}

                def g(x):
                    val, w = self.excess(j, x, warm_prev)
                    cache[x] = w
                    return val - self.q
                tol = 1e-4 * (self.se_u[j] if np.isfinite(self.se_u[j]) and self.se_u[j] > 0 else 1e-3)
                lo, hi = sorted((t_prev, t))
                return _roots.root(g, lo, hi, tol)
            t_prev, warm_prev = t, warm
            step *= 2.0
        return sign * math.inf

    def intervals(self):
        """[(lo_u, hi_u)] per parameter in internal coordinates (+-inf: open side)."""
        return [(self.side(j, -1), self.side(j, +1)) for j in range(self.u_hat.size)]
