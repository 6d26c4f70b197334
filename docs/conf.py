"""Sphinx configuration of the jkrcyl documentation (``make docs``: -W, every gallery example executed)."""
import os
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))            # the source tree (the package is installed editable by make docs too)
os.environ.setdefault("MPLBACKEND", "Agg")

import jkrcyl  # noqa: E402

project = "jkrcyl"
author = "the jkrcyl developers"
copyright = "the jkrcyl developers, MIT licence"
release = version = jkrcyl.__version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx-mathjax-offline",      # MathJax 3 copied into the site (mathjax_path): the docs render offline
    "sphinx.ext.viewcode",
    "numpydoc",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "gallery/README.rst", "**/GALLERY_HEADER.rst"]
suppress_warnings = ["myst.header"]      # generated/DERIVATION.md starts at '#' inside a page that has its own title

# --- MyST: Markdown pages, $...$ and $$...$$ math (generated/DERIVATION.md) -------------------------------------
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist"]
myst_heading_anchors = 3

# --- API reference: autodoc + numpydoc ---------------------------------------------------------------------------
autosummary_generate = True
autodoc_default_options = {"members": True}
autodoc_typehints = "none"
autodoc_member_order = "bysource"
numpydoc_show_class_members = False      # members are documented by autodoc below each class
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False

# --- the gallery: executed at every build (each example <= 30 s; the set within the 5-minute budget) -------------
sphinx_gallery_conf = {
    "examples_dirs": "gallery",
    "gallery_dirs": "gallery_auto",
    "filename_pattern": r"/plot_",
    "within_subsection_order": "FileNameSortKey",
    "download_all_examples": False,
    "remove_config_comments": True,
    "matplotlib_animations": False,
    "image_scrapers": ("matplotlib",),
    "abort_on_example_error": True,
    "show_memory": False,
    "min_reported_time": 1,
}

# --- HTML ----------------------------------------------------------------------------------------------------------
html_theme = "pydata_sphinx_theme"
html_title = f"jkrcyl {release}"
html_static_path = []
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
}
html_show_sourcelink = False


# --- plain-text docstrings and the generated report, read as they are -------------------------------------------
SUBSTITUTION = re.compile(r"(?<![\\`|])\|(?=[^\s|`])([^|`\n]*?[^\s|`\\])\|(?![`|])")
REFERENCE = re.compile(r"(?<=[A-Za-z0-9])_(?=[\s,.;:)\]]|$)")


def _plain_text(app, what, name, obj, options, lines):
    """Docstrings are plain text with the paper's notation: absolute values |x| (|alpha*/beta*|, |P*|) and names
    ending in an underscore (lambda_), which reStructuredText reads as a substitution and a hyperlink reference.
    Escape both."""
    lines[:] = [REFERENCE.sub(r"\\_", SUBSTITUTION.sub(r"\\|\1\\|", line)) for line in lines]


def _derivation_text(app, relative_path, parent_docname, content):
    """generated/DERIVATION.md writes an integrand followed by '(...)' ('[sum_n w_n cos(n psi)](...)'), which
    Markdown reads as a link: escape the parenthesis."""
    if pathlib.Path(relative_path).name == "DERIVATION.md":
        content[0] = content[0].replace("](", "]\\(")


def setup(app):
    app.connect("autodoc-process-docstring", _plain_text)
    app.connect("include-read", _derivation_text)
