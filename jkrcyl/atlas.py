"""Regime atlas over the (M, vartheta) plane: fixed-load detachment, overclosure, zero-load contact.

For every pair of a grid (default 1000 x 1000, M in [0, 2], vartheta in [0.5, 5], plus a row
vartheta = inf, where M means M_R* of (7.6) and P* means P_R*) the kernel :func:`classify` decides

* ``sub_min``      the sub-critical branch (0 < a < a_crit) has a local minimum of P* (fixed-load
                   detachment); ``sub_a``, ``sub_P`` its contact parameter and P* (the lowest
                   local minimum, as :func:`jkrcyl.equilibria.adherence`), ``sub_feasible``
                   whether the gap inequality h(pi) >= 0 holds there, ``sub_nmin`` the number of
                   local minima found;
* ``sup_min``      the super-critical branch (a > a_crit) has a local minimum of P*;
  ``sup_detach``   ... and that (lowest) minimum has P* < 0 (super-critical detachment);
                   ``sup_a``, ``sup_P``, ``sup_feasible`` as above (always False for vartheta = inf:
                   a_crit = inf, no super-critical branch);
* ``overclosure``  walking the sub-critical branch from a = 0+ (P* = 0, h(pi) = 2 Delta) towards
                   a_crit, the gap inequality fails (h(pi) < 0, first at phi = pi) before the
                   sub-critical detachment point -- or anywhere on the branch when that branch has
                   no P* minimum; ``a_overclosure`` is the first root of h(pi);
* ``zero_load``    (8.1) has a root a0 > 0 (non-trivial zero-load contact); ``n_a0`` the number of
                   roots (2 for M < M_max(vartheta), 1 for vartheta = inf: a0 = (2 M_R*)^(2/3)),
                   ``a0_small``, ``a0_large`` the roots (equal when there is one);
* ``adherence``    the fixed-load adherence force exists: P* at the lowest *feasible* detachment
                   point among the sub-critical minimum and the super-critical minimum with P* < 0;
                   ``P_adh`` that P* (negative: a pull), ``a_adh`` its contact parameter and
                   ``adh_branch`` 1 = sub-critical, 2 = super-critical.

No NaN in the outputs: every value field is 0 where its boolean mask (``sub_min``, ``sup_min``,
``overclosure``, ``zero_load``, ``adherence``) is False.

Root finding: sign changes of dP*/da (the emitted ``equilibrium_star`` kernel), of h(pi) (``gap_pi``)
and of (8.1) on a fixed coarse grid per branch -- logarithmic in a near a = 0 and in |a - a_crit|
near the critical contact, logarithmic in a far out on the super-critical branch -- each refined by
Brent's method (inverse quadratic / secant steps safeguarded by bisection) and then bisection to
adjacent doubles.  A pair of stationary points closer together than one coarse cell is not
resolved (the reference :mod:`jkrcyl.equilibria` has the same limit at 4000 points).
"""
import math
import sys
import time

import numpy as np
from numba import njit, prange

from .critical import a_crit_kernel
from .generated.derivatives import load_slopes as _load_slopes
from .generated.gap import gap_pi as _gap_pi
from .generated.load import load_state as _load_state

EPS = 2.220446049250313e-16
# coarse grid, as fractions: sub-critical a = a_crit * s, super-critical a = a_crit * (1 + d)
_N_LOG_SUB = 40          # s = 1e-10 ... 0.5, geometric
_N_NEAR = 24             # 1 - s (and d) = 0.5 ... 1e-13, geometric
_N_FAR = 28              # super-critical: a/a_crit = 2 ... 1e5, geometric
RUBBERY_A_MAX = 3.0      # vartheta = inf: branch 0 < a < 3 as jkrcyl.equilibria (a_crit = inf)

FIELDS_BOOL = ("sub_min", "sub_feasible", "sup_min", "sup_detach", "sup_feasible", "overclosure",
               "zero_load", "adherence")
