"""The Maugis-Dugdale two-patch branch traced (notation and the fixed-arc state: jkrcyl.numerics.cohesive_two),
each state warm-started from its neighbour.

A state (:func:`solve_at`): one half-angle held, Newton in z = (the other, log d_bot, log d_top) on
[k_top, h(c) - h0, h(pi - c_top) - h0] (k_bot = 0 fixes delta at given arcs and zones).  The zone columns of the
Jacobian are differences at the same arcs (back-substitutions: only the zone right-hand side changes), the arc
column a secant update along the iterates, started from the neighbour's: one new fixed-arc system per step.
A new system near a factorised one (REUSE_SPAN) is solved by iterative refinement with that LU (:class:`BranchLaw`,
:class:`Refined`: O(n^2), to the LU's own residual).  The Newton is jkrcyl.numerics.roots.damped_newton; where
thin zones leave the residuals a rounding floor above tol (lambda ~ 1000) it ends at RESIDUAL_FLOOR.  Measured at
M = 0.2 (benchmarks/bench_cohesive_two.py): the whole branch (16 states and their flags) in ~0.8 s CPU at every
lambda from 20 to 1000 with the end layers (64 nodes per arc), where without them it took 2.6 / 29 s at lambda =
20 / 50 (225 / 564 nodes per arc: 216 assemblies of 0.09 s at 50).

The branch (:func:`trace`): JKR's (jkrcyl.analysis.tracing; the limit lambda -> inf, O(lambda^-2) away) is the
scaffold.  At each scaffold point the half-angle that varies most along it is held at JKR's value and the other
solved, from JKR's value plus the previous state's offset (then the other way round, then through a midpoint);
the trace starts where both arcs are largest (the zones thinnest relative to them) and walks to both ends,
stopping where a state is not found (e.g. both arcs small against the zones), an end at an axis followed down to
an arc END_ARC.  One node count for the whole problem (states are one discretisation, so a state solved alone at
that count equals the traced one), with the zones' end layers subtracted (cohesive_two_layer): the count of
JKR's near-touching arcs, at least cohesive_two.NODES_LAYER_TWO, whatever the zone length -- measured at M = 0.2
along the whole branch, lambda = 20 / 50: 48 nodes per arc are 1.4e-8 / 1.7e-7 off 128 in P*, 64 nodes 2e-11 /
3e-10 (without the layers the zones needed 8 sqrt(eps_max/d): 564 per arc at lambda = 50, 1.5 s per cold state).

Stability under each control from one Jacobian: jkrcyl.numerics.cohesive_two_stability.flags.
"""
import math
from collections import namedtuple

import numpy as np
from threadpoolctl import ThreadpoolController

from . import cohesive as _co
from . import cohesive_two as _two
from . import cohesive_two_layer as _layer
from . import cohesive_two_stability as _stab
from . import roots as _roots
from .cohesive_two_layer import check_lambda  # noqa: F401 (the analysis layer's refusal before any trace)

ZONE_MAX = 0.02           # the largest Dugdale zone estimate followed [rad] (lambda >~ 8 at M = 0.2)
SECANT_STEPS = 12         # Newton steps at most (a warm start takes 2-4)
RESIDUAL_FLOOR = 1e-8     # Newton ends where its steps stop reducing residuals below this (the rounding floor,
                          # above tol at thin zones: k_top ~2e-11, h(c) - h0 ~3e-12 at lambda = 1000 -- terms of
                          # size s0 ~ 85 cancel -- and k_top ~1e-10 at a top arc of 3.5e-4)
END_ARC = 1e-4            # a branch end at an axis: the smaller arc followed down to this [rad]
END_FACTOR = 0.1          # ... shrinking by this factor per state
REUSE_SPAN = 0.05         # arcs within this (in log half-angle) of a factorised pair reuse its LU
REFINE_STEPS = 12         # iterative refinement steps before a fresh LU
_BLAS = ThreadpoolController()


