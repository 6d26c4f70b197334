"""Pieces of the collocation kernels (jkrcyl.numerics.arc_angles) against mpmath (40 digits); the image rows of
the assembly (jkrcyl.numerics.arcs) against the row-by-row products."""
import math

import mpmath as mp
import pytest
import numpy as np

from jkrcyl.numerics import arc_angles as ak


def test_ell_half_series_and_log_branch():
    """_ell(t) = 2 log|sin(y)/y|, y = t/2: the Bernoulli series below SERIES_Y, the log above it."""
    ys = np.concatenate([np.geomspace(1e-9, 3.1, 300), -np.geomspace(1e-6, 3.1, 50),
                         [ak.SERIES_Y * (1 - 1e-15), ak.SERIES_Y]])
    with mp.workdps(40):
        for y in ys:
            ref = 2 * mp.log(abs(mp.sin(mp.mpf(y)) / mp.mpf(y)))
            got = ak.ell_half(y, math.sin(y))
            # series side: within 1e-17 of the truth; log side: the rounding of sin(y)/y and of the log
            tol = 1e-17 + 4e-16 * abs(float(ref)) if abs(y) < ak.SERIES_Y else 1e-15 * max(1.0, abs(float(ref)))
            assert abs(got - float(ref)) <= tol, (y, got, ref)


def test_log_sinc_coefficients_are_the_series():
    """LOGSINC against mpmath's Taylor coefficients of log(sin(y)/y) in y^2."""
    with mp.workdps(40):
        c = mp.taylor(lambda y: mp.log(mp.sin(y) / y) if y != 0 else mp.mpf(0), 0, 2 * len(ak.LOGSINC))
        for k, v in enumerate(ak.LOGSINC):
            assert abs(v - float(c[2 * k + 2])) <= 1e-16 * abs(v)


@pytest.mark.parametrize("ar", [0.0, 0.2])
@pytest.mark.parametrize("arcs_", [[(0.0, 2.5)], [(0.0, 3.1)], [(0.0, 1.4), (math.pi, 1.2)]])
def test_image_rows_by_dct_equal_the_row_products(ar, arcs_):
    """The same-arc rows' periodic images of an arc wider than 1 rad (arcs._image_rows: a DCT of the log moments)
    against two routes without it: the collocation matrix assembled with the product (moments) @ D row by row in
    the kernel (no rows passed), and numpy's (arcs._log_moments at x -+ 2 pi/e) @ D.  Measured: 2e-16 and 1e-15
    of the largest entry."""
    from jkrcyl.numerics import arcs, arcs_kernels, cohesive
    kernel = cohesive._law(1.0, 1.0, 10.0, 1 / 2.8, ar)[2]
    for n in (arcs.IMAGE_DCT_NODES, 200):
        sy = arcs.Arcs(arcs_, kernel, n)
        LD0, SD0 = arcs._tables(n, bool(sy.m))[-2:]
        A, rhs = np.empty_like(sy.A), np.empty_like(sy._rhs)
        arcs_kernels.assemble(sy._ac, sy._ae, sy.s, sy.D, kernel.k0, kernel.k1, kernel.ar, sy._xt, LD0, SD0, sy._Lam,
                              sy._Sig, sy._omega, sy._gcs, sy._gss, A, rhs, np.zeros((1, 0, n)))
        assert np.max(np.abs(A - sy.A)) <= 1e-14 * np.max(np.abs(A))
        rows = arcs._image_rows(sy._ae, sy._xt, n)
        for ia, e in enumerate(sy._ae):
            if e > 1.0:
                images = 2 * math.pi / e
                ref = (arcs._log_moments(sy._xt - images, n) + arcs._log_moments(sy._xt + images, n)) @ sy.D
                assert np.max(np.abs(rows[ia] - ref)) <= 1e-14 * np.max(np.abs(ref))
            else:
                assert not np.any(rows[ia])
