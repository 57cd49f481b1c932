"""``surfmet/records/`` is the only place that builds JSON quantities, and the dependency
between ``surfmet.records`` and ``surfmet.mechanics`` runs one way (issue 37, item 5).

A JSON quantity is a call of :func:`surfmet.units.quantity` (under any alias, or as an
attribute of the imported module) or a literal ``{"value": ..., "unit": ...}`` (or
``dict(value=..., unit=...)``). Both are counted by walking the syntax tree of every module
of ``surfmet/`` (outside ``surfmet/records/``), ``contact/`` and ``profiles/``: a local
helper such as ``q = lambda v, u: {"value": v, "unit": u}`` is caught by its literal.
"""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
UNITS = "surfmet.units"

# Not records, by what they are (counted on main: 32 and 1):
# - surfmet/io/: the readers build a scan's *metadata* (the data model: a stylus radius, an
#   instrument's printed Ra, read back by the commands, e.g. the tip radius by ``scales``),
#   in the same {"value", "unit"} form, at the edge where files come in; no result's record.
# - surfmet/units.py: the one definition of ``quantity`` itself (its body's literal).
METADATA_PACKAGE = "surfmet/io/"
DEFINITION = ("surfmet/units.py", "quantity")


def _is_quantity_literal(node: ast.AST) -> bool:
    """A ``{"value": .., "unit": ..}`` display or a ``dict(value=.., unit=..)`` call."""
    if isinstance(node, ast.Dict):
        keys = {k.value for k in node.keys if isinstance(k, ast.Constant)}
        return {"value", "unit"} <= keys
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "dict":
        return {"value", "unit"} <= {k.arg for k in node.keywords}
    return False


def _definition_lines(tree: ast.AST, name: str) -> set[int]:
    """The lines of the function ``name`` defined at the top of ``tree``."""
    return {line for node in getattr(tree, "body", [])
            if isinstance(node, ast.FunctionDef) and node.name == name
            for line in range(node.lineno, (node.end_lineno or node.lineno) + 1)}


def quantity_builders(tree: ast.AST) -> list[int]:
    """The line of every JSON quantity built in ``tree``."""
    names: set[str] = set()      # names bound to surfmet.units.quantity
    modules: set[str] = {UNITS}  # names bound to the surfmet.units module
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module == UNITS:
            names |= {a.asname or a.name for a in node.names if a.name == "quantity"}
        elif isinstance(node, ast.ImportFrom) and node.module == "surfmet":
            modules |= {a.asname or a.name for a in node.names if a.name == "units"}
        elif isinstance(node, ast.Import):
            modules |= {a.asname or a.name for a in node.names if a.name == UNITS}
    lines = []
    for node in ast.walk(tree):
        if _is_quantity_literal(node):
            lines.append(node.lineno)
        elif isinstance(node, ast.Call):
            f = node.func
            if (isinstance(f, ast.Name) and f.id in names) or (
                    isinstance(f, ast.Attribute) and f.attr == "quantity"
                    and ast.unparse(f.value) in modules):
                lines.append(node.lineno)
    return lines


def _modules(*packages: str) -> list[tuple[str, ast.AST]]:
    out = []
    for pkg in packages:
        for path in sorted((ROOT / pkg).rglob("*.py")):
            rel = path.relative_to(ROOT).as_posix()
            out.append((rel, ast.parse(path.read_text(encoding="utf-8"), rel)))
    return out


def test_scanner_counts_every_form():
    """The scanner itself: each way of building a quantity is seen once, reads are not."""
    src = '''
from surfmet.units import quantity as q
import surfmet.units as u
from surfmet import units
a = q(1.0, "m")
b = u.quantity(1.0, "m")
c = units.quantity(2.0, "N")
d = {"value": 1.0, "unit": "m"}
e = dict(value=1.0, unit="m")
f = d["value"], {"value": 1}, x.quantity(3)
'''
    assert len(quantity_builders(ast.parse(src))) == 5


def test_only_records_build_json_quantities():
    """0 JSON quantities built outside surfmet/records/ (the engines, the facades, the CLI
    and the demo included)."""
    found = {}
    for rel, tree in _modules("surfmet", "contact", "profiles"):
        if rel.startswith(("surfmet/records/", METADATA_PACKAGE)):
            continue
        lines = quantity_builders(tree)
        if rel == DEFINITION[0]:
            lines = sorted(set(lines) - _definition_lines(tree, DEFINITION[1]))
        if lines:
            found[rel] = lines
    total = sum(map(len, found.values()))
    assert not found, f"{total} JSON quantities built outside surfmet/records/: {found}"


def _imports(tree: ast.AST, rel: str) -> set[str]:
    """Every module ``tree`` imports, at the top or inside a function, relative ones
    resolved against ``rel``."""
    package = rel.rsplit("/", 1)[0].split("/")
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = package[:len(package) - node.level + 1]
                base = ".".join(parts + ([base] if base else []))
            out.add(base)
            out |= {f"{base}.{a.name}" for a in node.names}
    return out


def test_mechanics_never_imports_records():
    """One direction: surfmet.records may import surfmet.mechanics (it builds the records
    of the facades' results); surfmet.mechanics never imports surfmet.records, not even
    inside a function (the records module's docstring states it)."""
    bad = {}
    for rel, tree in _modules("surfmet/mechanics"):
        hits = sorted(m for m in _imports(tree, rel)
                      if m == "surfmet.records" or m.startswith("surfmet.records."))
        if hits:
            bad[rel] = hits
    assert not bad, f"surfmet.mechanics imports surfmet.records: {bad}"
    import surfmet.records

    assert "surfmet.mechanics never imports" in (surfmet.records.__doc__ or "")
