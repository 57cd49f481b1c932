"""The rotor study is an engine of its own (issue 37, item 6): a top-level package ``rotor``
beside ``contact`` and ``profiles``, with a public face (``rotor.__all__``) that the command
line and the facades use instead of its modules.

Read from the code's own syntax trees (no import needed), so that a new import of an
internal is caught wherever it hides (inside a function, under TYPE_CHECKING).
"""

from __future__ import annotations

import ast
import json
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _imports(folder: str) -> Iterator[tuple[str, int, str, tuple[str, ...]]]:
    """``(file, line, module, names)`` for every import under ``folder``; ``names`` is
    empty for ``import module``."""
    assert (ROOT / folder).is_dir(), folder
    for path in sorted((ROOT / folder).rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        rel = path.relative_to(ROOT).as_posix()
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                for alias in node.names:
                    yield rel, node.lineno, alias.name, ()
            elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                yield rel, node.lineno, node.module, tuple(a.name for a in node.names)


def _face() -> set[str]:
    """``rotor.__all__``, read in a fresh interpreter."""
    out = subprocess.run([sys.executable, "-c", "import json, rotor; print(json.dumps("
                          "rotor.__all__))"], cwd=ROOT, capture_output=True, text=True,
                         timeout=120)
    assert out.returncode == 0, out.stderr
    return set(json.loads(out.stdout))


def test_rotor_is_a_top_level_package_and_contact_holds_it_no_more():
    assert (ROOT / "rotor" / "__init__.py").is_file()
    assert not (ROOT / "contact" / "rotor").exists()
    for name in ("adequacy", "effect", "lane", "verdict"):
        assert (ROOT / "rotor" / f"{name}_calibration.json").is_file(), name


def test_surfmet_imports_only_the_rotor_face():
    face = _face()
    bad = []
    for folder in ("surfmet", "examples", "benchmarks"):
        for rel, line, module, names in _imports(folder):
            if module.startswith("rotor."):
                bad.append(f"{rel}:{line}: {module}")
            elif module == "rotor":
                bad += [f"{rel}:{line}: rotor.{n} (not in rotor.__all__)"
                        for n in names if n != "*" and n not in face]
    assert not bad, "imports of the rotor's internals:\n" + "\n".join(bad)


def test_the_cli_and_the_rotor_facades_use_the_face():
    # the command and its facades (they imported 17 of the study's internals before)
    users = [p.relative_to(ROOT).as_posix() for p in
             [ROOT / "surfmet" / "cli" / "rotor.py",
              *sorted((ROOT / "surfmet" / "mechanics").glob("*rotor*.py"))]]
    seen = {rel for rel, _, module, _ in _imports("surfmet") if module == "rotor"}
    assert "surfmet/cli/rotor.py" in seen
    assert set(users) & seen, users


def test_rotor_never_imports_surfmet():
    bad = [f"{rel}:{line}: {module}" for rel, line, module, _ in _imports("rotor")
           if module == "surfmet" or module.startswith("surfmet.")]
    assert not bad, bad


def test_contact_never_imports_rotor():
    # neither the package nor a room of contact's own called rotor
    bad = [f"{rel}:{line}: {module}" for rel, line, module, _ in _imports("contact")
           if "rotor" in module.split(".")]
    assert not bad, bad
    # nor lazily: every name of contact's face loads without any rotor module
    code = ("import json, sys, contact; [getattr(contact, n) for n in contact.__all__]; "
            "print(json.dumps(sorted(m for m in sys.modules if 'rotor' in m.split('.'))))")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                         text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    assert json.loads(out.stdout.strip().splitlines()[-1]) == []


_STAR = r"""
import inspect, json, sys
import rotor
light = sorted(m for m in sys.modules if m.startswith("rotor."))
namespace = {}
exec("from rotor import *", namespace)
missing = [n for n in rotor.__all__ if n not in namespace]
homes = {n: getattr(rotor, n).__module__ for n in rotor.__all__
         if inspect.isclass(getattr(rotor, n)) or inspect.isfunction(getattr(rotor, n))}
surfmet = sorted(m for m in sys.modules if m == "surfmet" or m.startswith("surfmet."))
print(json.dumps({"light": light, "missing": missing, "n": len(rotor.__all__),
                  "repeats": len(rotor.__all__) - len(set(rotor.__all__)),
                  "homes": homes, "surfmet": surfmet}))
"""


def test_star_import_is_clean_and_every_face_name_resolves():
    out = subprocess.run([sys.executable, "-c", _STAR], cwd=ROOT, capture_output=True,
                         text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    r = json.loads(out.stdout.strip().splitlines()[-1])
    assert r["light"] == []  # importing the face imports none of its modules
    assert r["missing"] == [] and r["repeats"] == 0 and r["n"] > 0
    # every name is defined in one of the engine's own modules, and loading all of them
    # never pulls in the user layer
    assert all(home.startswith("rotor.") for home in r["homes"].values()), r["homes"]
    assert r["surfmet"] == []


# issue 37, item 5 (the rotor's share): the rotor command and its facades print records, they
# do not build JSON quantities; the records live in surfmet/records/rotor*.py
ROTOR_USERS = ("surfmet/cli/rotor.py", "surfmet/mechanics/_rotor_adequacy.py",
               "surfmet/mechanics/_rotor_argument.py", "surfmet/mechanics/_rotor_sensitivity.py",
               "surfmet/mechanics/rotor_rough_bound.py", "surfmet/mechanics/rotor_verdict.py")


def _quantities(tree: ast.AST) -> list[int]:
    """Lines that build a JSON quantity: a call of ``quantity`` imported from surfmet.units,
    or a ``{"value": .., "unit": ..}`` display."""
    names = {a.asname or a.name for node in ast.walk(tree)
             if isinstance(node, ast.ImportFrom) and node.module == "surfmet.units"
             for a in node.names if a.name == "quantity"}
    lines = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Dict):
            keys = {k.value for k in node.keys if isinstance(k, ast.Constant)}
            if {"value", "unit"} <= keys:
                lines.append(node.lineno)
        elif (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
              and node.func.id in names):
            lines.append(node.lineno)
    return lines


def test_the_rotor_command_and_facades_build_no_json_quantities():
    found = {}
    for rel in ROTOR_USERS:
        path = ROOT / rel
        assert path.is_file(), rel
        lines = _quantities(ast.parse(path.read_text(encoding="utf-8")))
        if lines:
            found[rel] = lines
    assert not found, found
    records = sorted(p.name for p in (ROOT / "surfmet" / "records").glob("_rotor*.py"))
    assert records and all(_quantities(ast.parse((ROOT / "surfmet" / "records" / n)
                                                 .read_text(encoding="utf-8")))
                           for n in records), records
    # and one way: the records read the facades, the facades never import the records
    bad = [f"{rel}:{line}: {module}" for rel, line, module, _ in _imports("surfmet/mechanics")
           if "rotor" in rel and (module == "surfmet.records"
                                  or module.startswith("surfmet.records."))]
    assert not bad, bad


def test_the_type_checkers_view_of_the_face_is_the_face():
    """rotor/__init__.py imports every face name under TYPE_CHECKING (so that the facades'
    annotations such as ``RotorVerdict`` are real types to mypy, not Any through the lazy
    ``__getattr__``): the same names from the same private modules as the face's table."""
    import rotor

    tree = ast.parse((ROOT / "rotor" / "__init__.py").read_text(encoding="utf-8"))
    checked = {}
    for node in ast.walk(tree):
        if (isinstance(node, ast.If) and isinstance(node.test, ast.Name)
                and node.test.id == "TYPE_CHECKING"):
            for imp in node.body:
                assert isinstance(imp, ast.ImportFrom) and imp.module.startswith("rotor._")
                for alias in imp.names:
                    checked[alias.name] = imp.module
    assert checked == rotor._ATTRIBUTES