FIELDS_INT = ("sub_nmin", "sup_nmin", "n_a0", "adh_branch", "regime")
FIELDS_FLOAT = ("sub_a", "sub_P", "sup_a", "sup_P", "a_overclosure", "a0_small", "a0_large", "a_adh", "P_adh")
_NF = len(FIELDS_FLOAT)
_NI = len(FIELDS_INT) + len(FIELDS_BOOL)

# regime code bits (``regime`` field and the figure's colours)
BIT_SUB, BIT_SUB_FEAS, BIT_SUP, BIT_SUP_FEAS, BIT_OC, BIT_ZL = 1, 2, 4, 8, 16, 32


def _fractions():
    s = np.concatenate([np.geomspace(1e-10, 0.5, _N_LOG_SUB, endpoint=False),
                        1 - np.geomspace(0.5, 1e-13, _N_NEAR)])
    d = np.concatenate([np.geomspace(1e-13, 1.0, _N_NEAR, endpoint=False), np.geomspace(2.0, 1e5, _N_FAR) - 1])
    return s, d


# ------------------------------------------------------------------------------------------------
# scalar functions whose roots are sought (kind selects; p1..p3 are parameters)
K_DP, K_H, K_ZL, K_ZLMAX = 0, 1, 2, 3


@njit(cache=True)
def _f(kind, x, p1, p2, p3):
    if kind == K_DP:      # 4 pi dp/da (p = vartheta P*; Delta = beta* = 1): p1 = inv_theta, p2 = m
        return _load_slopes(1.0, x, 1.0, 0.0, p1, 4.0 * math.pi * p2)[0]
    if kind == K_H:       # h(pi)/Delta: p1 = inv_theta, p2 = m
        return _gap_pi(1.0, x, 1.0, p1, 4.0 * math.pi * p2)
    if kind == K_ZL:      # (8.1) times M: p1 = M, p2 = vartheta
        return x**1.5 - p1 * (x * x + 2.0 * p2 - math.log1p(x * x))
    # d/da log of a^1.5/(a^2 + 2 vartheta - log1p(a^2)), times the denominator: p2 = vartheta
    return 1.5 * (x * x + 2.0 * p2 - math.log1p(x * x)) - x * (2.0 * x - 2.0 * x / (1.0 + x * x))


@njit(cache=True)
def _root(kind, lo, hi, flo, fhi, p1, p2, p3):
    """Root in [lo, hi] with flo, fhi of opposite signs: Brent, then bisection to adjacent doubles."""
    a, b, fa, fb = lo, hi, flo, fhi
    c, fc = a, fa
    d = b - a
    e = d
    for _ in range(200):
        if (fb > 0.0) == (fc > 0.0):
            c, fc = a, fa
            d = b - a
            e = d
        if abs(fc) < abs(fb):
            a, fa = b, fb
            b, fb = c, fc
            c, fc = a, fa
        tol = 2.0 * EPS * abs(b) + 1e-300
        xm = 0.5 * (c - b)
        if abs(xm) <= tol or fb == 0.0:
            break
        if abs(e) >= tol and abs(fa) > abs(fb):
            s = fb / fa
            if a == c:
                p = 2.0 * xm * s
                q = 1.0 - s
            else:
                q = fa / fc
                r = fb / fc
                p = s * (2.0 * xm * q * (q - r) - (b - a) * (r - 1.0))
                q = (q - 1.0) * (r - 1.0) * (s - 1.0)
            if p > 0.0:
                q = -q
            p = abs(p)
            if 2.0 * p < min(3.0 * xm * q - abs(tol * q), abs(e * q)):
                e = d
                d = p / q
            else:
                d = xm
                e = d
        else:
            d = xm
            e = d
        a, fa = b, fb
        if abs(d) > tol:
            b = b + d
        else:
            b = b + (tol if xm > 0.0 else -tol)
        fb = _f(kind, b, p1, p2, p3)
    if fb == 0.0:
        return b
    # final bisection of the bracket [b, c] to adjacent doubles
    if (fb > 0.0) == (fc > 0.0):
        return b
    lo, hi, flo, fhi = (b, c, fb, fc) if b < c else (c, b, fc, fb)
    for _ in range(64):
        mid = 0.5 * (lo + hi)
        if mid <= lo or mid >= hi:
            break
        fm = _f(kind, mid, p1, p2, p3)
        if fm == 0.0:
            return mid
        if (fm > 0.0) == (flo > 0.0):
            lo, flo = mid, fm
        else:
            hi, fhi = mid, fm
    return lo if abs(flo) <= abs(fhi) else hi


