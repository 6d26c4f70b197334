"""Pull-off at a rate, any prescribed history, and cycles at a rate (what Contact.pull_off(rate=...),
Contact.respond and Contact.cycle(rate=...) call).

Each starts from an equilibrium at rest: the zero-load contact the pin snaps into at first contact (the
quasi-static path of jkrcyl.analysis.path), or for :func:`respond` the state that path reaches at the first held
value.  The held quantity is then driven linearly, piece by piece (jkrcyl.kinetics.run).
"""
from __future__ import annotations

import numpy as np

from .._validate import count, finite_scalar, real_array
from ..laws.kinetic import kinetics_of
from ..units import CONTROLS
from .history import TERMINAL
from .results import RateCycle, RatePullOff
from .run import Run, rest_start

MAX_RAMPS = 40             # a pull-off ramp is extended by factors of 4 at most this often
MAX_LOOPS = 60             # cycles driven at most until the loop repeats
LOOP_REPEATS = 1e-6        # relative change of the loop's work from one cycle to the next that counts as a repeat


def check_rate(rate) -> float:
    return finite_scalar("rate", rate, low=0.0, low_open=True)


def _none(control, rate, why):
    return RatePullOff(control, None, None, None, None, why, rate=rate)


def pull_off(contact, control: str, rate: float, route: str = "table", rtol: float = None) -> RatePullOff:
    """Ramp the load (P = -rate t, rate [N/m/s]) or the held approach (delta_w or delta = delta0 - rate t, rate
    [m/s]) from the zero-load contact at rest until an event ends the single patch (jkrcyl.kinetics.results)."""
    kinetics_of(contact.law)                 # control: checked by the callers (Contact.pull_off, rate_sweep)
    rate = check_rate(rate)
    if contact.w == 0:
        return _none(control, rate, "no adhesion (w = 0): the contact vanishes at P = 0")
    start, why = rest_start(contact, control)
    if start is None:
        return _none(control, rate, why)
    run = Run(contact, control, start, start.a, route, rtol)
    # the ramp's time scale: the adhesive part of the held quantity at the start over the rate, extended by
    # factors of 4 until an event
    t1, x0, end = run.ode.x1_ref * run.unit / rate, start.held(control), ""
    for _ in range(MAX_RAMPS):
        end = run.drive(t1, x0 - rate * t1, peak=control != "load")
        if end:
            break
        t1 *= 4.0
    hist = run.history()
    if end not in TERMINAL:
        return RatePullOff(control, None, None, None, None, f"no event up to t = {hist.t[-1]:.6g} s "
                           f"({CONTROLS[control].physical} = {x0 - rate * hist.t[-1]:.6g})", rate=rate, history=hist)
    i = hist.peak
    ev = hist.events[-1]
    what = {"separation": "the contact vanished", "top-contact": "the gap at phi = pi closed first",
            "range-end": "the contact grew to the end of the modelled single patch"}[end]
    if end == "range-end":
        return RatePullOff(control, None, None, None, None, what, kind=end, rate=rate, history=hist)
    return RatePullOff(control, float(hist.P[i]), float(hist.contact_width[i]), ev.delta, None,
                       f"{end}: {what} at t = {ev.t:.6g} s", kind=end, rate=rate, history=hist,
                       delta_work_at_event=ev.delta_work)


def respond(contact, t, P=None, delta_work=None, delta=None, route: str = "table", rtol: float = None):
    """The History under the held quantity given at the instants t [s] (increasing), linear in between: P [N/m],
    delta_work or delta [m] (exactly one), from the equilibrium at rest at its first value."""
    kinetics_of(contact.law, "t")
    given = {k: v for k, v in (("P", P), ("delta_work", delta_work), ("delta", delta)) if v is not None}
    if len(given) != 1:
        raise ValueError("P: give exactly one of P [N/m], delta_work [m] and delta [m] (arrays, one per t)")
    (name, values), = given.items()
    control = {"P": "load", "delta": "grip", "delta_work": "grip-work"}[name]
    t, x = real_array("t", t).ravel(), real_array(name, values).ravel()
    if t.size < 2 or t.size != x.size:
        raise ValueError(f"t must have at least 2 instants and as many as {name} ({x.size}), got {t.size}")
    if not (np.all(np.isfinite(t)) and np.all(np.isfinite(x))):
        raise ValueError(f"t and {name} must be finite")
    if not np.all(np.diff(t) > 0):
        raise ValueError("t must be strictly increasing")
    if contact.w == 0:
        raise ValueError("w must be > 0 for crack kinetics (without adhesion the edges carry no crack)")
    start, why = rest_start(contact, control, float(x[0]))
    if start is None:
        raise ValueError(f"{name}: {why}")
    run = Run(contact, control, start, _largest_contact(contact, control, start, x.max()), route, rtol, t[0])
    for k in _corners(t, x)[1:]:
        if run.drive(float(t[k]), float(x[k]), peak=control != "load", times=t, energy=True):
            break
    return run.history()


