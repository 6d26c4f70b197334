"""Classification of every (M, vartheta) pair of the atlas grid (numba, one kernel per pair).

For every pair (default 1000 x 1000, M in [0, 2], vartheta in [0.5, 5], plus a row vartheta = inf,
where M means M_R* of (7.6) and P* means P_R*) :func:`classify` decides

* ``sub_min``      the sub-critical branch (0 < a < a_crit) has a local minimum of P* (a fixed-load
                   adherence point); ``sub_a``, ``sub_P`` its contact parameter and P* (the lowest
                   local minimum, as :func:`jkrcyl.equilibria.adherence`), ``sub_feasible`` whether the
                   gap inequality h(pi) >= 0 holds there, ``sub_nmin`` the number of local minima found;
* ``sup_min``      the super-critical branch (a > a_crit) has a local minimum of P*;
  ``sup_detach``   ... and that (lowest) minimum has P* < 0; ``sup_a``, ``sup_P``, ``sup_feasible`` as
                   above (always False for vartheta = inf: a_crit = inf, no super-critical branch);
* ``zero_load``    (8.1) has a root a0 > 0 (non-trivial zero-load contact); ``n_a0`` the number of
                   roots (2 for M < M_max(vartheta), 1 for vartheta = inf), ``a0_small``, ``a0_large``;
* ``adherence``    the lowest *feasible* fixed-load adherence point among the sub-critical minimum and
                   the super-critical minimum with P* < 0: ``P_adh``, ``a_adh``, ``adh_branch`` (1 sub-,
                   2 super-critical);
* ``confined``     what slow pulling under load control does to the pin in the hole (codes
                   :data:`CONFINED`), from the load path of :func:`jkrcyl.analysis.confined.confined_events`:
                   start at the stable, feasible zero-load contact (the largest; without one, the
                   stable feasible state of largest P*), follow the branch towards lower P* and stop at
                   the first event -- the fold (P* minimum, where the state turns unstable) or h(pi) = 0
                   (the top contact forms).  At a fold the branch decides what follows, because dG/dP* at
                   fixed a is < 0 sub-critically and > 0 super-critically (jkrcyl.equilibria): on the
                   sub-critical branch a further pull raises G, the pin detaches and lands on the top of
                   the hole (``CONF_TRANSFER``); on the super-critical one it lowers G and the contact
                   grows round into full contact (``CONF_ZIP``).  When the gap closes first
                   (``CONF_TOP``) what follows needs the two-patch analysis (~1 s per pair):
                   :func:`classify` does it only with ``two_patch=True`` and then refines those pairs
                   to ``CONF_TOP_TRANSFER`` / ``CONF_TOP_FULL`` / ``CONF_TWO_PATCH``.  ``event_a``,
                   ``event_P``: contact parameter and P* of that first event (0 for ``CONF_NONE``).

No NaN in the outputs: every value field is 0 where its boolean mask is False.

Root finding: sign changes of dP*/da, of h(pi) and of (8.1) on a fixed coarse grid per branch --
logarithmic in a near a = 0 and in |a - a_crit| near the critical contact, logarithmic in a far out on
the super-critical branch -- refined by the layer's Brent solver (jkrcyl.numerics.roots) to adjacent
doubles.  A pair of stationary points closer together than one coarse cell is not resolved (the
reference :mod:`jkrcyl.equilibria` has the same limit at 4000 points).  Kernels: jkrcyl.numerics.kernels
(p, dp/da, h(pi), a_crit) and jkrcyl.numerics.zero_load ((8.1) and M_max).
"""
import math
import sys

import numpy as np
from numba import njit, prange

from .. import equilibria
from ..numerics import kernels, roots, zero_load

# coarse grid, as fractions: sub-critical a = a_crit * s, super-critical a = a_crit * (1 + d)
_N_LOG_SUB = 40          # s = 1e-10 ... 0.5, geometric
_N_NEAR = 24             # 1 - s (and d) = 0.5 ... 1e-13, geometric
_N_FAR = 28              # super-critical: a/a_crit = 2 ... 1e5, geometric
RUBBERY_A_MAX = 3.0      # vartheta = inf: branch 0 < a < 3 as jkrcyl.equilibria (a_crit = inf)

