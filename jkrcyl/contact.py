"""A pin in a conforming hole: physical inputs in, equilibrium states out (thin layer over the kernels).

Units: any consistent set (SI: R, Delta [m], w [J/m^2], moduli [Pa], loads per unit length [N/m]).
"""
import math
from dataclasses import dataclass

import numpy as np

from ._validate import PRESSURE_A_MAX, angle, contact_parameter, count, finite_scalar
from .analysis import branches as _br
from .analysis import confined as _confined
from .analysis import cycle as _cycle
from .analysis import forward as _fw
from .analysis import pull_off as _pull_off
from .analysis import tracing as _tr
from .contact_cohesive import CohesiveLaw
from .materials import Materials
from .model import two_patch as _two
from .model.problem import Problem
from .model.single_patch import physical, solver
from .numerics import kernels as _k

PARALLEL_MIN = _k.PARALLEL_MIN   # state() uses the prange kernel from this many contact parameters on


@dataclass(frozen=True)
class Contact(CohesiveLaw):
    """Hole radius R, clearance Delta = R - R_D >= 0, work of adhesion w >= 0, the materials, and the edge law:
    sigma0 = None (JKR: adhesion of zero range, the Griffith edge) or the Maugis-Dugdale cohesive strength
    sigma0 > 0 [Pa] (the traction sigma0 wherever 0 < gap <= h0 = w/sigma0; needs w > 0 and Delta > 0; or give
    the transition parameter: :meth:`with_lambda`).  Every analysis (solve, pull_off, cycle, curve, adherence)
    uses the law; two patches and full contact are modelled for JKR only (ValueError with sigma0)."""

    R: float
    Delta: float
    w: float
    materials: Materials
    sigma0: float = None

    def __post_init__(self):
        object.__setattr__(self, "R", finite_scalar("R", self.R, low=0.0, low_open=True))
        object.__setattr__(self, "Delta", finite_scalar("Delta", self.Delta, low=0.0))
        if self.Delta >= self.R:
            raise ValueError(f"Delta must be in [0, R) = [0, {self.R:g}) (the pin radius R_D = R - Delta must be "
                             f"> 0), got {self.Delta!r}")
        object.__setattr__(self, "w", finite_scalar("w", self.w, low=0.0))
        if not isinstance(self.materials, Materials):
            raise ValueError(f"materials must be a jkrcyl.Materials, got {type(self.materials).__name__}")
        if self.sigma0 is not None:
            object.__setattr__(self, "sigma0", finite_scalar("sigma0", self.sigma0, low=0.0, low_open=True))
            if self.w == 0 or self.Delta == 0:
                raise ValueError(f"sigma0: a cohesive law needs w > 0 and Delta > 0 (h0 = w/sigma0, lengths over "
                                 f"Delta), got w = {self.w!r}, Delta = {self.Delta!r}")

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
        """The receding contact a_crit (section 4: the pole of the load), for this material pair (alpha* != 0
        included: the single-patch solver's pole); inf for a rigid cradle at alpha* = 0 (section 7.2)."""
        return solver(Problem.of_materials(self.materials)).a_crit

    @property
    def problem(self):
        """The normalised problem (section 6) of this contact (needs Delta > 0)."""
        return Problem.of(self)

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

    # --- states --------------------------------------------------------------------------------
    def state(self, a, method="auto"):
        """Equilibrium at contact parameter(s) a = tan(eps/2) > 0: see :class:`State`.

        method: "closed-form" (the paper's (4.4)-(5.10); ValueError unless alpha* = 0), "numeric" (collocation
        solution of (2.1)/(5.2), jkrcyl.numerics.one_arc, any alpha*) or "auto" (closed form where alpha* = 0).
        """
        self._require_griffith("state(a)")
        if method not in ("auto", "closed-form", "numeric"):
            raise ValueError(f"method must be 'auto', 'closed-form' or 'numeric', got {method!r}")
        if method == "closed-form":
            self.materials.require_closed_form("method='closed-form'")
        arr = contact_parameter(a)
        flat = np.ascontiguousarray(arr.ravel())
        sv = physical(self, method)
        fields = {k: _shaped(v, arr.shape) for k, v in sv.states(flat).items()}
        return State(contact=self, a=_shaped(flat, arr.shape), **fields)

    def approach_work(self, P, delta):
        """Work-conjugate approach delta_work = delta + P/(8 pi G_I) [m] (derive/green.py) of a state with load P
        [N/m] and the paper's approach delta [m] (5.8); only the net load enters (the n = 1 Michell mode), so it
        holds for one patch, two patches and full contact alike.  Scalars or arrays of equal shape."""
        shape = np.broadcast(np.asarray(P), np.asarray(delta)).shape
        out = _k.approach_work(P, delta, inv_G_I=self.materials.inv_G_I)
        return _shaped(out, shape)

    # --- sections 6 and 8 ----------------------------------------------------------------------------
    def curve(self, regime="sub-critical", n=2000):
        """Equilibrium branch with P [N/m], delta and delta_work [m]: jkrcyl.equilibria.curve."""
        return _br.curve(self.problem, regime, count("n", n, low=2)).with_units(self.load_scale, self.Delta)

    def adherence(self, control="load", confined=True):
        """Adherence points (P* minima for control='load', stationary approach for 'grip', 'grip-work') with P
        [N/m], delta and delta_work [m], and (load) what a further pull does, ``outcome``:
        jkrcyl.equilibria.adherence."""
        from . import equilibria
        pts = equilibria.adherence_of(self.problem, control, confined=confined)
        return [p.with_units(self.load_scale, self.Delta) for p in pts]

    def two_patch(self, n=None):
        """Two-patch branches (second contact at the top of the hole), with P [N/m], delta, delta_work [m]."""
        pb = _two.require_finite_theta(self.problem.require_confined("two_patch() is"))
        return tuple(b.with_units(self.load_scale, self.Delta) for b in _tr.branches(pb, n))

    def confined_events(self):
        """What follows when the gap closes at phi = pi under slow pulling: jkrcyl.analysis.confined."""
        return _confined.confined_events(_two.require_finite_theta(self.problem.require_confined("confined_events() is")))

    # --- forward problems and paths (jkrcyl.analysis) -----------------------------------------------------
    def solve(self, P=None, delta=None, branches=None, delta_work=None):
        """Every equilibrium at load P [N/m], the paper's approach delta [m] or the work-conjugate approach
        delta_work [m] (exactly one; stability under that control): a list of jkrcyl.results.Equilibrium
        sorted by contact size.  ``branches``: keys of jkrcyl.analysis.forward.BRANCH_SOLVERS to search (two-patch
        states are traced by continuation: seconds the first time, cached per contact)."""
        given = {k: v for k, v in (("P", P), ("delta", delta), ("delta_work", delta_work)) if v is not None}
        if len(given) != 1:
            raise ValueError("P: give exactly one of P [N/m], delta [m] and delta_work [m]")
        self._require_clearance("solve")
        (name, value), = given.items()
        control = {"P": "load", "delta": "grip", "delta_work": "grip-work"}[name]
        target = finite_scalar(name, value) / (self.load_scale if name == "P" else self.Delta)
        names = _fw.check_branches(branches, self.problem)
        return _fw.solve_normalised(self.problem, _fw.Units.of(self), control, target, names)

    def pull_off(self, control="load"):
        """Detachment along the stable path from first contact (force [N/m], width, approach) or why not, under
        control 'load', 'grip-work' (a machine holding delta_work) or 'grip' (the paper's delta):
        jkrcyl.analysis.pull_off."""
        _fw.check_control(control)
        self._require_clearance("pull_off")
        return _pull_off.pull_off(self.problem, _fw.Units.of(self), control)

    def cycle(self, P_max=None, P_min=None, control="load", n=2000, delta_max=None, delta_min=None):
        """Quasi-static cycle from first contact up to the maximum, down to the minimum and up again (path, jumps,
        energy dissipated [J/m]): P_max, P_min [N/m] under control='load'; delta_max, delta_min [m] (limits of the
        held approach: delta for 'grip', delta_work for 'grip-work') otherwise.  jkrcyl.analysis.cycle."""
        _fw.check_control(control)
        self._require_clearance("cycle")
        n = count("n", n, low=10)
        names = ("P_max", "P_min") if control == "load" else ("delta_max", "delta_min")
        given = dict(P_max=P_max, P_min=P_min, delta_max=delta_max, delta_min=delta_min)
        other = [k for k, v in given.items() if v is not None and k not in names]
        if other:
            raise ValueError(f"{other[0]} does not apply to control={control!r} (give {' and '.join(names)})")
        if given[names[0]] is None or given[names[1]] is None:
            raise ValueError(f"{names[0]}: control={control!r} needs {names[0]} and {names[1]}")
        hi, lo = finite_scalar(names[0], given[names[0]]), finite_scalar(names[1], given[names[1]])
        if not lo < hi:
            raise ValueError(f"{names[1]} must be < {names[0]}, got {names[1]} = {lo!r}, {names[0]} = {hi!r}")
        return _cycle.cycle(self.problem, _fw.Units.of(self), control, hi, lo, n, self.approach_work)

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
        self._require_griffith("pressure(a, phi)")
        a_arr, phi_arr = _broadcast(contact_parameter(a), angle(phi))
        if np.max(a_arr) > PRESSURE_A_MAX:
            raise ValueError(f"a must be <= {PRESSURE_A_MAX:g} in pressure() (the bounded part of (5.4) loses its "
                             f"digits beyond: atanh near 1), got {np.max(a_arr)!r}")
        wrapped = np.mod(phi_arr + math.pi, 2 * math.pi) - math.pi
        wrapped = np.where(wrapped == -math.pi, math.pi, wrapped).ravel()
        flat_a = a_arr.ravel()
        nb, nu = np.zeros(flat_a.size), np.zeros(flat_a.size)
        sv = physical(self)
        for ai in np.unique(flat_a):
            sel = flat_a == ai
            nb[sel], nu[sel] = sv.pressure(float(ai), wrapped[sel])
        if parts:
            return _shaped(nb, a_arr.shape), _shaped(nu, a_arr.shape)
        return _shaped(nb + nu, a_arr.shape)

    def gap(self, a, phi):
        """Gap h(phi) of (5.9) [m]: numpy-broadcast over a and phi; 0 inside the contact."""
        self._require_griffith("gap(a, phi)")
        a_arr, phi_arr = _broadcast(contact_parameter(a), angle(phi))
        return _shaped(physical(self).gap(a_arr.ravel(), phi_arr.ravel()), a_arr.shape)


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
