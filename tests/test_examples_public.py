"""Examples and documentation import only public faces (issue 36, "public faces").

What a user copies from the gallery (examples/**/*.py), the notebooks (examples/*.ipynb),
the narrative pages (the ```python blocks of docs/*.md, the ``.. code-block:: python``
blocks of docs/*.rst) and README.md must name the API the packages promise: no import from
a module path with a private component (``contact._rolling``, ``surfmet.plots._style``;
dunders such as ``__future__`` are fine), and every imported name must exist in the public
module it is imported from (so that a page cannot name what the face does not export). On
main before this change, 15 imports broke the rule (``from contact._exponent import
local_exponent``, ``from surfmet._extract import extract_profile``...).
"""

from __future__ import annotations

import ast
import importlib
import json
import re
import textwrap
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
FENCE = re.compile(r"^\s*```\s*(\w*)")
RST_BLOCK = re.compile(r"^(\s*)\.\. (?:code-block|code|sourcecode)::\s*(?:python|pycon|py)\s*$")


@dataclass(frozen=True)
class Snippet:
    where: str   # "path:line" of the code's first line
    code: str


@dataclass(frozen=True)
class Import:
    where: str
    module: str              # the module path imported (from), or imported as a whole
    names: tuple[str, ...]   # the names taken from it (empty for ``import module``)


def _name(path: Path) -> str:
    return path.relative_to(ROOT).as_posix() if path.is_relative_to(ROOT) else str(path)


def _markdown_blocks(path: Path) -> list[Snippet]:
    lines = path.read_text(encoding="utf-8").splitlines()
    out, i = [], 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        lang, start, body = m.group(1).lower(), i + 2, []
        i += 1
        while i < len(lines) and not lines[i].lstrip().startswith("```"):
            body.append(lines[i])
            i += 1
        i += 1
        if lang in ("python", "py", "pycon"):
            out.append(Snippet(f"{_name(path)}:{start}", "\n".join(body)))
    return out


def _rst_blocks(path: Path) -> list[Snippet]:
    lines = path.read_text(encoding="utf-8").splitlines()
    out = []
    for i, line in enumerate(lines):
        m = RST_BLOCK.match(line)
        if not m:
            continue
        indent, body, j = len(m.group(1)), [], i + 1
        while j < len(lines) and (not lines[j].strip()
                                  or len(lines[j]) - len(lines[j].lstrip()) > indent):
            body.append(lines[j])
            j += 1
        code = textwrap.dedent("\n".join(body))
        code = "\n".join(ln for ln in code.splitlines() if not ln.lstrip().startswith(":"))
        out.append(Snippet(f"{_name(path)}:{i + 2}", code))
    return out


def _notebook_cells(path: Path) -> list[Snippet]:
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    return [Snippet(f"{_name(path)}:cell {k}", "".join(c["source"]))
            for k, c in enumerate(cells) if c.get("cell_type") == "code"]


def _doctest_code(code: str) -> str:
    """A ``>>>`` session as plain code (the prompts and outputs dropped)."""
    if ">>>" not in code:
        return code
    keep = [ln.lstrip()[4:] for ln in code.splitlines()
            if ln.lstrip().startswith((">>> ", "... ")) or ln.strip() in (">>>", "...")]
    return "\n".join(keep)


