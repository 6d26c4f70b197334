"""The edge equation of a single patch with crack kinetics, integrated in time.

Both edges of the bottom patch move at the crack speed V(G/w) of the law (jkrcyl.laws.kinetic; positive
opening), so d eps/dt = -V/R, with G/w = g|g| and g = (X(t) - X0(a))/X1(a) fixed by the held quantity X(t)
(p, delta/Delta or delta_work/Delta; jkrcyl.kinetics.arc).

Two devices keep the equation regular:

* the contact vanishes in finite time: near separation G ~ X^2/a and V ~ a^(-1/n) (power law), so a^(1 + 1/n)
  falls at a finite rate, and the state variable is z = (a/a_ref)^q, q = 1 + 1/n (separation: z = 0, an event);
* past a fold of the quasi-static branch the edges run away in a time that may be far below the resolution of t
  (v* -> inf: the quasi-static limit): where |dz/dt| exceeds RUNAWAY times the drive's own rate of z, the
  integration restarts with its time origin there, so that the run-away is resolved in the offset from it.

The work on the pin W = int p d(dw) and the dissipation D = int 2 m^2 (G/w - 1)(-d eps) (kernel energy units,
4 pi Delta^2/beta*) are integrated alongside, W by parts so that its integrand holds no rate of the state (which
is rounding noise where the contact tracks its equilibrium): W = Q + B(t) - B(t_0), dQ/dt = -dw dX/dt with
B = X dw under load (X = p), dQ/dt = p dX/dt with B = 0 under grip-work (X = dw) and B = c p^2/2 under grip
(X = dn, dw = dn + c p).  scipy's LSODA (Adams where the contact runs, BDF where it relaxes
stiffly onto its equilibrium) with the analytic Jacobian, stepped here; events (separation, h(pi) = 0, the peak
tension, the end of the tabulated range, the run-away) are roots on its dense output.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np
from scipy.integrate import LSODA, Radau

from ..numerics import roots as _roots
from .arc import B0, B1, DN0, DN1, DW0, DW1, H0, H1, HELD, P0, P1

A_FLOOR = 1e-12        # a/a_ref below which the states are those at the floor (the time left there is negligible)
RUNAWAY = 1e3          # |dz/dt| over the drive's rate F_ref at which the integration restarts its time origin
RTOL = 1e-10           # default relative tolerance of the integrator
RTOL_MAX = 1e-7        # where the contact tracks its equilibrium within G/w - 1 ~ 1e-8 and below, that difference
#                        is rounding noise (a cancellation of held and equilibrium values) and the implicit solve
#                        cannot meet a tight tolerance: it is relaxed, tenfold at a time, up to this
FIRST_STEP = 1e-12     # of the segment: LSODA restarts mid-way on a stiff slow manifold from a tiny step
ATOL_ENERGY = 1e-4     # of rtol times the adhesion energy of the reference contact: the error control of Q, D
#                        where asked for (cycles: the loop's energy is the answer; where the contact tracks its
#                        equilibrium stiffly that control costs many steps, so pull-offs go without)
CRAWL_STEPS = 500      # LSODA steps in a row below CRAWL_STEP of the segment: it is stuck at its explicit (Adams)
CRAWL_STEP = 1e-8      # stability limit on a stiff path whose rates are rounding noise; Radau takes over there
MAX_STEPS = 200_000    # steps of one segment (a few thousand in the hardest cases measured): beyond, a ValueError
EVENT_KINDS = ("separation", "top-contact", "range-end", "peak-tension", "runaway")


@dataclass(frozen=True)
class Linear:
    """A held quantity (kernel units) linear in time: x0 + slope (t - t0)."""

    t0: float
    x0: float
    slope: float

    def value(self, t):
        return self.x0 + self.slope * (t - self.t0)


class EdgeODE:
    """The edge equation of one problem, law and control (module docstring); lengths in kernel units, t [s]."""

    def __init__(self, problem, law, R: float, control: str, arc, a_ref: float):
        self.problem, self.law, self.R, self.control, self.arc = problem, law, R, control, arc
        self.i0, self.i1 = HELD[control]
        self.q = 1.0 + 1.0 / law.n
        self.u_ref = math.log(a_ref)
        self.z_floor = A_FLOOR ** self.q
        self.m2 = problem.m ** 2
        self.c = problem.work_shift
        self.x1_ref = abs(arc.at(self.u_ref)[0][self.i1])     # the adhesive scale of the held quantity
        self.energy_atol = self.m2 * a_ref                    # the adhesion energy of the reference contact
        self.drive, self.F_ref, self.t_origin, self.relaxed = None, 1.0, 0.0, 0.0

    def start(self, drive: Linear, duration: float):
        """Set the drive of a segment and the rate F_ref of z it imposes (or 1/duration for a hold)."""
        self.drive = drive
        self.F_ref = max(abs(drive.slope) / self.x1_ref, 1.0 / duration)

    # --- the state at (t, z) --------------------------------------------------------------------------------
    def local(self, t, z, held=None):
        """(a, y, dy/du, g, x = G/w, V [m/s], du/dt, dg/dt) at time t and z (held at the floor below it), the
        held quantity the drive's at t or ``held``."""
        z = max(z, self.z_floor)
        u = self.u_ref + math.log(z) / self.q
        a = math.exp(u)
        y, dy = self.arc.at(u)
        i0, i1 = self.i0, self.i1
        g = ((self.drive.value(t) if held is None else held) - y[i0]) / y[i1]
        x = g * abs(g)
        V = self.law.speed(x)
        du_dt = -V / self.R * (1.0 + a * a) / (2.0 * a)
        dg_dt = (self.drive.slope - (dy[i0] + g * dy[i1]) * du_dt) / y[i1]
        return a, y, dy, g, x, V, du_dt, dg_dt

    def fun(self, tau, Y):
        """d(z, Q, D)/dtau at t = t_origin + tau."""
        t, z = self.t_origin + tau, max(Y[0], self.z_floor)
        a, y, dy, g, x, V, du_dt, dg_dt = self.local(t, z)
        held = y[DW0] + g * y[DW1] if self.control == "load" else -(y[P0] + g * y[P1])
        return np.array([self.q * z * du_dt, -held * self.drive.slope, 2.0 * self.m2 * (x - 1.0) * V / self.R])

    def jac(self, tau, Y):
        """d(fun)/d(z, Q, D): exact in z; Q and D do not feed back, and their rows are left 0 (Newton's iteration
        on them then converges with that on z)."""
        t, z = self.t_origin + tau, max(Y[0], self.z_floor)
        a, y, dy, g, x, V, du_dt, _ = self.local(t, z)
        i0, i1 = self.i0, self.i1
        geo = (1.0 + a * a) / (2.0 * a)
        dx_du = 2.0 * abs(g) * (-(dy[i0] + g * dy[i1]) / y[i1])
        J = np.zeros((3, 3))
        J[0, 0] = (self.q * du_dt + (a * a - 1.0) / (2.0 * a) * (-V / self.R)
                   - geo * self.law.speed_slope(x) / self.R * dx_du)
        return J

    # --- events -------------------------------------------------------------------------------------------
    def watch(self, t, Y):
        """The event functions at time t and state Y = (z, Q, D), in the order of :data:`EVENT_KINDS`: z
        (separation), h(pi)/Delta, the distance to the end of the tabulated range, p (its smallest value, the
        peak tension, is found by :func:`peaks`, not as a root), |dz/dt| - RUNAWAY F_ref."""
        z = Y[0]
        a, y, dy, g, x, V, du_dt, dg_dt = self.local(t, z)
        u = self.u_ref + math.log(max(z, self.z_floor)) / self.q
        run = abs(self.q * max(z, self.z_floor) * du_dt) - RUNAWAY * self.F_ref
        return np.array([z, y[H0] + g * y[H1], self.arc.u_last - u, y[P0] + g * y[P1], run])

    # --- the record of states ---------------------------------------------------------------------------------
    def record(self, Y, held):
        """Columns (t, p, dn, dw, eps, G/w, V, h, W, D, potential) of states Y (4 x k) at the held values ``held``
        (k), kernel units; where the contact is gone (z at the floor) eps = 0 and G/w, V are infinite."""
        t, z = Y[0], np.maximum(Y[1], self.z_floor)
        rows = [self.local(ti, zi, xi) for ti, zi, xi in zip(t, z, held)]
        a = np.array([r[0] for r in rows])
        y = np.array([r[1] for r in rows]).reshape(-1, 10)
        g, x, V = (np.array([r[k] for r in rows]) for k in (3, 4, 5))
        p, dn, dw = y[:, P0] + g * y[:, P1], y[:, DN0] + g * y[:, DN1], y[:, DW0] + g * y[:, DW1]
        h, B = y[:, H0] + g * y[:, H1], y[:, B0] + g * y[:, B1]
        eps = 2.0 * np.arctan(a)
        total = 0.5 * ((1.0 + dn) * p - B) - 2.0 * self.m2 * eps + 0.5 * self.c * p * p
        gone = Y[1] <= self.z_floor
        eps, x, V = np.where(gone, 0.0, eps), np.where(gone, np.inf, x), np.where(gone, np.inf, V)
        if self.control != "load" and gone.any():          # the free pin at the held approach: no load, no contact
            p, dn, dw, total = (np.where(gone, v, q) for v, q in ((0.0, p), (held, dn), (held, dw), (0.0, total)))
        return t, p, dn, dw, eps, x, V, h, Y[2] + self.boundary(held, p, dw), Y[3], total

    def boundary(self, held, p, dw):
        """B of W = Q + B - B(t_0) (module docstring), at the rows' held values, loads and approaches; the caller
        subtracts its value at the start."""
        if self.control == "load":
            return held * dw
        return 0.5 * self.c * p * p if self.control == "grip" else np.zeros_like(p)


