"""The fit's view of the library's JKR model: contacts, single-patch states by superposition, the material helpers.

Every contact the fit evaluates is built by :func:`contact` (the one place: an edge law given to Contact flows
through here), and every state comes from the library's single-patch solver (jkrcyl.model.single_patch: closed
forms where alpha* = 0, the collocation solver of (2.1) otherwise), in its kernel scale (a Slice: p = P
beta*/(4 pi Delta), lengths over Delta, slopes along the equilibrium and the fixed-arc derivatives p_k, dn_k that
jkrcyl.model.stability turns into stability flags).  One fact makes the fit cheap:

* superposition: at a fixed arc the problem is linear in the edge coefficient k of nu ~ -k/sqrt(eps - |phi|),
  which the contact's edge law fixes at its adhesion (:func:`edge_coefficient`; Griffith's (3.5)-(3.6): k =
  m/pi, m = M vartheta, i.e. K = sqrt(8 w/beta*)).  So every field of a Slice is ``base + k unit`` with the
  base at k = 0 and the unit part per unit k, both depending on the pair's shape only (vartheta, (1/G_I)/beta*,
  alpha*/beta*: scaling both moduli by one factor keeps them).  They are solved once per shape and set of
  contact parameters (:func:`unit_slices`) from two library states, one without adhesion and one at M = 1.

tests/test_fit.py holds the superposed states to Contact.state at 1e-10 relative over random pairs.
"""
from __future__ import annotations

import functools
import math
from typing import NamedTuple

import numpy as np

from ..contact import Contact
from ..materials import Materials
from ..model.patch import SLOPE_OF, Slice  # noqa: F401  (SLOPE_OF: for jkrcyl.fit.branch)
from ..model.single_patch import solver

LINEAR_FIELDS = ("p", "dp_da", "dn", "ddn_da", "dw", "ddw_da", "h", "B")   # base + k unit
FIXED_ARC = ("p_k", "dn_k")      # the fixed-arc derivatives: the same at every k (the problem is linear in k)
CURVATURE_STEP = 1e-4            # d2P/da2 by central differences of the exact slope, in log a (error ~1e-8)


def a_of_width(width, R):
    """a = tan(eps/2) of a contact width 2 R eps [m]."""
    return np.tan(np.asarray(width, dtype=float) / (4 * R))


def width_of_a(a, R):
    """Contact width 2 R eps = 4 R atan(a) [m]."""
    return 4 * R * np.arctan(np.asarray(a, dtype=float))


def contact(R, Delta, w, materials, strength=None, law=None) -> Contact:
    """The library's contact (validates R, Delta, w; strength: the cohesive sigma0 [Pa], None for JKR; law: an edge
    law, Contact(..., law=)): every contact of the fit is built here.  A strength makes the law Dugdale's: the
    superposed path's law (resolved once from the user's, jkrcyl.fit.estimate) then has no say."""
    return Contact(R=R, Delta=Delta, w=w, materials=materials, sigma0=strength,
                   law=law if strength is None else None)


def contact_with_lambda(R, Delta, w, materials, lambda_) -> Contact:
    """The library's cohesive contact of transition parameter lambda_ (Contact.with_lambda)."""
    return Contact.with_lambda(R, Delta, w, materials, lambda_)


def law_coefficient(pb, m: float) -> float:
    """k of the edge law of the normalised problem pb at the adhesion m = M vartheta (kernel scale; Griffith's
    (3.5)-(3.6): k = m/pi, K = sqrt(8 w/beta*)): the one place the fit asks a law for the adhesive part.  The
    superposition holds for laws that fix k at an edge in equilibrium (the fit's JKR path)."""
    return pb.edge.edge_coefficient(m)


def edge_coefficient(c: Contact) -> float:
    """k of the contact's edge law at its adhesion, in the kernel scale of its normalised problem."""
    pb = c.problem
    return law_coefficient(pb, pb.m)


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


# --- the shape's unit states --------------------------------------------------------------------------------
class Unit(NamedTuple):
    """Single-patch fields at contact parameters a, kernel scale: {field: (base at k = 0, part per unit k)} for
    :data:`LINEAR_FIELDS`, and the fixed-arc derivatives p_k, dn_k."""

    a: np.ndarray
    parts: dict
    p_k: np.ndarray
    dn_k: np.ndarray


def _problems(materials):
    """(problem without adhesion, problem at M = 1, k of the latter) of the pair (R, Delta: any; M ~ sqrt(w))."""
    probe = contact(1.0, 1e-3, 1.0, materials)
    dry, sticky = contact(1.0, 1e-3, 0.0, materials), contact(1.0, 1e-3, 1.0 / probe.M ** 2, materials)
    return dry.problem, sticky.problem, edge_coefficient(sticky)


