"""The sub-critical branch of a fitted contact: its table, the stable segment and the pull-off, through the core.

The table holds the unit parts of jkrcyl.fit.model at PER_DECADE nodes per decade of a below the pole (a_top
1e-7 .. a_top for alpha* = 0, a_top 1e-4 .. a_top otherwise, where the collocation solver's adhesionless part
loses digits further down); per contact they superpose into the library's Slices, whose stability flags are
jkrcyl.model.stability's (the chain rule of section 8.3, the one rule of the library) and feasibility the gap
inequality h(pi) >= 0.  The path is jkrcyl.analysis.path.walk (the library's load-path walker) on that track,
from first contact (the smallest stable, feasible state where the held quantity is 0, as
jkrcyl.analysis.landing.first_contact lands) down to the pull-off and up to the end of the segment.  Folds are refined
on cubic splines of the unit parts in log a (through the exact values at the nodes; for the segment of
approach data) or on exact states (:func:`pull_off`, the force the fit refuses rows with and reports).  Where
first contact lands elsewhere than on this branch the fit asks Contact.pull_off itself.
tests/test_fit_converge.py holds :func:`pull_off` to Contact.pull_off at 1e-8 over random pairs.
"""
from __future__ import annotations

import functools
import math

import numpy as np
from scipy.interpolate import CubicSpline

from ..analysis import path as _path
from ..model import stability as _stab
from ..numerics import roots as _roots
from ..units import CONTROLS
from . import model

RIGID_A_MAX = 3.0    # vartheta = inf, alpha* = 0: no pole; the branch is searched up to this a
TOP_GAP = 1e-3       # the branch ends at a_crit (1 - TOP_GAP): loads there are ~1/TOP_GAP times the typical ones
PER_DECADE = 80      # table nodes per decade of a (a cubic spline in log a: ~1e-7 relative between nodes) ...
PER_DECADE_NUMERIC = 64   # ... and for alpha* != 0 (one collocation solve per node and unit: cost)
DECADES = 7          # the table spans a_top 1e-7 .. a_top (alpha* = 0) ...
DECADES_NUMERIC = 4  # ... or a_top 1e-4 .. a_top: below, the solver's adhesionless part loses digits (1e-5 at 1e-5)
SPLINE_FIELDS = ("p", "dw", "dn")   # the held quantities (and their slopes) interpolated for the search
SEARCH_TOL = 1e-12   # relative tolerance of a root on the splines
POLISH = 2           # Newton steps of a refined root on exact states (exact=True)


def _exact(materials):
    """The pair's solver rounds at the double-precision level (its closed forms)."""
    return model.shape(materials)[0].noise <= 1e-14


def branch_top(materials) -> float:
    """Largest a of the table: just below the pole (and within the solver's range), or RIGID_A_MAX without one."""
    ac = model.pole(materials)
    top = RIGID_A_MAX if math.isinf(ac) else ac * (1 - TOP_GAP)
    return min(top, model.resolved(materials) * (1 - TOP_GAP))


