"""The single patch of a :class:`jkrcyl.Contact` at a given contact size a = tan(eps/2): its state, pressure and
gap in SI units (the law's dimensional solver: JKR's Griffith edge, closed form where alpha* = 0), and
:class:`State`, what :meth:`AtContactSize.state` returns."""
import math
from dataclasses import dataclass

import numpy as np

from ._validate import PRESSURE_A_MAX, angle, contact_parameter
from .numerics import kernels as _k


class AtContactSize:
    """Methods of Contact at a given contact parameter a (the law's ``physical`` solver, Griffith laws)."""

    def state(self, a, method="auto"):
        """Equilibrium at contact parameter(s) a = tan(eps/2) > 0: see :class:`State`.

        method: "closed-form" (the paper's (4.4)-(5.10); ValueError unless alpha* = 0), "numeric" (collocation
        solution of (2.1)/(5.2), jkrcyl.numerics.one_arc, any alpha*) or "auto" (closed form where alpha* = 0).
        """
        if method not in ("auto", "closed-form", "numeric"):
            raise ValueError(f"method must be 'auto', 'closed-form' or 'numeric', got {method!r}")
        if method == "closed-form":
            self.materials.require_closed_form("method='closed-form'")
        arr = contact_parameter(a)
        flat = np.ascontiguousarray(arr.ravel())
        sv = self._physical(method)
        fields = {k: _shaped(v, arr.shape) for k, v in sv.states(flat).items()}
        return State(contact=self, a=_shaped(flat, arr.shape), **fields)

    def approach_work(self, P, delta):
        """Work-conjugate approach delta_work = delta + P/(8 pi G_I) [m] (derive/green.py) of a state with load P
        [N/m] and the paper's approach delta [m] (5.8); only the net load enters (the n = 1 Michell mode), so it
        holds for one patch, two patches and full contact alike.  Scalars or arrays of equal shape."""
        shape = np.broadcast(np.asarray(P), np.asarray(delta)).shape
        out = _k.approach_work(P, delta, inv_G_I=self.materials.inv_G_I)
        return _shaped(out, shape)

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
                             f"digits beyond: atanh near 1), got {np.max(a_arr)!r}")
        wrapped = np.mod(phi_arr + math.pi, 2 * math.pi) - math.pi
        wrapped = np.where(wrapped == -math.pi, math.pi, wrapped).ravel()
        flat_a = a_arr.ravel()
        nb, nu = np.zeros(flat_a.size), np.zeros(flat_a.size)
        sv = self._physical()
        for ai in np.unique(flat_a):
            sel = flat_a == ai
            nb[sel], nu[sel] = sv.pressure(float(ai), wrapped[sel])
        if parts:
            return _shaped(nb, a_arr.shape), _shaped(nu, a_arr.shape)
        return _shaped(nb + nu, a_arr.shape)

    def gap(self, a, phi):
        """Gap h(phi) of (5.9) [m]: numpy-broadcast over a and phi; 0 inside the contact."""
        a_arr, phi_arr = _broadcast(contact_parameter(a), angle(phi))
        return _shaped(self._physical().gap(a_arr.ravel(), phi_arr.ravel()), a_arr.shape)



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

    contact: "jkrcyl.Contact"
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
