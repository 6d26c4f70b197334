"""A contact driven in time: the start at rest, the integration segment by segment, the History it records.

:class:`Run` holds one contact, control and law: the edge equation (jkrcyl.kinetics.integrate) on the arc
states of one route (jkrcyl.kinetics.arc: 'table', the default, or 'direct'), starting from an equilibrium at
rest, and collects the states of every segment (linear pieces of the drive) into a :class:`History` in SI units.
"""
from __future__ import annotations

import functools
import math

import numpy as np

from ..analysis import landing as _land
from ..analysis import path as _path
from ..analysis import tracks as _tracks
from ..analysis import reasons as _reasons
from ..laws.kinetic import kinetics_of
from . import integrate as _int
from .arc import DirectArc, TabulatedArc
from .history import Event, History

ROUTES = ("table", "direct")
GROWTH = 1.05           # the tabulated range reaches this far above the largest contact a drive can reach


def check_route(route) -> str:
    if not isinstance(route, str) or route not in ROUTES:
        raise ValueError(f"route must be one of {', '.join(repr(r) for r in ROUTES)}, got {route!r}")
    return route


@functools.lru_cache(maxsize=64)
def rest_start(contact, control: str, held=None):
    """The equilibrium at rest a drive starts from: the zero-load contact of first contact (the quasi-static
    path, jkrcyl.analysis.path) or, with ``held`` (the held quantity, SI), the state that path reaches at it.
    Returns (state, '') or (None, why not); cached per contact."""
    pb, un = contact.problem, contact.units
    _, to, _ = _land.first_contact(pb, un, "load")
    if to is None:
        return None, _reasons.no_first_contact_reason(pb)
    if to.branch != "sub-critical" or to.side != "bottom":
        return None, (f"the zero-load contact is on the {to.branch} branch (full contact, two patches or a "
                      "super-critical contact: crack kinetics are modelled for the sub-critical bottom patch)")
    if held is None:
        return to, ""
    track = _tracks.track(pb, un, to.branch, "bottom", control)
    _, event, s = _path.walk(track, track.index(to.a), held)
    if event != "target":
        return None, f"no stable contact at rest at the start of the history (the quasi-static path: {event})"
    return s, ""


class Run:
    """One contact driven under one control from an equilibrium at rest (kernel units inside, SI outside)."""

    def __init__(self, contact, control: str, start, a_max: float, route: str = "table", rtol: float = None,
                 t0: float = 0.0):
        self.law = kinetics_of(contact.law)
        self.contact, self.control = contact, control
        pb = self.problem = contact.problem
        self.units = contact.units
        self.rtol = _int.RTOL if rtol is None else rtol
        a0 = start.a
        if check_route(route) == "direct":
            arc = DirectArc(pb)
            arc.u_last = math.log(min(GROWTH * a_max, 0.5 * (a_max + arc.solver.a_crit)))
        else:
            hi = min(GROWTH * a_max, 0.5 * (a_max + float(DirectArc(pb).solver.a_crit)))
            arc = TabulatedArc(pb, math.log(a0 * _int.A_FLOOR), math.log(hi))
        self.ode = _int.EdgeODE(pb, self.law, contact.R, control, arc, a0)
        self.Y = np.array([t0, 1.0, 0.0, 0.0])               # (t, z, Q, D): at rest at t0
        self.held = self.to_kernel(start.held(control))
        self.rows, self.held_at, self.events, self.note = [self.Y.copy()], [self.held], [], ""
        self.ode.start(_int.Linear(t0, self.held, 0.0), 1.0)

    # --- units --------------------------------------------------------------------------------------------
    @property
    def unit(self) -> float:
        """SI per kernel unit of the held quantity: N/m (load) or m (either approach)."""
        return self.units.per_kernel(self.control)

    def to_kernel(self, value):
        return value / self.unit

    # --- driving --------------------------------------------------------------------------------------------
    def drive(self, t1: float, target: float, peak: bool = False, times=None, energy: bool = False) -> str:
        """Move the held quantity linearly from its present value to ``target`` (SI) at t1 [s]: the terminal
        event's kind, or '' (the drive reached t1).  ``times``: instants in (t, t1] to record besides the
        integrator's own steps; ``energy``: the work and dissipation under the integrator's error control."""
        t0, x1 = float(self.Y[0]), self.to_kernel(target)
        slope = (x1 - self.held) / (t1 - t0)
        drive = _int.Linear(t0, self.held, slope)
        steps, found, terminal = _int.segment(self.ode, drive, t1, self.Y, self.rtol, peak, times is not None,
                                               energy)
        pts = [(s, 1, Y, None) for s, Y, _ in steps]
        pts += [(s, 1, Y, None) for s, Y in _at_times(steps, t0, times)] if times is not None else []
        pts += [(s, 0, Y, kind) for kind, s, Y in found if kind != "segment-end"]
        last = None
        for s, _, Y, kind in sorted(pts, key=lambda e: (e[0], e[1])):
            if kind is None and s == last:
                continue                                    # a step where an event was recorded
            last = s
            if kind == "separation":
                Y = Y.copy()
                Y[1] = 0.0                                  # exactly gone (the event's root is z = 0)
            self.rows.append(Y)
            self.held_at.append(drive.value(float(Y[0])))
            if kind is not None:
                self.events.append((kind, len(self.rows) - 1, drive))
        self.Y = np.array(steps[-1][1])
        self.held = drive.value(float(self.Y[0])) if terminal else x1
        return terminal

    def _note(self):
        if not self.ode.relaxed:
            return self.note
        return (self.note + "; " if self.note else "") + (
            f"tolerance relaxed to {self.ode.relaxed:g} where G/w - 1 fell to rounding (the contact at its "
            "equilibrium)")

    def history(self) -> History:
        """The states recorded so far, in SI units."""
        un, ode = self.units, self.ode
        Y = np.array(self.rows).T
        t, p, dn, dw, eps, x, V, h, W, D, total = ode.record(Y, np.array(self.held_at))
        W = W - W[0]                                       # the work since the start
        w = self.contact.law.edge_work(self.contact.w)
        P = self.units.from_kernel("load", p)
        hist = History(control=self.control, t=t, P=P, delta=dn * un.Delta, delta_work=dw * un.Delta, eps=eps,
                       contact_width=2 * un.R * eps, G=w * x, v=V, h_pi=h * un.Delta, work=W * un.energy_scale,
                       dissipated=D * un.energy_scale, potential=total * un.energy_scale, note=self._note())
        # a peak of the tension is an event where it is the largest so far (not a wiggle of a tracked plateau)
        events = tuple(Event(kind, float(t[i]), float(P[i]), float(hist.delta[i]), float(hist.delta_work[i]), i)
                       for kind, i, _ in self.events if kind != "peak-tension" or P[i] <= P[:i + 1].min())
        return History(**{**hist.__dict__, "events": events})


def _at_times(steps, t0, times):
    """[(s, state)] at the instants ``times`` inside the segment: t(s) increases, so each s is found by bisection
    on the dense output of its step (60 halvings: to the last bit of s)."""
    t_steps = np.array([t0] + [Y[0] for _, Y, _ in steps])
    times = np.asarray(times, dtype=float)
    out = []
    for tq in times[(times > t_steps[0]) & (times < t_steps[-1])]:
        j = int(np.searchsorted(t_steps, tq))               # the step ending at or after tq
        key, _, dense = steps[j - 1]
        lo, hi = dense.t_old, dense.t
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if dense(mid)[0] < tq else (lo, mid)
        Y = dense(hi)
        Y[0] = tq
        out.append(((key[0], hi), Y))
    return out
