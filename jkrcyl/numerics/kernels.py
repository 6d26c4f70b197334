"""The one bridge between the generated kernels (jkrcyl.generated) and the library.

Only this module imports jkrcyl.generated (tests/test_layer.py enforces it).  It calls every kernel by keyword
and hands back named results, so that a new kernel argument or output cannot silently shift positions.  The
kernels take ``inv_theta = 1/vartheta`` (0 for the rigid cradle); the normalised ones of section 6 work in the
kernel scale ``m = M vartheta``, ``p = vartheta P*`` with Delta = beta* = 1 (jkrcyl.model.problem.Problem
converts, once).
"""
import functools
import math
from collections import namedtuple

import numpy as np
from numba import njit

from ..generated import derivatives as _der
from ..generated import gap as _gap
from ..generated import green as _green
from ..generated import load as _load
from ..generated import special as _special
from ..generated import state as _state
from ..generated import zero_load as _zl
from . import roots

PARALLEL_MIN = 20000   # full_state uses the prange kernel from this many contact parameters on

FullState = _state.FullState      # P, B, C, c0, c1, r0, K, G_release, delta, h_pi
Pressure = namedtuple("Pressure", ["bounded", "unbounded"])
StarM = namedtuple("StarM", _der.EquilibriumStar._fields + ("h_pi_over_Delta",))


def _empty(result, n):
    return result(*(np.empty(n) for _ in result._fields))


def _array(x):
    return np.ascontiguousarray(x, dtype=float)


# --- dimensional kernels (Contact) ------------------------------------------------------------------
def full_state(a, *, R, Delta, beta, inv_theta, inv_G_I, zeta):
    """Equilibrium state at the contact parameters a (1-D): a :data:`FullState` of arrays."""
    a = _array(a)
    out = _empty(FullState, a.size)
    # prange over all cores for long inputs: bit-identical to the serial loop (tests/test_parallel.py)
    fill = _state.full_state_into_parallel if a.size >= PARALLEL_MIN else _state.full_state_into
    fill(out, Delta=Delta, R=R, a=a, beta=beta, inv_G_I=inv_G_I, inv_theta=inv_theta, zeta=zeta)
    return out


def approach_work(P, delta, *, inv_G_I):
    """Work-conjugate approach delta_work = delta + P/(8 pi G_I) [m] (derive/green.py); P [N/m], delta [m]
    of equal shape."""
    P, delta = np.broadcast_arrays(np.asarray(P, dtype=float), np.asarray(delta, dtype=float))
    out = np.empty(P.size)
    _green.approach_work_into(out, P=_array(P.ravel()), delta=_array(delta.ravel()), inv_G_I=inv_G_I)
    return out.reshape(P.shape)


@functools.lru_cache(maxsize=1024)
def work_shift(gb):
    """c in delta_work/Delta = delta/Delta + c p (p = P beta*/(4 pi Delta)): the derived k1_work - k1 of
    derive/green.py, read off the emitted kernel (approach_work_star at delta = 0, p = 1), never retyped."""
    out = np.empty(1)
    _green.approach_work_star_into(out, delta_over_Delta=np.zeros(1), gb=gb, p=np.ones(1))
    return float(out[0])


def pressure(a, phi, *, R, Delta, beta, inv_theta, zeta):
    """Pressure N(phi) of (5.4) [Pa] at one contact parameter a, phi 1-D inside the contact."""
    phi = _array(phi)
    out = _empty(_load.Pressure, phi.size)
    _load.pressure_into(out, Delta=Delta, R=R, a=float(a), beta=beta, inv_theta=inv_theta, phi=phi,
                        zeta=zeta)
    return Pressure(bounded=out.N_bounded, unbounded=out.N_unbounded)


def gap(a, phi, *, Delta, beta, inv_theta, zeta):
    """Gap h(phi) of (5.9) [m]; a and phi 1-D of equal length."""
    a, phi = _array(a), _array(phi)
    out = np.empty(a.size)
    _gap.gap_into(out, Delta=Delta, a=a, beta=beta, inv_theta=inv_theta, phi=phi, zeta=zeta)
    return out


def gap_pi(a, *, Delta, beta, inv_theta, zeta):
    """Gap at phi = pi (5.10) [m] at the contact parameters a (1-D); Delta = 0 allowed."""
    a = _array(a)
    out = np.empty(a.size)
    _gap.gap_pi_into(out, Delta=Delta, a=a, beta=beta, inv_theta=inv_theta, zeta=zeta)
    return out


# --- normalised kernels (section 6: equilibria, atlas) ----------------------------------------------
def bond_star(a, *, inv_theta, m):
    """B of (4.5a) in the kernel scale, int nu dphi = B R beta*/(4 pi Delta) (Delta = beta* = R = 1), at the 1-D a:
    with p it gives the elastic energy [(1 + delta/Delta) p - B]/2 of a state (jkrcyl.model.patch.Slice)."""
    a = _array(a)
    out = _empty(_load.LoadState, a.size)
    _load.load_state_into(out, Delta=1.0, R=1.0, a=a, beta=1.0, inv_theta=inv_theta, zeta=4.0 * math.pi * m)
    return out.B / (4 * math.pi)


