"""pytest configuration of the jkrcyl suite: hypothesis profiles, the fuzz scaling, a bounds-check guard.

Hypothesis draws the same examples for everyone (profile ``jkrcyl``, loaded here for CI and a user alike): the
seed of each property test is derived from the test itself (derandomize) and no example database is replayed, so
``make test`` on any machine runs the tests CI runs. ``make fuzz`` (``--hypothesis-profile=fuzz``) draws fresh
random examples, ten times as many; a failure it finds is added to its test as an ``@example`` (hypothesis prints
the falsifying example and a ``git apply`` patch that adds it), so that every later ``make test`` runs it.
"""
import os
import pathlib

import numba
import pytest
from hypothesis import Phase, settings

ROOT = pathlib.Path(__file__).resolve().parents[1]


def _numba_cache_per_worker():
    """Under pytest-xdist each worker compiles into a numba cache of its own (subprocesses inherit it). numba's
    cache is not safe for two processes compiling one function at once: both pick the same data file for their
    signatures, and the index can end up naming the other's machine code."""
    worker = os.environ.get("PYTEST_XDIST_WORKER")
    if not worker:
        return
    base = pathlib.Path(os.environ.get("NUMBA_CACHE_DIR") or ROOT / ".pytest_cache" / "numba")
    os.environ["NUMBA_CACHE_DIR"] = str(base / worker)
    numba.config.reload_config()        # before jkrcyl is imported: the kernels' cache locator reads it


_numba_cache_per_worker()

#: the examples a property test draws under a profile = its own ``max_examples`` times the profile's
#: ``max_examples`` over hypothesis' default (100): 1 for ``jkrcyl``, 10 for ``fuzz``
DEFAULT_MAX_EXAMPLES = 100

settings.register_profile("jkrcyl", derandomize=True, database=None, print_blob=True)
settings.register_profile("fuzz", derandomize=False, max_examples=10 * DEFAULT_MAX_EXAMPLES, print_blob=True)
settings.load_profile("jkrcyl")        # the hypothesis plugin loads --hypothesis-profile after this (fuzz)


def pytest_addoption(parser):
    parser.addoption("--update-generated", action="store_true", default=False,
                     help="tests/test_generated_up_to_date.py: write the fresh derivation into generated/ "
                          "instead of failing on a difference (compare-or-update, like make derive)")


def pytest_configure(config):
    """numba's cache key does not include the bounds-check flag: with NUMBA_BOUNDSCHECK=1 and the default cache
    (next to the sources) the kernels compiled without checks would be loaded and nothing would be checked."""
    if numba.config.BOUNDSCHECK and not numba.config.CACHE_DIR:
        raise pytest.UsageError("NUMBA_BOUNDSCHECK=1 needs NUMBA_CACHE_DIR set to a cache of its own "
                                "(make test-boundscheck does this)")


def pytest_collection_modifyitems(config, items):
    """Scale every property test's own max_examples by the loaded profile (x10 under fuzz). A test's
    ``@settings(max_examples=n)`` otherwise wins over any profile, and the suite sets it on every property test.
    The slow property tests (seconds to a minute an example) report a failing example as found, unshrunk, outside
    ``make fuzz``: shrinking one took longer than CI's whole budget (session 34, tests/test_loop_work.py)."""
    factor = settings.default.max_examples / DEFAULT_MAX_EXAMPLES
    fuzz = factor != 1
    done = set()
    for item in items:
        test = getattr(item, "obj", None)
        own = getattr(test, "_hypothesis_internal_use_settings", None)   # where @settings/@given keep them
        if own is None or id(test) in done:                             # parametrized: one function, many items
            continue
        changes = {"max_examples": max(1, round(own.max_examples * factor))} if fuzz else {}
        if not fuzz and item.get_closest_marker("slow") is not None:
            changes["phases"] = tuple(p for p in own.phases if p is not Phase.shrink)
        if changes:
            test._hypothesis_internal_use_settings = settings(own, **changes)
        done.add(id(test))
