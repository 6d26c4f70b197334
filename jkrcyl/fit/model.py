"""The adapter between jkrcyl.fit and the library's JKR model (the cohesive law's is jkrcyl.fit.cohesive).

The fit needs the load P [N/m] and the work-conjugate approach delta_work [m] of the single bottom arc at given
contact parameters a = tan(eps/2) (width = 2 R eps), for any material pair: ``Contact.state(a)`` (closed forms
where alpha* = 0, the collocation solver of (2.1) otherwise).  Two facts make the fit cheap:

* superposition: at a fixed arc the problem is linear in the clearance Delta and in the edge stress-intensity
  factor, which Griffith's condition (3.5)-(3.6) fixes at K = sqrt(8 w/beta*); so (4.4) and its collocation
  twin read P = Delta p1(a) - sqrt(w) p2(a), delta_work = Delta q1(a) + sqrt(w) q2(a);
* scaling both moduli by one factor f keeps vartheta, alpha*/beta* and (1/G_I)/beta* and divides beta* by f:
  then P = f Delta p1 - sqrt(f w) p2 and delta_work = Delta q1 + sqrt(w/f) q2 with the parts of the
  unscaled pair (stresses scale with f Delta and K, displacements with Delta and K/f).

Both are checked against direct ``Contact.state`` calls in tests/test_fit.py.  The parts come from two states,
one without adhesion (w = 0) and one without clearance (Delta = 0), so neither is a difference of two numbers.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from ..contact import Contact
from ..materials import Materials
from ..model.single_patch import resolution as _resolution
from ..numerics import roots as _roots

W_REF = 1.0          # [J/m^2] the adhesive part is computed at this w and scaled by sqrt(w/W_REF)
LOG_STEP = 1e-4      # central differences in log a for the slopes of the parts (error ~1e-8 relative) ...
LOG_STEP_NUMERIC = 1e-3   # ... and for alpha* != 0, whose adhesionless part carries ~1e-9 noise at a ~ 1e-3
RIGID_A_MAX = 3.0    # vartheta = inf, alpha* = 0: no pole; the branch is searched up to this a
TOP_GAP = 1e-3       # the branch ends at a_crit (1 - TOP_GAP): loads there are ~1/TOP_GAP times the typical ones


def a_of_width(width, R):
    """a = tan(eps/2) of a contact width 2 R eps [m]."""
    return np.tan(np.asarray(width, dtype=float) / (4 * R))


def width_of_a(a, R):
    """Contact width 2 R eps = 4 R atan(a) [m]."""
    return 4 * R * np.arctan(np.asarray(a, dtype=float))


def contact(R, Delta, w, materials, strength=None) -> Contact:
    """The library's contact (validates R, Delta, w; strength: the cohesive sigma0 [Pa], None for JKR)."""
    return Contact(R=R, Delta=Delta, w=w, materials=materials, sigma0=strength)


def scaled(materials: Materials, f: float) -> Materials:
    """Both shear moduli times f (Kolosov constants kept): vartheta, alpha*/beta* unchanged, beta* / f."""
    return Materials(G=materials.G * f, kappa=materials.kappa, G_I=materials.G_I * f, kappa_I=materials.kappa_I)


def young(materials: Materials, body: str) -> float:
    """Plane-strain Young's modulus E = 2 G (1 + nu), nu = (3 - kappa)/4, of 'hole' or 'pin' [Pa]."""
    G, kappa = (materials.G, materials.kappa) if body == "hole" else (materials.G_I, materials.kappa_I)
    return 2 * G * (1 + (3 - kappa) / 4)


def with_young(materials: Materials, body: str, E: float) -> Materials:
    """The pair with one body's Young's modulus replaced (its Poisson ratio kept)."""
    if body == "hole":
        return Materials(G=E / (2 * (1 + (3 - materials.kappa) / 4)), kappa=materials.kappa,
                         G_I=materials.G_I, kappa_I=materials.kappa_I)
    return Materials(G=materials.G, kappa=materials.kappa, G_I=E / (2 * (1 + (3 - materials.kappa_I) / 4)),
                     kappa_I=materials.kappa_I)


def contact_modulus(materials: Materials) -> float:
    """E* = 4/beta* [Pa] (plane strain: 1/E* = sum (1 - nu^2)/E over both bodies, section 2)."""
    return 4.0 / materials.beta


