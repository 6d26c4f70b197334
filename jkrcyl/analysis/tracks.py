"""Tracks: a single-patch branch as a polyline in the held quantity, what the walker (jkrcyl.analysis.path.walk)
walks along.  :class:`SingleTrack` takes the branch's whole table (jkrcyl.analysis.branches.table): every
state's slopes, stability flags and feasibility.  :class:`LazyTrack` computes the flags of a grid index only when
a walk reads it: for the cohesive law a table point's slopes cost two collocation LUs and its feasibility a gap
check on ~240 exterior angles (jkrcyl.numerics.cohesive.gap_check), while its held values (p, delta,
delta_work) come from the trace's cached contacts (SinglePatch.table_values); a walk reads the flags only at
the points it passes and in the cell of its event, and a fold is refined from the slopes of that cell alone.
The flags and slopes are the table's own (the same per-point data, the same arithmetic), so a walk on either
track passes the same points and ends at the same event and state (tests/test_lazy_track.py).  :func:`track`
picks the lazy one where the solver gives held values without its table.
"""
from __future__ import annotations

import math

import numpy as np

from ..model.problem import Problem
from ..model.single_patch import solver
from ..model import stability as _stab
from ..units import CONTROLS, CURVE_FIELD, Units
from . import branches as _br
from . import forward as _fw


class SingleTrack:
    """A single-patch branch (bottom or top, the mirror) on its dense table, the held quantity physical."""

    def __init__(self, pb: Problem, un: Units, regime: str, side: str, control: str):
        c = _br.table(pb, regime)
        self.pb, self.un, self.regime, self.side, self.control = pb, un, regime, side, control
        self.name = regime + ("-top" if side == "top" else "")
        self.a = np.asarray(c.a)
        sgn = -1.0 if side == "top" else 1.0
        self.P = un.physical("load", sgn * np.asarray(c.P_star))
        d, dw = np.asarray(c.delta_over_Delta), np.asarray(c.delta_work_over_Delta)
        self.delta = un.physical("grip", -2 - d if side == "top" else d)
        self.delta_work = un.physical("grip-work", -2 - dw if side == "top" else dw)
        self.stable = np.asarray(getattr(c, CONTROLS[control].stable))
        self.feasible = np.asarray(c.feasible)

    @property
    def y(self):
        return getattr(self, CONTROLS[self.control].physical)

    def state_at(self, a):
        return _fw.single_patch_states(self.pb, self.un, self.regime, a, self.control, self.side)[0]

    def _field_target(self, value):
        """The solver field of the held quantity and the bottom branch's target for a physical value."""
        ctl = CONTROLS[self.control]
        if ctl.is_load:                                     # mirror: P -> -P, either approach -> -2 Delta - itself
            return ctl.field, self.un.to_kernel("load", -value if self.side == "top" else value)
        t = self.un.to_kernel(self.control, value)
        return ctl.field, (-2 - t if self.side == "top" else t)

    def exact(self, j, k, target):
        """The state between grid indices j, k where the held quantity equals target."""
        field, t = self._field_target(target)
        lo, hi = sorted((float(self.a[j]), float(self.a[k])))
        sv = solver(self.pb)
        flo, fhi = sv.value(field, lo) - t, sv.value(field, hi) - t
        r = sv.root(field, lo, hi, flo, fhi, t) if flo * fhi < 0 else None
        return self.state_at(float(self.a[k]) if r is None else r)

    def slope(self, i):
        """The held quantity's slope along the branch at grid index i (the table's Curve column, kernel scale)."""
        name, scaled = CURVE_FIELD[CONTROLS[self.control].field_slope]
        return float(getattr(_br.table(self.pb, self.regime), name)[i]) * (self.pb.scale if scaled else 1.0)

    def fold_a(self, j):
        """Contact parameter of the stationary point of the held quantity next to grid index j: the sign change
        of its slope in the table cell on either side of j, refined exactly as branches.roots refines it (the
        same bracket, so the same double as jkrcyl.analysis.branches.stationary_roots)."""
        field = CONTROLS[self.control].field_slope
        sv = solver(self.pb)
        for i in (j - 1, j):
            if 0 <= i < self.a.size - 1:
                lo, hi = self.slope(i), self.slope(i + 1)
                if np.sign(lo) * np.sign(hi) < 0:
                    r = sv.root(field, float(self.a[i]), float(self.a[i + 1]), lo, hi)
                    if r is not None:
                        return r
        return float(self.a[j])

    def fold(self, j):
        return self.state_at(self.fold_a(j))

    def index(self, a):
        return int(np.argmin(np.abs(np.log(self.a) - math.log(a))))