@functools.lru_cache(maxsize=32)
def shape(materials: Materials):
    """The pair's single-patch solvers (without adhesion, at M = 1) and the unit k: what the unit parts need."""
    dry, sticky, k = _problems(materials)
    return solver(dry), solver(sticky), k


POINTS_KEPT = 50_000  # unit states kept per pair (a subset of measured widths, a refined root: no new solve)
_points = {}


def _solve(materials, a):
    """The unit parts at a as rows (base of each LINEAR_FIELDS, unit of each, p_k, dn_k): two library states."""
    s0, s1, k1 = shape(materials)
    lo, hi = s0.states(a), s1.states(a)
    return np.array([getattr(lo, f) for f in LINEAR_FIELDS] + [(getattr(hi, f) - getattr(lo, f)) / k1
                                                               for f in LINEAR_FIELDS] + [hi.p_k, hi.dn_k])


def _unit(materials, a, keep=True):
    """The unit parts at a: solved where not kept, kept per point (keep=False: solved afresh, not kept)."""
    if keep:
        kept = _points.setdefault(materials, {})
        if len(kept) > POINTS_KEPT:
            kept.clear()
        new = np.array(sorted({float(x) for x in a if float(x) not in kept}))
        if new.size:
            kept.update(zip(new.tolist(), _solve(materials, new).T))
        table = np.array([kept[float(x)] for x in a]).T
    else:
        table = _solve(materials, a)
    n = len(LINEAR_FIELDS)
    parts = {f: (table[i], table[n + i]) for i, f in enumerate(LINEAR_FIELDS)}
    return Unit(np.asarray(a, dtype=float), parts, table[2 * n], table[2 * n + 1])


@functools.lru_cache(maxsize=64)
def _cached_unit(materials, a_bytes):
    return _unit(materials, np.frombuffer(a_bytes, dtype=float).copy())


def unit_slices(materials: Materials, a, keep=True) -> Unit:
    """The unit parts at the contact parameters a (1-D), cached per pair and set of a (the measured widths);
    keep=False: solved afresh (contact parameters that change with every evaluation, the located states of
    delta_work data)."""
    a = np.ascontiguousarray(np.atleast_1d(np.asarray(a, dtype=float)))
    return _cached_unit(materials, a.tobytes()) if keep else _unit(materials, a, keep=False)


def superpose(u: Unit, k: float) -> Slice:
    """The Slice at edge coefficient k (kernel scale)."""
    v = {f: base + k * unit for f, (base, unit) in u.parts.items()}
    return Slice(a=u.a, p_k=u.p_k, dn_k=u.dn_k, **v)


# --- physical states -------------------------------------------------------------------------------------------
class States(NamedTuple):
    """States of one contact at contact parameters a [SI]: load P [N/m], work-conjugate approach delta_work [m],
    gap at the top h_pi [m], the slopes dP/da, d delta_work/da and the Slice they come from."""

    a: np.ndarray
    P: np.ndarray
    delta_work: np.ndarray
    h_pi: np.ndarray
    dP_da: np.ndarray
    ddelta_work_da: np.ndarray
    slice: Slice


def load_per_p(c: Contact) -> float:
    """P / p: 4 pi Delta/beta* [N/m] (the kernel scale, section 6: p = vartheta P*, P* = P/load_scale)."""
    return c.units.per_kernel("load")


REF_W = 1.0          # [J/m^2] the reference contact of a pair's shape (any w > 0: M is proportional to sqrt(w))
REF_DELTA = 1e-3     # [R] its clearance (any in (0, R): M is proportional to 1/Delta)


@functools.lru_cache(maxsize=64)
def reference(R: float, materials: Materials, law=None):
    """(contact, its normalised problem) of the pair's shape at REF_W and REF_DELTA R under the edge law (None:
    JKR): what the scalings of :meth:`Superposed.of_inputs` start from (built by :func:`contact`)."""
    c = contact(R, REF_DELTA * R, REF_W, materials, law=law)
    return c, c.problem