# the load path's outcome (``confined`` field)
CONF_NONE, CONF_TRANSFER, CONF_ZIP, CONF_TOP, CONF_TOP_TRANSFER, CONF_TOP_FULL, CONF_TWO_PATCH, CONF_BONDED = range(8)
CONFINED = {
    CONF_NONE: "no load path (M = 0: no adhesion)",
    CONF_TRANSFER: "pull-off at the sub-critical fold: the pin detaches and lands on the top of the hole",
    CONF_ZIP: "fold on the super-critical branch: a further pull zips the contact round into full contact",
    CONF_TOP: "the gap closes at pi first: top contact forms (two-patch analysis not run)",
    CONF_TOP_TRANSFER: "top contact snaps in, the pin transfers to the top of the hole",
    CONF_TOP_FULL: "top contact snaps in and the contact runs into full contact",
    CONF_TWO_PATCH: "top contact forms and a two-patch state stable under load follows",
    CONF_BONDED: "no stable, feasible zero-load contact: at first touch the pin zips into full contact (bonded)",
}
# jkrcyl.analysis.confined regimes -> code (the refinement of CONF_TOP and the tests' reference)
FROM_TWOPATCH = {"no-path": CONF_NONE, "detachment": CONF_TRANSFER, "zip-full": CONF_ZIP,
                 "snap-in-transfer": CONF_TOP_TRANSFER, "snap-in-full": CONF_TOP_FULL,
                 "two-patch": CONF_TWO_PATCH, "bonded": CONF_BONDED}

FIELDS_BOOL = ("sub_min", "sub_feasible", "sup_min", "sup_detach", "sup_feasible", "zero_load", "adherence")
FIELDS_INT = ("sub_nmin", "sup_nmin", "n_a0", "adh_branch", "confined")
FIELDS_FLOAT = ("sub_a", "sub_P", "sup_a", "sup_P", "a0_small", "a0_large", "a_adh", "P_adh", "event_a",
                "event_P")
_NF = len(FIELDS_FLOAT)
_NI = len(FIELDS_INT) + len(FIELDS_BOOL)


def _fractions():
    s = np.concatenate([np.geomspace(1e-10, 0.5, _N_LOG_SUB, endpoint=False),
                        1 - np.geomspace(0.5, 1e-13, _N_NEAR)])
    d = np.concatenate([np.geomspace(1e-13, 1.0, _N_NEAR, endpoint=False), np.geomspace(2.0, 1e5, _N_FAR) - 1])
    return s, d


# --- the functions whose roots are sought: f(a, args), args = (inv_theta, m) -------------------------
@njit(cache=True)
def _dp(a, args):
    return kernels.dp_da_nb(a, args[0], args[1])


@njit(cache=True)
def _h(a, args):
    return kernels.h_pi_nb(a, args[0], args[1])


_dp_root = roots.brent_solver(_dp)
_h_root = roots.brent_solver(_h)


@njit(cache=True)
def _branch_min(args, nodes):
    """Lowest local minimum of p = vartheta P* over sign changes (- to +) of dp/da on the nodes.

    Returns (count, a, p) -- count 0: none."""
    cnt, best_a, best_p = 0, 0.0, 0.0
    x0 = nodes[0]
    f0 = _dp(x0, args)
    for k in range(1, nodes.shape[0]):
        x1 = nodes[k]
        f1 = _dp(x1, args)
        if f0 < 0.0 and f1 >= 0.0:
            r = x1 if f1 == 0.0 else _dp_root(x0, x1, f0, f1, args)
            p = kernels.p_nb(r, args[0], args[1])
            if cnt == 0 or p < best_p:
                best_a, best_p = r, p
            cnt += 1
        x0, f0 = x1, f1
    return cnt, best_a, best_p


@njit(cache=True)
def _stable(a, sub, args):
    """Stable under load: dP*/da > 0 on the sub-critical branch, < 0 on the super-critical one."""
    d = _dp(a, args)
    return d > 0.0 if sub else d < 0.0


@njit(cache=True)
def _start(args, n0, a0s, a0l, ac):
    """Start of the load path at first contact (jkrcyl.analysis.landing.first_contact): (a, sub?) of the smallest
    stable, feasible zero-load contact; a = 0 when there is none (the pin zips into full contact: bonded)."""
    for k in range(n0):
        a0 = a0s if k == 0 else a0l
        sub = not a0 > ac
        if _stable(a0, sub, args) and _h(a0, args) >= 0.0:
            return a0, sub
    return 0.0, True


@njit(cache=True)
def _first_event(args, a_start, sub, nodes):
    """Walk the branch from a_start towards lower P* (down in a sub-critically, up super-critically) over
    the nodes: (kind, a) of the first event -- kind 1 fold (dP*/da = 0), 2 top contact (h(pi) = 0),
    0 end of the branch (a = its last node)."""
    n = nodes.shape[0]
    step = -1 if sub else 1
    k = n - 1 if sub else 0
    while 0 <= k < n and (nodes[k] >= a_start if sub else nodes[k] <= a_start):
        k += step
    x0, d0, h0 = a_start, _dp(a_start, args), _h(a_start, args)
    while 0 <= k < n:
        x1 = nodes[k]
        d1, h1 = _dp(x1, args), _h(x1, args)
        fold = (d1 <= 0.0) if sub else (d1 >= 0.0)
        top = h1 < 0.0
        if top or fold:
            lo, hi = (x1, x0) if sub else (x0, x1)
            a_top = _h_root(lo, hi, h1 if sub else h0, h0 if sub else h1, args) if top else 0.0
            a_fold = 0.0
            if fold:
                a_fold = x1 if d1 == 0.0 else _dp_root(lo, hi, d1 if sub else d0, d0 if sub else d1, args)
            if top and (not fold or (a_top >= a_fold if sub else a_top <= a_fold)):
                return 2, a_top                         # the gap closes first (ties: the gap)
            return 1, a_fold
        x0, d0, h0 = x1, d1, h1
        k += step
    return 0, x0