@njit(cache=True)
def zero_load_max_nb(theta):
    """(M_max, a at the maximum) of (8.1), as jkrcyl.equilibria.zero_load_max_M; (inf, inf) for inf."""
    if math.isinf(theta):
        return math.inf, math.inf
    lo, hi = 1e-6, 1.0
    while _f(K_ZLMAX, hi, 0.0, theta, 0.0) > 0.0:
        hi *= 2.0
    am = _root(K_ZLMAX, lo, hi, _f(K_ZLMAX, lo, 0.0, theta, 0.0), _f(K_ZLMAX, hi, 0.0, theta, 0.0), 0.0, theta, 0.0)
    return am**1.5 / (am * am + 2.0 * theta - math.log1p(am * am)), am


@njit(cache=True)
def _p(x, inv_t, m):
    """p = P beta*/(4 pi Delta) = vartheta P* (P_R* for vartheta = inf) from the load kernel (4.4)."""
    return _load_state(1.0, 1.0, x, 1.0, inv_t, 4.0 * math.pi * m)[0] / (4.0 * math.pi)


@njit(cache=True)
def _branch_min(inv_t, m, nodes):
    """Lowest local minimum of p = vartheta P* over sign changes (- to +) of dp/da on the nodes.

    Returns (count, a, p) -- count 0: none."""
    n = nodes.shape[0]
    cnt = 0
    best_a = 0.0
    best_p = 0.0
    x0 = nodes[0]
    f0 = _f(K_DP, x0, inv_t, m, 0.0)
    for k in range(1, n):
        x1 = nodes[k]
        f1 = _f(K_DP, x1, inv_t, m, 0.0)
        if f0 < 0.0 and f1 > 0.0:
            r = _root(K_DP, x0, x1, f0, f1, inv_t, m, 0.0)
            p = _p(r, inv_t, m)
            if cnt == 0 or p < best_p:
                best_a, best_p = r, p
            cnt += 1
        elif f0 < 0.0 and f1 == 0.0:
            p = _p(x1, inv_t, m)
            if cnt == 0 or p < best_p:
                best_a, best_p = x1, p
            cnt += 1
        x0, f0 = x1, f1
    return cnt, best_a, best_p


@njit(cache=True)
def _first_overclosure(inv_t, m, nodes, a_stop):
    """First a on the nodes (<= a_stop, a_stop included) where h(pi) turns negative; 0 if none."""
    x0 = nodes[0]
    h0 = _f(K_H, x0, inv_t, m, 0.0)
    if h0 < 0.0:
        return x0
    n = nodes.shape[0]
    for k in range(1, n + 1):
        x1 = nodes[k] if k < n else a_stop
        if x1 > a_stop:
            x1 = a_stop
        if x1 <= x0:
            break
        h1 = _f(K_H, x1, inv_t, m, 0.0)
        if h1 < 0.0:
            return _root(K_H, x0, x1, h0, h1, inv_t, m, 0.0)
        if x1 >= a_stop:
            break
        x0, h0 = x1, h1
    return 0.0