#: the direction in which each event function crosses zero, and whether the event ends the segment
DIRECTION = np.array([-1, -1, -1, 0, 1])
TERMINAL = np.array([True, True, True, False, False])


class Dense:
    """The dense output of one step as a function of the time offset tau from its origin, giving (t, z, Q, D)."""

    def __init__(self, out, t_origin):
        self.out, self.t_origin, self.t_old, self.t = out, t_origin, out.t_old, out.t

    def __call__(self, tau):
        return np.concatenate([[self.t_origin + tau], self.out(tau)])


def segment(ode: EdgeODE, drive: Linear, t1: float, Y0, rtol=RTOL, peak=False, dense=False, energy=False):
    """Integrate from Y0 = (t0, z, Q, D) to t1 under a linear drive.  Returns (steps, events, terminal):
    steps [(key, Y, dense output or None)] after the start, events [(kind, key, Y)] in order (key: a sortable
    position along the segment), the terminal kind ('' at t1).  ``energy``: Q and D under the error control too
    (else they follow the steps of z).  Events are roots of :meth:`EdgeODE.watch` on the step's dense output
    (Brent, to adjacent doubles in time); ``peak``: the peak tensions too (:func:`peaks`).  Where the contact
    runs away (|dz/dt| > RUNAWAY F_ref: past a fold of a stiff, nearly quasi-static path it vanishes in a time
    that may lie below the resolution of t) the integration restarts with its time origin there."""
    t0 = float(Y0[0])
    ode.start(drive, t1 - t0)
    steps, events, restart, armed, Y = [], [], 0, True, np.asarray(Y0, dtype=float)
    method, crawl, taken = LSODA, 0, 0
    while True:
        ode.t_origin = t_o = float(Y[0])
        e = rtol * ATOL_ENERGY * ode.energy_atol if energy else 1e300
        solver = method(ode.fun, 0.0, Y[1:], t1 - t_o, rtol=rtol, atol=np.array([rtol * 1e-4, e, e]),
                       jac=ode.jac, first_step=min(FIRST_STEP * (t1 - t0), 0.5 * (t1 - t_o)))
        before = ode.watch(t_o, solver.y)
        runaway = False
        while solver.status == "running" and not runaway:
            tau_old = solver.t
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", UserWarning)          # lsoda's own words on a failure
                solver.step()
            if solver.status == "failed":
                if rtol >= RTOL_MAX:
                    x = ode.local(t_o + solver.t, solver.y[0])[4]
                    raise ValueError(f"rate: too slow to resolve: at t = {t_o + solver.t:.6g} s the contact "
                                     f"follows its equilibrium within rounding (G/w - 1 = {x - 1:.2g}): the "
                                     f"quasi-static answer (no rate) holds there; the integrator cannot resolve "
                                     f"the lag")
                rtol = min(10.0 * rtol, RTOL_MAX)                  # G/w - 1 below rounding: see RTOL_MAX
                ode.relaxed = max(ode.relaxed, rtol)
                Y = steps[-1][1] if steps else np.asarray(Y0, dtype=float)
                restart += 1
                break
            taken += 1
            if taken > MAX_STEPS:
                raise ValueError(f"rate: the history at this rate needs more than {MAX_STEPS} integrator steps "
                                 f"(t = {t_o + solver.t:.6g} s of {t1:.6g} s); a rate or v* nearer the "
                                 f"quasi-static limit is resolved faster by pull_off() without rate")
            crawl = crawl + 1 if solver.step_size < CRAWL_STEP * (t1 - t0) else 0
            if crawl > CRAWL_STEPS and method is LSODA:      # stuck at the Adams stability limit: Radau from here
                method, Y = Radau, (steps[-1][1] if steps else np.asarray(Y0, dtype=float))
                restart += 1
                break
            after = ode.watch(t_o + solver.t, solver.y)
            crossed = np.nonzero((np.sign(before) != np.sign(after)) & (DIRECTION * (after - before) > 0)
                                 & (armed | (np.arange(5) != 4)))[0]
            out = Dense(solver.dense_output(), t_o) if (dense or peak or crossed.size) else None
            roots = sorted((_root(ode, out, k, tau_old, solver.t, before[k], after[k]), k) for k in crossed)
            for tau, k in roots:
                Y = out(tau)
                kind = EVENT_KINDS[k]
                if kind == "runaway":                    # a new time origin here
                    steps.append(((restart, tau), Y, out))
                    restart, armed, runaway = restart + 1, False, True
                    break
                events.append((kind, (restart, tau), Y))
                if TERMINAL[k]:
                    steps.append(((restart, tau), Y, out))
                    return steps, events + (peaks(ode, steps) if peak else []), kind
            if not runaway:
                Y = np.concatenate([[t_o + solver.t], solver.y])
                steps.append(((restart, solver.t), Y, out))
                before = after
                armed = armed or after[4] < -0.99 * RUNAWAY * ode.F_ref      # re-armed once it has slowed down
        if solver.status == "finished" and not runaway:
            steps[-1][1][0] = t1                                             # the end of the drive, exactly
            return steps, events + (peaks(ode, steps) if peak else []), ""


