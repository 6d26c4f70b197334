"""The end-enrichment tables of jkrcyl.numerics.arcs_enrich (folded series, issue 18 speed item 1) against
two independent evaluations: the dense sums over all M_FINE Chebyshev terms at arccos of the stored points
(the former construction, written out here), and mpmath quadrature (40 digits) of the defining integrals
Lam = int log|x - s| T_k g_j w ds, Sig = int sign(x - s) T_k g_j w ds."""
import math

import mpmath as mp
import numpy as np
import pytest

from jkrcyl.numerics import arcs_enrich as en


def _dense(n):
    """Lam, Sig by the dense product of the log/sign moments of T_m with the coefficients of T_k g_j."""
    x, _ = en.table_points(n)
    th = np.arccos(np.clip(x, -1, 1))
    m = np.arange(1, en.M_FINE)
    LM = np.empty((x.size, en.M_FINE))
    SM = np.empty((x.size, en.M_FINE))
    LM[:, 0], SM[:, 0] = -math.pi * math.log(2), math.pi - 2 * th
    LM[:, 1:] = -math.pi * np.cos(np.outer(th, m)) / m
    SM[:, 1:] = -2 * np.sin(np.outer(th, m)) / m
    C = en._coefficients()
    Lam, Sig = [], []
    for j in range(en.N_ENRICH):
        P = np.zeros((en.K_TRIG, en.M_FINE))
        for k in range(en.K_TRIG):            # g T_k = sum_m c_m (T_{m+k} + T_|m-k|)/2, truncated
            P[k, k:] += 0.5 * C[j, :en.M_FINE - k]
            np.add.at(P[k], np.abs(np.arange(en.M_FINE) - k), 0.5 * C[j])
        Lam.append(LM @ P.T)
        Sig.append(SM @ P.T)
    return Lam, Sig


@pytest.mark.parametrize("n", [8, 24])
def test_tables_equal_dense_sums(n):
    Lam, Sig, _ = en.tables(n)
    dLam, dSig = _dense(n)
    for j in range(en.N_ENRICH):
        assert np.max(np.abs(Lam[j] - dLam[j])) < 1e-13 * np.max(np.abs(dLam[j]))
        assert np.max(np.abs(Sig[j] - dSig[j])) < 1e-13 * np.max(np.abs(dSig[j]))


def _g(j, s):
    xl = lambda r: r * mp.log(r) if r > 0 else mp.mpf(0)
    rp, rm = 1 - s, 1 + s
    return (xl(rp) + xl(rm), rp * xl(rp) + rm * xl(rm), xl(rp) ** 2 + xl(rm) ** 2)[j]


def _quad(kind, x, j, k):
    """The defining integral in theta (s = cos theta, w ds = d theta), split at the point."""
    with mp.workdps(40):
        x = mp.mpf(float(x))
        if kind == "log":
            # a node rounded onto the singular end point gets weight ~ 10^-40: counted as 0
            f = lambda t: (mp.log(abs(x - mp.cos(t))) if x != mp.cos(t) else 0) * mp.cos(k * t) * _g(j, mp.cos(t))
        else:
            f = lambda t: mp.sign(x - mp.cos(t)) * mp.cos(k * t) * _g(j, mp.cos(t))
        return mp.quad(f, [0, mp.acos(x), mp.pi])


@pytest.mark.parametrize("n", [16, 256])
def test_tables_against_quadrature(n):
    """Interior nodes and the extra end points, where the stored x differs most from the angle grid."""
    Lam, Sig, _ = en.tables(n)
    x, _ = en.table_points(n)
    for p in (0, n // 2, n + 1, n + 2):        # first node, a middle node, the end points next to s = 1
        for j, k in ((0, 0), (1, 7), (2, 33)):
            assert abs(Sig[j][p, k] - float(_quad("sign", x[p], j, k))) < 1e-14
            # log moment: M_FINE truncation of g_j's Chebyshev series (~M^-3) is the error, not the folding
            assert abs(Lam[j][p, k] - float(_quad("log", x[p], j, k))) < 5e-14


def test_table_points_are_the_collocation_points():
    from jkrcyl.numerics import arcs
    n = 40
    x, q = en.table_points(n)
    assert np.array_equal(x[:n], arcs._nodes(n))
    big = 2 * n * en.N_ENRICH
    assert np.max(np.abs(np.arccos(x) - q * math.pi / big)) < 1e-12
