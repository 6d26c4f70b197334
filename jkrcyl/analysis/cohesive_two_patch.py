"""The Maugis-Dugdale law's two-patch family through the model core: the branches traced
(jkrcyl.numerics.cohesive_two_branch: along JKR's, each state warm-started from its neighbour, where the zones are
small and it reaches JKR's ends; elsewhere the law's own, jkrcyl.numerics.cohesive_two_own: seeded at the top's
closing and continued by its own arclength -- none where its seeds fold in lambda), a state at a given
half-angle (cold, from JKR's state: jkrcyl.numerics.cohesive_two.solve's guess), the states at a load or an
approach, and the landing of a path on the branch (:meth:`CohesiveTwoPatch.land`).

Results are JKR's types (jkrcyl.results.TwoPatchCurve, TwoPatchState), normalised as section 6 (P* = p/vartheta);
for this law G_bot, G_top are the zones' J-integrals over w, s0 h(zone end)/w = h(c)/h0 (1 on the branch: the
contact edges have k = 0), gap_min the smallest gap outside both arcs, and TwoPatchState.energy is U* plus the
zones' interface energy, so that for both laws the total potential is energy - 2 M^2 vartheta (eps + eps_top)
(units 4 pi Delta^2 vartheta/beta*).  Branch ends: JKR's labels where reached ('single': the top arc shrinks to
END_ARC, its zone staying as a bridge; 'mirror' the same upside down), 'unresolved' where the states stop short
(e.g. the zones meet near full contact at small lambda); the own route's ends: 'single', 'mirror' (back at an
axis: a loop at lambda just above its fold), 'zones meet' or 'unresolved'.

alpha* = 0 only (the two-arc cohesive collocation); elsewhere a ValueError naming alpha_ratio.
"""
from __future__ import annotations

import functools
import math
import warnings

import numpy as np

from .._validate import count
from ..numerics import cohesive as _co
from ..numerics import cohesive_two as _ct
from ..numerics import cohesive_two_branch as _cb
from ..numerics import cohesive_two_own as _own
from ..numerics import cohesive_two_stability as _st
from ..numerics import roots as _roots
from ..model import two_patch as _two
from ..model.problem import Problem
from ..model.single_patch import solver
from ..notices import BranchLimitWarning
from ..results import TwoPatchCurve, TwoPatchState
from . import tracing as _tr

DEFAULT_POINTS = 12       # scaffold points per branch (JKR's branch resampled; benchmarks/bench_cohesive_two.py)
GAP_SAMPLES = 256         # exterior angles of the gap check


