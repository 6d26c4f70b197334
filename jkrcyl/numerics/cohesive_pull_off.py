"""Load-control pull-off of the Maugis-Dugdale contact (normalised; the model core wires it in).

The states with one contact and one zone form curves in the plane (eps, d), d = c - eps the zone length: the
zone end can turn back in eps (at lambda ~ 1-10 the first root of h(c) = h0 disappears at a fold and the curve
returns with a longer zone).  So the branch is traced by continuation (jkrcyl.numerics.cohesive_follow.follow,
the tracer of the model core's branch table) in (log eps, log d), from its end at eps -> 0 (the contact about to vanish,
joined there to the contactless state that touches), until the load rises through p = 0 (the zero-load state)
or the curve leaves the domain (the receding limit a_crit, or the zone reaching round).

Under a fixed load a one-parameter family of equilibria changes stability only where p turns along it, so
from the zero-load state (stable) the pull grows along the curve towards its touch end until p is minimal:
the pull-off p* is the first minimum of p met going back from the zero-load state ('fold', JKR-like), or the
touch end itself when p falls all the way ('touch': the contactless states beyond hold less, the pin detaches).
With the range reaching round (h0 > 2 Delta less the uniform pull) p >= 0 all along: no adherence force.
Collocation nodes: a function of eps only along the trace (the zone estimate m^2/(4 s0^2)), so that the residual
is smooth for the continuation; the minimum is refined in eps (Brent) on the branch through the traced point.
"""
import math
from collections import namedtuple

import numpy as np

from . import cohesive as _co
from . import roots as _roots
from . import cohesive_branch as _cb
from . import cohesive_follow as _fo
from . import cohesive_zones as _cz

PullOff = namedtuple("PullOff", ["p", "eps", "kind", "state", "zero_load", "reason"])
PullOff.__doc__ = """Load-control pull-off: p = P* beta*/(4 pi Delta) at detachment (None with a reason when the pin
does not adhere or the branch has no zero-load state), eps there (0 for 'touch'), kind 'fold' | 'touch' | None,
the state there (CohesiveState), the zero-load state (CohesiveState or None)."""

START = 1e-3                # the trace starts at eps = START times the half-plane scale 2 m^(2/3) (at most 1e-3)


def jump_reason(jump):
    """Why a branch whose zone stops reaching round by a jump (jkrcyl.numerics.cohesive_branch.top_opens:
    (eps, c, kind)) has no answer here."""
    eps, c, kind = jump
    return (f"not modelled: the zone reaches round the hole at small contacts and its zone end jumps to "
            f"c = {c:.6g} rad at eps = {eps:.6g} rad -- a {kind} "
            + {"top bridge": "(a zone at the top apart from the bottom one)",
               "second zone family": "(a zone end born at a fold in the contact size, while the round-zone states "
                                     "go on with their gap below the range all round)"}.get(kind,
               "(the round-zone states turn back in the contact size before joining the states that tend to JKR)")
            + ", not traced by the solver")


def floats_reason(jump):
    """Why a pin whose zone reaches round at first touch, on a branch whose round zone later jumps
    (jkrcyl.numerics.cohesive_branch.top_opens: (eps, c, kind)), does not pull from first contact."""
    eps, c, kind = jump
    return ("no adherence force from first contact: the pin floats in the range, which reaches round, and touches "
            f"onto round-zone contacts that push (p >= 0); pushed past the contact eps = {eps:.6g} rad its "
            f"round zone jumps ({kind}) onto contacts that pull")


