"""The documentation site (docs/): what `make test` can check without building it (`make docs` builds it with -W
and runs every gallery example; CI runs both).

* (every Python block of the getting-started page and of the user guide runs, and the numbers the text states
  are what the library returns: tests/test_guide_pages.py)
* every command line of the guide's sh blocks is a ``jkrcyl`` command that runs (exit status 0, no traceback; the
  README's own lines are run by tests/test_readme.py, the others here) or a make target in :data:`MAKE_TARGETS`;
* (the doctests of the public API's docstrings run: tests/test_doctests.py)
* the API reference names every public class and function (a new one cannot be left out), and every gallery
  image or page the text refers to belongs to an example that exists;
* every gallery example is a script with a title (sphinx-gallery's format) that compiles.
"""
import doctest
import importlib
import inspect
import pathlib
import re
import shlex

import pytest
from cli_run import run

ROOT = pathlib.Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
PAGES = [DOCS / "getting-started.md"] + sorted((DOCS / "guide").glob("*.md"))
BLOCK = re.compile(r"^```(\w*)\n(.*?)^```", re.S | re.M)
MAKE_TARGETS = {"make derive", "make test", "make explore", "make docs", "make figures", "make atlas",
                "make test-slow", "make test-boundscheck"}
LONG_RUNNING = {"jkrcyl explore"}          # a server: tests/test_explore.py runs it


def _blocks(page, lang):
    return [m.group(2) for m in BLOCK.finditer(page.read_text()) if m.group(1) == lang]


# --- the guide's command lines (its Python blocks and numbers: tests/test_guide_pages.py) ---------------------
def _sh_lines():
    out = []
    for page in PAGES:
        for text in _blocks(page, "sh"):
            for line in text.replace("\\\n", " ").splitlines():
                line = line.split(" #", 1)[0].strip()
                if line and not line.startswith("#"):
                    out.append(line)
    return out


def test_sh_lines_are_commands_or_make_targets():
    lines = _sh_lines()
    assert sum(line.startswith("jkrcyl ") for line in lines) >= 5
    for line in lines:
        assert line.startswith("jkrcyl ") or line in MAKE_TARGETS, line


def _readme_lines():
    """The README's command lines (tests/test_readme.py runs them), with the prefix the guide leaves out."""
    readme = ROOT / "README.md"
    return {line.split(" #", 1)[0].strip().replace(".venv/bin/jkrcyl ", "jkrcyl ", 1)
            for text in _blocks(readme, "sh") for line in text.replace("\\\n", " ").splitlines()}


def test_most_sh_lines_are_the_readme_ones():
    """The guide shows the README's commands (run there): the ones below run only what is new here."""
    lines = [x for x in _sh_lines() if x.startswith("jkrcyl ")]
    assert sum(x in _readme_lines() for x in lines) >= 5


@pytest.mark.parametrize("line", sorted({x for x in _sh_lines() if x.startswith("jkrcyl ") and x not in LONG_RUNNING
                                         and x not in _readme_lines()}))
def test_sh_command_runs(line, tmp_path):
    words = shlex.split(line)[1:]
    target = None
    if ">" in words:                      # stdout into a file, as the shell would
        i = words.index(">")
        words, target = words[:i], words[i + 1:]
        assert len(target) == 1, line
    assert not any(w in ("|", "<", ">", ">>", "&&", ";") for w in words), line
    r = run(*words, cwd=tmp_path)               # jkrcyl.cli.main in this process (tests/cli_run.py)
    assert r.returncode == 0 and "Traceback" not in r.stderr, (line, r.stderr[-2000:])
    assert r.stdout.strip(), line
    for flag in ("--plot", "--csv", "--figure"):
        if flag in words:
            assert (tmp_path / words[words.index(flag) + 1]).stat().st_size > 100, (line, flag)


# --- docstrings -------------------------------------------------------------------------------------------------
def test_the_explorer_examples_are_collected():
    """The runner above sees docstring examples (it would pass vacuously on a module it cannot read)."""
    import jkrcyl.explore.model as model
    tests = [t for t in doctest.DocTestFinder().find(model) if t.examples]
    assert len(tests) >= 2