class CohesiveTwoPatch:
    """The two-patch family of a problem with the Maugis-Dugdale edge (module docstring)."""

    def __init__(self, pb: Problem):
        _two.require_two_patch(pb)
        _cb.require_alpha_zero(pb.alpha_ratio)
        self.pb = pb
        self.jkr = Problem(pb.M, pb.theta, pb.gb, pb.alpha_ratio)
        m, s0, kernel = _co._law(pb.m, pb.edge.s0, pb.theta, pb.gb, 0.0)
        self.law = _cb.BranchLaw(m, s0, kernel, layered=True)

    # --- states ---------------------------------------------------------------------------------------------
    def result(self, st) -> TwoPatchState:
        """A numerics TwoPatchCohesive as a TwoPatchState (module docstring); _lin keeps the numerics state."""
        pb, th = self.pb, self.pb.scale
        ends = st.fields.gap(np.array([st.c, math.pi - st.c_top])) / st.h0_over_Delta
        total = _ct.potential(st)
        return TwoPatchState(M=pb.M, theta=pb.theta, gb=pb.gb, eps=float(st.eps), eps_top=float(st.eps_top),
                             P_star=float(st.p) / th, B_star=float(st.B) / th,
                             delta_over_Delta=float(st.delta_over_Delta), G_bot=float(ends[0]),
                             G_top=float(ends[1]),
                             energy=float(total + 2 * pb.m ** 2 * (st.eps + st.eps_top)) / th,
                             gap_min=gap_min(st), alpha_ratio=pb.alpha_ratio, _lin=st)

    def flags(self, s: TwoPatchState):
        """(stable_load, stable_grip, stable_grip_work) of a state (cohesive_two_branch.flags)."""
        with _cb.one_blas_thread():
            return _st.flags(_st.jacobian(self.law, s._lin), self.pb.work_shift)

    def potential(self, s: TwoPatchState) -> float:
        """The total potential in the kernel scale (units 4 pi Delta^2/beta*)."""
        return _ct.potential(s._lin)

    @functools.cached_property
    def n(self) -> int:
        """Nodes per arc of every state of the problem: from the largest arc of JKR's branches (one
        discretisation: a state solved alone equals the traced one); ValueError naming sigma0 (too thin zones,
        or too thick: cohesive_two_branch.branch_nodes)."""
        points = [p for p, _ in _tr.traced(self.jkr)]
        return _cb.branch_nodes(np.vstack(points) if points else np.full((1, 2), 0.1), self.law.m, self.law.s0,
                                scaffold=False)

    def state(self, eps=None, eps_top=None, guess=None) -> TwoPatchState:
        """The equilibrium with one half-angle given, the other from guess: Newton from JKR's state there (guess
        for JKR's secant) -- cold, independent of any traced branch; the node count of the branches."""
        ref = _two.solve(self.jkr, eps_top=eps_top, eps=eps, guess=guess)
        n = self.n
        held, value = (1, ref.eps_top) if eps is None else (0, ref.eps)
        return self.at(held, value, (ref.eps, ref.eps_top)[1 - held], n)

    def at(self, held, value, guess, n, d0=None) -> TwoPatchState:
        """The state with half-angle ``held`` (0: eps, 1: eps_top) at value, the other from guess, n nodes per
        arc; ValueError naming guess where none is found."""
        return self.result(self._solve(held, value, guess, n, d0)[0])

    def _solve(self, held, value, guess, n, d0=None, jx=None):
        """(numerics state, jx) of :meth:`at` (cohesive_two_branch.solve_at; d0: the zone lengths to start from,
        jx: a neighbour's Jacobian column)."""
        d0 = np.full(2, _co.dugdale_zone(self.law.m, self.law.s0)) if d0 is None else d0
        try:
            with _cb.one_blas_thread():
                return _cb.solve_at(self.law, held, value, guess, d0, n, jx)
        except _cb.NotFound:
            raise ValueError(f"guess: no cohesive two-patch state near {guess!r} (the other half-angle at "
                             f"{value!r})") from None

    # --- branches -------------------------------------------------------------------------------------------
    def branches(self, n=None) -> tuple:
        """Every branch (JKR's, followed under the law), each a TwoPatchCurve; n: points per scaffold branch
        (default DEFAULT_POINTS; the ends at an axis add the states down to END_ARC)."""
        n = DEFAULT_POINTS if n is None else count("n", n, low=4, high=1000)
        return _branches(self, n)

    def curve(self, states, jacobians, ends) -> TwoPatchCurve:
        pb = self.pb
        res = [self.result(s) for s in states]
        fl = np.array([_st.flags(J, pb.work_shift) for J in jacobians], dtype=bool).reshape(-1, 3)
        arr = lambda k: np.array([getattr(s, k) for s in res])
        sv = solver(self.jkr)
        eps, et = arr("eps"), arr("eps_top")
        P, d = arr("P_star"), arr("delta_over_Delta")
        a, at = np.tan(eps / 2), np.tan(et / 2)
        return TwoPatchCurve(M=pb.M, theta=pb.theta, gb=pb.gb, a=a, a_top=at, eps=eps, eps_top=et,
                             eps_star=sv.eps_star(a), eps_top_star=sv.eps_star(at), P_star=P, delta_over_Delta=d,
                             delta_work_over_Delta=d + pb.work_shift * pb.scale * P, gap_min=arr("gap_min"),
                             feasible=arr("gap_min") >= -1e-9, stable_load=fl[:, 0], stable_grip=fl[:, 1],
                             stable_grip_work=fl[:, 2], G_bot=arr("G_bot"), G_top=arr("G_top"), ends=tuple(ends),
                             alpha_ratio=pb.alpha_ratio)

    # --- states at a load or an approach --------------------------------------------------------------------
    def states_at(self, key: str, target: float) -> list:
        """The states where the field key (P_star, delta_over_Delta, delta_work_over_Delta) equals target: sign
        changes along each traced branch, refined by Brent's method in the half-angle that varies most over the
        bracket (the other held at its interpolated value)."""
        out = []
        for b in self.branches():
            v = np.asarray(getattr(b, key)) - target
            for i in _roots.sign_changes(v):
                s = self._refine(b, i, key, target, self.n)
                if s is None:              # said, not dropped silently (as jkrcyl.analysis.tracing.states_at)
                    warnings.warn(f"two-patch state at {key} = {target:.6g} not solved between the traced points "
                                  f"{i} and {i + 1}", BranchLimitWarning, stacklevel=2)
                else:
                    out.append(s)
        return out

    def along(self, b, i, k, n=None):
        """(state(x), xs) between points i and k of branch b: the half-angle that varies most held at x (xs: its
        values at i and k), the other solved -- from the chord for the first x, then warm from the state solved
        last (its offset from the chord, its zones, its Jacobian column: a search's states are close).  state(x)
        is the numerics state (cohesive_two.TwoPatchCohesive; :meth:`result` makes it a TwoPatchState); the
        bracket's end is solved first (:func:`_warm`)."""
        e, et = b.eps[[i, k]], b.eps_top[[i, k]]
        held = int(abs(math.log(et[1] / et[0])) > abs(math.log(e[1] / e[0])))
        xs, ys = (e, et) if held == 0 else (et, e)
        n = self.n if n is None else n
        chord = lambda x: ys[0] + (ys[1] - ys[0]) * (x - xs[0]) / (xs[1] - xs[0])
        last, memo = [], {}

        def state(x):
            x = float(x)
            if x not in memo:
                if last:
                    st, jx, x0 = last[0]
                    free = (st.eps, st.eps_top)[1 - held]
                    guess, d0 = chord(x) + free - chord(x0), np.array([st.c - st.eps, st.c_top - st.eps_top])
                    try:
                        memo[x] = self._solve(held, x, guess, n, d0, jx)
                    except ValueError:                   # warm start too far: cold, from the chord
                        memo[x] = self._solve(held, x, chord(x), n)
                else:
                    memo[x] = self._solve(held, x, chord(x), n)
                last[:] = [(memo[x][0], memo[x][1], x)]
            return memo[x][0]
        _warm(state, xs)
        return state, xs

    def _held_numeric(self, st, key: str) -> float:
        """:meth:`held` of a numerics state."""
        P = float(st.p) / self.pb.scale
        return {"P_star": P, "delta_over_Delta": float(st.delta_over_Delta),
                "delta_work_over_Delta": float(st.delta_over_Delta) + self.pb.work_shift * self.pb.scale * P}[key]

    def _refine(self, b, i, key, target, n):
        """The state in the bracket (i, i + 1) of branch b (:meth:`along`); Brent in x on key - target.  None
        where the bracket holds no state."""
        state, xs = self.along(b, i, i + 1, n)
        ends = np.asarray(getattr(b, key))[[i, i + 1]] - target        # the traced states' values: not re-solved
        try:
            lo, hi = (0, 1) if xs[0] < xs[1] else (1, 0)
            return self.result(state(_roots.brent(lambda x, _: self._held_numeric(state(x), key) - target,
                                                  xs[lo], xs[hi], (), ends[lo], ends[hi], xtol=1e-13 * max(xs))))
        except ValueError:
            return None

    def fold(self, b, i, k, key: str, sgn: int, target: float = math.inf):
        """The fold of the field key on branch b between points i and k (a bracket of the largest sgn * key):
        Brent's search (numerics.roots.minimum) in the held half-angle (:meth:`along`) to 1e-10 of the bracket; (state, 'fold'),
        or (state, 'target') where the fold lies past target (sgn * (key - target) > 0): the state at target
        between point i and the fold (Brent)."""
        state, xs = self.along(b, i, k)
        x, f = self._largest(state, xs, key, sgn)
        if sgn * (self._held_numeric(f, key) - target) <= 0:
            return self.result(f), "fold"
        x0 = float(xs[0])
        r = _roots.brent(lambda z, _: self._held_numeric(state(z), key) - target, min(x0, x), max(x0, x),
                         xtol=1e-13 * max(x0, x))
        return self.result(state(r)), "target"

    def _largest(self, state, xs, key, sgn):
        """The largest sgn * key between the half-angles xs: the project's minimiser (numerics.roots.minimum,
        Brent's parabolic search) on -sgn * key to 1e-10 of the bracket."""
        lo, hi = sorted(map(float, xs))
        x, _ = _roots.minimum(lambda x: -sgn * self._held_numeric(state(x), key), lo, 0.5 * (lo + hi), hi,
                              1e-10 * hi)
        return x, state(x)

    # --- the walker's landing ---------------------------------------------------------------------------------
    def land(self, control: str, value: float):
        """Where a path that reaches the branch with the held quantity of control ('load': P*, 'grip':
        delta/Delta, 'grip-work') at value lands: the states of the traced branches there, stable under the
        control first, then by contact size.  A list of (TwoPatchState, (stable_load, stable_grip,
        stable_grip_work)); [] where the branch does not reach the value."""
        key = {"load": "P_star", "grip": "delta_over_Delta", "grip-work": "delta_work_over_Delta"}.get(control)
        if key is None:
            raise ValueError(f"control must be 'load', 'grip' or 'grip-work', got {control!r}")
        which = ("load", "grip", "grip-work").index(control)
        got = [(s, self.flags(s)) for s in self.states_at(key, float(value))]
        return sorted(got, key=lambda sf: (not sf[1][which], -(sf[0].eps + sf[0].eps_top)))


