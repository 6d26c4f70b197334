"""A pin in a conforming hole: physical inputs in, equilibrium states out (thin layer over the kernels).

Units: any consistent set (SI: R, Delta [m], w [J/m^2], moduli [Pa], loads per unit length [N/m]).
"""
import math
from dataclasses import dataclass, replace

import numpy as np

from ._validate import PRESSURE_A_MAX, angle, contact_parameter, finite_scalar
from .critical import a_crit
from .numerics import kernels as _k
from .materials import Materials

PARALLEL_MIN = _k.PARALLEL_MIN   # state() uses the prange kernel from this many contact parameters on


@dataclass(frozen=True)
class Contact:
    """Hole radius R, clearance Delta = R - R_D >= 0, work of adhesion w >= 0, and the materials."""

    R: float
    Delta: float
    w: float
    materials: Materials

    def __post_init__(self):
        object.__setattr__(self, "R", finite_scalar("R", self.R, low=0.0, low_open=True))
        object.__setattr__(self, "Delta", finite_scalar("Delta", self.Delta, low=0.0))
        if self.Delta >= self.R:
            raise ValueError(f"Delta must be in [0, R) = [0, {self.R:g}) (the pin radius R_D = R - Delta must be "
                             f"> 0), got {self.Delta:g}")
        object.__setattr__(self, "w", finite_scalar("w", self.w, low=0.0))
        if not isinstance(self.materials, Materials):
            raise ValueError(f"materials must be a jkrcyl.Materials, got {type(self.materials).__name__}")

    # --- parameters of sections 3-6 ---------------------------------------------------------------
    @property
    def beta(self):
        """beta* [1/Pa]."""
        return self.materials.beta

    @property
    def theta(self):
        """vartheta (section 4); inf for a rigid cradle."""
        return self.materials.theta

    @property
    def A(self):
        """A = beta*/(2 pi) of (3.5)."""
        return self.beta / (2 * math.pi)

    @property
    def zeta(self):
        """zeta* = sqrt(2 w R/A) of (3.6)."""
        return math.sqrt(2 * self.w * self.R / self.A)

    @property
    def a_crit(self):
        return a_crit(self.theta)

    @property
    def load_scale(self):
        """P / P*: 4 pi Delta vartheta/beta* (section 6), or 4 pi Delta/beta* for vartheta = inf (7.6)."""
        self._require_clearance("P_star")
        th = self.theta
        return 4 * math.pi * self.Delta * (1 if math.isinf(th) else th) / self.beta

    @property
    def M(self):
        """M = sqrt(w A R)/(sqrt(2) Delta vartheta) (section 6); M_R* of (7.6) when vartheta = inf."""
        self._require_clearance("M")
        return self.zeta / self.load_scale

    def _require_clearance(self, what):
        if self.Delta == 0:
            raise ValueError(f"{what} is undefined for Delta = 0 (neat fit, section 7.3): "
                             "it normalises by Delta; use the dimensional values")

    def _args(self):
        return dict(Delta=self.Delta, beta=self.beta, inv_theta=self.materials.inv_theta, zeta=self.zeta)

    # --- states --------------------------------------------------------------------------------
    def state(self, a, method="auto"):
        """Equilibrium at contact parameter(s) a = tan(eps/2) > 0: see :class:`State`.

        method: "closed-form" (the paper's (4.4)-(5.10); ValueError unless alpha* = 0), "numeric" (collocation
        solution of (2.1)/(5.2), jkrcyl.numerics.arcs, any alpha*) or "auto" (closed form where alpha* = 0).
        """
        if method not in ("auto", "closed-form", "numeric"):
            raise ValueError(f"method must be 'auto', 'closed-form' or 'numeric', got {method!r}")
        if method == "closed-form":
            self.materials.require_closed_form("method='closed-form'")
        arr = contact_parameter(a)
        flat = np.ascontiguousarray(arr.ravel())
        if method == "numeric" or not self.materials.closed_form:
            return self._numeric_state(arr, flat)
        s = _k.full_state(flat, R=self.R, inv_G_I=self.materials.inv_G_I, **self._args())
        fields = {k: _shaped(v, arr.shape) for k, v in s._asdict().items()}
        return State(contact=self, a=_shaped(flat, arr.shape), **fields)

    def _numeric_state(self, arr, flat):
        from .numerics.arcs import single_arc_state
        m = self.materials
        out = single_arc_state(flat, R=self.R, Delta=self.Delta, w=self.w, beta=self.beta,
                               inv_theta=m.inv_theta, inv_G_I=m.inv_G_I, alpha_star=m.alpha_star)
        return State(contact=self, a=_shaped(flat, arr.shape), **{k: _shaped(v, arr.shape) for k, v in out.items()})

    def approach_work(self, P, delta):
        """Work-conjugate approach delta_work = delta + P/(8 pi G_I) [m] (derive/green.py) of a state with load P
        [N/m] and the paper's approach delta [m] (5.8); only the net load enters (the n = 1 Michell mode), so it
        holds for one patch, two patches and full contact alike.  Scalars or arrays of equal shape."""
        shape = np.broadcast(np.asarray(P), np.asarray(delta)).shape
        out = _k.approach_work(P, delta, inv_G_I=self.materials.inv_G_I)
        return _shaped(out, shape)

    # --- sections 6 and 8 (jkrcyl.equilibria) -------------------------------------------------------
    def curve(self, regime="sub-critical", n=2000):
        """Equilibrium branch (M, P*, delta/Delta, ... and P [N/m], delta [m]): jkrcyl.equilibria.curve."""
        from . import equilibria
        M, th, gb = equilibria.from_contact(self)
        cv = equilibria.curve(M, th, regime=regime, n=n, gb=gb, alpha_ratio=self.materials.alpha_ratio)
        return replace(cv, P=cv.P_star * self.load_scale, delta=cv.delta_over_Delta * self.Delta,
                       delta_work=cv.delta_work_over_Delta * self.Delta)

    def adherence(self, control="load", confined=True):
        """Adherence points (P* minima for control='load', d delta/da = 0 for 'grip') with P [N/m], delta and
        delta_work [m], and (load) what a further pull does, ``outcome``: jkrcyl.equilibria.adherence."""
        from . import equilibria
        M, th, gb = equilibria.from_contact(self)
        pts = equilibria.adherence(M, th, control=control, gb=gb, alpha_ratio=self.materials.alpha_ratio,
                                   confined=confined)
        return [replace(p, P=p.P_star * self.load_scale, delta=p.delta_over_Delta * self.Delta,
                        delta_work=p.delta_work_over_Delta * self.Delta) for p in pts]

    def two_patch(self, n=None):
        """Two-patch branches (second contact at the top of the hole): jkrcyl.equilibria.two_patch."""
        from . import equilibria
        M, th, gb = equilibria.from_contact(self)
        return equilibria.two_patch(M, th, n=n, gb=gb, alpha_ratio=self.materials.alpha_ratio)

    def confined_events(self):
        """What follows when the gap closes at phi = pi under slow pulling: jkrcyl.twopatch.confined_events."""
        from . import equilibria, twopatch
        M, th, gb = equilibria.from_contact(self)
        return twopatch.confined_events(M, th, gb=gb, alpha_ratio=self.materials.alpha_ratio)

    # --- forward problems (jkrcyl.forward, jkrcyl.cycle) -------------------------------------------------
    def solve(self, P=None, delta=None, branches=None, delta_work=None):
        """Every equilibrium at load P [N/m], the paper's approach delta [m] or the work-conjugate approach
        delta_work [m] (exactly one; stability under that control): :func:`jkrcyl.forward.solve`."""
        from .forward import solve
        return solve(self, P=P, delta=delta, branches=branches, delta_work=delta_work)

    def pull_off(self, control="load"):
        """Detachment along the stable path (force [N/m], width, approach) or why not, under control 'load',
        'grip-work' (a machine holding delta_work) or 'grip' (the paper's delta): :func:`jkrcyl.forward.pull_off`."""
        from .forward import pull_off
        return pull_off(self, control)

    def cycle(self, P_max=None, P_min=None, control="load", n=2000, delta_max=None, delta_min=None):
        """Quasi-static cycle from first contact (path, jumps, dissipated energy [J/m]): :func:`jkrcyl.cycle.cycle`."""
        from .cycle import cycle
        return cycle(self, P_max=P_max, P_min=P_min, control=control, n=n, delta_max=delta_max, delta_min=delta_min)

    def pressure(self, a, phi, parts=False):
        """Contact pressure N(phi) of (5.4) [Pa], compressive positive (section 6); 0 outside the contact.

        Parameters
        ----------
        a : float or array_like
            Contact parameter(s) tan(eps/2) > 0, numpy-broadcast against phi.
        phi : float or array_like
            Angle(s) from the bottom of the hole [rad], wrapped to (-pi, pi] as in :meth:`gap`.
        parts : bool
            False: the total N = bounded + unbounded.  True: the tuple (bounded, unbounded), the unbounded
            part being the r0 term of (5.4) (square-root singular at the edges, negative under adhesion).

        Returns
        -------
        ndarray or float, or a tuple of two when parts=True
        """
        a_arr, phi_arr = _broadcast(contact_parameter(a), angle(phi))
        if np.max(a_arr) > PRESSURE_A_MAX:
            raise ValueError(f"a must be <= {PRESSURE_A_MAX:g} in pressure() (the bounded part of (5.4) loses its "
                             f"digits beyond: atanh near 1), got {np.max(a_arr):g}")
        wrapped = np.mod(phi_arr + math.pi, 2 * math.pi) - math.pi
        wrapped = np.where(wrapped == -math.pi, math.pi, wrapped).ravel()
        flat_a = a_arr.ravel()
        nb, nu = np.zeros(flat_a.size), np.zeros(flat_a.size)
        for ai in np.unique(flat_a):
            sel = flat_a == ai
            nb[sel], nu[sel] = self._pressure_one(float(ai), wrapped[sel])
        if parts:
            return _shaped(nb, a_arr.shape), _shaped(nu, a_arr.shape)
        return _shaped(nb + nu, a_arr.shape)

    def _pressure_one(self, a, phi):
        """(bounded, unbounded) [Pa] at one contact parameter a, phi 1-D in (-pi, pi]."""
        if not self.materials.closed_form:
            return self._numeric_pressure(a, phi)
        inside = np.abs(phi) < 2 * math.atan(a)
        flat = np.ascontiguousarray(np.where(inside, phi, 0.0))
        nb, nu = _k.pressure(a, flat, R=self.R, **self._args())
        return np.where(inside, nb, 0.0), np.where(inside, nu, 0.0)

    def gap(self, a, phi):
        """Gap h(phi) of (5.9) [m]: numpy-broadcast over a and phi; 0 inside the contact."""
        a_arr, phi_arr = _broadcast(contact_parameter(a), angle(phi))
        if not self.materials.closed_form:
            return _shaped(self._numeric_gap(a_arr.ravel(), phi_arr.ravel()), a_arr.shape)
        h = _k.gap(a_arr.ravel(), phi_arr.ravel(), **self._args())
        return _shaped(h, a_arr.shape)


    # --- alpha* != 0: the collocation solution (jkrcyl.numerics.arcs) -----------------------------------
    def _griffith(self, a):
        from .numerics.arcs import griffith_arc
        m = self.materials
        return griffith_arc(a, R=self.R, Delta=self.Delta, w=self.w, beta=self.beta, inv_theta=m.inv_theta,
                            inv_G_I=m.inv_G_I, alpha_star=m.alpha_star)

    def _numeric_pressure(self, a, phi):
        """(bounded, unbounded) as for the closed form; unbounded = r0/sqrt(a^2 - x^2), x = tan(phi/2)."""
        lin, f, delta = self._griffith(a)
        flat = phi.ravel()
        N = f * lin.pressure(flat, delta, clearance=self.Delta)
        inside = np.abs(flat) < 2 * math.atan(a)
        r0 = -f * (self.Delta * lin.q0[2] + delta * lin.q1[2]) * math.sqrt(a * (1 + a * a))
        x = np.tan(np.where(inside, flat, 0.0) / 2)
        unb = np.where(inside, r0 / np.sqrt(np.where(inside, a * a - x * x, 1.0)), 0.0)
        return _shaped(N - unb, phi.shape), _shaped(unb, phi.shape)

    def _numeric_gap(self, a, phi):
        out = np.zeros(a.size)
        for ai in np.unique(a):
            sel = (a == ai) & (np.abs(phi) >= 2 * math.atan(ai))
            if sel.any():
                lin, f, delta = self._griffith(float(ai))
                out[sel] = lin.gap(phi[sel], delta, clearance=self.Delta)
        return out