def one_blas_thread():
    """A context with BLAS on one thread: the many small LUs, solves and products of a trace run ~20 x slower
    with OpenBLAS's workers spinning between them on a shared 2-core machine (lambda = 10: 42 LUs of 224
    unknowns took 0.21 s each, 2678 solves 4 ms each; on one thread the whole trace is ~1 s)."""
    return _BLAS.limit(limits=1, user_api="blas")


class Refined(_two.FixedArcs):
    """Fixed arcs whose systems are solved by iterative refinement preconditioned with a nearby pair's LU (the
    collocation matrix moves smoothly with the arcs): O(n^2) per solve instead of an O(n^3) LU; a fresh LU where
    the refinement does not reach the LU's own residual -- the answers are those of a direct solve to rounding."""

    def __init__(self, eps, eps_top, kernel, n, ref, layered=False):
        self.ref = ref
        super().__init__(eps, eps_top, kernel, n, layered)

    def factor(self):
        self.norm = float(np.max(np.sum(np.abs(self.sys.A), axis=1)))

    def solve(self, rhs):
        if not hasattr(self, "lu"):       # (once the refinement failed on this pair: its own LU from then on)
            x = self.ref.solve(rhs)
            for _ in range(REFINE_STEPS):
                r = rhs - self.sys.A @ x
                if np.max(np.abs(r)) <= 64 * np.finfo(float).eps * self.norm * np.max(np.abs(x)):
                    return x
                x = x + self.ref.solve(r)
            if not hasattr(self, "u0"):   # in the constructor: the caller (BranchLaw.arcs) factorises afresh
                raise NotConverged
            _two.FixedArcs.factor(self)   # later (a zone solution): this pair's LU, the direct solve
        return super().solve(rhs)


class NotConverged(Exception):
    """The refinement of :class:`Refined` did not converge in its constructor (the reference pair too far)."""


class BranchLaw(_two._Law):
    """cohesive_two's law whose fixed arcs reuse the LU of a nearby factorised pair (:class:`Refined`): a
    Newton step and the differences of :func:`jacobian` cost back-substitutions and products, not a new LU."""

    def __init__(self, m, s0, kernel, layered=False):
        super().__init__(m, s0, kernel, layered)
        self.ref = None
        self.factorisations = 0

    def arcs(self, eps, eps_top, n):
        key = (eps, eps_top, n)
        if key in self._arcs:
            return self._arcs[key]
        if len(self._arcs) > 8:
            self._arcs.clear()
        ref = self.ref
        fa = None
        if ref is not None and ref.sys.n == n and max(abs(math.log(eps / ref.eps)),
                                                      abs(math.log(eps_top / ref.eps_top))) < REUSE_SPAN:
            try:
                fa = Refined(eps, eps_top, self.kernel, n, ref, self.layered)
            except NotConverged:
                fa = None
        if fa is None:
            fa = self.ref = _two.FixedArcs(eps, eps_top, self.kernel, n, self.layered)
            self.factorisations += 1
        self._arcs[key] = fa
        return fa


Traced = namedtuple("Traced", ["states", "jacobians", "ends"])
Traced.__doc__ = """States in order, their Jacobians (:func:`jacobian`), the ends (JKR's label or 'unresolved')."""


class NotFound(Exception):
    """No state here (the zones meet, or Newton did not converge)."""


def require_alpha_zero(ar):
    """ValueError naming alpha_ratio unless alpha* = 0 (the two-arc cohesive collocation's kernel)."""
    if ar != 0.0:
        raise ValueError(f"alpha_ratio (the materials' alpha*/beta*) must be 0 for the Maugis-Dugdale two-patch "
                         f"states (the two-arc cohesive solver), got {ar!r}")


def follows_scaffold(law):
    """Whether the law's zones are small enough (Dugdale's estimate <= ZONE_MAX) for :func:`trace` along JKR's."""
    return _co.dugdale_zone(law.m, law.s0) <= ZONE_MAX


