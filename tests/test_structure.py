"""One model core.  The library's import graph has no cycle, every module is at most 350 lines, and only the
Griffith law's solver choice (jkrcyl.laws.griffith, with the engine it drives in jkrcyl/numerics and the
definition in jkrcyl/materials.py) branches on alpha*; only the laws (jkrcyl.laws) and the Contact's law argument
branch on the edge law.  Each check is shown to fail on a planted violation."""
import ast
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
LIBRARY = ROOT / "jkrcyl"
MAX_LINES = 350
# where alpha* may decide what happens: the solver factory, the engine, the materials' own definition
ALPHA_ALLOWED = {"jkrcyl/model/griffith.py", "jkrcyl/laws/griffith.py", "jkrcyl/materials.py", "jkrcyl/model/problem.py"}   # + validation
ALPHA_NAMES = {"alpha_ratio", "alpha_star", "ar", "closed_form", "ALPHA_TOLERANCE", "require_closed_form"}
# where the edge law may decide what happens: the laws themselves (jkrcyl/laws/), the interface and the problem's
# validation, the Contact fields that define it (sigma0 or law), the input parser
EDGE_ALLOWED = {"jkrcyl/model/edge.py", "jkrcyl/model/problem.py", "jkrcyl/contact.py",
                "jkrcyl/contact_cohesive.py", "jkrcyl/cli/inputs.py"}
EDGE_NAMES = {"Dugdale", "Griffith", "GRIFFITH", "sigma0", "s0", "edge", "lambda_", "Cohesive"}


def _files(root=ROOT):
    return sorted(p for p in (root / "jkrcyl").rglob("*.py") if "__pycache__" not in p.parts)