def _broadcast(*arrays):
    """np.broadcast_arrays as owned, writeable copies (numba warns on broadcast views)."""
    return [np.array(x) for x in np.broadcast_arrays(*arrays)]


def _shaped(values, shape):
    out = np.asarray(values).reshape(shape)
    return out[()] if out.ndim == 0 else out


@dataclass(frozen=True)
class State:
    """Equilibria at the contact parameters a (arrays shaped like a).

    P [N/m] (4.4), B [N/m] (4.5a), C [N/m] (4.5b), c0 [m], c1 [m] (2.6), r0 [Pa] (2.12),
    K [Pa m^1/2] (3.4), G_release [J/m^2] (3.5), delta [m] (5.8), h_pi [m] (5.10);
    delta_work [m]: the work-conjugate approach (derive/green.py).
    """

    contact: Contact
    a: np.ndarray
    P: np.ndarray
    B: np.ndarray
    C: np.ndarray
    c0: np.ndarray
    c1: np.ndarray
    r0: np.ndarray
    K: np.ndarray
    G_release: np.ndarray
    delta: np.ndarray
    h_pi: np.ndarray

    def __repr__(self):
        a, P = np.ravel(self.a), np.ravel(self.P)
        if a.size == 1:
            return (f"State(a={a[0]:.6g}, P={P[0]:.6g} N/m, delta={float(np.ravel(self.delta)[0]):.4g} m, "
                    f"feasible={bool(np.ravel(self.feasible)[0])})")
        return (f"State({a.size} points, a in [{a.min():.4g}, {a.max():.4g}], P in [{P.min():.4g}, {P.max():.4g}] "
                f"N/m, {int(np.sum(np.ravel(self.feasible)))} feasible)")

    @property
    def eps(self):
        """Contact half-angle eps = 2 atan(a) [rad]."""
        return 2 * np.arctan(self.a)

    @property
    def eps_star(self):
        """Normalised half-angle eps* = 2 atan(a/a_crit)/pi (section 6)."""
        return 2 * np.arctan(self.a / self.contact.a_crit) / math.pi

    @property
    def P_star(self):
        """P* = P beta*/(4 pi Delta vartheta) (section 6); P_R* of (7.6) when vartheta = inf."""
        return self.P / self.contact.load_scale

    @property
    def delta_over_Delta(self):
        self.contact._require_clearance("delta_over_Delta")
        return self.delta / self.contact.Delta

    @property
    def delta_work(self):
        """Work-conjugate approach delta_work = delta + P/(8 pi G_I) [m] (derive/green.py): displacement of the
        pin's centroid relative to the hole's rim for a load spread over the pin, so that P d(delta_work) is
        the work done on the contact.  The paper's delta (5.8) is the rims' approach with the load at the
        pin's centre; it differs by P/(8 pi G_I) and is not the conjugate of P (Fig. 7: negative stiffness)."""
        return self.contact.approach_work(self.P, self.delta)

    @property
    def delta_work_over_Delta(self):
        self.contact._require_clearance("delta_work_over_Delta")
        return self.delta_work / self.contact.Delta

    @property
    def h_pi_over_Delta(self):
        self.contact._require_clearance("h_pi_over_Delta")
        return self.h_pi / self.contact.Delta

    @property
    def feasible(self):
        """Gap inequality h >= 0 at every exterior angle; its minimum is min(0, h(pi)) (derive/gap.py)."""
        return self.h_pi >= 0