@functools.lru_cache(maxsize=16)
def of(pb: Problem) -> CohesiveTwoPatch:
    """The two-patch family of a problem with the Maugis-Dugdale edge, cached per problem (its traced branches
    with it)."""
    return CohesiveTwoPatch(pb)


def land_two_patch(pb: Problem, control: str, value: float) -> list:
    """For the walker (jkrcyl.analysis.path) where a path under the law reaches the two-patch branch (the top
    closes): the states of the traced branches with the held quantity of control ('load': P*, 'grip':
    delta/Delta, 'grip-work': delta_work/Delta) at value, stable under the control first, then the larger
    contact first -- a list of (TwoPatchState, (stable_load, stable_grip, stable_grip_work)); [] where the
    branch does not reach the value (CohesiveTwoPatch.land).  ValueError naming sigma0 or alpha_ratio where the
    law's branches are not followed (cohesive_two_branch.branch_nodes, require_alpha_zero).  E.g. at M = 0.2,
    vartheta = 1, lambda = 20: ``land_two_patch(pb, "load", -0.5)`` gives one state at P* = -0.5, unstable under
    every control (tests/test_cohesive_two_patch_branch.py).
    """
    return of(pb).land(control, value)


def gap_min(st) -> float:
    """min h/Delta outside both arcs (Chebyshev points of the open gap, clustered at the arc ends)."""
    return float(np.min(st.fields.gap(_two.exterior_angles(st.eps, st.eps_top, GAP_SAMPLES))))


