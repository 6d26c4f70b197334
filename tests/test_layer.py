"""Issue 9: one numerics layer.  Only jkrcyl/numerics/ may import the generated kernels, and jkrcyl never
imports the test reference package (reference/: printed formulas and mpmath models)."""
import ast
import math
import pathlib

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
LIBRARY = ROOT / "jkrcyl"
LAYER = LIBRARY / "numerics"

# Modules not yet converted to the layer (issue 9 items 3, 5): none left.
NOT_YET_CONVERTED = set()


def _imports(path, root=ROOT):
    """Absolute names of every module a source file imports (relative imports resolved)."""
    tree = ast.parse(path.read_text(), filename=str(path))
    package = list(path.relative_to(root).with_suffix("").parts[:-1])
    names = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names += [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = package[: len(package) - node.level + 1] if node.level else []
            module = ".".join(base + ([node.module] if node.module else []))
            names.append(module)
            names += [f"{module}.{alias.name}" for alias in node.names]
    return names


def _library_files():
    return sorted(p for p in LIBRARY.rglob("*.py") if "__pycache__" not in p.parts)


def _imports_generated(names):
    return any(n == "jkrcyl.generated" or n.startswith("jkrcyl.generated.") or n == "generated"
               or n.startswith("generated.") for n in names)


def test_only_the_layer_imports_generated():
    offenders = []
    for path in _library_files():
        rel = path.relative_to(ROOT).as_posix()
        if LAYER in path.parents or rel in NOT_YET_CONVERTED:
            continue
        if _imports_generated(_imports(path)):
            offenders.append(rel)
    assert not offenders, f"import jkrcyl.generated only in jkrcyl/numerics/ (the layer): {offenders}"


def test_allow_list_is_current():
    """Every module still allowed to import generated/ exists and still does (else drop it from the list)."""
    for rel in NOT_YET_CONVERTED:
        path = ROOT / rel
        assert not path.exists() or _imports_generated(_imports(path)), f"{rel} converted: remove it"


def test_library_never_imports_the_reference():
    offenders = [p.relative_to(ROOT).as_posix() for p in _library_files()
                 if any(n == "reference" or n.startswith("reference.") for n in _imports(p))]
    assert not offenders, f"reference/ is test reference only, never run-time code: {offenders}"


def test_the_check_sees_a_violation(tmp_path):
    """The AST check itself can fail: a module importing generated relatively is caught."""
    (tmp_path / "jkrcyl" / "sub").mkdir(parents=True)
    bad = tmp_path / "jkrcyl" / "sub" / "probe.py"
    bad.write_text("from ..generated import gap\n")
    assert _imports(bad, tmp_path) == ["jkrcyl.generated", "jkrcyl.generated.gap"]
    bad.write_text("from .. import generated\n")
    assert _imports_generated(_imports(bad, tmp_path))
    bad.write_text("from ..numerics.kernels import star\nimport reference.paper\n")
    assert not _imports_generated(_imports(bad, tmp_path))


# --- the layer's normalisation, against the definitions of section 6 -------------------------------
def test_normalise_theta_inf_and_finite():
    from jkrcyl.model.problem import Problem
    pb = Problem(0.3, math.inf, 1.0)
    assert (pb.inv_theta, pb.m, pb.scale) == (0.0, 0.3, 1.0)           # M is M_R*, P* is P_R* (7.6)
    pb = Problem(0.3, 2.0, 0.5)
    assert pb.inv_theta == 0.5 and pb.m == pytest.approx(0.6) and pb.scale == 2.0


def test_star_matches_contact_state():
    """P* and delta/Delta of the normalised kernels equal the dimensional state divided by its scales."""
    import jkrcyl
    from jkrcyl.model.closed_form import ClosedForm
    mats = jkrcyl.Materials(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0)
    c = jkrcyl.Contact(R=1.5, Delta=0.01, w=1e-4, materials=mats)
    a = np.array([0.05, 0.3, 0.8, 2.0])
    s = c.state(a)
    st = ClosedForm(c.problem).states(a)
    np.testing.assert_allclose(st.p / c.problem.scale, s.P / c.load_scale, rtol=1e-12)
    np.testing.assert_allclose(st.dn, s.delta / c.Delta, rtol=1e-12)
    np.testing.assert_allclose(st.h, s.h_pi / c.Delta, rtol=1e-12)


def test_roots_toolkit_python_and_numba_agree():
    """The same Brent source, plain Python and compiled, reaches adjacent doubles of sqrt(2)."""
    from numba import njit

    from jkrcyl.numerics import roots

    @njit
    def f(x, args):
        return x * x - args[0]

    py = roots.brent(lambda x, args: x * x - args[0], 0.0, 2.0, (2.0,))
    nb = roots.brent_solver(f)(0.0, 2.0, -2.0, 2.0, (2.0,))
    assert py == nb and abs(py - math.sqrt(2)) <= 2 * np.spacing(math.sqrt(2))
    assert roots.roots_on_grid(np.array([-1.0, 1.0, -1.0]), np.array([0.0, 1.0, 2.0]),
                               lambda lo, hi, flo, fhi: 0.5 * (lo + hi)) == [(0.5, 1), (1.5, -1)]


def test_brent_rejects_a_sign_change_through_a_pole():
    """The toolkit's bracketing: 1/x changes sign across x = 0 without a root; |f| grows as the bracket shrinks,
    so brent_or_pole (and the numba pair) report None; a genuine root is kept."""
    from numba import njit

    from jkrcyl.numerics import roots

    @njit
    def inv(x, args):
        return 1.0 / (x - args[0])

    pole = math.pi / 10
    assert roots.brent_or_pole(lambda x, a: 1.0 / (x - a[0]), -1.0, 2.0, (pole,)) is None
    assert roots.brent_or_pole_nb(roots.brent_solver(inv), inv, -1.0, 2.0, -1 / (1 + pole), 1 / (2 - pole),
                                  (pole,)) is None
    assert roots.brent_or_pole(lambda x, a: x - a[0], -1.0, 2.0, (0.3,)) == pytest.approx(0.3, abs=1e-15)
    assert roots.roots_on_grid(np.array([1.0, -1.0]), np.array([0.0, 1.0]), lambda *b: None) == []