@dataclass(frozen=True)
class Parts:
    """P = f Delta p1 - sqrt(f w) p2 [N/m], delta_work = Delta q1 + sqrt(w/f) q2 [m] at contact parameters a.

    p1 [N/m per m], p2 [N/m per sqrt(J/m^2)], q1 [1], q2 [m per sqrt(J/m^2)]; with slopes the first and
    second derivatives in a (``d1``, ``d2``: dicts of the same keys)."""

    a: np.ndarray
    p1: np.ndarray
    p2: np.ndarray
    q1: np.ndarray
    q2: np.ndarray
    d1: dict = None
    d2: dict = None

    def load(self, f, Delta, w, order=0):
        """P or its a-derivative of order 1, 2 [N/m]; w scalar or per point."""
        get = (lambda k: getattr(self, k)) if order == 0 else (self.d1 if order == 1 else self.d2).get
        return f * Delta * get("p1") - np.sqrt(f * w) * get("p2")

    def approach(self, f, Delta, w, order=0):
        """delta_work or its a-derivative of order 1, 2 [m]."""
        get = (lambda k: getattr(self, k)) if order == 0 else (self.d1 if order == 1 else self.d2).get
        return Delta * get("q1") + np.sqrt(w / f) * get("q2")


KEYS = ("p1", "p2", "q1", "q2")


def _exact(materials):
    """The library's solver for this pair rounds at the double-precision level (its closed forms)."""
    return _resolution(materials)[0] <= 1e-14


def _step(materials):
    return LOG_STEP if _exact(materials) else LOG_STEP_NUMERIC


def _raw_parts(R, materials, a):
    """(p1, p2, q1, q2) at the contact parameters a (1-D array) from two library states."""
    d_ref = R * 1e-3                                  # any Delta in (0, R): the part is linear in it
    dry = contact(R, d_ref, 0.0, materials).state(a)
    sticky = contact(R, 0.0, W_REF, materials).state(a)
    s = math.sqrt(W_REF)
    return (np.atleast_1d(dry.P) / d_ref, -np.atleast_1d(sticky.P) / s,
            np.atleast_1d(dry.delta_work) / d_ref, np.atleast_1d(sticky.delta_work) / s)


def parts(R, materials, a, slopes=False) -> Parts:
    """The parts at a (and, with slopes, their first and second a-derivatives by central differences in log a:
    the parts behave like powers of a near 0)."""
    a = np.atleast_1d(np.asarray(a, dtype=float))
    if not slopes:
        return Parts(a, *_cached_parts(R, materials, a.tobytes()))
    h = _step(materials)
    mid, up, down = (_cached_parts(R, materials, (a * math.exp(s)).tobytes()) for s in (0.0, h, -h))
    d1, d2 = {}, {}
    for k, m, u, dn in zip(KEYS, mid, up, down):
        g1, g2 = (u - dn) / (2 * h), (u - 2 * m + dn) / (h * h)    # d/dlog a, d2/dlog a^2
        d1[k], d2[k] = g1 / a, (g2 - g1) / (a * a)
    return Parts(a, *mid, d1=d1, d2=d2)


@functools.lru_cache(maxsize=64)
def _cached_parts(R, materials, a_bytes):
    return _raw_parts(R, materials, np.frombuffer(a_bytes, dtype=float).copy())


@functools.lru_cache(maxsize=32)
def pole(R, materials) -> float:
    """a at the receding-contact pole of the single arc: Contact.a_crit, the single-patch solver's pole (a_crit of
    (4.4) at alpha* = 0, inf for a rigid cradle then; the zero of 1/P without adhesion for any other pair)."""
    return contact(R, R * 1e-3, 0.0, materials).a_crit


def branch_top(R, materials) -> float:
    """Largest a searched on the sub-critical branch: just below the pole, or RIGID_A_MAX without one."""
    ac = pole(R, materials)
    return RIGID_A_MAX if math.isinf(ac) else ac * (1 - TOP_GAP)


PER_DECADE = 64      # table nodes per decade of a (cubic Hermite in log a: ~1e-8 relative between nodes)
DECADES = 7          # the table spans a_top 1e-7 .. a_top (alpha* = 0) ...
DECADES_NUMERIC = 4  # ... or a_top 1e-4 .. a_top: below, the solver's adhesionless part loses digits (1e-5 at 1e-5)