@njit(cache=True)
def _confined(args, n0, a0s, a0l, ac, sub_nodes, sup_nodes):
    """(code, a, p) of the load path's first event; see the module docstring."""
    if not args[1] > 0.0:
        return CONF_NONE, 0.0, 0.0
    a_start, sub = _start(args, n0, a0s, a0l, ac)
    if a_start == 0.0:
        return (CONF_NONE if math.isinf(ac) else CONF_BONDED), 0.0, 0.0
    kind, a = _first_event(args, a_start, sub, sub_nodes if sub else sup_nodes)
    p = kernels.p_nb(a, args[0], args[1])
    if kind == 2:
        return CONF_TOP, a, p
    return (CONF_TRANSFER if sub else CONF_ZIP), a, p


@njit(cache=True)
def _classify_one(M, theta, ac, mmax, am, s_frac, d_frac, fo, io, k):
    inf = math.isinf(theta)
    args = (0.0 if inf else 1.0 / theta, M if inf else M * theta)
    scale = 1.0 if inf else theta
    ns = s_frac.shape[0]
    sub_nodes = np.empty(ns)
    for i in range(ns):
        sub_nodes[i] = (RUBBERY_A_MAX if inf else ac) * s_frac[i]
    nsub, sa, sp = _branch_min(args, sub_nodes)
    sub_feas = nsub > 0 and _h(sa, args) >= 0.0
    nd = 0 if inf else d_frac.shape[0]
    sup_nodes = np.empty(nd)
    for i in range(nd):
        sup_nodes[i] = ac * (1.0 + d_frac[i])
    nsup, ua, up = (0, 0.0, 0.0) if inf else _branch_min(args, sup_nodes)
    sup_feas = nsup > 0 and _h(ua, args) >= 0.0
    sup_det = nsup > 0 and up < 0.0
    na0, a0s, a0l = zero_load.zero_load_roots_nb(M, theta, mmax, am)
    adh_b, aa, pa = 0, 0.0, 0.0
    if sub_feas:
        adh_b, aa, pa = 1, sa, sp / scale
    if sup_det and sup_feas and (adh_b == 0 or up / scale < pa):
        adh_b, aa, pa = 2, ua, up / scale
    conf, ea, ep = _confined(args, na0, a0s, a0l, ac, sub_nodes, sup_nodes)
    floats = (sa if nsub > 0 else 0.0, sp / scale if nsub > 0 else 0.0, ua if nsup > 0 else 0.0,
              up / scale if nsup > 0 else 0.0, a0s, a0l, aa, pa, ea, ep / scale)
    for q in range(_NF):
        fo[k, q] = floats[q]
    io[k, 0], io[k, 1], io[k, 2], io[k, 3], io[k, 4] = nsub, nsup, na0, adh_b, conf       # FIELDS_INT
    io[k, 5], io[k, 6], io[k, 7], io[k, 8] = nsub > 0, sub_feas, nsup > 0, sup_det        # FIELDS_BOOL
    io[k, 9], io[k, 10], io[k, 11] = sup_det and sup_feas, na0 > 0, adh_b > 0


@njit(parallel=True, cache=True)
def classify_parallel(Ms, thetas, acs, mmaxs, ams, s_frac, d_frac):
    """Classify every (M, vartheta) pair, rows vartheta (parallel over all pairs, prange).

    Returns (float fields (n_pairs, len(FIELDS_FLOAT)), int fields (n_pairs, len(FIELDS_INT + FIELDS_BOOL)));
    bit-identical to :func:`classify_serial`."""
    nt, nm = thetas.shape[0], Ms.shape[0]
    fo = np.zeros((nt * nm, _NF))
    io = np.zeros((nt * nm, _NI), dtype=np.int8)
    for k in prange(nt * nm):
        i = k // nm
        _classify_one(Ms[k - i * nm], thetas[i], acs[i], mmaxs[i], ams[i], s_frac, d_frac, fo, io, k)
    return fo, io


