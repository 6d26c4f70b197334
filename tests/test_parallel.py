"""The prange forms ``<kernel>_into_parallel`` give bit-identical results to the serial ``<kernel>_into``,
and a prange form is emitted only next to its serial form."""
import numpy as np
import pytest

from jkrcyl import generated
from jkrcyl.generated import state as S

# a spanning the documented range, shuffled so that every thread gets small and large a
A_VALUES = np.random.default_rng(6).permutation(np.logspace(-8, 4, 10_001))
DELTA, R, BETA, ZETA, INV_G_I = 1e-3, 1.0, 3.0, 2e-3, 1.0


def _same(serial, parallel):
    assert len(serial) == len(parallel)
    for s, p in zip(serial, parallel):
        assert s.shape == p.shape == A_VALUES.shape
        assert np.array_equal(s, p, equal_nan=True)
        assert np.isfinite(s).mean() > 0.99      # a_crit itself is the only place allowed to blow up


def _empty(result):
    return result(*(np.empty(A_VALUES.size) for _ in result._fields))


@pytest.mark.parametrize("inv_theta", [0.0, 1.0, 2.0])
def test_full_state(inv_theta):
    args = dict(Delta=DELTA, R=R, a=A_VALUES, beta=BETA, inv_G_I=INV_G_I, inv_theta=inv_theta, zeta=ZETA)
    serial, parallel = _empty(S.FullState), _empty(S.FullState)
    S.full_state_into(serial, **args)
    S.full_state_into_parallel(parallel, **args)
    _same(serial, parallel)


def test_every_parallel_form_has_a_serial_form():
    import importlib
    found = 0
    for name in generated.__all__:
        module = importlib.import_module(f"jkrcyl.generated.{name}")
        for n in dir(module):
            if n.endswith("_into_parallel"):
                found += 1
                assert callable(getattr(module, n[: -len("_parallel")], None))
    assert found