def _root(ode, out, k, lo, hi, f_lo, f_hi):
    """The time offset where event k crosses zero between two steps."""
    def f(tau, _):
        Y = out(tau)
        return ode.watch(Y[0], Y[1:])[k]
    return _roots.brent(f, lo, hi, (), f_lo, f_hi)


def peaks(ode: EdgeODE, steps):
    """[('peak-tension', key, Y)] at each local minimum of the load p over the steps, refined on the dense output
    of the two steps around it (Brent's minimisation of p itself, jkrcyl.numerics.roots.minimum: where the
    contact tracks its equilibrium stiffly, the rate of p is rounding noise, but p is not)."""
    p = np.array([ode.watch(Y[0], Y[1:])[3] for _, Y, _ in steps])
    out = []
    for i in range(1, len(steps) - 1):
        (k0, _, _), (k1, _, d1), (k2, _, d2) = steps[i - 1], steps[i], steps[i + 1]
        if not (p[i] <= p[i - 1] and p[i] < p[i + 1] and p[i] < 0) or not k0[0] == k1[0] == k2[0]:
            continue

        def load(tau):
            Y = (d1 if tau <= k1[1] else d2)(tau)
            return ode.watch(Y[0], Y[1:])[3]
        tau, best = _roots.minimum(load, k0[1], k1[1], k2[1], 1e-14 * max(abs(k2[1]), 1e-300))
        tau = tau if best < p[i] and k0[1] <= tau <= k2[1] else k1[1]
        out.append(("peak-tension", (k1[0], tau), (d1 if tau <= k1[1] else d2)(tau)))
    return out