class Table:
    """The unit parts at the nodes and their splines (values and exact slopes, each part times (1 - a/a_crit) so
    that the pole of (4.4) does not spoil the interpolation)."""

    def __init__(self, materials):
        self.materials, self.pole = materials, model.pole(materials)
        top = branch_top(materials)
        decades, per = (DECADES, PER_DECADE) if _exact(materials) else (DECADES_NUMERIC, PER_DECADE_NUMERIC)
        a = top * np.logspace(-decades, 0, decades * per + 1)
        a[-1] = top
        self.a, self.a_min, self.a_max = a, a[0], a[-1]
        self.unit = model.unit_slices(materials, a)
        # the weighted parts y = part (1 - a/a_crit): smooth through the pole, which the parts alone are not
        w = self._weight(a)[0]
        y = [self.unit.parts[f][i] * w for f in SPLINE_FIELDS for i in (0, 1)]
        self.x, self.y = np.log(a), np.array(y).T
        self.spline = CubicSpline(self.x, self.y)            # not-a-knot: O(h^4) like the states' own Hermite
        self.slope, self.curvature = self.spline.derivative(1), self.spline.derivative(2)
        self.dy = self.slope(self.x)                          # the same cubics in Hermite form (:meth:`point`)

    def _weight(self, a):
        if math.isinf(self.pole):
            return np.ones_like(a), np.zeros_like(a)
        return 1 - a / self.pole, np.full_like(a, -1 / self.pole)

    def interpolate(self, a, k, fields=SPLINE_FIELDS):
        """{field: (value, d/da, d2/da2)} of the held quantities p, dw, dn (kernel scale) at edge coefficient k."""
        a = np.asarray(a, dtype=float)
        x = np.log(a)
        cols = [c for f in fields for c in (2 * SPLINE_FIELDS.index(f), 2 * SPLINE_FIELDS.index(f) + 1)]
        y, yx, yxx = self.spline(x)[..., cols], self.slope(x)[..., cols], self.curvature(x)[..., cols]
        if math.isinf(self.pole):
            w, dw = 1.0, 0.0
        else:
            w, dw = (1 - a / self.pole)[..., None], -1 / self.pole
        a_ = a[..., None]
        v = y / w
        d1 = (yx / a_ - v * dw) / w
        d2 = ((yxx - yx) / (a_ * a_) - 2 * d1 * dw) / w
        return {f: tuple(z[..., 2 * i] + k * z[..., 2 * i + 1] for z in (v, d1, d2)) for i, f in enumerate(fields)}

    def point(self, field, a, k):
        """(value, d/da, d2/da2) of one held quantity at one a (the same cubic as :meth:`interpolate`, evaluated
        in floats: the roots on the table call it tens of times)."""
        x = math.log(a)
        i = min(max(int(np.searchsorted(self.x, x)) - 1, 0), self.x.size - 2)
        h = self.x[i + 1] - self.x[i]
        t = (x - self.x[i]) / h
        j = 2 * SPLINE_FIELDS.index(field)
        Y = []
        t2, t3 = t * t, t * t * t
        for col in (j, j + 1):          # the cubic Hermite basis and its first two derivatives in x = log a
            y0, y1, m0, m1 = self.y[i, col], self.y[i + 1, col], h * self.dy[i, col], h * self.dy[i + 1, col]
            Y.append(((2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * m0 + (3 * t2 - 2 * t3) * y1 + (t3 - t2) * m1,
                      ((6 * t2 - 6 * t) * (y0 - y1) + (3 * t2 - 4 * t + 1) * m0 + (3 * t2 - 2 * t) * m1) / h,
                      ((12 * t - 6) * (y0 - y1) + (6 * t - 4) * m0 + (6 * t - 2) * m1) / (h * h)))
        y, yx, yxx = (Y[0][n] + k * Y[1][n] for n in range(3))
        w = 1.0 if math.isinf(self.pole) else 1 - a / self.pole
        dw = 0.0 if math.isinf(self.pole) else -1 / self.pole
        v = y / w
        d1 = (yx / a - v * dw) / w
        return v, d1, ((yxx - yx) / (a * a) - 2 * d1 * dw) / w


@functools.lru_cache(maxsize=16)
def table(materials) -> Table:
    """The cached :class:`Table` of a pair's shape (the moduli's common factor does not enter it)."""
    return Table(materials)


class Track:
    """The branch of one contact as jkrcyl.analysis.path.walk reads it (held quantity ``y`` in the kernel scale,
    the core's stability and feasibility flags at the nodes); exact=True refines on exact states."""

    def __init__(self, sp, control, exact=False):
        self.sp, self.materials, self.control, self.exact_refine = sp, sp.materials, control, exact
        self.tab = table(sp.materials)
        self.k = sp.k
        s = model.superpose(self.tab.unit, self.k)
        self.held, self.held_slope = CONTROLS[control].field, CONTROLS[control].field_slope
        self.a = self.tab.a
        self.y = getattr(s, self.held)
        self.slope_y = getattr(s, self.held_slope)
        self.stable = _stab.single_patch_flags(s, sp.work_shift)[control]
        self.feasible = s.gap_open

    def _spline(self, name, a, order=0):
        """A held quantity or its slope (``name``, a Slice field) at one a from the splines, or its a-derivative."""
        f = name if name in model.SLOPE_OF else next(g for g, s in model.SLOPE_OF.items() if s == name)
        return self.tab.point(f, a, self.k)[(0 if name == f else 1) + order]

    def _root(self, name, lo, hi, flo, fhi, target=0.0):
        """Where the field ``name`` equals target in [lo, hi] (a sign change of the node values; None: a pole): on
        the splines, then (exact=True) POLISH Newton steps on exact superposed states, the slope from the splines."""
        f = lambda x: self._spline(name, x) - target
        r = _roots.root(f, lo, hi, SEARCH_TOL * hi)
        if _roots.is_pole(f(r), flo - target, fhi - target):
            return None
        if not self.exact_refine:
            return r
        for _ in range(POLISH):
            value = float(getattr(model.superpose(model.unit_slices(self.materials, [r]), self.k), name)[0])
            step = (value - target) / self._spline(name, r, order=1)
            r = min(max(r - step, lo), hi)
            if abs(step) <= 1e-14 * r:
                break
        return r

    def state_at(self, a):
        return self.sp.states([float(a)])

    def index(self, a):
        return int(np.argmin(np.abs(np.log(self.a) - math.log(a))))

    def exact(self, j, k, target):
        """The state between nodes j, k where the held quantity equals target."""
        lo, hi = sorted((j, k))
        r = self._root(self.held, float(self.a[lo]), float(self.a[hi]), float(self.y[lo]), float(self.y[hi]), target)
        return self.state_at(self.a[k] if r is None else r)

    def fold_a(self, j):
        """a of the stationary point of the held quantity in a table cell next to node j (its slope changes sign
        there), or node j itself when neither cell brackets one."""
        v = self.slope_y
        for i in (j - 1, j):
            if 0 <= i < v.size - 1 and np.sign(v[i]) * np.sign(v[i + 1]) < 0:
                r = self._root(self.held_slope, float(self.a[i]), float(self.a[i + 1]), float(v[i]), float(v[i + 1]))
                if r is not None:
                    return r
        return float(self.a[j])

    def fold(self, j):
        return self.state_at(self.fold_a(j))

    def first_contact(self):
        """Node index of the smallest stable, feasible state where the held quantity is 0 (and its a), or None."""
        for r, _ in _roots.roots_on_grid(self.y, self.a, lambda lo, hi, flo, fhi: self._root(self.held, lo, hi,
                                                                                              flo, fhi)):
            i = int(np.searchsorted(self.a, r))
            near = slice(max(i - 1, 0), i + 1)          # the flags of the cell's nodes, where they agree ...
            ok = self.stable[near] & self.feasible[near]
            if ok.all() != ok.any():                   # ... else the core's rule at the root itself
                s = model.superpose(model.unit_slices(self.materials, [r]), self.k)
                ok = _stab.single_patch_flags(s, self.sp.work_shift)[self.control] & s.gap_open
            if ok.all():
                return self.index(r), r
        return None


def segment(sp, control):
    """(a_lo, a_hi): the part of the sub-critical branch the path from first contact reaches under control
    ('load' or 'grip-work') for the contact of a jkrcyl.fit.model.Superposed: walked down to its pull-off (or where
    the gap at the top closes) and up to where it turns, closes the gap or the table ends.  The whole table where
    first contact lands elsewhere."""
    tr = Track(sp, control)
    start = tr.first_contact()
    if start is None:
        return tr.a[0], tr.a[-1]
    ends = []
    for target in (-math.inf, math.inf):
        _, event, s = _path.walk(tr, start[0], target)
        ends.append(float(s.a[0]))
    return min(ends), max(ends)


class PullOff:
    """The fit's fixed-load pull-off: P [N/m] (None: no detachment), the state there (a, width [m]), why."""

    def __init__(self, P, a=None, width=None, reason=""):
        self.P, self.a, self.width, self.reason = P, a, width, reason

    def __repr__(self):
        return f"PullOff(P={self.P!r}, a={self.a!r}, reason={self.reason!r})"


def pull_off(c, materials, control="load") -> PullOff:
    """Detachment along the path from first contact (jkrcyl.analysis.pull_off's path, walked on this branch's
    track with exact refinement); Contact.pull_off itself where first contact is not on it."""
    if c.w == 0:
        return PullOff(None, reason="no adhesion (w = 0)")
    tr = Track(model.Superposed.of(c, materials), control, exact=True)
    start = tr.first_contact()
    if start is None:
        return _core(c, control)
    _, event, s = _path.walk(tr, start[0], -math.inf)
    if event != "fold":
        return _core(c, control)        # the gap closes first, or the table ends: the core says what follows
    a = float(s.a[0])
    sl = model.superpose(model.unit_slices(materials, [a]), tr.k)
    if _stab.fixed_arc_derivatives(sl, tr.sp.work_shift)[control][0] > 0:
        return _core(c, control)        # a further pull closes the edge: the contact grows, no detachment
    return PullOff(float(s.P[0]), a, float(model.width_of_a(a, c.R)), "detachment: the contact shrinks away")


def _core(c, control):
    po = c.pull_off(control=control)
    a = None if po.state is None else po.state.a
    return PullOff(po.P, a, po.contact_width, po.reason)
