"""The half-plane limit of the Maugis-Dugdale pin (cylinder on a flat, Baney and Hui 1997) from the derived closed
form generated/cohesive.half_plane_state: its load-control pull-off, the asymptote of the pull-off for small M
(Delta/R -> 0), the figure's Baney-Hui line (jkrcyl.plotting.cohesive).

In the normalised variables at m = 1 (p/m^(4/3) = Baney-Hui's Pbar, eps/(2 m^(2/3)) = their abar): s0 = lambda/4,
the state with the contact eps has its zone end c where the opening is h0 = 1/s0 (a root in c > eps: the opening
grows with c), and p = eps^2/4 - 2 s0 sqrt(c^2 - eps^2).  The pull-off is the minimum of p over eps > 0, or its
eps -> 0 limit (the zone alone) when p falls all the way there (small lambda).
"""
import math


from ..generated import cohesive as _gc
from .._validate import finite_scalar
from . import roots as _roots

EPS_SMALL = 1e-7            # the 'zone alone' end of the scan (abar = 5e-8)


def half_plane_load(eps, lam):
    """Pbar at the contact eps = 2 abar of the law lambda (m = 1)."""
    s0 = lam / 4

    def closure(ratio):
        return _gc.half_plane_state(c=ratio * eps, eps=eps, s0=s0).opening * s0 - 1

    hi = 2.0
    while closure(hi) < 0:
        hi *= 2
    ratio = _roots.root(closure, 1 + 1e-15, hi)
    return _gc.half_plane_state(c=ratio * eps, eps=eps, s0=s0).p


def half_plane_pull_off(lam):
    """Baney-Hui's load-control pull-off Pbar_c(lambda) < 0 (lambda > 0): -1.19055 (JKR) for lambda -> inf,
    -sqrt(2 lambda) for lambda -> 0."""
    lam = finite_scalar("lambda", lam, low=0.0, low_open=True)
    f = lambda x: half_plane_load(math.exp(x), lam)
    xs = [math.log(EPS_SMALL) + k * (math.log(20.0) - math.log(EPS_SMALL)) / 60 for k in range(61)]
    vals = [f(x) for x in xs]
    i = min(range(len(vals)), key=vals.__getitem__)
    if i == 0:
        return vals[0]
    return min(_roots.minimum(f, xs[i - 1], xs[i], xs[min(i + 1, 60)], 1e-12)[1], vals[0])
