"""The public API's docstrings: their examples run (doctest) and print what they say, and they name modules that
exist and carry no issue numbers.

The examples' printed values are checked against something independent inside the examples themselves where one
exists (a closed form, a quadrature of the pressure, the general solution at a special case); here they only have
to run.  The docstring check covers every file of jkrcyl/ (DOCUMENTED) and is shown to fail on planted docstrings.
"""
import ast
import doctest
import importlib
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
FLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE

# modules whose docstrings carry examples (each must run at least one)
DOCTEST_MODULES = (
    "jkrcyl.contact", "jkrcyl.contact_analyses", "jkrcyl.contact_fields", "jkrcyl.contact_cohesive", "jkrcyl.materials",
    "jkrcyl.critical", "jkrcyl.units", "jkrcyl.equilibria", "jkrcyl.equilibria_points", "jkrcyl.equilibria_confined",
    "jkrcyl.special", "jkrcyl.results.curves", "jkrcyl.results.paths", "jkrcyl.results.states",
    "jkrcyl.laws", "jkrcyl.laws.griffith", "jkrcyl.laws.dugdale", "jkrcyl.model.edge", "jkrcyl.atlas",
    "jkrcyl.atlas.draw", "jkrcyl.atlas.files", "jkrcyl.plotting.confined", "jkrcyl.plotting.cycle",
    "jkrcyl.plotting.paper_pressure", "jkrcyl.plotting.paper_stability", "jkrcyl.plotting.registry",
    "jkrcyl.plotting.style", "jkrcyl.laws.kinetic", "jkrcyl.kinetics.sweep", "jkrcyl.kinetics.history",
    "jkrcyl.kinetics.results", "jkrcyl.plotting.rate", "jkrcyl.fit.estimate", "jkrcyl.explore.model", "jkrcyl.numerics.zero_load",
    "jkrcyl.fit.data", "jkrcyl.fit.result",
)

# every library file's docstrings are held to the naming rules below
DOCUMENTED = tuple(sorted(p.relative_to(ROOT).as_posix() for p in (ROOT / "jkrcyl").rglob("*.py")
                          if "__pycache__" not in p.parts))

ISSUE = re.compile(r"\bissues?\s+#?\d+", re.IGNORECASE)
DOTTED = re.compile(r"\bjkrcyl(?:\.[A-Za-z_]\w*)+")


@pytest.mark.parametrize("name", DOCTEST_MODULES)
def test_examples_run(name):
    if name.startswith("jkrcyl.plotting") or name == "jkrcyl.atlas.draw":
        pytest.importorskip("matplotlib").use("Agg")
    module = importlib.import_module(name)
    runner = doctest.DocTestRunner(optionflags=FLAGS)
    report = []
    for test in doctest.DocTestFinder().find(module, name):
        runner.run(test, out=report.append)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, "".join(report)
    assert result.attempted > 0, f"{name}: no examples found"


def _docstrings(source):
    """(line, text) of the module's, every class's and every function's docstring."""
    tree = ast.parse(source)
    nodes = [tree] + [n for n in ast.walk(tree) if isinstance(n, (ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef))]
    out = []
    for node in nodes:
        doc = ast.get_docstring(node, clean=False)
        if doc is not None:
            out.append((node.body[0].lineno, doc))
    return out


def _resolves(dotted):
    """Whether jkrcyl.a.b.c names something: the longest prefix that imports as a module, the rest attributes."""
    parts = dotted.split(".")
    for k in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:k]))
        except ImportError:
            continue
        for attr in parts[k:]:
            if not hasattr(obj, attr):
                return False
            obj = getattr(obj, attr)
        return True
    return False


def naming_faults(source):
    """Issue numbers and jkrcyl.* names that do not resolve, in the docstrings of a module's source."""
    faults = []
    for line, doc in _docstrings(source):
        faults += [f"line {line}: {m.group(0)!r}" for m in ISSUE.finditer(doc)]
        faults += [f"line {line}: {m.group(0)!r} does not resolve" for m in DOTTED.finditer(doc)
                   if not _resolves(m.group(0))]
    return faults


@pytest.mark.parametrize("path", DOCUMENTED)
def test_docstrings_name_what_exists(path):
    faults = naming_faults((ROOT / path).read_text())
    assert not faults, f"{path}: {faults}"


def test_naming_check_fails_on_planted_docstrings():
    planted = '''"""Regime atlas (issue 6 item 3).

    See jkrcyl.twopatch.confined_events and jkrcyl.equilibria.no_such_function; jkrcyl.equilibria.curve is fine.
    """


def f():
    """As before (Issue #19)."""
'''
    faults = naming_faults(planted)
    assert len(faults) == 4, faults
    assert any("issue 6" in f for f in faults) and any("Issue #19" in f for f in faults)
    assert any("jkrcyl.twopatch.confined_events" in f for f in faults)
    assert any("jkrcyl.equilibria.no_such_function" in f for f in faults)
