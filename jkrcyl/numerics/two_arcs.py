"""Two contact arcs (bottom |phi| < eps, top |phi - pi| < eps_top) at fixed half-angles: the unit cases of
numerics.arcs.Linear with the engine's node policy, for jkrcyl.model.two_patch.

Near-touching arcs: the density varies on the scale of the gap g = pi - eps - eps_top between them, so Chebyshev
needs ~ sqrt(eps/g) times more nodes (Bernstein ellipse through the gap).  At alpha* = 0, 20 sqrt(eps/g) puts the
STATE within ~1e-11 of 200 nodes (M 0.2, vartheta 1: eps_top 0.3633, g 0.166: 79 nodes, measured 2e-12 in eps and
8e-12 in P*; 18 sqrt(eps/g), 71 nodes, left 3e-11 and 1.04e-10, the node-policy test's bound on one machine's
rounding -- spectral: 60, 80 nodes 2e-9, 4e-13 in eps); the earlier 8 sqrt(eps/g) left 7e-5 in eps at g 0.166.
alpha* != 0: the algebraic end terms need about twice as many, at least 32, in multiples of 8 (one enrichment
table per node count), from 8 sqrt(eps/g).
"""
import functools
import math

from . import arcs as _arcs

N_NODES = 24            # nodes per arc at alpha* = 0 (spectral: 1e-12 at moderate arcs)
NODES_PER_GAP = 20      # alpha* = 0: GAP_BASE + NODES_PER_GAP sqrt(eps/g) nodes per arc (module docstring), at most NODES_MAX
GAP_BASE = 0
NODES_MAX = 400
AR_PER_GAP = 8          # alpha* != 0: AR_NODES_FACTOR * 8 sqrt(eps/g)
N_NODES_ALPHA = 32      # alpha* != 0: at least this many (1e-12 at moderate arcs against 128 nodes)
AR_NODES_FACTOR = 2     # alpha* != 0 near-touching arcs: 16 sqrt(eps/g) nodes (7e-10 at g = 0.24, eps = 2)


def nodes(eps, eps_top, n, ar):
    """Nodes per arc for the pair of half-angles (module docstring)."""
    g = math.pi - eps - eps_top
    need = NODES_PER_GAP * math.sqrt(max(eps, eps_top) / g) if g > 0 else 0.0
    if ar == 0.0:
        return max(n, int(min(GAP_BASE + need, NODES_MAX)))
    need = AR_PER_GAP * math.sqrt(max(eps, eps_top) / g) if g > 0 else 0.0
    return min(8 * math.ceil(max(n, N_NODES_ALPHA, AR_NODES_FACTOR * need) / 8), 256)


def linear(eps, eps_top, theta, gb, ar, n=N_NODES, exact=False):
    """numerics.arcs.Linear at the half-angles: q0, q1 = [P*, B*, k_bot, k_top] of the (Delta, unit delta) cases;
    at least n nodes per arc (:func:`nodes`), or exactly n (a root search's one discretisation: the sign of det A
    relative to :func:`reference_sign` holds at a fixed count only)."""
    return _arcs.two_patch_linear(eps, eps_top, theta, gb, n if exact else nodes(eps, eps_top, n, ar), ar)


@functools.lru_cache(maxsize=None)
def reference_sign(n, theta, gb, ar):
    """sign(det A) for two arcs of 1e-3 rad at n nodes (far from every singular configuration: the log term
    dominates); with alpha* != 0 the enrichment columns flip the sign of det with n mod 3."""
    return _arcs.two_patch_linear(1e-3, 1e-3, theta, gb, n, ar).sign_det