def sources() -> list[Path]:
    """The files read: the examples' scripts, the pages and README.md, the notebooks."""
    return (sorted((ROOT / "examples").rglob("*.py")) + sorted((ROOT / "docs").glob("*.md"))
            + [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.rst"))
            + sorted((ROOT / "examples").glob("*.ipynb")))


def snippets() -> list[Snippet]:
    found = []
    for path in sources():
        if path.suffix == ".py":
            found.append(Snippet(_name(path),
                                 path.read_text(encoding="utf-8")))
        elif path.suffix == ".md":
            found += _markdown_blocks(path)
        elif path.suffix == ".rst":
            found += _rst_blocks(path)
        else:
            found += _notebook_cells(path)
    return found


def _parse(snippet: Snippet) -> ast.Module:
    code = _doctest_code(snippet.code)
    # IPython magics and shell escapes of a notebook cell are not Python
    code = "\n".join(ln for ln in code.splitlines() if not ln.lstrip().startswith(("%", "!")))
    try:
        return ast.parse(code)
    except SyntaxError as exc:
        raise AssertionError(f"{snippet.where}: not Python ({exc})") from None


def imports(snippet: Snippet) -> list[Import]:
    out = []
    for node in ast.walk(_parse(snippet)):
        if isinstance(node, ast.Import):
            out += [Import(f"{snippet.where}:{node.lineno}", a.name, ()) for a in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            out.append(Import(f"{snippet.where}:{node.lineno}", node.module,
                              tuple(a.name for a in node.names)))
    return out


def private_component(module: str) -> str | None:
    """The first component of a dotted path that is private (``_x``, not a dunder)."""
    for part in module.split("."):
        if part.startswith("_") and not (part.startswith("__") and part.endswith("__")):
            return part
    return None


OURS = ("surfmet", "contact", "profiles", "rotor")


def all_imports() -> list[Import]:
    return [imp for s in snippets() for imp in imports(s)]


def test_the_sources_are_found():
    assert ROOT / "README.md" in sources()
    where = {s.where.split(":")[0] for s in snippets()}
    assert {"examples/paper_2022/contact.py", "examples/howto/plot_roughness.py",
            "docs/quickstart.md", "examples/first_look.ipynb"} <= where
    assert len(all_imports()) > 50


def test_private_component_rule():
    assert private_component("contact._rolling") == "_rolling"
    assert private_component("surfmet.plots._style") == "_style"
    assert private_component("__future__") is None
    assert private_component("surfmet.mechanics.hertz_check") is None


def test_examples_and_docs_import_no_private_module():
    bad = [f"{imp.where}: {imp.module} ({private_component(imp.module)})"
           for imp in all_imports() if private_component(imp.module)]
    assert not bad, "imports from private modules (use the public face):\n" + "\n".join(bad)


def test_every_imported_name_is_on_the_public_face():
    missing = []
    for imp in all_imports():
        if imp.module.split(".")[0] not in OURS or private_component(imp.module):
            continue  # a dependency's import, or already refused above
        try:
            module = importlib.import_module(imp.module)
        except ImportError as exc:
            missing.append(f"{imp.where}: import {imp.module}: {exc}")
            continue
        for name in imp.names:
            if name == "*":
                continue
            if private_component(name):
                missing.append(f"{imp.where}: {imp.module}.{name} is private")
            elif not hasattr(module, name):
                missing.append(f"{imp.where}: {imp.module} has no {name}")
    assert not missing, "\n".join(missing)


@pytest.mark.parametrize("code, expected", [
    ("from contact._rolling import log_loads", ["contact._rolling"]),
    ("import surfmet.cli._common as c", ["surfmet.cli._common"]),
    (">>> from surfmet._extract import extract_profile\n>>> 1\n1", ["surfmet._extract"]),
    ("from __future__ import annotations\nfrom contact import material", []),
])
def test_the_rule_catches_each_spelling(code, expected):
    found = [i.module for i in imports(Snippet("case", code)) if private_component(i.module)]
    assert found == expected


def test_the_pages_code_blocks_are_read(tmp_path):
    md = tmp_path / "page.md"
    md.write_text("text\n```python\nfrom contact._fields import radial_average\n```\n"
                  "```sh\nsurfmet info x.x3p\n```\n", encoding="utf-8")
    rst = tmp_path / "page.rst"
    rst.write_text("Text\n\n.. code-block:: python\n   :caption: c\n\n"
                   "   import surfmet._batch\n\n   x = 1\n\nMore text.\n", encoding="utf-8")
    found = [i.module for b in _markdown_blocks(md) + _rst_blocks(rst) for i in imports(b)]
    assert found == ["contact._fields", "surfmet._batch"]