class Column:
    """A read-only column of a track: value k computed by compute(k) on first read (what a walk reads: col[k],
    col.size)."""

    def __init__(self, size: int, compute):
        self.size, self._compute, self._seen = size, compute, {}

    def __len__(self):
        return self.size

    def __getitem__(self, k):
        k = int(k)
        if not 0 <= k < self.size:
            raise IndexError(f"k must be in [0, {self.size}), got {k}")
        if k not in self._seen:
            self._seen[k] = self._compute(k)
        return self._seen[k]

    @property
    def computed(self) -> int:
        """How many entries have been computed (the work a walk caused)."""
        return len(self._seen)


class LazyTrack(SingleTrack):
    """A SingleTrack (bottom or top, the mirror) on its solver's table grid with the held quantities from
    SinglePatch.table_values and ``stable``, ``feasible`` as :class:`Column` s (module docstring)."""

    def __init__(self, pb: Problem, un: Units, regime: str, side: str, control: str):
        self.pb, self.un, self.regime, self.side, self.control = pb, un, regime, side, control
        self.name = regime + ("-top" if side == "top" else "")
        sv = solver(pb)
        self.a, p = _br.table_values(pb, regime, "p")
        d, dw = _br.table_values(pb, regime, "dn")[1], _br.table_values(pb, regime, "dw")[1]
        sgn = -1.0 if side == "top" else 1.0
        self.P = un.physical("load", sgn * (p / pb.scale))               # as the table's P* = p/scale
        self.delta = un.physical("grip", -2 - d if side == "top" else d)
        self.delta_work = un.physical("grip-work", -2 - dw if side == "top" else dw)
        a = [float(x) for x in self.a]
        self.stable = Column(len(a), lambda k: bool(self._slice(a[k], "stable")))
        self.feasible = Column(len(a), lambda k: bool(sv.point(a[k]).feasible))
        self._a = a

    def _slice(self, a, what):
        """The stability flag under this control, or the held quantity's slope as the table holds it (its Curve
        column, scaled back to the kernel scale: the same arithmetic as branches.table_values)."""
        s = solver(self.pb).states([a])
        if what == "stable":
            return _stab.single_patch_flags(s, self.pb.work_shift)[self.control][0]
        name, scaled = CURVE_FIELD[CONTROLS[self.control].field_slope]
        k = self.pb.scale
        column = {"dP_star_da": s.dp_da / k, "ddelta_da": s.ddn_da, "ddelta_work_da": s.ddw_da}[name]
        return float(column[0] * (k if scaled else 1.0))

    def slope(self, i):
        """As SingleTrack.slope, from the state at grid index i alone."""
        return self._slice(self._a[i], "slope")


def track(pb: Problem, un: Units, regime: str, side: str, control: str):
    """The track of a single-patch branch: a :class:`LazyTrack` where the solver gives the held values without
    its table (SinglePatch.table_values, the cohesive law), else :class:`SingleTrack`."""
    if solver(pb).table_values(regime, "p") is None:
        return SingleTrack(pb, un, regime, side, control)
    return LazyTrack(pb, un, regime, side, control)
