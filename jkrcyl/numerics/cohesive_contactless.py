"""The Maugis-Dugdale pin without contact, as branches of the model core, from the closed form of
jkrcyl.numerics.cohesive_zones (notation of jkrcyl.numerics.cohesive: kernel scale, lengths over Delta).

* Held by its bottom zone (jkrcyl.model.cohesive's 'contactless' family): its end and its per-point data in the
  form of the contact branch's (jkrcyl.numerics.cohesive_branch.Point).
* Held by zones at the bottom and the top: the continuation of a top bridge (jkrcyl.numerics.cohesive_top_zone)
  whose contact vanishes (its end 'touch').  From the two-zone state touching the bottom (h(0) = 0) the bottom
  zone shrinks and the top one grows until the top touches (h(pi) = 0): the family is its own mirror (phi -> phi +
  pi: c and c_top swapped, p -> -p, delta/Delta -> -2 - delta/Delta), through the symmetric state c = c_top
  (p = 0, delta = -Delta), and past the top touch the mirror of the bridge (contact at the top) goes on.  The
  approach is closed form in (c, c_top) (h(c) = h0), c_top a scalar root of h(pi - c_top) = h0 at each c.
  Measured (M 0.1, vartheta 10, gb 1/2.8, lambda 20): c 0.01442 -> 0.00314, c_top 0.00312 -> 0.01444, 33 states.
"""
import math

import numpy as np

from . import cohesive as _co
from . import cohesive_zones as _cz
from . import roots as _roots
from .cohesive_branch import Point


def contactless_end(law):
    """(c, touches): where the contactless states (one bottom zone) end -- the touch c (h(0) = 0, joined to the
    contact branch), or just below pi/2 (the approach's pole) when the contact branch starts with zones 'all'."""
    touch = law.touch[0]
    if touch is None:
        return math.pi / 2 * (1 - 1e-6), False         # no touch (or a sign change through the pole pi/2)
    return touch.c, True


def contactless_point(law, c):
    """Per-point data of the contactless state with the zone |phi| < c, slopes d/dc (central differences of the
    closed form).  Rows (X, g) in (delta, c): along T = (-g_c, g_delta), dX/dT = -det, stable where
    dg/dc|_X = det/X_delta > 0, so D_X = sigma X_delta: D_p = 0 (the pin, a rigid body held by its zone, is a
    saddle under load), D_dn = sigma = sign(dc/dT) = sign(g_delta) = -sign(cos c)."""
    st = _cz.contactless_state(c, law.m, law.s0, law.theta, law.gb, law.ar)
    hc = 1e-5 * min(c, abs(math.pi / 2 - c), math.pi - c)
    plus, minus = (_cz.contactless_state(c + s * hc, law.m, law.s0, law.theta, law.gb, law.ar) for s in (1, -1))
    dp, ddn = (plus.p - minus.p) / (2 * hc), (plus.delta_over_Delta - minus.delta_over_Delta) / (2 * hc)
    sigma = -1.0 if math.cos(c) > 0 else 1.0
    return Point(0.0, c, st.delta_over_Delta, st.p, st.B, dp, ddn, 0.0, sigma, st.h_pi_over_Delta, st.zones,
                 st.fields, st)


# --- the pin held by zones at the bottom and the top: the top bridge's continuation past the touch -------------
TWO_ZONE_RATIO = 0.95       # the bottom zone c shrinks by this factor per point
TWO_ZONE_MAX_POINTS = 400
TWO_ZONE_STEP = 1e-4        # two_zone_slopes, two_zone_grip_matrix: central differences relative to each zone


def two_zone_state(law, c, c_top):
    """The state without contact with the zones |phi| < c and |phi - pi| < c_top (the approach from h(c) = h0 in
    closed form: jkrcyl.numerics.cohesive_zones.contactless_state)."""
    return _cz.contactless_state(c, law.m, law.s0, law.theta, law.gb, law.ar, c_top)


def _top_residual(law, c, c_top):
    """h(pi - c_top) - h0 of the two-zone state (c, c_top): zero on the family."""
    return two_zone_state(law, c, c_top).fields.gap(math.pi - c_top)[0] - law.h0


def _c_top_near(law, c, guess):
    """The top zone end c_top solving h(pi - c_top) = h0 at the bottom zone c, the root nearest to guess (a
    bracket grown geometrically on both sides, Brent to adjacent doubles); None within a factor e^2."""
    f0, step = _top_residual(law, c, guess), 1e-3
    while step < 2.0:
        for x in (guess * math.exp(-step), min(guess * math.exp(step), (math.pi - c) * (1 - 1e-9))):
            fx = _top_residual(law, c, x)
            if fx * f0 <= 0:
                a, b = sorted((guess, x))
                fa, fb = (f0, fx) if a == guess else (fx, f0)
                return _roots.brent(lambda y, _: _top_residual(law, c, y), a, b, (), fa, fb)
        step *= 2
    return None


TOUCH_OFFSETS = np.concatenate([-np.geomspace(0.5, 1e-8, 17), [0.0], np.geomspace(1e-8, 0.5, 17)])


