"""``make test-boundscheck`` really checks: there every numba kernel is compiled with bounds checking, so an index
out of range raises IndexError instead of reading or writing past an array (a wrong number or a crash). The kernel
below is cached like the library's, so a run that loaded kernels compiled without checks would fail here."""
import numba
import numpy as np
import pytest

pytestmark = [pytest.mark.boundscheck,
              pytest.mark.skipif(not numba.config.BOUNDSCHECK, reason="NUMBA_BOUNDSCHECK=1 only (make test-boundscheck)")]


@numba.njit(cache=True, error_model="numpy")
def _last_plus(values, offset):
    return values[values.size - 1 + offset]


def test_an_index_past_the_end_raises_index_error():
    values = np.arange(4.0)
    assert _last_plus(values, 0) == 3.0
    with pytest.raises(IndexError):
        _last_plus(values, 1)