@njit(cache=True)
def _classify_one(M, theta, ac, mmax, am, s_frac, d_frac, fo, io, k):
    inf = math.isinf(theta)
    inv_t = 0.0 if inf else 1.0 / theta
    m = M if inf else M * theta
    scale = 1.0 if inf else theta
    ns = s_frac.shape[0]
    # --- sub-critical branch
    sub_nodes = np.empty(ns)
    if inf:
        for i in range(ns):
            sub_nodes[i] = RUBBERY_A_MAX * s_frac[i]
    else:
        for i in range(ns):
            sub_nodes[i] = ac * s_frac[i]
    nsub, sa, sp = _branch_min(inv_t, m, sub_nodes)
    sub_feas = False
    if nsub > 0:
        sub_feas = _f(K_H, sa, inv_t, m, 0.0) >= 0.0
    # --- overclosure before sub-critical detachment (or anywhere on a branch without one)
    a_stop = sa if nsub > 0 else sub_nodes[ns - 1]
    aoc = _first_overclosure(inv_t, m, sub_nodes, a_stop)
    # --- super-critical branch
    nsup, ua, up = 0, 0.0, 0.0
    sup_feas = False
    if not inf:
        nd = d_frac.shape[0]
        sup_nodes = np.empty(nd)
        for i in range(nd):
            sup_nodes[i] = ac * (1.0 + d_frac[i])
        nsup, ua, up = _branch_min(inv_t, m, sup_nodes)
        if nsup > 0:
            sup_feas = _f(K_H, ua, inv_t, m, 0.0) >= 0.0
    sup_det = nsup > 0 and up < 0.0
    # --- zero-load contact (8.1)
    na0, a0s, a0l = 0, 0.0, 0.0
    if M > 0.0:
        if inf:
            na0 = 1
            a0s = (2.0 * M) ** (2.0 / 3.0)
            a0l = a0s
        elif M < mmax:
            g_lo = _f(K_ZL, 0.0, M, theta, 0.0)
            g_m = _f(K_ZL, am, M, theta, 0.0)
            hi = max(10.0, 4.0 / (M * M))
            g_hi = _f(K_ZL, hi, M, theta, 0.0)
            if g_lo < 0.0 and g_m > 0.0 and g_hi < 0.0:
                na0 = 2
                a0s = _root(K_ZL, 0.0, am, g_lo, g_m, M, theta, 0.0)
                a0l = _root(K_ZL, am, hi, g_m, g_hi, M, theta, 0.0)
    # --- adherence: lowest feasible detachment point
    adh_b, aa, pa = 0, 0.0, 0.0
    if nsub > 0 and sub_feas:
        adh_b, aa, pa = 1, sa, sp / scale
    if sup_det and sup_feas and (adh_b == 0 or up / scale < pa):
        adh_b, aa, pa = 2, ua, up / scale
    oc = aoc > 0.0
    code = 0
    if nsub > 0:
        code |= 1
    if sub_feas:
        code |= 2
    if sup_det:
        code |= 4
    if sup_det and sup_feas:
        code |= 8
    if oc:
        code |= 16
    if na0 > 0:
        code |= 32
    fo[k, 0] = sa if nsub > 0 else 0.0
    fo[k, 1] = sp / scale if nsub > 0 else 0.0
    fo[k, 2] = ua if nsup > 0 else 0.0
    fo[k, 3] = up / scale if nsup > 0 else 0.0
    fo[k, 4] = aoc
    fo[k, 5] = a0s
    fo[k, 6] = a0l
    fo[k, 7] = aa
    fo[k, 8] = pa
    io[k, 0] = nsub
    io[k, 1] = nsup
    io[k, 2] = na0
    io[k, 3] = adh_b
    io[k, 4] = code
    io[k, 5] = nsub > 0
    io[k, 6] = sub_feas
    io[k, 7] = nsup > 0
    io[k, 8] = sup_det
    io[k, 9] = sup_det and sup_feas
    io[k, 10] = oc
    io[k, 11] = na0 > 0
    io[k, 12] = adh_b > 0