class Superposed:
    """The states of one contact (its materials: ``materials`` times a factor f; ``materials`` is the shape of the
    cache) from the unit parts: the edge coefficient k of its law, the kernel scale L = P/p [N/m] and Delta [m].

    :meth:`of` reads them off a built contact; :meth:`of_inputs` (the fit's every evaluation) off the pair's
    reference contact by the scalings of section 6 (M proportional to sqrt(G_c beta*)/Delta, G_c the law's edge
    work, P/p = 4 pi Delta/beta*), with the law asked for k at the scaled M."""

    def __init__(self, materials, k, L, D, work_shift, make_contact):
        self.materials, self.k, self.L, self.D, self.work_shift = materials, k, L, D, work_shift
        self._make = make_contact

    @classmethod
    def of(cls, c: Contact, materials: Materials) -> "Superposed":
        pb = c.problem
        return cls(materials, law_coefficient(pb, pb.m), c.units.per_kernel("load"), c.Delta, pb.work_shift,
                   lambda: c)

    @classmethod
    def of_inputs(cls, R, Delta, w, f, materials, law=None) -> "Superposed":
        """The contact of clearance Delta [m], work of adhesion w [J/m^2], the pair ``materials`` times f and the
        edge law (None: JKR) (ValueError outside 0 < Delta < R, w >= 0, f > 0, as Contact would)."""
        if not (0 < Delta < R and w >= 0 and f > 0 and math.isfinite(w) and math.isfinite(f)):
            raise ValueError(f"Delta, w: outside 0 < Delta < R, w >= 0 (Delta = {Delta!r}, w = {w!r}, f = {f!r})")
        ref, pb = reference(R, materials, law)
        M = pb.M * math.sqrt(ref.law.edge_work(w) / (ref.law.edge_work(REF_W) * f)) * ref.Delta / Delta
        return cls(materials, law_coefficient(pb, M * pb.scale), ref.units.per_kernel("load") * f * Delta / ref.Delta,
                   Delta, pb.work_shift,
                   lambda: contact(R, Delta, w, scaled(materials, f) if f != 1.0 else materials, law=law))

    @functools.cached_property
    def contact(self) -> Contact:
        """The library's contact (built on demand: the pull-off and the checks ask it)."""
        return self._make()

    def slice(self, a, keep=True) -> Slice:
        return superpose(unit_slices(self.materials, a, keep), self.k)

    def physical(self, s: Slice) -> States:
        L, D = self.L, self.D
        return States(s.a, L * s.p, D * s.dw, D * s.h, L * s.dp_da, D * s.ddw_da, s)

    def states(self, a, keep=True) -> States:
        """States at the contact parameters a (1-D; keep: see :func:`unit_slices`)."""
        return self.physical(self.slice(a, keep))

    def loads(self, a, slopes=False):
        """(P, dP/da) [N/m] at a (dP/da None unless slopes): the load alone, for the width residuals."""
        parts = unit_slices(self.materials, a).parts
        P = self.L * (parts["p"][0] + self.k * parts["p"][1])
        return P, (self.L * (parts["dp_da"][0] + self.k * parts["dp_da"][1]) if slopes else None)

    def load_curvature(self, a) -> np.ndarray:
        """d2P/da2 [N/m] at a: central differences of the exact slope dP/da in log a (step CURVATURE_STEP)."""
        a = np.asarray(a, dtype=float)
        h = CURVATURE_STEP
        up, down = (unit_slices(self.materials, a * math.exp(s)).parts["dp_da"] for s in (h, -h))
        return self.L * ((up[0] - down[0]) + self.k * (up[1] - down[1])) / (2 * h * a)


def states(c: Contact, materials: Materials, a) -> States:
    """States of contact c (its materials: ``materials`` times a common factor, the shape of the cache) at a."""
    return Superposed.of(c, materials).states(a)


def linear_columns(R, Delta, materials, a):
    """Columns (values, a-slopes, a-curvatures; each of shape (2, n)) of P = x1 c1 + x2 c2 at fixed contact
    parameters a for the pair's shape ``materials`` times any factor f, clearance Delta and work of adhesion w:
    x1 = f Delta/Delta_0, x2 = sqrt(f w/w_0) with the reference Delta_0 = Delta and w_0 = 1 J/m^2 (the adhesive
    amplitude of the law: k Delta is proportional to sqrt(f w), Griffith's K = sqrt(8 w/beta*); :func:`amplitude_w`
    inverts it).  For the linear least-squares start."""
    c = contact(R, Delta, 1.0, materials)
    L, k = load_per_p(c), edge_coefficient(c)
    a = np.asarray(a, dtype=float)
    out = []
    for field in ("p", "dp_da"):
        parts = unit_slices(materials, a).parts[field]
        out.append(np.array([L * parts[0], L * k * parts[1]]))
    h = CURVATURE_STEP
    up, down = (unit_slices(materials, a * math.exp(s)).parts["dp_da"] for s in (h, -h))
    curvature = [(up[i] - down[i]) / (2 * h * a) for i in (0, 1)]
    out.append(np.array([L * curvature[0], L * k * curvature[1]]))
    return out


def amplitude_w(x2, f):
    """w [J/m^2] of the adhesive amplitude x2 of :func:`linear_columns` at modulus factor f: x2 = sqrt(f w/1)."""
    return x2 * x2 / f


def pole(materials: Materials) -> float:
    """a at the receding-contact pole of the single arc: the single-patch solver's a_crit (inf for a rigid cradle
    at alpha* = 0; section 4)."""
    return shape(materials)[0].a_crit


def resolved(materials: Materials) -> float:
    """The largest contact parameter the pair's single-patch solver resolves."""
    return shape(materials)[0].a_max
