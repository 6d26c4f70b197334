"""Crack kinetics at the contact edges: rate-dependent adhesion (Gent and Schultz; Maugis and Barquins).

Each contact edge is a crack whose energy release rate G depends on its speed v along the hole's surface
(v = R |d eps/dt|, m/s):

* opening crack (the contact recedes):  G = w [1 + phi(v)];
* closing crack (the contact advances): w = G [1 + phi(v)];

with phi(v) = (a_T v/v*)^n by default (a_T: the WLF or Arrhenius shift of the reference speed to the test
temperature, :func:`wlf_shift`, :func:`arrhenius_shift`), or a user function phi(v) >= 0, increasing, phi(0) = 0.
At rest (v = 0) both read G = w, JKR's Griffith condition (3.5)-(3.6): :class:`Kinetic` is a
:class:`~jkrcyl.laws.Griffith` law, so every quasi-static answer of a Contact with it (solve, pull_off and cycle
without a rate, the state) is JKR's, bit for bit.  Time histories (pull_off, respond and cycle with a rate) are
jkrcyl.kinetics.

Inverted for the speed, with x = G/w:  v = phi^-1(x - 1) opening (x > 1), v = phi^-1(1/x - 1) closing
(0 < x < 1), unbounded as x -> 0 (an edge without tension closes at once).  For n > 1 the law's own
v ~ |x - 1|^(1/n) has an unbounded slope at rest, on which an implicit integrator chatters: within
X_REST = 1e-9 of rest it is smoothed, v* f (f^2 + X_REST^2)^((1/n - 1)/2) with f = phi(|v|) signed (a user phi:
the chord to rest), a change of G below 1e-9 w.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Optional

from .._validate import finite_scalar
from ..numerics import roots as _roots
from .griffith import Griffith

N_MAX = 2.0                 # 0 < n <= 2: the exponents reported for elastomers lie in 0.1 ... 0.8
X_CLOSE = 1e-4              # G/w below which a closing edge's speed is continued linearly (far beyond any test)
X_REST = 1e-9               # |G/w - 1| within which the speed is linear in G/w (module docstring)
_GAS_CONSTANT = 8.314462618  # J/(mol K)


def wlf_shift(T, T_ref, C1=8.86, C2=101.6):
    """The WLF shift factor a_T = 10^(-C1 (T - T_ref)/(C2 + T - T_ref)).  Pass it as ``Kinetic(..., shift=a_T)``.

    Parameters
    ----------
    T, T_ref : float
        The test and the reference temperature (K or degC alike).
    C1, C2 : float, optional
        The WLF constants [-, K]; the defaults are the universal ones at T_ref = T_g + 50 K.

    Returns
    -------
    float
        a_T (> 1 below T_ref: the crack law's reference speed v*/a_T is slower).

    Raises
    ------
    ValueError
        Naming T: at or below T_ref - C2, where the WLF form diverges; a temperature or constant not finite.

    Examples
    --------
    >>> round(wlf_shift(20.0, 20.0), 12)
    1.0
    """
    T, T_ref = finite_scalar("T", T), finite_scalar("T_ref", T_ref)
    C1, C2 = finite_scalar("C1", C1), finite_scalar("C2", C2)
    if C2 + T - T_ref <= 0:
        raise ValueError(f"T must be > T_ref - C2 = {T_ref - C2!r} (the WLF form diverges there), got {T!r}")
    return 10.0 ** (-C1 * (T - T_ref) / (C2 + T - T_ref))


def arrhenius_shift(T, T_ref, activation_energy):
    """The Arrhenius shift a_T = exp[(E_a/R_gas)(1/T - 1/T_ref)].  Pass it as ``Kinetic(..., shift=a_T)``.

    Parameters
    ----------
    T, T_ref : float
        The test and the reference temperature [K], > 0.
    activation_energy : float
        E_a [J/mol], >= 0.

    Returns
    -------
    float
        a_T.

    Raises
    ------
    ValueError
        Naming the parameter: a temperature <= 0, a negative activation energy, a value not finite.

    Examples
    --------
    >>> arrhenius_shift(293.15, 293.15, 5e4)
    1.0
    >>> round(arrhenius_shift(283.15, 293.15, 5e4), 3)             # 10 K colder: cracks 2.06 times slower
    2.064
    """
    T = finite_scalar("T", T, low=0.0, low_open=True)
    T_ref = finite_scalar("T_ref", T_ref, low=0.0, low_open=True)
    Ea = finite_scalar("activation_energy", activation_energy, low=0.0)
    return math.exp(Ea / _GAS_CONSTANT * (1.0 / T - 1.0 / T_ref))


@dataclass(frozen=True)
class Kinetic(Griffith):
    """Rate-dependent JKR edges: G = w [1 + phi(v)] opening, w = G [1 + phi(v)] closing (module docstring).

    Parameters
    ----------
    v_star : float
        Reference crack speed v* [m/s] > 0: phi(v*) = 1 at a_T = 1.
    n : float
        Exponent of phi = (v/v*)^n, 0 < n <= 2.  With a user ``phi`` it is still needed: the exponent of phi at
        high speed, which sets the variable the integrator uses near separation (eps^(1 + 1/n)).
    phi : callable, optional
        phi(v) [dimensionless] of the speed v [m/s] in place of (v/v*)^n: increasing, phi(0) = 0.
    shift : float, optional
        The shift factor a_T > 0 of the test temperature (phi evaluated at a_T v): :func:`wlf_shift`,
        :func:`arrhenius_shift`.  Default (None) 1.

    Raises
    ------
    ValueError
        Naming the parameter: v_star, n, phi or shift outside its range.

    Examples
    --------
    >>> import jkrcyl
    >>> law = jkrcyl.laws.Kinetic(v_star=1e-6, n=0.6)
    >>> law.edge_release(2e-6) == 1 + 2 ** 0.6            # G/w of an edge opening at 2 v*
    True
    >>> abs(law.speed(1 + 2 ** 0.6) / 2e-6 - 1) < 1e-12    # and back
    True
    """

    v_star: float
    n: float
    phi: Optional[Callable[[float], float]] = None
    shift: Optional[float] = None
    name = "JKR with crack kinetics"
    param = "kinetics"

    def __post_init__(self):
        object.__setattr__(self, "v_star", finite_scalar("v_star", self.v_star, low=0.0, low_open=True))
        object.__setattr__(self, "n", finite_scalar("n", self.n, low=0.0, high=N_MAX, low_open=True))
        shift = 1.0 if self.shift is None else self.shift
        object.__setattr__(self, "shift", finite_scalar("shift", shift, low=0.0, low_open=True))
        if self.phi is not None:
            if not callable(self.phi):
                raise ValueError(f"phi must be a function of the crack speed v [m/s], got {self.phi!r}")
            ok = [self._phi_value(v) for v in (0.0, self.v_star, 2 * self.v_star)]
            if ok[0] != 0 or not 0 < ok[1] < ok[2]:
                raise ValueError(f"phi must be increasing with phi(0) = 0, got phi(0, v*, 2 v*) = {ok!r}")

    @property
    def reference_speed(self) -> float:
        """v*/a_T [m/s]: the speed at which phi = 1 at the test temperature (the power law)."""
        return self.v_star / self.shift

    def _phi_value(self, v):
        try:
            out = float(self.phi(v))
        except Exception as exc:        # a user function: say which input broke it
            raise ValueError(f"phi: the user function failed at v = {v!r}: {exc}") from None
        if not math.isfinite(out) or out < 0:
            raise ValueError(f"phi must be finite and >= 0, got phi({v!r}) = {out!r}")
        return out

    def phi_of(self, v: float) -> float:
        """phi(v) at the test temperature (a_T applied), v >= 0 [m/s]."""
        if self.phi is None:
            return (v / self.reference_speed) ** self.n
        return self._phi_value(self.shift * v)

    def edge_release(self, v: float) -> float:
        """G/w of an edge moving at the crack speed v [m/s]: 1 + phi(v) opening (v > 0), 1/(1 + phi(|v|))
        closing (v < 0)."""
        f = self.phi_of(abs(v))
        return 1.0 + f if v >= 0 else 1.0 / (1.0 + f)

    def _phi_inverse(self, f: float) -> float:
        """The speed v >= 0 with phi(v) = f >= 0."""
        if f <= 0:
            return 0.0
        if self.phi is None:
            return self.reference_speed * f ** (1.0 / self.n)
        hi = self.reference_speed
        while self.phi_of(hi) < f:
            hi *= 4.0
            if hi > 1e300:
                raise ValueError(f"phi: the user function stays below {f!r} at every speed (it must grow without "
                                 "bound, as (v/v*)^n does)")
        lo = 0.0
        return _roots.brent(lambda v, _: self.phi_of(v) - f, lo, hi, (), -f, self.phi_of(hi) - f)

    def _power(self, f: float) -> float:
        """v_ref sign(f) |f|^(1/n), for n > 1 smoothed within X_REST of rest: v_ref f (f^2 + X_REST^2)^((1/n - 1)/2)."""
        k = 1.0 / self.n
        if k >= 1.0:
            return self.reference_speed * math.copysign(abs(f) ** k, f)
        return self.reference_speed * f * (f * f + X_REST * X_REST) ** (0.5 * (k - 1.0))

    def _power_slope(self, f: float) -> float:
        k = 1.0 / self.n
        if k >= 1.0:
            return self.reference_speed * (1.0 if k == 1.0 else k * abs(f) ** (k - 1.0))
        q = f * f + X_REST * X_REST
        return self.reference_speed * q ** (0.5 * (k - 3.0)) * (k * f * f + X_REST * X_REST)

    def speed(self, x: float) -> float:
        """The crack speed [m/s] at G/w = x: positive opening (x > 1, the contact recedes), negative closing
        (x < 1, it advances); continued linearly below x = X_CLOSE (a closing edge without tension moves at
        once: the continuation only keeps an implicit integrator's trial points finite)."""
        if x < X_CLOSE:
            return self.speed(X_CLOSE) + self.speed_slope(X_CLOSE) * (x - X_CLOSE)
        f = x - 1.0 if x >= 1.0 else 1.0 - 1.0 / x            # phi(|v|) at this x, signed as v
        if self.phi is None:
            return self._power(f)
        if self.n > 1.0 and abs(f) < X_REST:                 # the chord to rest (module docstring)
            return f / X_REST * self._phi_inverse(X_REST)
        return math.copysign(self._phi_inverse(abs(f)), f)

    def speed_slope(self, x: float) -> float:
        """d(speed)/dx [m/s]: analytic for the power law, a difference quotient for a user phi."""
        if x < X_CLOSE:
            x = X_CLOSE
        f, df_dx = (x - 1.0, 1.0) if x >= 1.0 else (1.0 - 1.0 / x, 1.0 / (x * x))
        if self.phi is None:
            return self._power_slope(f) * df_dx
        if self.n > 1.0 and abs(f) < X_REST:
            return self._phi_inverse(X_REST) / X_REST * df_dx
        h = 1e-6 * max(abs(x - 1.0), X_REST)
        return (self.speed(x + h) - self.speed(x - h)) / (2 * h)


def CrackKinetics(v_star, n, phi=None, shift=None) -> Kinetic:
    """The common case, ``jkrcyl.CrackKinetics(v_star, n)``: :class:`Kinetic` with phi = (a_T v/v*)^n.

    Parameters
    ----------
    v_star, n, phi, shift
        As :class:`Kinetic`.

    Returns
    -------
    Kinetic
        The law, for ``jkrcyl.Contact(..., kinetics=...)``.

    Raises
    ------
    ValueError
        As :class:`Kinetic`.

    Examples
    --------
    >>> import jkrcyl
    >>> jkrcyl.CrackKinetics(v_star=1e-6, n=0.6) == jkrcyl.laws.Kinetic(v_star=1e-6, n=0.6)
    True
    """
    return Kinetic(v_star=v_star, n=n, phi=phi, shift=shift)


def kinetics_of(law, what: str = "rate") -> Kinetic:
    """The contact's law if it has crack kinetics, else a ValueError naming ``what`` (the argument that asked for
    time: rate, t): the one place that asks whether an edge law moves in time."""
    if isinstance(law, Kinetic):
        return law
    raise ValueError(f"{what}: a rate-dependent answer needs crack kinetics at the contact edges, e.g. "
                     f"Contact(..., kinetics=jkrcyl.CrackKinetics(v_star=..., n=...)); this contact's law is "
                     f"{law.name} (quasi-static: leave {what} out)")


def kinetics_or_none(law) -> Optional[Kinetic]:
    """The law if it has crack kinetics, else None (what Contact.kinetics reads)."""
    return law if isinstance(law, Kinetic) else None


def law_with(kinetics, law, sigma0):
    """The contact's law= from its shorthand kinetics= (both given: they must agree; not with sigma0: the
    cohesive law with kinetics is not modelled)."""
    if kinetics is None:
        return law
    if not isinstance(kinetics, Kinetic):
        raise ValueError(f"kinetics must be a jkrcyl.laws.Kinetic, e.g. jkrcyl.CrackKinetics(v_star=1e-6, n=0.6), "
                         f"got {kinetics!r}")
    if sigma0 is not None:
        raise ValueError("kinetics: crack kinetics with the cohesive law (sigma0) are not modelled")
    if law is not None and law != kinetics:
        raise ValueError(f"kinetics: give the law once (kinetics={kinetics!r}, law={law!r})")
    return kinetics
