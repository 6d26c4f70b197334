"""The `jkrcyl` command line run in this process: what a subprocess would see, without paying for a fresh
interpreter (import + numba cache load, ~3 s a run on a loaded machine) every time.

:func:`run` returns what :func:`subprocess.run` returns (``returncode``, ``stdout``, ``stderr``); the parts of a real
run a test can check are kept: argparse's exits (``--help``, ``--version``, usage errors) are exit statuses, a
warning is printed on stderr as Python prints it by default (a second stderr line fails a one-line check as it
would in a subprocess), and an exception the command does not handle propagates and fails the test (where a
subprocess would print a traceback). The real entry points (``python -m jkrcyl``, ``python -m jkrcyl.cli``, a
broken pipe) keep subprocess tests of their own: tests/test_bad_input.py, tests/test_kinetic_cli.py.
"""
import contextlib
import io
import os
import pathlib
import subprocess
import warnings

import matplotlib

ROOT = pathlib.Path(__file__).resolve().parents[1]


def _default_filters():
    """The warning filters of a fresh interpreter (no ``-W``): DeprecationWarning shown in __main__ only."""
    warnings.resetwarnings()
    for category in (DeprecationWarning, PendingDeprecationWarning, ImportWarning, ResourceWarning):
        warnings.simplefilter("ignore", category)
    warnings.filterwarnings("default", category=DeprecationWarning, module="__main__")


@contextlib.contextmanager
def _chdir(path):
    """contextlib.chdir of Python 3.11, for the 3.10 the README allows."""
    before = os.getcwd()
    os.chdir(path)
    try:
        yield
    finally:
        os.chdir(before)


def run(*args, cwd=ROOT):
    """``python -m jkrcyl *args`` in this process, in directory ``cwd``, with matplotlib on Agg (MPLBACKEND=Agg)."""
    from jkrcyl import cli
    matplotlib.use("Agg")
    out, err = io.StringIO(), io.StringIO()

    def show(message, category, filename, lineno, file=None, line=None):
        err.write(warnings.formatwarning(message, category, filename, lineno, line))

    with _chdir(cwd), contextlib.redirect_stdout(out), contextlib.redirect_stderr(err), \
            warnings.catch_warnings():
        _default_filters()
        warnings.showwarning = show
        try:
            code = cli.main([str(a) for a in args])
        except SystemExit as exc:             # argparse: --help, --version, a usage error
            code = exc.code
    code = 0 if code is None else code
    assert isinstance(code, int), f"exit status {code!r}"
    return subprocess.CompletedProcess(["jkrcyl", *args], code, out.getvalue(), err.getvalue())


def run_script(path, *args):
    """``python path *args`` in this process, from the repository root: the script runs as __main__ (runpy, argv
    patched); returns its stdout, and fails the test on a nonzero exit or an exception."""
    import runpy
    import sys
    out, argv = io.StringIO(), sys.argv
    sys.argv = [str(path), *map(str, args)]
    try:
        with _chdir(ROOT), contextlib.redirect_stdout(out):
            runpy.run_path(str(path), run_name="__main__")
    except SystemExit as exc:
        assert exc.code in (None, 0), exc.code
    finally:
        sys.argv = argv
    return out.getvalue()
