"""Maugis-Dugdale states beyond a contact with one zone: the pin without contact, held by a zone at
the bottom and/or a zone at the top (closed form up to the zone ends), the free pin inside a range that reaches
round, and contacts with a second zone at the top of the hole.  Normalisation and notation as
jkrcyl.numerics.cohesive (zones: the bottom one |phi| < c, the top one |phi - pi| < c_top).

Without contact the gap is h/Delta = (1 - cos phi) - (delta/Delta) cos phi + s0 Z(phi), linear in delta: the
condition h(c) = h0 at the bottom zone's end gives delta in closed form, the top zone's end h(pi - c_top) = h0
is a scalar root.  A top zone is a bridge the pin pulls to itself: its own traction closes the gap where it acts,
so for one bottom zone there can be no, one or two top zones (a small one, and a large one); every root found
on a scan of c_top is returned.
"""
import math

import numpy as np

from . import cohesive as _co
from . import roots as _roots

TOP_SCAN = np.concatenate([np.geomspace(1e-6, 0.05, 12)[:-1], np.arange(0.05, math.pi, 0.05)])


def contactless_state(c, m, s0, theta, gb, ar=0.0, c_top=0.0):
    """The state without contact with the zones |phi| < c and |phi - pi| < c_top, in closed form.

    delta/Delta from h(c) = h0 (0 < c < pi, c != pi/2: there the approach drops out of h(c) and there is no such
    state); p = -s0 (2 sin c - 2 sin c_top).  The top zone is assumed, not solved (h(pi - c_top) = h0 is the
    condition :func:`contactless_states` solves).  Feasible while 0 <= h <= h0 on the zones and h > h0 elsewhere
    (jkrcyl.numerics.cohesive.gap_check): from the pin touching the bottom (:func:`contactless_touch`) to c -> 0."""
    c = _co.finite_scalar("c", c, low=0.0, high=math.pi, low_open=True)
    c_top = _co.finite_scalar("c_top", c_top, low=0.0, high=math.pi)
    m, s0, kernel = _co._law(m, s0, theta, gb, ar)
    if m == 0.0:
        raise ValueError("m must be > 0 for a contactless cohesive state (w > 0), got 0")
    if c >= math.pi or abs(math.cos(c)) < 1e-12:
        raise ValueError(f"c must be in (0, pi) and not pi/2, got {c:g}")
    if c + c_top >= math.pi:
        raise ValueError(f"c_top must be < pi - c (else the zones meet: floating_range), got {c_top:g}")
    zones = _co.zones_of(c, c_top)
    h0 = m * m / s0
    dn = (2 * math.sin(c / 2) ** 2 + s0 * _co.zone_displacement(c, zones, kernel)[0] - h0) / math.cos(c)
    return _co._state(0.0, c, None, dn, None, zones, m, s0, kernel, gb, 0, c_top)


def contactless_states(c, m, s0, theta, gb, ar=0.0):
    """Every state without contact whose bottom zone is |phi| < c: the one without top zone and those with a top
    zone, the roots in c_top of h(pi - c_top) = h0 on a scan (TOP_SCAN) refined by Brent.  Sorted by c_top;
    feasibility not checked (gap_check)."""
    states = [contactless_state(c, m, s0, theta, gb, ar)]

    def top_residual(ct):
        s = contactless_state(c, m, s0, theta, gb, ar, ct)
        return s.fields.gap(math.pi - ct)[0] - s.h0_over_Delta

    grid = TOP_SCAN[TOP_SCAN < math.pi - c]
    vals = [top_residual(ct) for ct in grid]
    for i in range(len(grid) - 1):
        if vals[i] * vals[i + 1] < 0:
            ct = _roots.root(top_residual, grid[i], grid[i + 1])
            states.append(contactless_state(c, m, s0, theta, gb, ar, ct))
    return states


def top_zone_states(eps, m, s0, theta, gb, ar=0.0, n=None):
    """Every state with the contact |phi| < eps, its zone |phi| < c and a second zone |phi - pi| < c_top at the top
    (c + c_top < pi): for each c_top the bottom zone end solves h(c) = h0 (as jkrcyl.numerics.cohesive
    .cohesive_state), and c_top is a root of h(pi - c_top) = h0 on a scan (TOP_SCAN) refined by Brent.  Nodes as
    the state without top zone.  Feasibility not checked (gap_check).  The family through the small root (the
    top bridge, from c_top = 0 where h(pi) = h0 to the top's closing): jkrcyl.numerics.cohesive_top_zone."""
    base = _co.cohesive_state(eps, m, s0, theta, gb, ar, n)
    if base.zones == "all" or base.m == 0.0:
        return []
    kernel = base.fields.kernel
    fc = base.fields.fc
    h0 = base.h0_over_Delta

    def solve(ct):
        d = fc.zone_end(s0, h0, _co.dugdale_zone(base.m, s0) / 2, ct)
        if d is None:
            return None
        zones = _co.zones_of(eps + d, ct)
        dn, u = fc.solve(zones, s0)
        return eps + d, zones, dn, u

    def top_residual(ct):
        c, zones, dn, u = solve(ct)
        return fc.gap(math.pi - ct, dn, u, zones, s0)[0] - h0

    out = []
    prev = None
    for ct in TOP_SCAN[TOP_SCAN < math.pi - base.c]:
        sol = solve(ct)
        if sol is None:                                   # the zones meet: the 'all' state
            break
        val = top_residual(ct)
        if prev is not None and prev[1] * val < 0:
            ct_root = _roots.root(top_residual, prev[0], ct)
            c, zones, dn, u = solve(ct_root)
            out.append(_co._state(eps, c, fc, dn, u, zones, base.m, s0, kernel, gb, base.n, ct_root))
        prev = (ct, val)
    return out


