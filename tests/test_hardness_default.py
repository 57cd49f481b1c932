"""The default hardness is decided in one place: :func:`contact._material_pair.resolve_pair`
(with :meth:`contact._material_pair.MaterialPair.with_hardness` for the user's value): the
user's hardness, else the softer body's table value (issue 37, item 5). No facade or
engine re-decides it with its own ``pair.hardness if hardness is None else hardness``.
"""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
HOME = "contact/_material_pair.py"
PAIRS = {"pair", "mats", "materials", "pair_"}  # the names a resolved pair goes by


def _is_none_test(node: ast.AST) -> bool:
    """``<name> is None`` somewhere in ``node`` (an ``and`` of tests included)."""
    return any(isinstance(n, ast.Compare) and isinstance(n.left, ast.Name)
               and any(isinstance(op, ast.Is) for op in n.ops)
               and any(isinstance(c, ast.Constant) and c.value is None for c in n.comparators)
               for n in ast.walk(node))


def _pair_hardness(node: ast.AST) -> bool:
    """``pair.hardness`` (or ``mats.hardness``...): a resolved pair's default hardness."""
    return (isinstance(node, ast.Attribute) and node.attr == "hardness"
            and isinstance(node.value, ast.Name) and node.value.id in PAIRS)


def redecisions(tree: ast.AST) -> list[int]:
    """Lines that choose between a given hardness and a pair's default themselves:
    ``h = pair.hardness if h is None else h`` and ``if h is None: h = pair.hardness``."""
    lines = []
    for node in ast.walk(tree):
        if isinstance(node, ast.IfExp) and _is_none_test(node.test) and (
                _pair_hardness(node.body) or _pair_hardness(node.orelse)):
            lines.append(node.lineno)
        elif isinstance(node, ast.If) and _is_none_test(node.test):
            lines += [n.lineno for stmt in node.body for n in ast.walk(stmt)
                      if isinstance(n, ast.Assign) and _pair_hardness(n.value)]
    return lines


def test_the_checker_finds_both_forms():
    src = ("def f(hardness, pair, mats, plastic):\n"
           "    hardness = pair.hardness if hardness is None else hardness\n"
           "    if hardness is None and plastic:\n"
           "        hardness = mats.hardness\n"
           "    h = pair.with_hardness(hardness).hardness\n")
    assert sorted(redecisions(ast.parse(src))) == [2, 4]


def test_one_home_for_the_default_hardness():
    found = {}
    for pkg in ("surfmet", "contact", "profiles"):
        for path in sorted((ROOT / pkg).rglob("*.py")):
            rel = path.relative_to(ROOT).as_posix()
            if rel == HOME:
                continue
            lines = redecisions(ast.parse(path.read_text(encoding="utf-8")))
            if lines:
                found[rel] = lines
    assert not found, f"the default hardness re-decided outside {HOME}: {found}"