def pull_off_load(m, s0, theta, gb, ar=0.0, steps=(0.1, 0.3), start=START, xtol=1e-10, zero_load=True):
    """The load-control pull-off from the zero-load state (module docstring): m = M vartheta > 0, s0 > 0.
    steps: the first and the largest continuation step in (log eps, log(c - eps)) (the minimum is refined by
    Brent on the branch either way; larger steps, fewer states: the (lambda, M) map uses (0.3, 1.2)); start: where
    the trace starts, relative to the half-plane scale (a minimum of p below it is taken for the touch end);
    xtol: of the minimum in eps (p* is flat there: 1e-6 gives p* to ~1e-12); zero_load=False skips refining the
    zero-load state (PullOff.zero_load is then None)."""
    m, s0, _ = _co._law(m, s0, theta, gb, ar)
    none = lambda reason, zero=None: PullOff(None, None, None, None, zero, reason)
    if m == 0.0:
        return none("no adhesion (m = 0)")
    law = _cb.Law(m, s0, theta, gb, ar)
    eps_lo, eps_hi = min(start * 2 * m ** (2 / 3), 1e-3), law.eps_hi
    def load(x):
        eps, d = math.exp(x[0]), math.exp(x[1])
        fc = law.fixed(eps)
        zones = _co.zones_of(eps + d)
        dn, u = fc.solve(zones, s0)
        return fc.load_width(u, zones, s0)[0]

    def along(e_ref, d_near):
        """States near the zone length d_near with the contact (nodes, layer) of e_ref: smooth in eps."""
        n, layered = law.contact(e_ref)
        return lambda e: _co.cohesive_state(e, m, s0, theta, gb, ar, n=n, near=d_near, layered=layered)

    start = law.state(eps_lo)
    if start.zones == "all":
        # h0 >= 2 Delta: the range alone reaches round and no state pulls (a jump there changes no answer); else
        # the pin floats in the range and touches onto round-zone contacts that push: it stays at the touch at
        # P = 0 -- a jump of the round zone (cohesive_branch.top_opens) lies beyond, reached only by pushing
        opens = _cb.opens_of(law) if law.h0 < 2.0 else None
        if start.p >= 0 and opens is not None:
            return none(floats_reason(opens))
        return none("no adherence force: the zone reaches round (p >= 0)" if start.p >= 0 else
                    "the contact branch starts in a zone reaching round")

    left_by_load = [False, None]        # whether the last step out of the domain crossed p = 0, and to where

    def inside(x):
        eps, d = math.exp(x[0]), math.exp(x[1])
        in_box = eps_lo * 0.999 <= eps < eps_hi and eps + d < math.pi * (1 - 1e-9)
        left_by_load[:] = in_box and load(x) >= 0, x
        return in_box and not left_by_load[0]

    x0 = np.array([math.log(eps_lo), math.log(start.c - eps_lo)])
    # without the zero-load state the trace need not creep up to p = 0: a step out of it ends the trace
    pts, stopped = _fo.follow(law, x0, inside, h0=steps[0], h_max=steps[1],
                              done=None if zero_load else lambda y: left_by_load[0])
    if stopped:                         # the branch was not followed to where it leaves the domain
        return none(stopped)
    eps_end, d_end = np.exp(pts[-1])
    if left_by_load[0]:                 # the branch's point past p = 0 closes the search for a minimum of p
        pts = np.vstack([pts, left_by_load[1]])
    p = np.array([load(x) for x in pts])
    if not (left_by_load[0] and eps_lo * 1.01 < eps_end and (not zero_load or (
            eps_end < eps_hi * 0.999 and eps_end + d_end < math.pi * (1 - 1e-6)))):
        return none("no zero-load contact on the branch: p < 0 all along it (it ends at the receding limit, "
                    "turns back to eps -> 0 or its zone reaches round)")
    state = along(eps_end, d_end)
    zero = _zero_load(state, eps_end) if zero_load else None
    # the walk starts at the zero-load contact only if it is feasible (the model core's rule); without the refined
    # state the branch's point just past p = 0 stands in for it
    first = zero if zero is not None else state(math.exp(left_by_load[1][0]))
    if first is not None and not _co.gap_check(first, 120).feasible:
        return none("no feasible zero-load contact: the gap closes or the law is broken off the contact there", zero)
    # back from the zero-load end: the first minimum of p, or the touch end
    for j in range(len(p) - 2, 0, -1):
        if p[j - 1] > p[j] < p[j + 1] and (pts[j, 0] - pts[j - 1, 0]) * (pts[j + 1, 0] - pts[j, 0]) <= 0:
            st = _fold_past_eps_fold(law, pts, j, load, xtol)      # the three points straddle a fold in eps
            return PullOff(st.p, st.eps, "fold", st, zero, "")
        if p[j - 1] > p[j] < p[j + 1]:
            eps_j, d_j = np.exp(pts[j])
            on_branch = along(eps_j, d_j)
            f = lambda e: (lambda st: math.inf if st is None else st.p)(on_branch(e))
            lo, hi = sorted((math.exp(pts[j - 1][0]), math.exp(pts[j + 1][0])))
            x, _ = _roots.minimum(f, lo, eps_j, hi, xtol)     # bounded where the re-solved point is not lowest
            st = on_branch(x)
            return PullOff(st.p, x, "fold", st, zero, "")
    touch = _cz.contactless_touch(m, s0, theta, gb, ar, eps_small=min(1e-6, eps_lo * 1e-3))
    if touch is None:
        return none("the branch ends in a zone reaching round (p -> 0)", zero)
    return PullOff(touch.p, 0.0, "touch", touch, zero, "")


def _fold_past_eps_fold(law, pts, j, load, xtol):
    """The state of least p near the traced point j whose neighbours straddle a fold of the branch in eps (eps is
    no parameter there): refined in log(c - eps), which runs through such a fold, eps by secant at each."""
    span = 2 * np.abs(pts[j + 1] - pts[j - 1]).max()
    on = lambda ld: _fo.fixed_zone(law, np.array([pts[j, 0], ld]), span)
    f = lambda ld: (lambda y: math.inf if y is None else load(y))(on(ld))
    lo, hi = sorted((pts[j - 1, 1], pts[j + 1, 1]))
    y = on(_roots.minimum(f, lo, pts[j, 1], hi, xtol)[0])
    if y is None:
        y = pts[j]
    eps, c = math.exp(y[0]), math.exp(y[0]) + math.exp(y[1])
    fc, zones = law.fixed(eps), _co.zones_of(c)
    dn, u = fc.solve(zones, law.s0)
    return _co._state(eps, c, fc, dn, u, zones, law.m, law.s0, law.kernel, law.gb, fc.sys.n)


def _zero_load(state, eps_end):
    """The zero-load state just past the traced end (p < 0 there, >= 0 a little further in eps)."""
    hi = eps_end
    for _ in range(60):
        hi *= 1.0005
        s = state(hi)
        if s is None or s.p >= 0:
            break
    if s is None:
        return state(eps_end)
    return state(_roots.root(lambda e: state(e).p, eps_end, hi, xtol=1e-13 * eps_end))