@njit(parallel=True, cache=True)
def classify_parallel(Ms, thetas, acs, mmaxs, ams, s_frac, d_frac):
    """Classify every (M, vartheta) pair, rows vartheta (parallel over all pairs, prange).

    Returns (float fields (n_pairs, 9), int fields (n_pairs, 13)) in the order of FIELDS_FLOAT and
    FIELDS_INT + FIELDS_BOOL; bit-identical to :func:`classify_serial`."""
    nt, nm = thetas.shape[0], Ms.shape[0]
    fo = np.zeros((nt * nm, _NF))
    io = np.zeros((nt * nm, _NI), dtype=np.int8)
    for k in prange(nt * nm):
        i = k // nm
        j = k - i * nm
        _classify_one(Ms[j], thetas[i], acs[i], mmaxs[i], ams[i], s_frac, d_frac, fo, io, k)
    return fo, io


@njit(cache=True)
def classify_serial(Ms, thetas, acs, mmaxs, ams, s_frac, d_frac):
    """Serial form of :func:`classify_parallel`."""
    nt, nm = thetas.shape[0], Ms.shape[0]
    fo = np.zeros((nt * nm, _NF))
    io = np.zeros((nt * nm, _NI), dtype=np.int8)
    for k in range(nt * nm):
        i = k // nm
        j = k - i * nm
        _classify_one(Ms[j], thetas[i], acs[i], mmaxs[i], ams[i], s_frac, d_frac, fo, io, k)
    return fo, io


@njit(cache=True)
def _row_constants(thetas):
    n = thetas.shape[0]
    ac = np.empty(n)
    mm = np.empty(n)
    am = np.empty(n)
    for i in range(n):
        ac[i] = a_crit_kernel(thetas[i])
        mm[i], am[i] = zero_load_max_nb(thetas[i])
    return ac, mm, am