def branch_nodes(points, m, s0, ar=0.0, scaffold=True):
    """Nodes per arc for the states near the points (k, 2), with the end layers subtracted (module docstring: a
    count independent of lambda); ValueError naming sigma0 where the zones are too thin (lambda beyond
    cohesive_two_layer.LAMBDA_MAX) or, for the scaffold (JKR's branch followed), not small (d > ZONE_MAX: low
    lambda, where JKR's branch is no guide to the law's; the law's own branch, jkrcyl.numerics.cohesive_two_own,
    is traced there)."""
    d = _co.dugdale_zone(m, s0)
    if scaffold and d > ZONE_MAX:
        raise ValueError(f"sigma0: the two-patch branches are followed from JKR's where the Dugdale zones are "
                         f"small (~{d:.3g} rad > {ZONE_MAX} here: the transition parameter lambda = "
                         f"{4 * s0 / m ** (2 / 3):.3g} is too small for it)")
    _layer.check_lambda(m, s0)
    return max(_two.nodes(e, et, d, ar, layered=True) for e, et in points)


def residual(law, held, value, z, n):
    """[k_top, h(c) - h0, h(pi - c_top) - h0] at z = (the free half-angle, log d_bot, log d_top), the other
    half-angle (held: 0 eps, 1 eps_top) at value and k_bot = 0; None outside the domain (the zones meet)."""
    x, d = z[0], np.exp(z[1:])
    eps, eps_top = (x, value) if held == 1 else (value, x)
    if not (0 < eps and 0 < eps_top and eps + eps_top + d.sum() < math.pi):
        return None
    zones = _co.zones_of(eps + d[0], eps_top + d[1])
    fa, dn, u, k = law.pieces(eps, eps_top, zones, n)
    h = fa.gap(np.array([eps + d[0], math.pi - eps_top - d[1]]), dn, u, zones, law.s0)
    return np.array([k[1], h[0] - law.h0, h[1] - law.h0])


def solve_at(law, held, value, guess, d0, n, jx=None, tol=1e-11):
    """The state with the half-angle ``held`` (0: eps, 1: eps_top) at value, the other from guess and the zone
    lengths from d0: Newton in z = (x, log d_bot, log d_top) whose d-columns are differences at the same arcs
    (back-substitutions) and whose x-column is a secant update along the iterates (started from jx, a
    neighbour's, or one difference): one LU per step.  Returns (TwoPatchCohesive, jx); raises NotFound."""
    f = lambda z: residual(law, held, value, z, n)
    scale = np.array([max(1.0, law.m), max(1.0, law.h0), max(1.0, law.h0)])
    z = np.array([guess, *np.log(d0)], dtype=float)
    col = [jx]                                           # the x-column, secant-updated along the iterates

    def jacobian(z, r):
        J = np.empty((3, 3))
        for j in (1, 2):
            rj = f(z + 1e-6 * np.eye(3)[j])
            if rj is None:
                return None
            J[:, j] = (rj - r) / 1e-6
        if col[0] is None:
            h = 1e-7 * z[0]
            rj = f(z + h * np.eye(3)[0])
            if rj is None:
                return None
            col[0] = (rj - r) / h
        J[:, 0] = col[0]
        return J if np.all(np.isfinite(J)) and np.linalg.cond(J) < 1e14 else None    # (singular: no state here)

    def secant(z, dz, r, rt, J):
        if dz[0] != 0:
            col[0] = (rt - r - J[:, 1:] @ dz[1:]) / dz[0]

    got = _roots.damped_newton(f, z, jacobian, scale, tol, np.array([0.2 * z[0], 2.0, 2.0]), SECANT_STEPS, 6,
                               RESIDUAL_FLOOR * scale, secant)
    if got is None:
        raise NotFound
    z, jx = got[0], col[0]
    d = np.exp(z[1:])
    eps, eps_top = (z[0], value) if held == 1 else (value, z[0])
    return _two.state(law, eps, eps_top, eps + d[0], eps_top + d[1], n), jx


def _free_index(points, i):
    """The half-angle that varies least along the scaffold at point i: it is solved, the other (the branch's
    local parameter) held."""
    lo, hi = points[max(i - 1, 0)], points[min(i + 1, len(points) - 1)]
    return int(np.argmin(np.abs(np.log(hi) - np.log(lo))))


