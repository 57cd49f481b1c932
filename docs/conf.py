"""Sphinx configuration of surfmet's documentation.

Build (from the repository root)::

    python3 -m sphinx -W --keep-going -b html docs docs/_build/html

Warnings are errors: a broken cross-reference to surfmet's, contact's or profiles' own
objects, a page left out of every toctree, a docstring numpydoc cannot parse and a gallery
example that raises all fail the build. The API pages are written here from the packages'
``__all__`` lists (``docs/api/``, not tracked), so a name made public is documented without
editing a page.
"""

from __future__ import annotations

import inspect
import os
import pkgutil
import sys
from importlib import import_module
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(DOCS / "_ext"))
os.environ.setdefault("MPLBACKEND", "Agg")

import surfmet  # noqa: E402

project = "surfmet"
author = "surfmet developers"
copyright = "surfmet developers, MIT licence"
release = surfmet.__version__
version = release

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "numpydoc",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
    "surfmet_xref",  # docs/_ext: a reference to a name that does not exist fails
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
templates_path = ["_templates"]
exclude_patterns = ["_build", "api/_*", "auto_examples/*.ipynb", "auto_examples/*/*.ipynb"]

# -- the narrative pages (docs/*.md) ---------------------------------------------------------
myst_heading_anchors = 4  # docs link to sections by GitHub's slugs (scales.md#contact-from-...)
myst_enable_extensions = ["dollarmath"]

# -- API reference -------------------------------------------------------------------------
autosummary_generate = True
autosummary_imported_members = True
autodoc_typehints = "none"  # numpydoc's Parameters section states the types
autodoc_default_options = {"members": True, "member-order": "bysource"}
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False

# Every reference to one of the project's own objects must resolve (nitpicky); references
# to the outside world (numpy, the standard library, matplotlib) are not checked, as the
# build runs offline without intersphinx inventories.
nitpicky = True
nitpick_ignore_regex = [(r"py:.*", r"^(?!(surfmet|contact|profiles)\b).*")]

# -- gallery -------------------------------------------------------------------------------
sphinx_gallery_conf = {
    "examples_dirs": [str(ROOT / "examples")],
    "gallery_dirs": ["auto_examples"],
    # every example runs at build time and shows its output and figures: the how-tos as
    # they are, the paper's scripts (examples/paper_2022, minutes to an hour each in full)
    # in the reduced form their pages describe, from the command line that
    # docs/_ext/gallery_argv.py gives them (``SCRIPT [OUTDIR] --gallery``)
    "filename_pattern": r"\.py$",
    "ignore_pattern": r"__init__\.py",
    "reset_argv": "gallery_argv.reset_argv",
    "within_subsection_order": "FileNameSortKey",
    "download_all_examples": False,
    "remove_config_comments": True,
    "abort_on_example_error": False,
    "only_warn_on_example_error": False,
    "matplotlib_animations": False,
    "reset_modules": ("matplotlib",),
    "capture_repr": ("_repr_html_", "__repr__"),
    "show_memory": False,
}

# -- HTML ----------------------------------------------------------------------------------
html_theme = "pydata_sphinx_theme"
html_title = f"surfmet {release}"
html_theme_options = {"show_toc_level": 2, "navigation_with_keys": False}
html_static_path: list[str] = []

# -- the API pages, written from __all__ -----------------------------------------------------
#: packages whose public face is their ``__all__`` (one page each, one entry per name)
FACES = {
    "surfmet": "The top level: reading and writing scans, the data model, the errors.",
    "surfmet.io": "Readers and writers, format detection, the format registry.",
    "contact": "The contact-mechanics engine's public face.",
    "profiles": "The 1D engine's public face.",
    "rotor": "The rotor study's engine: its public face.",
}
#: packages whose modules are each a public face (one page per module)
FACADES = {
    "surfmet.mechanics": "One facade per model command, between the command line and "
    ":mod:`contact`.",
}


def _title(text: str) -> str:
    return f"{text}\n{'=' * len(text)}\n"


def _face_page(name: str, blurb: str) -> str:
    module = import_module(name)
    names = sorted(getattr(module, "__all__", []), key=str.lower)
    names = [n for n in names if not n.startswith("_")]
    lines = [
        _title(f"``{name}``"),
        blurb,
        "",
        f".. automodule:: {name}",
        "   :no-members:",
        "",
        f".. currentmodule:: {name}",
        "",
        ".. autosummary::",
        "   :toctree: generated/",
        "",
    ]
    lines += [f"   {n}" for n in names]
    return "\n".join(lines) + "\n"


def _facade_page(name: str, blurb: str) -> str:
    package = import_module(name)
    modules = sorted(
        m.name for m in pkgutil.iter_modules(package.__path__) if not m.name.startswith("_")
    )
    lines = [
        _title(f"``{name}``"),
        blurb,
        "",
        # the package's docstring as text: an automodule here would make the module list
        # below relative to it, which autosummary resolves wrongly for some names
        inspect.getdoc(package) or "",
        "",
        ".. autosummary::",
        "   :toctree: generated/",
        "",
    ]
    lines += [f"   {name}.{m}" for m in modules]
    return "\n".join(lines) + "\n"


def _write_if_changed(path: Path, text: str) -> None:
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")


def write_api_pages(app: object = None) -> None:
    """Write ``docs/api/*.rst`` from the packages' public lists."""
    api = DOCS / "api"
    api.mkdir(exist_ok=True)
    pages = {n: _face_page(n, b) for n, b in FACES.items()}
    pages.update({n: _facade_page(n, b) for n, b in FACADES.items()})
    for name, text in pages.items():
        _write_if_changed(api / f"{name}.rst", text)
    index = [
        _title("API reference"),
        "The public faces of the four packages. ``profiles``, ``contact`` and ``rotor`` take "
        "arrays, tables and SI numbers; ``surfmet`` takes scans and files.",
        "",
        ".. toctree::",
        "   :maxdepth: 1",
        "",
    ] + [f"   {name}" for name in pages]
    _write_if_changed(api / "index.rst", "\n".join(index) + "\n")


write_api_pages()