@njit(cache=True)
def classify_serial(Ms, thetas, acs, mmaxs, ams, s_frac, d_frac):
    """Serial form of :func:`classify_parallel`."""
    nt, nm = thetas.shape[0], Ms.shape[0]
    fo = np.zeros((nt * nm, _NF))
    io = np.zeros((nt * nm, _NI), dtype=np.int8)
    for k in range(nt * nm):
        i = k // nm
        _classify_one(Ms[k - i * nm], thetas[i], acs[i], mmaxs[i], ams[i], s_frac, d_frac, fo, io, k)
    return fo, io


@njit(cache=True)
def _row_constants(thetas):
    n = thetas.shape[0]
    ac, mm, am = np.empty(n), np.empty(n), np.empty(n)
    for i in range(n):
        ac[i] = kernels.a_crit_nb(thetas[i])
        mm[i], am[i] = zero_load.zero_load_max_nb(thetas[i])
    return ac, mm, am


def _check_grid(Ms, thetas):
    Ms = np.ascontiguousarray(np.asarray(Ms, dtype=float))
    thetas = np.ascontiguousarray(np.asarray(thetas, dtype=float))
    if Ms.ndim != 1 or thetas.ndim != 1 or Ms.size == 0 or thetas.size == 0:
        raise ValueError("M and theta must be non-empty 1-D grids")
    if not np.all(np.isfinite(Ms)) or np.any(Ms < 0):
        raise ValueError("M must be finite and >= 0")
    if np.any(np.isnan(thetas)) or np.any(thetas < 0.5):
        raise ValueError("theta must be >= 0.5 (or inf)")
    return Ms, thetas


def classify(Ms, thetas, parallel=True, chunk_rows=None, progress=False, two_patch=False):
    """Atlas on the grid Ms x thetas (thetas may contain inf: M is then M_R*).

    Returns a dict: M (n_M,), theta (n_theta,), a_crit, zero_load_M_max (per theta; inf for inf),
    and every field of FIELDS_BOOL/INT/FLOAT as an (n_theta, n_M) array.  progress: a tqdm bar (stderr)
    over the chunks of rows (the chunks are independent: the unit to distribute, e.g. with Dask).
    two_patch: refine every CONF_TOP pair by :func:`jkrcyl.equilibria.confined_events` (~1 s each).
    """
    from tqdm import tqdm
    Ms, thetas = _check_grid(Ms, thetas)
    ac, mm, am = _row_constants(thetas)
    s_frac, d_frac = _fractions()
    kern = classify_parallel if parallel else classify_serial
    nt, nm = thetas.size, Ms.size
    if chunk_rows is None:
        chunk_rows = max(1, min(nt, 200000 // max(nm, 1)))
    fos, ios = [], []
    with tqdm(total=nt, unit="rows", disable=not progress, file=sys.stderr, leave=True) as bar:
        for r0 in range(0, nt, chunk_rows):
            r1 = min(nt, r0 + chunk_rows)
            fo, io = kern(Ms, thetas[r0:r1], ac[r0:r1], mm[r0:r1], am[r0:r1], s_frac, d_frac)
            fos.append(fo)
            ios.append(io)
            bar.update(r1 - r0)
    fo = np.concatenate(fos).reshape(nt, nm, _NF)
    io = np.concatenate(ios).reshape(nt, nm, _NI)
    out = {"M": Ms, "theta": thetas, "a_crit": ac, "zero_load_M_max": mm}
    for q, name in enumerate(FIELDS_FLOAT):
        out[name] = np.ascontiguousarray(fo[:, :, q])
    for q, name in enumerate(FIELDS_INT):
        out[name] = np.ascontiguousarray(io[:, :, q])
    for q, name in enumerate(FIELDS_BOOL):
        out[name] = np.ascontiguousarray(io[:, :, len(FIELDS_INT) + q].astype(bool))
    if two_patch:
        _refine_top(out, progress)
    return out


def _refine_top(out, progress):
    """CONF_TOP pairs -> the two-patch analysis' answer (jkrcyl.analysis.confined; gb of an incompressible pin:
    the class depends on the fixed-load path only)."""
    from tqdm import tqdm
    rows, cols = np.nonzero(out["confined"] == CONF_TOP)
    for i, j in tqdm(list(zip(rows, cols)), unit="pairs", disable=not progress, file=sys.stderr):
        th, M = out["theta"][i], out["M"][j]
        if math.isfinite(th) and M > 0:
            ev = equilibria.confined_events(M, th, gb=equilibria.incompressible_gb(th))
            out["confined"][i, j] = FROM_TWOPATCH[ev.regime]


def default_grid(n_M=1000, n_theta=1000, M_max=2.0, theta_min=0.5, theta_max=5.0, with_inf=True):
    """M = linspace(0, M_max, n_M); vartheta = linspace(theta_min, theta_max, n_theta) (+ inf)."""
    Ms = np.linspace(0.0, M_max, n_M)
    th = np.linspace(theta_min, theta_max, n_theta)
    if with_inf:
        th = np.append(th, np.inf)
    return Ms, th