class Branch:
    """The parts along the sub-critical branch as cubic Hermite splines in x = log a (values and slopes at
    PER_DECADE nodes per decade, from a_top 1e-7 (1e-4 for alpha* != 0) to a_top), each times (1 - a/a_crit) so that the pole of
    (4.4) does not spoil the interpolation.  Evaluating it costs microseconds for any material pair."""

    def __init__(self, R, materials):
        from scipy.interpolate import CubicHermiteSpline
        self.top = branch_top(R, materials)
        self.pole = pole(R, materials)
        decades = DECADES if _exact(materials) else DECADES_NUMERIC
        a = self.top * np.logspace(-decades, 0, decades * PER_DECADE + 1)
        a[-1] = self.top
        self.a_min, self.a_max = a[0], a[-1]
        h = _step(materials)
        # slopes of the weighted parts y = part (1 - a/a_crit) by central differences in log a: y is smooth
        # through the pole, the parts alone are not (differences of them would carry (h/(1 - a/a_crit))^2)
        y = [[v * self._weight(a * math.exp(s))[0] for v in _cached_parts(R, materials, (a * math.exp(s)).tobytes())]
             for s in (0.0, h, -h)]
        y0, yp, ym = (np.array(v).T for v in y)
        self.spline = CubicHermiteSpline(np.log(a), y0, (yp - ym) / (2 * h))   # all four parts at once
        self.slope, self.curvature = self.spline.derivative(1), self.spline.derivative(2)

    def _weight(self, a):
        if math.isinf(self.pole):
            return np.ones_like(a), np.zeros_like(a)
        return 1 - a / self.pole, np.full_like(a, -1 / self.pole)

    def parts(self, a) -> Parts:
        """Parts with first and second a-derivatives at a in [a_min, a_max]."""
        a = np.asarray(a, dtype=float)
        x = np.log(a)
        w, dw = self._weight(a)
        y, yx, yxx = self.spline(x), self.slope(x), self.curvature(x)       # shape (..., 4)
        a, w, dw = a[..., None], w[..., None], dw[..., None]
        ya, yaa = yx / a, (yxx - yx) / (a * a)             # d/da, d2/da2 of y = part * w
        vals = y / w                                       # w'' = 0
        d1 = (ya - vals * dw) / w
        d2 = (yaa - 2 * d1 * dw) / w
        split = lambda z: {k: z[..., i] for i, k in enumerate(KEYS)}
        v = split(vals)
        return Parts(a[..., 0], v["p1"], v["p2"], v["q1"], v["q2"], d1=split(d1), d2=split(d2))

    def nodes(self):
        return np.exp(self.spline.x)


@functools.lru_cache(maxsize=16)
def branch(R, materials) -> Branch:
    """The cached :class:`Branch` of a pair (the moduli's common factor does not enter the parts)."""
    return Branch(R, materials)


def segment(R, materials, f, Delta, w, quantity="load"):
    """(a_lo, a_hi): the part of the sub-critical branch stable under fixed load (quantity='load': from the
    fold, the minimum of P, up to where dP/da turns negative again or the pole) or fixed delta_work
    ('approach'), section 8.3: dG/da|_P > 0 is dP/da > 0 below a_crit, dG/da|_delta_work > 0 is
    d delta_work/da > 0.  a_lo = a_min of the table when the slope is positive there (no fold on it)."""
    br = branch(R, materials)
    grid = br.nodes()
    p = br.parts(grid)
    g = p.load(f, Delta, w, 1) if quantity == "load" else p.approach(f, Delta, w, 1)
    pos = g > 0
    if not pos.any():
        return None
    i = int(np.argmax(pos))
    lo = br.a_min if i == 0 else _slope_root(br, f, Delta, w, quantity, grid[i - 1], grid[i])
    after = np.nonzero(~pos[i:])[0]
    hi = br.a_max if after.size == 0 else _slope_root(br, f, Delta, w, quantity, grid[i + after[0] - 1],
                                                        grid[i + after[0]])
    return lo, hi


def _slope_root(br, f, Delta, w, quantity, lo, hi):
    def slope(x):
        p = br.parts(np.array([x]))
        return float((p.load(f, Delta, w, 1) if quantity == "load" else p.approach(f, Delta, w, 1))[0])
    return _roots.brent(lambda x, _: slope(x), lo, hi)


def fold(R, materials, f, Delta, w, quantity="load"):
    """(a, P, delta_work) at the fixed-load pull-off (the minimum of P on the sub-critical branch, quantity='load')
    or at the fixed-delta_work pull-off ('approach'); None if the stable segment has no lower fold (w = 0)."""
    seg = segment(R, materials, f, Delta, w, quantity)
    if seg is None or seg[0] == branch(R, materials).a_min:
        return None
    p = branch(R, materials).parts(np.array([seg[0]]))
    return seg[0], float(p.load(f, Delta, w)[0]), float(p.approach(f, Delta, w)[0])