def classify(Ms, thetas, parallel=True, chunk_rows=None, progress=None):
    """Atlas on the grid Ms x thetas (thetas may contain inf: M is then M_R*).

    Returns a dict: M (n_M,), theta (n_theta,), a_crit, zero_load_M_max (per theta; inf for inf),
    and every field of FIELDS_BOOL/INT/FLOAT as an (n_theta, n_M) array.  ``progress(done, total)``
    is called after each chunk of rows."""
    Ms = np.ascontiguousarray(np.asarray(Ms, dtype=float))
    thetas = np.ascontiguousarray(np.asarray(thetas, dtype=float))
    if Ms.ndim != 1 or thetas.ndim != 1 or Ms.size == 0 or thetas.size == 0:
        raise ValueError("M and theta must be non-empty 1-D grids")
    if not np.all(np.isfinite(Ms)) or np.any(Ms < 0):
        raise ValueError("M must be finite and >= 0")
    if np.any(np.isnan(thetas)) or np.any(thetas < 0.5):
        raise ValueError("theta must be >= 0.5 (or inf)")
    ac, mm, am = _row_constants(thetas)
    s_frac, d_frac = _fractions()
    kern = classify_parallel if parallel else classify_serial
    nt, nm = thetas.size, Ms.size
    if chunk_rows is None:
        chunk_rows = max(1, min(nt, 200000 // max(nm, 1)))
    fos, ios = [], []
    for r0 in range(0, nt, chunk_rows):
        r1 = min(nt, r0 + chunk_rows)
        fo, io = kern(Ms, thetas[r0:r1], ac[r0:r1], mm[r0:r1], am[r0:r1], s_frac, d_frac)
        fos.append(fo)
        ios.append(io)
        if progress:
            progress(r1, nt)
    fo = np.concatenate(fos).reshape(nt, nm, _NF)
    io = np.concatenate(ios).reshape(nt, nm, _NI)
    out = {"M": Ms, "theta": thetas, "a_crit": ac, "zero_load_M_max": mm}
    for q, name in enumerate(FIELDS_FLOAT):
        out[name] = np.ascontiguousarray(fo[:, :, q])
    for q, name in enumerate(FIELDS_INT):
        out[name] = np.ascontiguousarray(io[:, :, q])
    for q, name in enumerate(FIELDS_BOOL):
        out[name] = np.ascontiguousarray(io[:, :, len(FIELDS_INT) + q].astype(bool))
    return out


def default_grid(n_M=1000, n_theta=1000, M_max=2.0, theta_min=0.5, theta_max=5.0, with_inf=True):
    """M = linspace(0, M_max, n_M); vartheta = linspace(theta_min, theta_max, n_theta) (+ inf)."""
    Ms = np.linspace(0.0, M_max, n_M)
    th = np.linspace(theta_min, theta_max, n_theta)
    if with_inf:
        th = np.append(th, np.inf)
    return Ms, th


# ------------------------------------------------------------------------------------------------
NOTE = ("vartheta = inf row: M is M_R* = sqrt(wAR)/(sqrt(2) Delta) and P* is P_R* = P beta*/(4 pi Delta) "
        "of (7.6). Value fields are 0 where their mask is False (no NaN).")


def write_npz(path, atlas):
    np.savez_compressed(path, note=np.array(NOTE), fields_bool=np.array(FIELDS_BOOL),
                        fields_int=np.array(FIELDS_INT), fields_float=np.array(FIELDS_FLOAT), **atlas)


CSV_COLUMNS = ("theta", "M") + FIELDS_BOOL + FIELDS_INT + FIELDS_FLOAT


def write_csv(path, atlas):
    """One row per (vartheta, M) pair; booleans 0/1, theta 'inf' on the rigid-cradle row."""
    nt, nm = atlas["theta"].size, atlas["M"].size
    TH, MM = np.meshgrid(atlas["theta"], atlas["M"], indexing="ij")
    cols = [TH.ravel(), MM.ravel()]
    cols += [atlas[k].ravel().astype(np.int64) for k in FIELDS_BOOL + FIELDS_INT]
    cols += [atlas[k].ravel() for k in FIELDS_FLOAT]
    fmt = ["%.17g", "%.17g"] + ["%d"] * (len(FIELDS_BOOL) + len(FIELDS_INT)) + ["%.17g"] * len(FIELDS_FLOAT)
    with open(path, "w") as fh:
        fh.write(f"# {NOTE}\n")
        fh.write(",".join(CSV_COLUMNS) + "\n")
        np.savetxt(fh, np.column_stack(cols), fmt=fmt, delimiter=",")


def regime_label(code):
    """Legend text of a regime code (zero-load bit ignored)."""
    if code & BIT_SUB:
        s = "sub-critical detachment" + ("" if code & BIT_SUB_FEAS else " (overclosed)")
        if code & BIT_OC:
            s += ", overclosed window before it"
    elif code & BIT_OC:
        s = "overclosure, no sub-critical detachment"
    else:
        s = "no detachment"
    if code & BIT_SUP:
        s += "; super-critical detachment" + ("" if code & BIT_SUP_FEAS else " (overclosed)")
    return s


def draw(atlas, path_stem):
    """Regime map: coloured regions in (M, vartheta), contours of the adherence force P*, the
    zero-load limit M_max(vartheta) of (8.1), and a strip for vartheta = inf (M = M_R*)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap, BoundaryNorm
    from matplotlib.patches import Patch

    Ms, th = atlas["M"], atlas["theta"]
    fin = np.isfinite(th)
    has_inf = (~fin).any()
    code = atlas["regime"] & ~BIT_ZL          # zero-load is drawn as a line, not a colour
    present = sorted(set(np.unique(code).tolist()))
    palette = ["#d9d9d9", "#a6cee3", "#fdbf6f", "#b2df8a", "#fb9a99", "#cab2d6", "#ffff99", "#8dd3c7",
               "#bebada", "#80b1d3", "#fccde5", "#e5d8bd"]
    idx = {c: i for i, c in enumerate(present)}
    img = np.vectorize(idx.get)(code) if code.size else code
    cmap = ListedColormap([palette[i % len(palette)] for i in range(len(present))])
    norm = BoundaryNorm(np.arange(len(present) + 1) - 0.5, len(present))
    fig = plt.figure(figsize=(10, 8.2))
    gs = fig.add_gridspec(2, 1, height_ratios=[12, 1] if has_inf else [1, 0.0001], hspace=0.08)
    ax = fig.add_subplot(gs[0])
    tf = th[fin]
    dM = (Ms[-1] - Ms[0]) / max(len(Ms) - 1, 1)
    dT = (tf[-1] - tf[0]) / max(len(tf) - 1, 1) if tf.size else 1.0
    ext = [Ms[0] - dM / 2, Ms[-1] + dM / 2, tf[0] - dT / 2, tf[-1] + dT / 2] if tf.size else None
    if tf.size:
        ax.imshow(img[fin], origin="lower", aspect="auto", extent=ext, cmap=cmap, norm=norm,
                  interpolation="nearest")
        P = np.where(atlas["adherence"][fin], atlas["P_adh"][fin], np.nan)   # NaN only for plotting
        if np.isfinite(P).sum() > 4 and len(Ms) > 2 and tf.size > 2:
            lev = [-5, -3, -2, -1.5, -1, -0.75, -0.5, -0.3, -0.2, -0.1, -0.05]
            lo = np.nanmin(P)
            lev = [v for v in lev if v > lo]
            if lev:
                cs = ax.contour(Ms, tf, P, levels=lev, colors="k", linewidths=0.7, linestyles="solid")
                ax.clabel(cs, fmt="%g", fontsize=7)
        mmax = atlas["zero_load_M_max"][fin]
        ax.plot(mmax, tf, color="tab:red", lw=1.6, ls="--")
        ax.set_xlim(ext[0], ext[1])
        ax.set_ylim(ext[2], ext[3])
    ax.set_ylabel(r"$\vartheta$")
    ax.set_title(r"Fixed-load regimes over $(M, \vartheta)$; contours: adherence force $P^*$ "
                 "(lowest feasible detachment)", fontsize=10)
    handles = [Patch(facecolor=palette[idx[c] % len(palette)], edgecolor="k", lw=0.3, label=regime_label(c))
               for c in present]
    handles.append(plt.Line2D([], [], color="tab:red", ls="--", label=r"$M_{max}(\vartheta)$: zero-load contact (8.1) for $M < M_{max}$"))
    ax.legend(handles=handles, loc="upper right", fontsize=7, framealpha=0.9)
    if has_inf:
        ax.tick_params(labelbottom=False)
        ax2 = fig.add_subplot(gs[1], sharex=ax)
        ax2.imshow(img[~fin][:1], origin="lower", aspect="auto", extent=[ext[0], ext[1], 0, 1] if ext else None,
                   cmap=cmap, norm=norm, interpolation="nearest")
        ax2.set_yticks([0.5])
        ax2.set_yticklabels([r"$\infty$"])
        ax2.set_xlabel(r"$M$  ($M_R^*$ of (7.6) in the $\vartheta = \infty$ strip)")
    else:
        ax.set_xlabel(r"$M$")
    written = []
    for ext_ in ("png", "pdf"):
        p = f"{path_stem}.{ext_}"
        fig.savefig(p, dpi=110, metadata={"CreationDate": None} if ext_ == "pdf" else None)
        written.append(p)
    plt.close(fig)
    return written


def text_progress(stream=sys.stderr):
    t0 = time.perf_counter()

    def bar(done, total):
        width = 30
        k = int(width * done / total)
        stream.write(f"\r[{'#' * k}{'.' * (width - k)}] {done}/{total} rows  {time.perf_counter() - t0:6.1f} s")
        if done == total:
            stream.write("\n")
        stream.flush()
    return bar
