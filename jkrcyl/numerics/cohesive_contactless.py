"""The Maugis-Dugdale pin without contact, held by its bottom zone, as a branch of the model core
(jkrcyl.model.cohesive's 'contactless' family): its end and its per-point data in the form of the contact branch's
(jkrcyl.numerics.cohesive_branch.Point), from the closed form of jkrcyl.numerics.cohesive_zones."""
import math

from . import cohesive_zones as _cz
from .cohesive_branch import Point


def contactless_end(law):
    """(c, touches): where the contactless states (one bottom zone) end -- the touch c (h(0) = 0, joined to the
    contact branch), or just below pi/2 (the approach's pole) when the contact branch starts with zones 'all'."""
    touch = _cz.contactless_touch(law.m, law.s0, law.theta, law.gb, law.ar)
    if touch is None or abs(touch.c - math.pi / 2) < 1e-6 or abs(touch.fields.gap(0.0)[0]) > 1e-8 * (1 + law.h0):
        return math.pi / 2 * (1 - 1e-6), False         # no touch (or a sign change through the pole pi/2)
    return touch.c, True


def contactless_point(law, c):
    """Per-point data of the contactless state with the zone |phi| < c, slopes d/dc (central differences of the
    closed form).  Rows (X, g) in (delta, c): along T = (-g_c, g_delta), dX/dT = -det, stable where
    dg/dc|_X = det/X_delta > 0, so D_X = sigma X_delta: D_p = 0 (the pin, a rigid body held by its zone, is a
    saddle under load), D_dn = sigma = sign(dc/dT) = sign(g_delta) = -sign(cos c)."""
    st = _cz.contactless_state(c, law.m, law.s0, law.theta, law.gb, law.ar)
    hc = 1e-5 * min(c, abs(math.pi / 2 - c))
    plus, minus = (_cz.contactless_state(c + s * hc, law.m, law.s0, law.theta, law.gb, law.ar) for s in (1, -1))
    dp, ddn = (plus.p - minus.p) / (2 * hc), (plus.delta_over_Delta - minus.delta_over_Delta) / (2 * hc)
    sigma = -1.0 if math.cos(c) > 0 else 1.0
    return Point(0.0, c, st.delta_over_Delta, st.p, st.B, dp, ddn, 0.0, sigma, st.h_pi_over_Delta, st.zones,
                 st.fields, st)
