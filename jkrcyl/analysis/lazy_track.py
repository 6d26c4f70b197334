"""A single-patch track whose stability and feasibility are computed only where a walk reads them.

jkrcyl.analysis.path.SingleTrack takes a branch's whole table (jkrcyl.analysis.branches.table): every state's
slopes, stability flags and feasibility.  For the cohesive law a table point's slopes cost two collocation LUs and
its feasibility a gap check on ~240 exterior angles (jkrcyl.numerics.cohesive.gap_check), while its held values
(p, delta, delta_work) come from the trace's cached contacts (SinglePatch.table_values).  :class:`LazyTrack`
holds those values and computes the flags of a grid index when first read: a walk (jkrcyl.analysis.path.walk)
reads them only at the points it passes and in the cell of its event, and a fold is refined from the slopes of
that cell alone.  The flags and slopes are the table's own (the same per-point data, the same arithmetic), so a
walk on either track passes the same points and ends at the same event and state (tests/test_lazy_track.py).
"""
from __future__ import annotations

import numpy as np

from ..model.problem import Problem
from ..model.single_patch import solver
from ..model import stability as _stab
from ..units import CONTROLS, CURVE_FIELD, Units
from . import branches as _br
from . import path as _path

_EAGER = _path.SingleTrack       # (the walker's own class, whatever path.SingleTrack is later bound to)


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


class LazyTrack(_EAGER):
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

    def fold_a(self, j):
        """As SingleTrack.fold_a, from the slopes of the cells either side of j only."""
        field = CONTROLS[self.control].field_slope
        sv = solver(self.pb)
        for i in (j - 1, j):
            if 0 <= i < len(self._a) - 1:
                lo, hi = self._slice(self._a[i], "slope"), self._slice(self._a[i + 1], "slope")
                if np.sign(lo) * np.sign(hi) < 0:
                    r = sv.root(field, self._a[i], self._a[i + 1], lo, hi)
                    if r is not None:
                        return r
        return float(self.a[j])


def track(pb: Problem, un: Units, regime: str, side: str, control: str):
    """The track of a single-patch branch: a :class:`LazyTrack` where the solver gives the held values without
    its table (SinglePatch.table_values, the cohesive law), else jkrcyl.analysis.path.SingleTrack."""
    if solver(pb).table_values(regime, "p") is None:
        return _EAGER(pb, un, regime, side, control)
    return LazyTrack(pb, un, regime, side, control)
