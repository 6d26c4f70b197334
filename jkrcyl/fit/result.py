"""FitResult: estimates, 95 % intervals, covariance, residuals, a text table and a plot."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from . import branch, model
from .params import DESCRIPTION


@dataclass
class FitResult:
    """The outcome of :func:`jkrcyl.fit.fit`.

    values, intervals, standard_errors: dicts keyed by the free parameter names (``w``, ``w_loading``,
    ``w_unloading`` [J/m^2], ``E`` (contact modulus E* = 4/beta*), ``E_hole``, ``E_pin`` [Pa], ``Delta``,
    ``offset`` [m], ``sigma0`` [Pa]: the cohesive strength); intervals are (lower, upper) at ``confidence`` by
    ``interval_method`` (+-inf or 0 where the data do not bound a parameter; see ``notes``).  covariance, correlation: arrays in the order of ``names``.
    residuals: measured minus fitted (P [N/m] for width data; for delta_work data the residual of the
    variable with the error: delta_work [m], P [N/m], or both stacked); normalised_residuals: divided by the
    stated standard deviations (equal to residuals when none was stated).  pull_off: {w [J/m^2]: the fixed-load
    pull-off force [N/m] of the fitted contact (None: no detachment on the path from first contact)}, the force the
    rows were checked against (Contact.pull_off's path; jkrcyl.fit.checks).

    Examples
    --------
    >>> import jkrcyl, numpy as np
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> c = jkrcyl.Contact(R=0.01, Delta=3e-6, w=0.05, materials=m)     # synthetic widths of a known contact
    >>> width = np.linspace(7e-3, 20e-3, 12)
    >>> res = jkrcyl.fit(P=c.state(np.tan(width / 0.04)).P, width=width, R=0.01, Delta=3e-6, materials=m,
    ...                  free=("w",), sigma_P=1.0, interval=None)
    >>> res.names, res.kind, res.n, round(res.contact().w, 6)
    (('w',), 'width', 12, 0.05)
    >>> res.table().splitlines()[0].split()[:3]
    ['parameter', 'value', 'std']
    """

    names: tuple
    values: dict
    intervals: dict
    standard_errors: dict
    covariance: np.ndarray
    correlation: np.ndarray
    residuals: np.ndarray
    normalised_residuals: np.ndarray
    cost: float                   # sum of squared normalised residuals (of raw residuals when no error is stated;
                                  # 2 x the robust cost for robust losses)
    dof: int
    sigma: float                  # residual scale: 1 when errors are stated, else sqrt(S/dof) in residual units
    confidence: float
    interval_method: str
    loss: str
    control: str
    kind: str                     # 'width' or 'delta_work'
    n: int
    materials: object             # the fitted jkrcyl.Materials
    Delta: float
    R: float
    nfev: int
    notes: list = field(default_factory=list)
    fixed: dict = field(default_factory=dict)
    pull_off: dict = field(default_factory=dict)    # {w [J/m^2]: fixed-load pull-off force [N/m] or None}
    law: object = None                              # the edge law of the superposed path (None: JKR)
    _problem: object = field(default=None, repr=False)
    _u: Optional[np.ndarray] = field(default=None, repr=False)

    @property
    def moduli(self):
        """Young's moduli of the hole and the pin and the contact modulus E* of the fitted pair [Pa]."""
        m = self.materials
        return {"E_hole": model.young(m, "hole"), "E_pin": model.young(m, "pin"), "E_star": model.contact_modulus(m)}

    def contact(self, leg="loading"):
        """The fitted jkrcyl.Contact (w of the leg when the legs have their own)."""
        w = self.values.get(f"w_{leg}", self.values.get("w", self.fixed.get("w")))
        return model.contact(self.R, self.Delta, w, self.materials, self.values.get("sigma0", self.fixed.get("sigma0")),
                             self.law)

    def table(self):
        """The result as text: one row per parameter (value, standard error, interval, unit), then the fit."""
        lo_name = f"{100 * self.confidence:g}% lower"
        rows = [f"{'parameter':<12} {'value':>13} {'std error':>12} {lo_name:>13} {'upper':>13}  unit"]
        for n in self.names:
            lo, hi = self.intervals.get(n, (math.nan, math.nan))
            rows.append(f"{n:<12} {self.values[n]:>13.6g} {self.standard_errors[n]:>12.4g} {lo:>13.6g} "
                        f"{hi:>13.6g}  {DESCRIPTION[n][0]}")
        mod = self.moduli
        rows.append(f"fitted pair: E_hole = {mod['E_hole']:.6g} Pa, E_pin = {mod['E_pin']:.6g} Pa, "
                    f"E* = {mod['E_star']:.6g} Pa; Delta = {self.Delta:.6g} m, R = {self.R:.6g} m")
        law = self.contact().lambda_
        rows += [] if law is None else [f"Maugis-Dugdale law: lambda = {law:.6g}, h0 = w/sigma0 = "
                                        f"{self.contact().h0:.6g} m"]
        for w, P in self.pull_off.items():
            leg = "" if len(self.pull_off) == 1 else f" (w = {w:.6g} J/m^2)"
            rows.append(f"fixed-load pull-off force of the fitted model{leg}: " +
                        ("none (no detachment on the path from first contact)" if P is None else f"{P:.6g} N/m"))
        unit = "N/m" if self.kind == "width" or self._problem.mode != "load-exact" else "m"
        scale = "errors as stated" if self._problem.sigma_known else f"residual scale {self.sigma:.4g} {unit}"
        rows.append(f"{self.n} points ({self.kind}), control {self.control}, loss {self.loss}, "
                    f"sum of squares {self.cost:.6g} on {self.dof} degrees of freedom ({scale}); "
                    f"intervals: {self.interval_method}")
        if len(self.names) > 1:
            pairs = [f"{self.names[i]}-{self.names[j]} {self.correlation[i, j]:+.3f}"
                     for i in range(len(self.names)) for j in range(i + 1, len(self.names))]
            rows.append("correlation: " + ", ".join(pairs))
        rows += [f"note: {t}" for t in self.notes]
        return "\n".join(rows)

    def __str__(self):
        return self.table()

    def plot(self, path, n=400):
        """Data, fitted curve and a residual panel, written to path (PNG, PDF, SVG by suffix); needs matplotlib.
        Width data: P against width; delta_work data: P against delta_work."""
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        pr, d = self._problem, self._problem.data
        fig, (ax, axr) = plt.subplots(2, 1, figsize=(6.4, 6.4), sharex=True,
                                      gridspec_kw={"height_ratios": [3, 1]})
        legs = [("all", np.ones(d.n, bool))] if d.unloading is None else \
            [("loading", ~d.unloading), ("unloading", d.unloading)]
        for leg, sel in legs:
            xs, Ps = _curve(pr, self._u, sel, n)
            label = "fit" if leg == "all" else f"fit, {leg}"
            ax.plot(xs * 1e3, Ps, "-", lw=1.5, label=label)
            err = None if d.sigma_P is None else d.sigma_P[sel]
            xerr = None if d.sigma_x is None else d.sigma_x[sel] * 1e3
            ax.errorbar(d.x[sel] * 1e3, d.P[sel], yerr=err, xerr=xerr, fmt="o", ms=3.5, lw=0.8,
                        label="data" if leg == "all" else f"data, {leg}")
        ax.axhline(0, color="0.6", lw=0.6)
        xlabel = "contact width 2 R eps [mm]" if d.kind == "width" else "approach delta_work [mm]"
        ax.set_ylabel("load P [N/m]")
        parts = [f"{k} = {self.values[k]:.4g} [{self.intervals[k][0]:.4g}, {self.intervals[k][1]:.4g}]"
                 for k in self.names]
        ax.set_title("; ".join(parts), fontsize=8)
        ax.legend(fontsize=8)
        res = self.normalised_residuals[: d.n]          # delta_work data with both errors: the load residuals
        axr.plot(d.x * 1e3, res, "o", ms=3.5)
        axr.axhline(0, color="0.4", lw=0.8)
        axr.set_xlabel(xlabel)
        unit = "N/m" if d.kind == "width" or pr.mode != "load-exact" else "m"
        axr.set_ylabel("residual / sigma" if pr.sigma_known else f"residual [{unit}]")
        fig.tight_layout()
        fig.savefig(path, dpi=150)
        plt.close(fig)
        return path


def _curve(problem, u, sel, n):
    """(x, P) of the fitted curve over the range of the selected points (stable segment for delta_work data)."""
    d, R = problem.data, problem.R
    inp = problem.spec.inputs(u)
    w = float(inp.w[sel][0])
    if d.kind == "width":
        lo, hi = d.x[sel].min(), d.x[sel].max()
        pad = 0.05 * (hi - lo)
        xs = np.linspace(max(lo - pad, lo / 2), min(hi + pad, 2 * math.pi * R * 0.999), n)
        return xs, problem.curve_width(u, xs, w)
    sp = inp.superposed(R, w)
    lo_seg, hi_seg = branch.segment(sp, problem.control)
    a_pts = problem.states(u)[sel]
    top = min(a_pts.max() * 1.02, hi_seg)
    a = np.geomspace(min(lo_seg, a_pts.min()), max(top, a_pts.max()), n)
    st = sp.states(a)
    return st.delta_work + inp.offset, st.P