def _warm(state, xs):
    """Solve the bracket's first end (else its second) so that the search's states start warm from it: cold from the
    chord a tiny top arc's end may not be found (vartheta inf, gb 1/2, lambda 20, M_R* 0.5: eps_top 0.0091 -- its
    zones far from the Dugdale estimate), and one state at a level was dropped.  Neither found: the search starts
    cold, as before."""
    for x in xs:
        try:
            state(x)
            return
        except ValueError:
            continue


@functools.lru_cache(maxsize=16)
def _branches(fam: CohesiveTwoPatch, n: int) -> tuple:
    _cb.check_lambda(fam.law.m, fam.law.s0)       # refused before JKR's scaffold is traced (~30 s at M 0.3)
    out = []
    for b in _tr.branches(fam.jkr, n):
        points = np.column_stack([b.eps, b.eps_top])
        out += [fam.curve(t.states, t.jacobians, t.ends) for t in _traced(fam, points, b.ends)]
    return tuple(out)


def _traced(fam: CohesiveTwoPatch, points, ends) -> list:
    """The law's branches near JKR's (points, ends): along JKR's as a scaffold where the zones are small
    (cohesive_two_branch.trace: cheaper, ~16 states) and it reaches JKR's ends; else the law's own, seeded at the
    axis ends (cohesive_two_own.branches) -- [] where its seeds fold in lambda (the law has no two-patch states
    there: M = 0.5, lambda = 20; M = 0.2, lambda = 3).  ValueError naming sigma0 where neither finds a state."""
    law = fam.law
    scaffold = None
    with _cb.one_blas_thread():
        if _cb.follows_scaffold(law):
            scaffold = _cb.trace(law, points, ends, fam.n)
            if scaffold.states and "unresolved" not in scaffold.ends:
                return [scaffold]
        try:
            return _own.branches(law, points, ends, fam.n)
        except _own.NoSeed:
            if scaffold is not None and scaffold.states:
                return [scaffold]
    # never a silent drop: JKR's branch is there, the law's was not found from it
    arc = float(np.max(np.min(points, axis=1)))
    raise ValueError(f"sigma0: JKR's two-patch branch (its smaller arc at most {arc:.3g} rad) is not followed "
                     f"under the law: no state found from it (Dugdale zones ~"
                     f"{_co.dugdale_zone(law.m, law.s0):.3g} rad)")
