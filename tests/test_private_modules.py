"""Public faces, private modules (scikit-image's split; docs/architecture.md, "Public and
private modules").

A package of ``contact``, ``profiles`` or ``surfmet`` (a directory with ``__init__.py``) is
public; a module in it is private (``_name.py``) unless its package names it as a module:
a room of its lazy face (the table passed to ``attach``: ``SUBMODULES``, ``SUBPACKAGES``,
``__all__``) or an entry of a plug-in table (``SUBCOMMANDS``, ``FORMAT_MODULES``), whose
entries are module names by design. Dunder modules (``__init__``, ``__main__``) keep their
names. Every table that keeps a module public is named, with its reason, in
docs/architecture.md. On the tree before issue 36, 161 modules broke the rule
(``contact/bem/iteration.py``, ``profiles/filters.py``, ``surfmet/model.py``...).
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
ROOTS = ("contact", "profiles", "surfmet")
PLUGIN_TABLES = ("SUBCOMMANDS", "FORMAT_MODULES")
ARCHITECTURE = ROOT / "docs" / "architecture.md"


def _strings(node: ast.AST) -> list[str]:
    if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
        return [e.value for e in node.elts
                if isinstance(e, ast.Constant) and isinstance(e.value, str)]
    return []


def _module_tables(init: Path) -> dict[str, str]:
    """``{module name: the table of the package's __init__ that names it}``."""
    tree = ast.parse(init.read_text(encoding="utf-8"))
    assigned: dict[str, list[str]] = {}
    for node in tree.body:
        if isinstance(node, ast.Assign):
            for target in node.targets:
                if isinstance(target, ast.Name):
                    assigned[target.id] = _strings(node.value)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            assigned[node.target.id] = _strings(node.value) if node.value else []
    tables: dict[str, str] = {}
    for node in ast.walk(tree):
        if (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
                and node.func.id == "attach" and len(node.args) >= 2
                and isinstance(node.args[1], ast.Name)):
            for name in assigned.get(node.args[1].id, []):
                tables.setdefault(name, node.args[1].id)
    for table in PLUGIN_TABLES:
        for name in assigned.get(table, []):
            tables.setdefault(name, table)
    return tables


def _packages() -> list[Path]:
    found = []
    for top in ROOTS:
        for init in sorted((ROOT / top).rglob("__init__.py")):
            rel = init.parent.relative_to(ROOT)
            if all((ROOT.joinpath(*rel.parts[:i]) / "__init__.py").exists()
                   for i in range(1, len(rel.parts) + 1)):
                found.append(init.parent)
    return found


def _survey() -> tuple[list[str], dict[str, set[str]]]:
    """``(modules breaking the rule, {"package.TABLE": the modules it keeps public})``."""
    offenders: list[str] = []
    keeping: dict[str, set[str]] = {}
    for folder in _packages():
        package = ".".join(folder.relative_to(ROOT).parts)
        tables = _module_tables(folder / "__init__.py")
        for path in sorted(folder.glob("*.py")):
            name = path.stem
            if name.startswith("_"):  # private, or a dunder module
                continue
            if name in tables:
                keeping.setdefault(f"{package}.{tables[name]}", set()).add(name)
            else:
                offenders.append(path.relative_to(ROOT).as_posix())
    return offenders, keeping


def test_every_module_is_private_unless_its_package_names_it():
    offenders, _ = _survey()
    assert not offenders, (f"{len(offenders)} public modules that no table of their "
                           f"package names (make them private: _name.py): {offenders}")


def test_the_public_tables_and_their_reasons_are_in_the_architecture_page():
    _, keeping = _survey()
    text = ARCHITECTURE.read_text(encoding="utf-8")
    match = re.search(r"^## Public and private modules$(.*?)(?=^## )", text, re.M | re.S)
    assert match, "docs/architecture.md has no section 'Public and private modules'"
    section = match.group(1)
    missing = sorted(t for t in keeping if f"`{t}`" not in section)
    assert keeping and not missing, f"tables keeping modules public, not explained: {missing}"
    # and the section names no table that keeps nothing public any more
    roots = "|".join(ROOTS)
    named = set(re.findall(rf"`((?:{roots})(?:\.\w+)*\.(?:__all__|[A-Z_]+))`", section))
    assert named <= set(keeping), sorted(named - set(keeping))


def test_no_module_has_a_public_twin():
    """``x.py`` beside ``_x.py`` would be a rename half done (a merge that added the old
    name back): one of them is dead or shadowed."""
    twins = [p.relative_to(ROOT).as_posix() for folder in _packages()
             for p in sorted(folder.glob("_*.py"))
             if not p.stem.startswith("__") and p.with_name(p.name[1:]).exists()]
    assert not twins, twins