def _module(path, root=ROOT):
    parts = list(path.relative_to(root).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imported(path, root=ROOT, modules=()):
    """The jkrcyl modules a file imports (anywhere in it: lazy imports count), relative imports resolved;
    ``from package import submodule`` is an import of the submodule (not of the package's __init__)."""
    tree = ast.parse(path.read_text())
    package = _module(path, root).split(".")
    if path.name != "__init__.py":
        package = package[:-1]
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            base = package[: len(package) - node.level + 1] if node.level else []
            mod = ".".join(base + ([node.module] if node.module else []))
            subs = {f"{mod}.{a.name}" for a in node.names} & set(modules)
            out |= subs if len(subs) == len(node.names) else subs | {mod}
    return out


def _graph(root=ROOT):
    mods = {_module(p, root): p for p in _files(root)}
    return {m: {n for n in _imported(p, root, mods) if n in mods and n != m} for m, p in mods.items()}


def _cycle(graph):
    """One import cycle as a list of modules, or None (depth-first search)."""
    state, stack = {}, []

    def visit(m):
        state[m] = 1
        stack.append(m)
        for n in sorted(graph[m]):
            if state.get(n) == 1:
                return stack[stack.index(n):] + [n]
            if n not in state:
                found = visit(n)
                if found:
                    return found
        state[m] = 2
        stack.pop()
        return None
    for m in sorted(graph):
        if m not in state:
            found = visit(m)
            if found:
                return found
    return None


def test_no_import_cycle():
    assert _cycle(_graph()) is None, " -> ".join(_cycle(_graph()))


def test_every_module_is_short():
    long = {p.relative_to(ROOT).as_posix(): n for p in _files()
            if (n := len(p.read_text().splitlines())) > MAX_LINES}
    assert not long, f"modules over {MAX_LINES} lines: {long}"


def _alpha_branches(path, forbidden=ALPHA_NAMES):
    """Lines where a condition (if, while, conditional expression, comprehension filter, assert) reads alpha*
    (or another set of forbidden names)."""
    tree = ast.parse(path.read_text())
    tests = []
    for node in ast.walk(tree):
        if isinstance(node, (ast.If, ast.While, ast.IfExp, ast.Assert)):
            tests.append(node.test)
        elif isinstance(node, ast.comprehension):
            tests += node.ifs
    hits = []
    for t in tests:
        names = {n.id for n in ast.walk(t) if isinstance(n, ast.Name)}
        names |= {n.attr for n in ast.walk(t) if isinstance(n, ast.Attribute)}
        if names & forbidden:
            hits.append(t.lineno)
    return hits


def test_only_the_solver_interface_branches_on_alpha():
    offenders = {}
    for p in _files():
        rel = p.relative_to(ROOT).as_posix()
        if rel in ALPHA_ALLOWED or rel.startswith("jkrcyl/numerics/"):
            continue
        if hits := _alpha_branches(p):
            offenders[rel] = hits
    assert not offenders, f"branch on alpha* outside jkrcyl.model.griffith (file: lines): {offenders}"


def test_only_the_solver_interface_branches_on_the_edge_law():
    """No switch on the edge law (Griffith/Dugdale, sigma0, s0) outside the solver factory and the law's
    definition: the analyses go through the single-patch interface for either law."""
    offenders = {}
    for p in _files():
        rel = p.relative_to(ROOT).as_posix()
        if rel in EDGE_ALLOWED or rel.startswith(("jkrcyl/numerics/", "jkrcyl/laws/")):
            continue
        if hits := _alpha_branches(p, EDGE_NAMES):
            offenders[rel] = hits
    assert not offenders, f"branch on the edge law outside jkrcyl.laws (file: lines): {offenders}"


def test_the_checks_see_planted_violations(tmp_path):
    pkg = tmp_path / "jkrcyl"
    (pkg / "sub").mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "sub" / "__init__.py").write_text("")
    (pkg / "sub" / "one.py").write_text("from . import two\n")
    (pkg / "sub" / "two.py").write_text("def f():\n    from .one import g\n")
    assert _cycle(_graph(tmp_path)) == ["jkrcyl.sub.one", "jkrcyl.sub.two", "jkrcyl.sub.one"]
    (pkg / "sub" / "two.py").write_text("x = 1\n")
    assert _cycle(_graph(tmp_path)) is None
    probe = pkg / "sub" / "three.py"
    probe.write_text("def f(pb):\n    return 1 if pb.alpha_ratio == 0 else 2\n")
    assert _alpha_branches(probe) == [2]
    probe.write_text("def f(pb):\n    return pb.alpha_ratio * 2\n")
    assert _alpha_branches(probe) == []
    probe.write_text("def f(pb):\n    if isinstance(pb.edge, Dugdale):\n        return 1\n")
    assert _alpha_branches(probe, EDGE_NAMES) == [2] and _alpha_branches(probe) == []
    (pkg / "sub" / "four.py").write_text("from .. import sub\nfrom . import one\n")
    g = _graph(tmp_path)
    assert g["jkrcyl.sub.four"] == {"jkrcyl.sub", "jkrcyl.sub.one"}


@pytest.mark.parametrize("name", ["jkrcyl.laws.griffith", "jkrcyl.analysis.path", "jkrcyl.results"])
def test_the_graph_is_read(name):
    """The graph sees the core's imports (a check that reads nothing would pass vacuously)."""
    g = _graph()
    assert name in g and g[name]


def test_the_derivation_never_imports_the_test_reference():
    """derive/ types the prints it compares with; reference/ is the tests' own typing (two independent copies)."""
    offenders = []
    for p in sorted((ROOT / "derive").glob("*.py")):
        names = _imported(p) | {a.name for n in ast.walk(ast.parse(p.read_text())) if isinstance(n, ast.Import)
                                for a in n.names}
        if any(n == "reference" or n.startswith("reference.") for n in names):
            offenders.append(p.name)
    assert not offenders, offenders


ROOT_FINDERS = {"brentq", "brenth", "ridder", "bisect", "newton", "toms748", "root_scalar", "fsolve", "root",
                "minimize_scalar"}


