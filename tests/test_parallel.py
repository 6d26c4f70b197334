"""The prange forms ``<kernel>_parallel`` give bit-identical results to the serial ``<kernel>_array``."""
import numpy as np
import pytest

from jkrcyl.generated import approach as A
from jkrcyl.generated import gap as G
from jkrcyl.generated import load as L

# a spanning the documented range, shuffled so that every thread gets small and large a
A_VALUES = np.random.default_rng(6).permutation(np.logspace(-8, 4, 10_001))
DELTA, R, BETA, ZETA, INV_G_I = 1e-3, 1.0, 3.0, 2e-3, 1.0


def _same(serial, parallel):
    serial = serial if isinstance(serial, tuple) else (serial,)
    parallel = parallel if isinstance(parallel, tuple) else (parallel,)
    assert len(serial) == len(parallel)
    for s, p in zip(serial, parallel):
        assert s.shape == p.shape == A_VALUES.shape
        assert np.array_equal(s, p, equal_nan=True)
        assert np.isfinite(s).mean() > 0.99      # a_crit itself is the only place allowed to blow up


@pytest.mark.parametrize("inv_theta", [0.0, 1.0, 2.0])
def test_load_state(inv_theta):
    args = dict(Delta=DELTA, R=R, a=A_VALUES, beta=BETA, inv_theta=inv_theta, zeta=ZETA)
    _same(L.load_state_array(**args), L.load_state_parallel(**args))


@pytest.mark.parametrize("inv_theta", [0.0, 1.0, 2.0])
def test_approach(inv_theta):
    args = dict(Delta=DELTA, a=A_VALUES, beta=BETA, inv_G_I=INV_G_I, inv_theta=inv_theta, zeta=ZETA)
    _same(A.approach_array(**args), A.approach_parallel(**args))


@pytest.mark.parametrize("inv_theta", [0.0, 1.0, 2.0])
def test_gap_pi(inv_theta):
    args = dict(Delta=DELTA, a=A_VALUES, beta=BETA, inv_theta=inv_theta, zeta=ZETA)
    _same(G.gap_pi_array(**args), G.gap_pi_parallel(**args))


def test_every_array_form_has_a_parallel_form():
    for module in (A, G, L):
        arrays = {n[: -len("_array")] for n in dir(module) if n.endswith("_array")}
        assert arrays and all(callable(getattr(module, f"{n}_parallel", None)) for n in arrays)