def star_m(a, *, inv_theta, m, gb):
    """Normalised equilibrium in the kernel's own scale (p = P beta*/(4 pi Delta), m = M vartheta; M_R* and
    P_R* for vartheta = inf) at the contact parameters a (1-D): a :data:`StarM` -- the emitted EquilibriumStar
    (p, delta/Delta, delta_work/Delta, their slopes; at fixed a: (1/w) dG/dp and d(delta/Delta)/dp) and
    h(pi)/Delta (5.10).  m must be > 0 ((1/w) dG/dp ~ 1/m; p and delta are exact for any tiny m)."""
    a = _array(a)
    out = _empty(_der.EquilibriumStar, a.size)
    _der.equilibrium_star_into(out, a=a, gb=gb, inv_theta=inv_theta, m=m)
    return StarM(*out, h_pi_over_Delta=gap_pi(a, Delta=1.0, beta=1.0, inv_theta=inv_theta, zeta=4 * math.pi * m))


STAR_FIELDS = {"P_star": 0, "dP_star_da": 1, "delta_over_Delta": 2, "ddelta_da": 3, "delta_work_over_Delta": 4,
               "ddelta_work_da": 5, "h_pi": 6}


@njit(cache=True)
def star_residual_nb(a, args):
    """Field k of the normalised equilibrium minus a target: args = (inv_theta, m, gb, k, scale, target),
    k as :data:`STAR_FIELDS` (P* fields divide the kernel's p by scale, as :func:`star`)."""
    inv_theta, m, gb, k, scale, target = args
    if k == 6:
        return _gap.gap_pi(Delta=1.0, a=a, beta=1.0, inv_theta=inv_theta, zeta=4.0 * math.pi * m) - target
    r = _der.equilibrium_star(a=a, gb=gb, inv_theta=inv_theta, m=m)
    value = (r.p, r.dp_da, r.delta_over_Delta, r.ddelta_da, r.delta_work_over_Delta, r.ddelta_work_da)[k]
    return (value / scale if k < 2 else value) - target


# numba scalars of the atlas: Delta = beta* = 1, m = M vartheta
@njit(cache=True)
def p_nb(a, inv_theta, m):
    """p = vartheta P* (P_R* for vartheta = inf) from the load (4.4)."""
    r = _load.load_state(Delta=1.0, R=1.0, a=a, beta=1.0, inv_theta=inv_theta, zeta=4.0 * math.pi * m)
    return r.P / (4.0 * math.pi)


@njit(cache=True)
def dp_da_nb(a, inv_theta, m):
    """dp/da along the equilibrium (sign of dP*/da)."""
    r = _der.load_slopes(Delta=1.0, a=a, beta=1.0, inv_G_I=0.0, inv_theta=inv_theta,
                         zeta=4.0 * math.pi * m)
    return r.dP_da / (4.0 * math.pi)


@njit(cache=True)
def h_pi_nb(a, inv_theta, m):
    """h(pi)/Delta of (5.10)."""
    return _gap.gap_pi(Delta=1.0, a=a, beta=1.0, inv_theta=inv_theta, zeta=4.0 * math.pi * m)


# --- a_crit (section 4) and the zero-load contact (8.1) ------------------------------------------------
@njit(cache=True)
def _critical(u, args):
    r = _zl.critical_equation(theta=args[0], u=u)
    return r.f, r.df_du


_critical_newton = roots.newton_solver(_critical)


@njit(cache=True)
def a_crit_nb(theta):
    """a_crit(vartheta), unchecked (inf for inf): Newton on u = a^2 for f(u) = 2 vartheta - log1p(u) - 2u^2,
    decreasing and concave, so Newton from the right of the root converges monotonically."""
    if math.isinf(theta):
        return math.inf
    return math.sqrt(_critical_newton(max(math.sqrt(theta), 2.0 * theta), (theta,)))


@njit(cache=True)
def zero_load_residual_nb(a, args):
    """(8.1) times M: a^(3/2) - m (2 + inv_theta (a^2 - log(1 + a^2))); args = (inv_theta, m)."""
    return _zl.zero_load_residual(a=a, inv_theta=args[0], m=args[1])


@njit(cache=True)
def zero_load_rigid_nb(m):
    """The zero-load contact of the rigid cradle, m = M_R*."""
    return _zl.zero_load_rigid(m=m)


@njit(cache=True)
def zero_load_stationary_nb(a, args):
    """> 0 below the a of M_max, < 0 above it; args = (vartheta,)."""
    return _zl.zero_load_max(a=a, theta=args[0]).stationary


@njit(cache=True)
def zero_load_M0_nb(a, theta):
    """The M for which a is a zero-load contact: a^(3/2)/(a^2 + 2 vartheta - log(1 + a^2))."""
    return _zl.zero_load_max(a=a, theta=theta).M0


# --- special cases of section 7 (derive/special.py) ---------------------------------------------------
def special(name, **args):
    """A kernel of generated/special.py by name, on numpy arrays (vectorised over its arguments)."""
    kernel = getattr(_special, name)
    arrays = {k: np.asarray(v, dtype=float) for k, v in args.items()}
    shape = np.broadcast_shapes(*(v.shape for v in arrays.values()))
    flat = {k: np.ascontiguousarray(np.broadcast_to(v, shape)).ravel() for k, v in arrays.items()}
    values = [kernel(**{k: float(v[i]) for k, v in flat.items()}) for i in range(int(np.prod(shape)))]
    return np.asarray(values).reshape(shape + np.shape(values[0]) if values else shape)