def _forbidden_calls(path):
    """Lines that import a scipy root finder (or minimiser) or call np.gradient: the one root toolkit is
    jkrcyl/numerics/roots.py, and a slope across grid points is not a stability rule."""
    hits = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("scipy"):
            if {a.name for a in node.names} & ROOT_FINDERS:
                hits.append(node.lineno)
        elif isinstance(node, ast.Attribute) and (node.attr in ROOT_FINDERS and isinstance(node.value, ast.Name)
                                                  and node.value.id in {"optimize", "opt"} or node.attr == "gradient"):
            hits.append(node.lineno)
    return hits


def test_one_root_toolkit_and_no_grid_slopes():
    offenders = {}
    for p in _files():
        rel = p.relative_to(ROOT).as_posix()
        if rel != "jkrcyl/numerics/roots.py" and (hits := _forbidden_calls(p)):
            offenders[rel] = hits
    assert not offenders, f"scipy root finder or np.gradient outside jkrcyl/numerics/roots.py: {offenders}"


def test_the_root_check_sees_planted_violations(tmp_path):
    probe = tmp_path / "probe.py"
    for text, expected in (("from scipy.optimize import brentq\n", [1]), ("import numpy as np\ny = np.gradient(x)\n", [2]),
                           ("from scipy import optimize\nx = optimize.minimize_scalar(f)\n", [2]),
                           ("from scipy.optimize import least_squares\n", [])):
        probe.write_text(text)
        assert _forbidden_calls(probe) == expected, text



def _library_modules():
    """The dotted names of the library's modules and packages."""
    out = set()
    for p in _files():
        rel = p.relative_to(ROOT).with_suffix("")
        out.add(".".join(rel.parts[:-1] if rel.name == "__init__" else rel.parts))
    return out


def _deferred_imports(path, package, modules):
    """(line, module) of each import inside a function of the module file path (package: its dotted package;
    modules: the library's): the module it loads (``from a import b``: a.b where that is a module, else a)."""
    out = []
    for f in ast.walk(ast.parse(path.read_text())):
        if not isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef)) or f.name == "__getattr__":
            continue                                     # a module __getattr__ is the lazy-attribute idiom
        for s in ast.walk(f):
            if isinstance(s, ast.Import):
                out += [(s.lineno, a.name) for a in s.names]
            elif isinstance(s, ast.ImportFrom):
                parts = package.split(".")
                base = ".".join(parts[:len(parts) - s.level + 1] + ([s.module] if s.module else [])) \
                    if s.level else s.module
                out += [(s.lineno, f"{base}.{a.name}" if f"{base}.{a.name}" in modules else base) for a in s.names]
    return out


def _loaded_by_import():
    """The modules ``import jkrcyl`` loads (in a fresh interpreter)."""
    code = "import sys, jkrcyl; print('\\n'.join(sys.modules))"
    return set(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                              cwd=ROOT).stdout.split())


def _pointless_deferrals(root, loaded):
    modules = _library_modules() if root == ROOT else set()
    offenders = {}
    for p in _files(root):
        rel = p.relative_to(root).with_suffix("")
        package = ".".join(rel.parts[:-1])
        if hits := [line for line, mod in _deferred_imports(p, package, modules) if mod in loaded]:
            offenders[rel.as_posix()] = hits
    return offenders


def test_imports_inside_functions_defer_something():
    """An import inside a function must defer a module ``import jkrcyl`` does not load already (an optional or
    heavy dependency -- matplotlib, bokeh, dask, scipy.optimize -- or a part loaded on first use, as
    jkrcyl.kinetics); one of a module already loaded only hides the dependency from the reader."""
    offenders = _pointless_deferrals(ROOT, _loaded_by_import())
    assert not offenders, f"imports inside functions of modules that import jkrcyl loads already: {offenders}"


def test_the_deferral_check_sees_a_planted_violation(tmp_path):
    pkg = tmp_path / "jkrcyl"
    pkg.mkdir()
    (pkg / "one.py").write_text("def f():\n    import math\n    import matplotlib\n    from . import two\n")
    assert _pointless_deferrals(tmp_path, {"math", "jkrcyl"}) == {"jkrcyl/one": [2, 4]}
