"""The edge equation of a single patch with crack kinetics, integrated in time.

Both edges of the bottom patch move at the crack speed V(G/w) of the law (jkrcyl.laws.kinetic; positive
opening), so d eps/dt = -V/R, with G/w = g|g| and g = (X(t) - X0(a))/X1(a) fixed by the held quantity X(t)
(p, delta/Delta or delta_work/Delta; jkrcyl.kinetics.arc).

Two changes of variable keep the equation regular:

* the contact vanishes in finite time: near separation G ~ X^2/a and V ~ a^(-1/n) (power law), so a^(1 + 1/n)
  falls at a finite rate, and the state variable is z = (a/a_ref)^q, q = 1 + 1/n (separation: z = 0, an event);
* past a fold of the quasi-static branch the edges run away in a time that may be far below the resolution of t
  (v* -> inf: the quasi-static limit), so the independent variable is an arclength s with
  dt/ds = 1/N, dz/ds = F/N, N = 1 + |F|/F_ref (F = dz/dt, F_ref the drive's own rate of z): s is t where the
  contact follows the drive and z where it runs away.

The work on the pin W = int p d(dw) and the dissipation D = int 2 m^2 (G/w - 1)(-d eps) (kernel energy units,
4 pi Delta^2/beta*) are integrated alongside, W by parts so that its integrand holds no rate of the state (which
is rounding noise where the contact tracks its equilibrium): W = Q + B(t) - B(t_0), dQ/dt = -dw dX/dt with
B = X dw under load (X = p), dQ/dt = p dX/dt with B = 0 under grip-work (X = dw) and B = c p^2/2 under grip
(X = dn, dw = dn + c p).  scipy's LSODA (Adams where the contact runs, BDF where it relaxes
stiffly onto its equilibrium) with the analytic Jacobian, stepped here; events (separation, h(pi) = 0, the peak
tension, the end of the tabulated range, the end of the segment) are roots on its dense output.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import LSODA

from ..numerics import roots as _roots
from .arc import B0, B1, DN0, DN1, DW0, DW1, H0, H1, HELD, P0, P1

A_FLOOR = 1e-12        # a/a_ref below which the states are those at the floor (the time left there is negligible)
RTOL = 1e-10           # default relative tolerance of the integrator
FIRST_STEP = 1e-12     # of the arclength span: LSODA restarts mid-way on a stiff slow manifold from a tiny step
ATOL_ENERGY = 1e-4     # of rtol times the adhesion energy of the reference contact: the error control of Q, D
#                        where asked for (cycles: the loop's energy is the answer; where the contact tracks its
#                        equilibrium stiffly that control costs many steps, so pull-offs go without)
EVENT_KINDS = ("separation", "top-contact", "range-end", "peak-tension", "segment-end")


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
        self.drive, self.F_ref = None, 1.0

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

    def fun(self, s, Y):
        """d(t, z, Q, D)/ds."""
        t, z = Y[0], max(Y[1], self.z_floor)
        a, y, dy, g, x, V, du_dt, dg_dt = self.local(t, z)
        F = self.q * z * du_dt
        N = 1.0 + abs(F) / self.F_ref
        held = y[DW0] + g * y[DW1] if self.control == "load" else -(y[P0] + g * y[P1])
        return np.array([1.0, F, -held * self.drive.slope, 2.0 * self.m2 * (x - 1.0) * V / self.R]) / N

    def jac(self, s, Y):
        """d(fun)/d(t, z, Q, D): exact in (t, z); Q and D do not feed back, and their rows are left 0 (Newton's
        iteration on them then converges with that on z)."""
        t, z = Y[0], max(Y[1], self.z_floor)
        a, y, dy, g, x, V, du_dt, _ = self.local(t, z)
        i0, i1 = self.i0, self.i1
        F = self.q * z * du_dt
        geo = (1.0 + a * a) / (2.0 * a)
        dV_dx = self.law.speed_slope(x)
        dx_du = 2.0 * abs(g) * (-(dy[i0] + g * dy[i1]) / y[i1])
        F_z = self.q * du_dt + (a * a - 1.0) / (2.0 * a) * (-V / self.R) - geo * dV_dx / self.R * dx_du
        F_t = -self.q * z * geo * dV_dx / self.R * 2.0 * abs(g) * self.drive.slope / y[i1]
        N = 1.0 + abs(F) / self.F_ref
        sg = math.copysign(1.0, F) / self.F_ref
        J = np.zeros((4, 4))
        J[0, 0], J[0, 1] = -sg * F_t / (N * N), -sg * F_z / (N * N)
        J[1, 0], J[1, 1] = F_t / (N * N), F_z / (N * N)
        return J

    # --- events -------------------------------------------------------------------------------------------
    def watch(self, Y, t_end: float, peak: bool):
        """The event functions at a state, in the order of :data:`EVENT_KINDS`: z (separation), h(pi)/Delta,
        the distance to the end of the tabulated range, dp/dt (the peak tension; 1 unless watched), t - t_end."""
        t, z = Y[0], Y[1]
        a, y, dy, g, x, V, du_dt, dg_dt = self.local(t, z)
        dp = (dy[P0] + g * dy[P1]) * du_dt + y[P1] * dg_dt if peak else 1.0
        u = self.u_ref + math.log(max(z, self.z_floor)) / self.q
        return np.array([z, y[H0] + g * y[H1], self.arc.u_last - u, dp, t - t_end])

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
DIRECTION = np.array([-1, -1, -1, 1, 1])
TERMINAL = np.array([True, True, True, False, True])


def segment(ode: EdgeODE, drive: Linear, t1: float, Y0, rtol=RTOL, peak=False, dense=False, energy=False):
    """Integrate from Y0 = (t0, z, W, D) to t1 under a linear drive.  Returns (steps, events, terminal):
    steps [(s, Y, dense output or None)] after the start, events [(kind, s, Y)] in order, the terminal kind
    ('' at t1).  ``energy``: the work and dissipation under the error control too (else they follow the steps
    of (t, z)).  Events are roots of :meth:`EdgeODE.watch` on the step's dense output (Brent, to adjacent
    doubles in s)."""
    t0 = float(Y0[0])
    ode.start(drive, t1 - t0)
    e = rtol * ATOL_ENERGY * ode.energy_atol if energy else 1e300
    atol = np.array([rtol * max(abs(t0), abs(t1)) * 1e-3, rtol * 1e-4, e, e])
    z_max = math.exp(ode.q * (ode.arc.u_last - ode.u_ref))         # the arclength is t plus the path of z/F_ref
    span = 2.0 * (t1 - t0) + 4.0 * (Y0[1] + z_max) / ode.F_ref
    solver = LSODA(ode.fun, 0.0, np.asarray(Y0, dtype=float), span, rtol=rtol, atol=atol, jac=ode.jac,
                   first_step=FIRST_STEP * span)
    before = ode.watch(solver.y, t1, peak)
    steps, events = [], []
    while True:
        s_old = solver.t
        solver.step()
        if solver.status == "failed":
            raise ArithmeticError(f"kinetics: the integrator failed at t = {solver.y[0]!r} s")
        after = ode.watch(solver.y, t1, peak)
        crossed = np.nonzero((np.sign(before) != np.sign(after)) & (DIRECTION * (after - before) > 0))[0]
        out = solver.dense_output() if (dense or crossed.size) else None
        roots = sorted((_root(ode, out, k, s_old, solver.t, before[k], after[k], t1, peak), k) for k in crossed)
        for s, k in roots:
            Y = out(s)
            if EVENT_KINDS[k] == "segment-end":
                Y[0] = t1                                  # the end of the drive, exactly
            events.append((EVENT_KINDS[k], s, Y))
            if TERMINAL[k]:
                steps.append((s, Y, out))
                return steps, events, "" if EVENT_KINDS[k] == "segment-end" else EVENT_KINDS[k]
        steps.append((solver.t, solver.y.copy(), out))
        if solver.status == "finished":
            raise ArithmeticError(f"kinetics: the arclength span ended at t = {solver.y[0]!r} s before {t1!r}")
        before = after


def _root(ode, out, k, lo, hi, f_lo, f_hi, t_end, peak):
    """The arclength where event k crosses zero between two steps."""
    return _roots.brent(lambda s, _: ode.watch(out(s), t_end, peak)[k], lo, hi, (), f_lo, f_hi)