def _step(law, target, prev, prev_at, free, n, slope, depth=2):
    """The state near the scaffold point target, from the previous state prev (at the scaffold point prev_at):
    the free half-angle solved from target + prev's offset, the other held at target's (with the slope, then a
    difference); then the other way round; then through the midpoint (depth levels at most).  Returns (state,
    slope, free); raises NotFound."""
    d0 = np.array([prev.c - prev.eps, prev.c_top - prev.eps_top])
    offset = np.array([prev.eps, prev.eps_top]) - prev_at
    for f, jx in ((free, slope), (free, None), (1 - free, None))[0 if slope is not None else 1:]:
        try:
            st, jx = solve_at(law, 1 - f, target[1 - f], target[f] + offset[f], d0, n, jx)
            return st, (jx if jx is not None and np.all(np.isfinite(jx)) else None), f
        except NotFound:
            continue
    mid = np.sqrt(target * prev_at)                      # halfway in log half-angles
    if depth == 0:
        raise NotFound
    st, _, f = _step(law, mid, prev, prev_at, free, n, None, depth - 1)
    return _step(law, target, st, mid, f, n, None, depth - 1)


def _walk(law, points, order, n, start):
    """Solve along the scaffold points in the given order of indices from start = (state, index) (module
    docstring); stops at the first point not reached.  Returns [(index, state)]."""
    out = []
    (prev, prev_i), slope, prev_free = start, None, None
    for i in order:
        free = _free_index(points, i)
        try:
            st, slope, f = _step(law, points[i], prev, points[prev_i], free, n, slope if free == prev_free else None)
        except NotFound:
            break
        out.append((i, st))
        prev, prev_i, prev_free = st, i, f
    return out


def _to_axis(law, st, n):
    """From the last state st towards the axis its smaller arc runs to (scaffold end 'single' or 'mirror'): that
    arc held and shrunk by END_FACTOR per state down to END_ARC (by its square root, twice, where a step fails;
    with the slope of the last state, then a difference), the other solved.  Returns (states, reached)."""
    out, small = [], int(st.eps_top < st.eps)
    jx = None
    while True:
        arcs = np.array([st.eps, st.eps_top])
        if arcs[small] <= END_ARC:
            return out, True
        d0 = np.array([st.c - st.eps, st.c_top - st.eps_top])
        for factor, slope in [(END_FACTOR ** (0.5 ** k), s) for k in range(3) for s in (jx, None)]:
            try:
                st, jx = solve_at(law, small, max(arcs[small] * factor, 0.99 * END_ARC), arcs[1 - small], d0, n,
                                  slope)
                break
            except NotFound:
                continue
        else:
            return out, False
        out.append(st)


def trace(law, points, ends, n):
    """The states along the scaffold points (k, 2) with JKR's end labels ends (module docstring): a Traced whose
    ends are JKR's where the states reach them (an end 'single' or 'mirror': the smaller arc down to END_ARC)
    and 'unresolved' elsewhere."""
    points = np.asarray(points, dtype=float)
    points = points[np.min(points, axis=1) > END_ARC]        # JKR's ends at an axis: reached by _to_axis
    d0 = np.full(2, _co.dugdale_zone(law.m, law.s0))
    for mid in np.argsort(-np.min(points, axis=1))[:3]:      # the start: both arcs large (far from the zones)
        free = _free_index(points, mid)
        try:
            st, _ = solve_at(law, 1 - free, points[mid][1 - free], points[mid][free], d0, n)
            break
        except NotFound:
            continue
    else:
        return Traced((), (), ("unresolved", "unresolved"))
    sides = []
    for order, end in ((range(mid + 1, len(points)), ends[1]), (range(mid - 1, -1, -1), ends[0])):
        got = [s for _, s in _walk(law, points, order, n, (st, mid))]
        last = got[-1] if got else st
        reached = len(got) == len(order)
        if end in ("single", "mirror") and reached:
            more, reached = _to_axis(law, last, n)
            got += more
        sides.append((got, end if reached else "unresolved"))
    states = tuple(sides[1][0][::-1]) + (st,) + tuple(sides[0][0])
    return Traced(states, tuple(_stab.jacobian(law, s) for s in states), (sides[1][1], sides[0][1]))