def _corners(t, x):
    """The indices where the piecewise-linear history changes slope (and both ends): one segment per piece."""
    slope = np.diff(x) / np.diff(t)
    scale = np.max(np.abs(slope)) + 1e-300
    turn = np.nonzero(np.abs(np.diff(slope)) > 1e-12 * scale)[0] + 1
    return [0, *turn.tolist(), t.size - 1]


def _largest_contact(contact, control, start, x_max):
    """The largest contact the history can reach: the equilibrium at its largest held value on the branch of
    the start (a kinetic contact lags behind it; at least the start)."""
    if x_max <= start.held(control):
        return start.a
    s, _ = rest_start(contact, control, float(x_max))
    return start.a if s is None else max(start.a, s.a)


def cycle(contact, control, hi, lo, rate, n=2000, route="table", rtol=None) -> RateCycle:
    """Drive the held quantity from the zero-load contact at rest up to hi, down to lo and up again at ``rate``
    until the contact at the top repeats (:data:`LOOP_REPEATS`) or an event ends the single patch."""
    kinetics_of(contact.law)
    rate = check_rate(rate)
    n = count("n", n, low=10)
    start, why = rest_start(contact, control)
    if start is None or contact.w == 0:
        raise ValueError(f"rate: {why or 'no adhesion (w = 0)'}: no cycle to drive")
    x0 = start.held(control)
    if not lo < x0 < hi:
        raise ValueError(f"{CONTROLS[control].physical}: the cycle must contain the start at rest, "
                         f"{lo!r} < {x0!r} < {hi!r}")
    run = Run(contact, control, start, _largest_contact(contact, control, start, hi), route, rtol)
    legs, tops, loops, end, repeated = [0], [], [], "", False
    t, x = 0.0, x0
    for k in range(2 * MAX_LOOPS + 1):
        target = hi if k % 2 == 0 else lo
        t += abs(target - x) / rate
        x = target
        end = run.drive(t, target, peak=control != "load", energy=True)
        legs.append(len(run.rows) - 1)
        if end:
            break
        if k % 2 == 0:
            tops.append(len(run.rows) - 1)
            if len(tops) >= 2:
                loops.append(_loop_work(run, tops[-2], tops[-1]))
            if len(loops) >= 2 and abs(loops[-1] - loops[-2]) <= LOOP_REPEATS * abs(loops[-1]):
                repeated = True
                break
    hist = run.history()
    energy = edge = None
    if len(tops) >= 2 and not end:
        i, j = tops[-2], tops[-1]
        energy, edge = float(hist.work[j] - hist.work[i]), float(hist.dissipated[j] - hist.dissipated[i])
    leg_of = np.searchsorted(np.array(legs[1:]), np.arange(len(hist.t)), side="left")
    keep = np.unique(np.linspace(0, len(hist.t) - 1, min(n, len(hist.t))).astype(int))
    note = "" if repeated else (f"{end}: the single patch ended at t = {hist.t[-1]:.6g} s" if end else
                                f"the loop's work still changed by {abs(loops[-1] / loops[-2] - 1):.2g} per cycle "
                                f"after {MAX_LOOPS} cycles (dissipated: the last loop's)")
    a = np.tan(hist.eps / 2)
    return RateCycle(control=control, P=hist.P[keep], delta=hist.delta[keep], branch=np.full(keep.size, "kinetic"),
                     a=a[keep], stable=np.zeros(keep.size, bool), leg=leg_of[keep], jumps=[], dissipated=energy,
                     closed_from_leg=(len(legs) - 3) if repeated else None, delta_work=hist.delta_work[keep],
                     note=note, limits=(lo, hi), rate=rate, frequency=rate / (2 * (hi - lo)), history=hist,
                     edge_dissipation=edge)


def _loop_work(run, i, j):
    """int P d(delta_work) between recorded rows i and j (kernel units: the History's work column there)."""
    W = run.ode.record(np.array([run.rows[i], run.rows[j]]).T, np.array([run.held_at[i], run.held_at[j]]))[8]
    return float(W[1] - W[0])
