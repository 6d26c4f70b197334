"""The hypothesis set-up of tests/conftest.py: ``make test`` draws the same examples on every run and machine (no
switch on CI), ``make fuzz`` (``--hypothesis-profile=fuzz``) fresh random ones, ten times as many.

A toy property test with its own ``@settings(max_examples=7)`` is run by pytest in a subprocess beside a copy of
the suite's conftest; it writes the examples it was called with to a file.
"""
import json
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
TOY = '''
import json, os
from hypothesis import given, settings, strategies as st

DRAWN = []

@settings(max_examples=7, deadline=None)
@given(st.integers())
def test_draw(x):
    DRAWN.append(x)

def test_zz_write():
    with open(os.environ["DRAWN_FILE"], "w") as f:
        json.dump(DRAWN, f)
'''


@pytest.fixture(scope="module")
def toy(tmp_path_factory):
    folder = tmp_path_factory.mktemp("toy_suite")
    shutil.copyfile(ROOT / "tests" / "conftest.py", folder / "conftest.py")
    (folder / "test_toy.py").write_text(TOY)
    return folder


def drawn(folder, *options, env_ci=None):
    """The examples the toy test was called with in one run (CI set or unset as given)."""
    out = folder / "drawn.json"
    env = {k: v for k, v in os.environ.items() if k not in ("CI", "PYTEST_XDIST_WORKER")}
    if env_ci is not None:
        env["CI"] = env_ci
    env["DRAWN_FILE"] = str(out)
    r = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-p", "no:xdist",
                        *options, "test_toy.py"], cwd=folder, env=env, capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    return json.loads(out.read_text())


def test_make_test_draws_the_same_examples_with_and_without_ci(toy):
    here, on_ci = drawn(toy), drawn(toy, env_ci="true")
    assert len(here) == 7
    assert here == on_ci


def test_fuzz_draws_fresh_examples_ten_times_as_many(toy):
    first, again = drawn(toy, "--hypothesis-profile=fuzz"), drawn(toy, "--hypothesis-profile=fuzz")
    assert len(first) == len(again) == 70
    assert first != again
