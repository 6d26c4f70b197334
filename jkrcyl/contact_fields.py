"""The single patch of a :class:`jkrcyl.Contact` at a given contact size a = tan(eps/2): its state, pressure and
gap in SI units (the law's dimensional solver: JKR's Griffith edge, closed form where alpha* = 0), and
:class:`State`, what :meth:`AtContactSize.state` returns."""
import math
from dataclasses import dataclass
from typing import Tuple, Union

import numpy as np
from numpy.typing import ArrayLike

from ._validate import PRESSURE_A_MAX, angle, contact_parameter
from .numerics import kernels as _k


class AtContactSize:
    """Methods of :class:`jkrcyl.Contact` at a given contact parameter a (the Griffith law's physical solver)."""

    def state(self, a: ArrayLike, method: str = "auto") -> "State":
        """The equilibria at contact parameter(s) a = tan(eps/2): load, approach, gap and edge fields in SI units.

        Parameters
        ----------
        a : float or array_like
            Contact parameter(s) tan(eps/2) > 0 (eps the contact half-angle), in [1e-100, 1e20].
        method : str
            'closed-form' (the paper's (4.4)-(5.10)), 'numeric' (collocation solution of (2.1)/(5.2),
            jkrcyl.model.collocation, any alpha*) or 'auto' (the closed form where alpha* = 0).

        Returns
        -------
        State
            Arrays shaped like a.

        Raises
        ------
        ValueError
            Naming a (not real, not positive, outside the domain) or method (unknown; 'closed-form' where
            alpha* != 0), or the law's parameter for a law without a single patch at given a (Maugis-Dugdale:
            use :meth:`at_contact`).

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
        >>> s = pin.state(0.5)
        >>> round(float(s.P), 2), round(float(s.G_release), 12)      # N/m; G = w: the edge in equilibrium (3.5)
        (-1551.19, 0.05)
        >>> bool(abs(pin.state(0.5, method="numeric").P / s.P - 1) < 1e-10)    # collocation of (2.1)
        True
        >>> pin.state([0.2, 0.5, 0.8]).P.shape
        (3,)
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

    def approach_work(self, P: ArrayLike, delta: ArrayLike) -> Union[np.ndarray, float]:
        """The work-conjugate approach delta_work = delta + P/(8 pi G_I) [m] of a state (derive/green.py).

        Only the net load enters (the n = 1 Michell mode), so it holds for one patch, two patches and full contact
        alike: the displacement of the pin's centroid for a load spread over the pin, so that P d(delta_work) is
        the work done on the contact.

        Parameters
        ----------
        P : float or array_like
            Load per unit length [N/m].
        delta : float or array_like
            The paper's approach (5.8) [m], shaped like P.

        Returns
        -------
        ndarray or float
            delta_work [m], shaped like the broadcast of P and delta.

        Raises
        ------
        ValueError
            Where P and delta do not broadcast against each other (numpy's message).

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
        >>> round(float(pin.approach_work(-1000.0, 0.0)) * 1e9, 4)        # -1000/(8 pi 1e9) m, in nm
        -39.7887
        """
        shape = np.broadcast(np.asarray(P), np.asarray(delta)).shape
        out = _k.approach_work(P, delta, inv_G_I=self.materials.inv_G_I)
        return _shaped(out, shape)

    def pressure(self, a: ArrayLike, phi: ArrayLike,
                 parts: bool = False) -> Union[np.ndarray, float, Tuple[Union[np.ndarray, float], ...]]:
        """The contact pressure N(phi) of (5.4) [Pa], compressive positive (section 6); 0 outside the contact.

        Parameters
        ----------
        a : float or array_like
            Contact parameter(s) tan(eps/2), in (0, 1e4], numpy-broadcast against phi.
        phi : float or array_like
            Angle(s) from the bottom of the hole [rad], wrapped to (-pi, pi] as in :meth:`gap`.
        parts : bool
            False: the total N = bounded + unbounded.  True: the tuple (bounded, unbounded), the unbounded
            part being the r0 term of (5.4) (square-root singular at the edges, negative under adhesion).

        Returns
        -------
        ndarray or float, or a tuple of two when parts=True
            Shaped like the broadcast of a and phi.

        Raises
        ------
        ValueError
            Naming a (outside (0, 1e4]: atanh near 1 loses the bounded part) or phi (not real), or the law's
            parameter for a law without a single patch at given a.

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
        >>> eps = 2 * math.atan(0.5)
        >>> [round(float(N)) for N in pin.pressure(0.5, [0.0, 1.01 * eps])]      # Pa: tension at the centre
        [-65790, 0]
        >>> x, wx = np.polynomial.legendre.leggauss(200)        # in t, phi = eps sin(t): smooth at the edges
        >>> t = x * math.pi / 2
        >>> N = pin.pressure(0.5, eps * np.sin(t))
        >>> P = pin.R * eps * math.pi / 2 * np.sum(wx * N * np.cos(eps * np.sin(t)) * np.cos(t))
        >>> bool(abs(P / pin.state(0.5).P - 1) < 1e-9)                  # the load (4.4) is the pressure's resultant
        True
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

    def gap(self, a: ArrayLike, phi: ArrayLike) -> Union[np.ndarray, float]:
        """The gap h(phi) of (5.9) [m] between the pin and the hole; 0 inside the contact.

        Parameters
        ----------
        a : float or array_like
            Contact parameter(s) tan(eps/2) > 0, numpy-broadcast against phi.
        phi : float or array_like
            Angle(s) from the bottom of the hole [rad].

        Returns
        -------
        ndarray or float
            Shaped like the broadcast of a and phi; h(pi) is :attr:`State.h_pi` (5.10).

        Raises
        ------
        ValueError
            Naming a or phi (not real, out of range), or the law's parameter for a law without a single patch
            at given a.

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
        >>> h = pin.gap(0.5, [0.0, math.pi])
        >>> float(h[0]), bool(abs(h[1] / pin.state(0.5).h_pi - 1) < 1e-12)     # 0 in the contact; h(pi) (5.10)
        (0.0, True)
        """
        a_arr, phi_arr = _broadcast(contact_parameter(a), angle(phi))
        return _shaped(self._physical().gap(a_arr.ravel(), phi_arr.ravel()), a_arr.shape)


def _broadcast(*arrays):
    """np.broadcast_arrays as owned, writeable copies (numba warns on broadcast views)."""
    return [np.array(x) for x in np.broadcast_arrays(*arrays)]


def _shaped(values, shape):
    if not shape:                                     # one state: its scalar (what out[()] gives), no reshape
        return np.asarray(values).flat[0]
    out = np.asarray(values).reshape(shape)
    return out[()] if out.ndim == 0 else out


@dataclass(frozen=True)
class State:
    """Single-patch equilibria of a :class:`jkrcyl.Contact` at the contact parameters a (what
    :meth:`jkrcyl.Contact.state` returns; every field an array shaped like a, a 0-d value for a scalar a).

    Attributes
    ----------
    contact : jkrcyl.Contact
        The contact that made the states.
    a : ndarray
        Contact parameters tan(eps/2).
    P, B, C : ndarray
        Load (4.4) and the coefficients (4.5a), (4.5b) [N/m].
    c0, c1 : ndarray
        The coefficients (2.6) of the displacement condition (2.7) [m].
    r0 : ndarray
        The coefficient of the unbounded, edge-singular term of the pressure (2.12) [Pa].
    K : ndarray
        Stress-intensity factor at the edges (3.4) [Pa m^1/2].
    G_release : ndarray
        Energy release rate (3.5) [J/m^2]: w at every state (the Griffith edge in equilibrium).
    delta, h_pi : ndarray
        The paper's approach (5.8) and the gap at phi = pi (5.10) [m].

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
    >>> pin.state(0.5)
    State(a=0.5, P=-1551.19 N/m, delta=-2.8e-07 m, feasible=True)
    >>> s = pin.state(0.5)
    >>> round(float(s.K)), round(math.sqrt(8 * pin.w / pin.beta))       # K at G = w: (pi/4) A K^2 = w (3.5)
    (11952, 11952)
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

    def __repr__(self) -> str:
        a, P = np.ravel(self.a), np.ravel(self.P)
        if a.size == 1:
            return (f"State(a={a[0]:.6g}, P={P[0]:.6g} N/m, delta={float(np.ravel(self.delta)[0]):.4g} m, "
                    f"feasible={bool(np.ravel(self.feasible)[0])})")
        return (f"State({a.size} points, a in [{a.min():.4g}, {a.max():.4g}], P in [{P.min():.4g}, {P.max():.4g}] "
                f"N/m, {int(np.sum(np.ravel(self.feasible)))} feasible)")

    @property
    def eps(self) -> np.ndarray:
        """Contact half-angle eps = 2 atan(a) [rad]."""
        return 2 * np.arctan(self.a)

    @property
    def eps_star(self) -> np.ndarray:
        """Normalised half-angle eps* = 2 atan(a/a_crit)/pi (section 6): 1/2 at the receding contact a_crit."""
        return 2 * np.arctan(self.a / self.contact.a_crit) / math.pi

    @property
    def P_star(self) -> np.ndarray:
        """P* = P beta*/(4 pi Delta vartheta) (section 6); P_R* of (7.6) when vartheta = inf.  ValueError for
        Delta = 0 (naming P_star)."""
        return self.P / self.contact.load_scale

    @property
    def delta_over_Delta(self) -> np.ndarray:
        """delta/Delta, the approach (5.8) over the clearance.  ValueError for Delta = 0 (neat fit)."""
        self.contact._require_clearance("delta_over_Delta")
        return self.delta / self.contact.Delta

    @property
    def delta_work(self) -> np.ndarray:
        """Work-conjugate approach delta_work = delta + P/(8 pi G_I) [m] (derive/green.py).

        The displacement of the pin's centroid relative to the hole's rim for a load spread over the pin, so that
        P d(delta_work) is the work done on the contact.  The paper's delta (5.8) is the rims' approach with the
        load at the pin's centre; it differs by P/(8 pi G_I) and is not the conjugate of P (Fig. 7: negative
        stiffness)."""
        return self.contact.approach_work(self.P, self.delta)

    @property
    def delta_work_over_Delta(self) -> np.ndarray:
        """delta_work/Delta.  ValueError for Delta = 0 (neat fit)."""
        self.contact._require_clearance("delta_work_over_Delta")
        return self.delta_work / self.contact.Delta

    @property
    def h_pi_over_Delta(self) -> np.ndarray:
        """h(pi)/Delta, the gap at the top of the hole (5.10) over the clearance.  ValueError for Delta = 0."""
        self.contact._require_clearance("h_pi_over_Delta")
        return self.h_pi / self.contact.Delta

    @property
    def feasible(self) -> np.ndarray:
        """The gap inequality h >= 0 at every exterior angle; its minimum is min(0, h(pi)) (derive/gap.py)."""
        return self.h_pi >= 0