def contactless_touch(m, s0, theta, gb, ar=0.0, eps_small=1e-6):
    """The contactless state that touches, h(0) = 0: the end eps -> 0 of the contact branch, where it joins the
    contactless states (found from the zone of the contact state at eps_small, refined on h(0) = 0).  None when
    that zone reaches round (zones 'all': the pin floats, p = 0, :func:`floating_range`)."""
    m, s0, _ = _co._law(m, s0, theta, gb, ar)
    if m == 0.0:
        return None
    c0 = _co.cohesive_state(eps_small, m, s0, theta, gb, ar).c
    if c0 >= math.pi:
        return None

    def h_bottom(c):
        return contactless_state(c, m, s0, theta, gb, ar).fields.gap(0.0)[0]

    # bracket the root next to c0 without crossing the pole of the approach at c = pi/2
    lo_end, hi_end = (0.0, math.pi / 2) if c0 < math.pi / 2 else (math.pi / 2, math.pi)
    for width in 1e-6 * 4.0 ** np.arange(12):
        lo, hi = max(c0 * (1 - width), lo_end + 1e-9), min(c0 * (1 + width), hi_end - 1e-9)
        if h_bottom(lo) * h_bottom(hi) < 0:
            c = _roots.root(h_bottom, lo, hi)
            return contactless_state(c, m, s0, theta, gb, ar)
    return None


JUNCTION = 1e-6     # law_touch's first contact: this times the touch's zone end (the contact branch's trace starts
                    # there: its states differ from the touch by ~(eps/c)^2, delta by 2.9e-8 at eps 1e-6 and
                    # lambda 20, 6.0e-7 at lambda 50 (c 0.0144, 0.0023; M 0.1, vartheta 10, gb 1/2.8))


def law_touch(law):
    """(touch, eps_first): the zone-only pin touching the bottom (:func:`contactless_touch`) where the contact
    branch of the law (jkrcyl.numerics.cohesive_branch.Law) starts from it, and the contact its trace starts at,
    JUNCTION times the touch's zone end (at most law.eps_lo); (None, law.eps_lo) where there is no touch, it lies
    at the approach's pole pi/2 or it is not refined to h(0) = 0."""
    touch = contactless_touch(law.m, law.s0, law.theta, law.gb, law.ar)
    if touch is None or abs(touch.c - math.pi / 2) < 1e-6 or abs(touch.fields.gap(0.0)[0]) > 1e-8 * (1 + law.h0):
        return None, law.eps_lo
    return touch, min(law.eps_lo, JUNCTION * touch.c)


def floating_range(m, s0, theta, gb, ar=0.0):
    """(lo, hi) of delta/Delta of the states without contact whose zone is the whole circle (every gap in
    (0, h0]; h0 >= 2 less the uniform pull); p = 0 for all of them (a uniform traction has no resultant).  None if
    empty.  The gap is (1 - cos phi) - (delta/Delta) cos phi + s0 Z_all, Z_all = 2 pi (k0 - 1 + ar) (constant)."""
    m, s0, kernel = _co._law(m, s0, theta, gb, ar)
    zc = s0 * _co.zone_displacement(0.0, _co.zones_of(math.pi), kernel)[0]
    h0 = m * m / s0
    # (1 - cos phi)(1 + d) - d + zc is monotone in phi: h(0) = zc - d and h(pi) = 2 + d + zc bound it
    lo, hi = max(zc - h0, -2 - zc), min(zc, h0 - 2 - zc)
    return (lo, hi) if lo < hi else None


def floating_state(dn, m, s0, theta, gb, ar=0.0):
    """The pin floating at delta/Delta = dn with its zone the whole circle (no contact, p = 0), in closed form;
    its total potential is constant over :func:`floating_range` (dE = p d(delta) = 0)."""
    m, s0, kernel = _co._law(m, s0, theta, gb, ar)
    return _co._state(0.0, math.pi, None, float(dn), None, _co.zones_of(math.pi), m, s0, kernel, gb, 0)
