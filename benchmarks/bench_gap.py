"""Benchmark (not a test): h(pi) per point, closed-form numba kernel vs scipy.integrate.quad of (5.10).

Run: python benchmarks/bench_gap.py   (needs scipy, which the package itself does not).

The quadrature side is the paper's recipe: (5.10) with the integral J_pi evaluated by adaptive
QUADPACK (QAWS, weight (eps - psi)^(-1/2) for the end singularity of the pressure (5.4)), and the
approach delta of (5.3) by QAWS with weight log(psi) (eps - psi)^(-1/2).  Both at epsrel = 1e-13.
The state (P, B, c0, c1, r0) is the closed form of (4.4)-(4.5a), (2.6), (3.6b) in both cases.
Prints the time per point of each, their ratio, and the largest difference between them.
"""
import math
import time
import warnings

import numpy as np
from scipy.integrate import IntegrationWarning, quad

from jkrcyl.generated.gap import gap_pi_into

R, DELTA, BETA, INV_THETA, ZETA = 1.0, 1e-3, 3.0, 1.0, 2e-3      # identical materials, vartheta = 1
KAPPA_I, INV_G_I = 2.0, 1.0                                          # (kappa_I + 1)/(2 G_I) = beta (1 - t/2)


def state(a):
    """(4.4), (4.5a), (2.6) and r0 of (3.6b) in the stable forms (1/vartheta, log1p)."""
    t, E, L, sa = INV_THETA, math.sqrt(1 + a * a), math.log1p(a * a), math.sqrt(a)
    D = 2 - t * (L + 2 * a**4)
    P = 2 * E**2 * (4 * math.pi * DELTA * a**2 / BETA - ZETA * sa * (2 + t * (a**2 - L))) / D
    B = 4 / (R * BETA) * (2 * math.pi * DELTA * (L + 2 * a**4) - ZETA * BETA * sa * (1 + 2 * a**2)) / D
    c0 = -DELTA - R * BETA * B * t / (8 * math.pi)
    c1 = BETA * P / (2 * math.pi)
    r0 = -E * ZETA * sa / (math.pi * R)
    return P, B, c0, c1, r0


def h_pi_quad(a):
    """(5.10) with J_pi and delta (5.3) by scipy.integrate.quad (QAWS weights for the end singularities)."""
    P, B, c0, c1, r0 = state(a)
    eps, k = 2 * math.atan(a), 4 / (R * BETA)
    ce = math.cos(eps / 2)

    def n_times_root(psi):          # N(psi) sqrt(eps - psi): smooth on [0, eps]
        cp = math.cos(psi / 2)
        sn = math.sin((eps + psi) / 2)
        root = math.sqrt(max(eps - psi, 0.0))
        s = math.sqrt(max(math.sin((eps - psi) / 2) * sn, 0.0))
        ratio = math.sqrt(max(eps - psi, 0.0) / max(math.sin((eps - psi) / 2) * sn, 1e-300)) if s > 0 else \
            math.sqrt(2.0 / math.sin(eps))
        return r0 * cp * ce * ratio + (k * c1 * cp * s - k * c0 * math.log((cp + s) / ce)) * root

    opts = dict(epsabs=0.0, epsrel=1e-13, limit=200)
    j_pi = quad(lambda p: n_times_root(p) * 4 * math.cos(p) * math.log(2 * math.cos(p / 2)), 0, eps,
                weight="alg", wvar=(0, -0.5), **opts)[0]
    # J of (5.3): 4 cos(psi) log(2 sin(psi/2)) = 4 cos(psi) [log(psi) + log(2 sin(psi/2)/psi)]
    j_log = quad(lambda p: n_times_root(p) * 4 * math.cos(p), 0, eps, weight="alg-loga", wvar=(0, -0.5), **opts)[0]
    j_reg = quad(lambda p: n_times_root(p) * 4 * math.cos(p) * math.log(2 * math.sin(p / 2) / p if p > 0 else 1.0),
                 0, eps, weight="alg", wvar=(0, -0.5), **opts)[0]
    j = j_log + j_reg
    gI = (KAPPA_I + 1) * INV_G_I / 2
    delta = -R / (4 * math.pi) * (gI * B + P * INV_G_I / R + BETA * j)
    return 2 * DELTA + delta - R / (4 * math.pi) * (gI * B - P * INV_G_I / R - BETA * j_pi)


def main():
    warnings.simplefilter("ignore", IntegrationWarning)   # QUADPACK roundoff notes at 1e-13
    a = np.logspace(-3, 1, 400)
    a = a[np.abs(2 - INV_THETA * (np.log1p(a * a) + 2 * a**4)) > 1e-2]     # away from a_crit (infinite load)
    hk = np.empty(a.size)
    gap_pi_into(hk[:2], DELTA, a[:2].copy(), BETA, INV_THETA, ZETA)        # compile
    reps = 200
    t0 = time.perf_counter()
    for _ in range(reps):
        gap_pi_into(hk, DELTA, a, BETA, INV_THETA, ZETA)
    t_kernel = (time.perf_counter() - t0) / (reps * a.size)
    t0 = time.perf_counter()
    hq = np.array([h_pi_quad(x) for x in a])
    t_quad = (time.perf_counter() - t0) / a.size
    err = np.max(np.abs(hk - hq) / np.maximum(np.abs(hq), DELTA))
    print(f"h(pi), {a.size} points, a in [{a[0]:.0e}, {a[-1]:.0e}], identical materials, vartheta = 1")
    print(f"  closed-form numba kernel : {t_kernel * 1e9:10.1f} ns/point")
    print(f"  scipy quad of (5.10)     : {t_quad * 1e9:10.1f} ns/point")
    print(f"  speed-up                 : {t_quad / t_kernel:10.0f}x")
    print(f"  max |kernel - quad| / max(|h|, Delta) = {err:.1e}")


if __name__ == "__main__":
    main()