# --- the API reference and the links ----------------------------------------------------------------------------
def _documented():
    """The objects docs/api/*.rst names (automodule :members: lists expanded) and the text itself."""
    text = "\n".join(p.read_text() for p in (DOCS / "api").glob("*.rst"))
    names = set(re.findall(r"^\.\. auto(?:class|function|data|module):: ([\w.]+)", text, re.M))
    for m in re.finditer(r"^\.\. automodule:: ([\w.]+)\n   :members: ([\w, \n]+?)\n(?:\n|$)", text, re.M):
        names |= {f"{m.group(1)}.{n.strip()}" for n in m.group(2).replace("\n", " ").split(",")}
    return names, text


@pytest.mark.parametrize("module, extra", [("jkrcyl", ()), ("jkrcyl.laws", ()), ("jkrcyl.results", ()),
                                           ("jkrcyl.explore", ()), ("jkrcyl.kinetics", ()),
                                           ("jkrcyl.plotting.rate", ("sweep_figure", "loops_figure", "width_figure",
                                                                     "save", "parameters_text")),
                                           ("jkrcyl.fit", ()), ("jkrcyl.plotting", ("plot_cycle",)),
                                           ("jkrcyl.atlas", ("classify", "default_grid", "draw"))])
def test_api_reference_names_every_public_object(module, extra):
    names, text = _documented()
    mod = importlib.import_module(module)
    public = [n for n in getattr(mod, "__all__", []) if callable(getattr(mod, n, None)) and
              not isinstance(getattr(mod, n), type(mod))] + list(extra)
    if module == "jkrcyl.plotting":           # figure helpers of the paper's figures are documented as a registry
        public = [n for n in public if n in ("plot_cycle", "cycle_figure", "confined_figure", "draw_confined",
                                             "draw_all", "write_csv", "FigureSpec")]
    missing = [n for n in public if not re.search(rf"\.\. auto\w+:: (?:{re.escape(module)}\.)?{n}\b", text)
               and f"{module}.{n}" not in names]
    assert not missing, f"{module}: not in docs/api/*.rst: {missing}"


def test_referenced_gallery_examples_exist():
    text = "\n".join(p.read_text() for p in DOCS.rglob("*.md") if "_build" not in p.parts)
    refs = set(re.findall(r"sphx_glr_(plot_\w+?)_\d{3}\.png", text)) | set(re.findall(r"gallery_auto/(plot_\w+)", text))
    assert refs
    for name in refs:
        assert (DOCS / "gallery" / f"{name}.py").exists(), name
    for image in re.findall(r"```\{image\} \.\./([\w./]+)", text):
        assert (DOCS / image).exists(), image


@pytest.mark.parametrize("example", sorted((DOCS / "gallery").glob("plot_*.py")), ids=lambda p: p.name)
def test_gallery_example_has_a_title_and_compiles(example):
    text = example.read_text()
    compile(text, str(example), "exec")
    title = re.match(r'"""\n(.+)\n(=+)\n', text)
    assert title and len(title.group(2)) >= len(title.group(1)), f"{example.name}: no sphinx-gallery title"


# --- numpydoc sections of the public functions -----------------------------------------------------------------
NUMPYDOC_APIS = [("jkrcyl.equilibria", None), ("jkrcyl.units", None), ("jkrcyl", "Contact")]


def _public_callables(module, cls):
    mod = importlib.import_module(module)
    if cls is not None:
        owner = getattr(mod, cls)
        return [(f"{cls}.{n}", getattr(owner, n)) for n in dir(owner)
                if not n.startswith("_") and inspect.isfunction(getattr(owner, n))]
    return [(n, getattr(mod, n)) for n in getattr(mod, "__all__", []) if inspect.isfunction(getattr(mod, n))]


@pytest.mark.parametrize("module, cls", NUMPYDOC_APIS)
def test_public_functions_have_numpydoc_sections(module, cls):
    """Every public function of these APIs says what it returns and shows an example (numpydoc sections), and
    names its parameters where it has any."""
    faults = []
    for name, f in _public_callables(module, cls):
        doc = inspect.getdoc(f) or ""
        needed = ["Returns", "Examples"] + (["Parameters"] if len(inspect.signature(f).parameters) > (cls is not None)
                                            else [])
        faults += [f"{name}: {s}" for s in needed if not re.search(rf"^{s}\n-+$", doc, re.M)]
    assert not faults, faults