def two_zone_touch(law, last):
    """The two-zone state that touches the bottom (h(0) = 0) next to ``last``, the top bridge's last state before
    its contact vanishes (jkrcyl.numerics.cohesive_top_zone, end 'touch'): h(0) at c = last.c exp(TOUCH_OFFSETS)
    (c_top the root next to last's; none where the top zone has vanished on one side), Brent on the sign change
    nearest last.c; None where there is none."""
    def h_bottom(c, _=None):
        ct = _c_top_near(law, c, last.c_top)
        return math.nan if ct is None else two_zone_state(law, c, ct).fields.gap(0.0)[0]
    cs = last.c * np.exp(TOUCH_OFFSETS)
    h = np.array([h_bottom(c) for c in cs])
    pairs = [k for k in range(len(cs) - 1) if np.isfinite(h[k]) and np.isfinite(h[k + 1]) and h[k] * h[k + 1] <= 0]
    if not pairs:
        return None
    k = min(pairs, key=lambda i: abs(TOUCH_OFFSETS[i] + TOUCH_OFFSETS[i + 1]))
    c = cs[k] if h[k] == 0 else _roots.brent(h_bottom, cs[k], cs[k + 1], (), h[k], h[k + 1])
    return two_zone_state(law, c, _c_top_near(law, c, last.c_top))


def two_zone_trace(law, touch, ratio=TWO_ZONE_RATIO):
    """The pin held by zones at the bottom and the top, from the two-zone state ``touch`` (h(0) = 0) into h(0) > 0:
    the bottom zone c shrinks by ``ratio`` per point, c_top the root next to the last (predicted linearly in log c),
    up to where the top touches (h(pi) = 0, refined by Brent in c: the mirror of ``touch``, c and c_top swapped).
    Returns (states, end): end 'top touches', 'no root' (no c_top next to the last: a fold in c), 'bottom zone
    vanishes' (c below 1e-9 of the touch's) or 'points' (TWO_ZONE_MAX_POINTS)."""
    states, prev, c = [touch], None, touch.c
    while len(states) < TWO_ZONE_MAX_POINTS:
        last = states[-1]
        c = last.c * ratio
        if c < 1e-9 * touch.c:
            return states, "bottom zone vanishes"
        guess = last.c_top if prev is None else \
            last.c_top * (last.c_top / prev.c_top) ** (math.log(c / last.c) / math.log(last.c / prev.c))
        ct = _c_top_near(law, c, guess) or _c_top_near(law, c, last.c_top)
        if ct is None or c + ct >= math.pi:
            return states, "no root"
        st = two_zone_state(law, c, ct)
        if st.h_pi_over_Delta <= 0:
            return states + [_top_touch(law, last, st)], "top touches"
        prev = last
        states.append(st)
    return states, "points"


def _top_touch(law, before, after):
    """The two-zone state between before (h(pi) > 0) and after (h(pi) <= 0) where h(pi) = 0: Brent in c."""
    def h_top(c, _=None):
        ct = _c_top_near(law, c, before.c_top)
        return math.nan if ct is None else two_zone_state(law, c, ct).h_pi_over_Delta
    c = _roots.brent(h_top, after.c, before.c, (), after.h_pi_over_Delta, before.h_pi_over_Delta)
    return two_zone_state(law, c, _c_top_near(law, c, before.c_top))


def two_zone_slopes(law, st):
    """d(p, delta/Delta, c_top)/dc along the two-zone family at st (central differences in c, c_top re-solved)."""
    h = TWO_ZONE_STEP * st.c
    got = [two_zone_state(law, st.c + s * h, _c_top_near(law, st.c + s * h, st.c_top)) for s in (1, -1)]
    return tuple((getattr(got[0], k) - getattr(got[1], k)) / (2 * h) for k in ("p", "delta_over_Delta", "c_top"))


def _held_gaps(law, dn, c, c_top):
    """h(c) - h0 and h(pi - c_top) - h0 at the approach dn with the zone ends held (no contact: the gap is
    2 sin^2(phi/2) - dn cos(phi) + s0 Z(phi), jkrcyl.numerics.cohesive_zones)."""
    phi = np.array([c, math.pi - c_top])
    z = _co.zone_displacement(phi, _co.zones_of(c, c_top), law.kernel)
    return 2 * np.sin(phi / 2) ** 2 - dn * np.cos(phi) + law.s0 * z - law.h0


def two_zone_matrix(law, st, work_shift=0.0):
    """G_ij = d(h(c_i) - h0)/dc_j of the two-zone state st with the zone ends held at a held approach: delta
    (work_shift 0, grip) or delta_work = delta + work_shift p (grip-work; p = -2 s0 (sin c - sin c_top) moves with
    the zones).  The held energy's Hessian is 2 s0 G (as jkrcyl.numerics.cohesive_top_zone.zone_matrix).  Under
    load the pin has no contact to hold it: the energy's Hessian in (delta, c, c_top) has a zero delta-delta entry
    beside non-zero ones, a saddle."""
    held = st.delta_over_Delta + work_shift * st.p
    G = np.empty((2, 2))
    for j, h in enumerate(TWO_ZONE_STEP * np.array([st.c, st.c_top])):
        g = []
        for sgn in (1, -1):
            c, ct = st.c + sgn * h * (j == 0), st.c_top + sgn * h * (j == 1)
            p = -2 * law.s0 * (math.sin(c) - math.sin(ct))
            g.append(_held_gaps(law, held - work_shift * p, c, ct))
        G[:, j] = (g[0] - g[1]) / (2 * h)
    return G
