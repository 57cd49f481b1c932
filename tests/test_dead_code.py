"""No dead functions: every function and method of the engines and of surfmet is used.

The scan (an AST walk, names matched as identifiers):

- **defined**: every ``def`` in ``contact/``, ``profiles/``, ``surfmet/`` (and ``rotor/``
  once the rotor is an engine of its own), at any depth, and every module-level callable
  bound from a factory of the same module (``force = _argtype(units.parse_force, ...)``);
- **used**: a name, an attribute, an imported name or an identifier-like string (a numba
  kernel or a subcommand looked up by name) anywhere in the packages outside the function's
  own body and outside ``__all__``, in tests, benchmarks and examples, or a word of the docs.

A function none of these uses is **dead**. A function the package, the benchmarks, the
examples and the docs never use but the tests do is **test-only**: kept alive by its own
test. That is allowed only for the public API (a name in some ``__all__``, or a public
method of a class in one) and for the entries of ``TEST_ONLY``, each with its reason.

Not scanned: dunder methods (Python calls them), functions registered by a decorator call
(``@register_reader(...)``: the registry holds them), IPython's ``_repr_*_`` hooks. A name
shared by two functions keeps both alive; the scan sees names, not call graphs.
"""

from __future__ import annotations

import ast
import re
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("contact", "profiles", "surfmet", "rotor")
DOCS = ("docs", "README.md", "CHANGELOG.md", "DEVELOPERS.md", "pyproject.toml")
_IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_HOOK = re.compile(r"_repr_[a-z]+_")

# Internal functions that only the tests call, each kept for a reason. "module:qualname".
TEST_ONLY = {
    "contact.adhesion.ball:edge_radius":
        "the validation's sub-pixel contact radius (tests/maugis_sphere.py reads Maugis' "
        "curve with it; the module docstring documents it)",
    "contact.adhesion.line:jkr_line_load":
        "JKR's closed form for the cylinder, the line solver's truth beside "
        "jkr_line_pull_off, which the package uses",
    "contact.halfspace.pair:HalfSpacePair.self_normal":
        "the coupled operator's self-influence, the operator protocol's third member "
        "(issue 37 item 1); tested against Convolution.self_influence",
    "contact.roughcontact._greenwood_tripp:asperity_mean_pressure":
        "one asperity's mean pressure under the elastic-plastic law, the check that the "
        "CEB and cap laws bound it by K·H (tests/test_greenwood_tripp.py)",
    "contact.viscoelastic._traction3d:rolling_sphere_tractions":
        "the 3D viscoelastic tractions of a rolling ball in one call (normal solve, then "
        "tractions), the engine's entry that the traction tests validate",
    "surfmet.areal._material_ratio:inverse_material_ratio":
        "Smc(mr), an ISO 25178-2 functional parameter the module's table names",
}


@dataclass(frozen=True)
class Definition:
    module: str
    qualname: str
    name: str
    path: Path
    line: int
    public: bool
    own: Counter  # the names its own body uses (recursion is no use from outside)

    @property
    def key(self) -> str:
        return f"{self.module}:{self.qualname}"

    def where(self) -> str:
        return f"{self.path}:{self.line} {self.qualname}"


def _uses(tree: ast.AST) -> Counter:
    """Names, attributes, imported names and identifier-like strings in ``tree``."""
    out: Counter = Counter()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            # a binding is no use: ``force = _argtype(...)`` must not keep ``force`` alive
            out[node.id] += not isinstance(node.ctx, ast.Store)
        elif isinstance(node, ast.Attribute):
            out[node.attr] += 1
        elif isinstance(node, ast.alias):
            out[node.name.rsplit(".", 1)[-1]] += 1
        elif isinstance(node, ast.Constant) and isinstance(node.value, str):
            if re.fullmatch(r"[A-Za-z_][\w.:]*", node.value):  # getattr(mod, "kernel")
                out.update(re.split(r"[.:]", node.value))
    return out


def _strip_all(tree: ast.Module) -> set[str]:
    """The module's ``__all__`` names; its strings are blanked so they count as no use."""
    names: set[str] = set()
    for node in tree.body:
        targets = node.targets if isinstance(node, ast.Assign) else (
            [node.target] if isinstance(node, ast.AnnAssign) else [])
        if any(isinstance(t, ast.Name) and t.id == "__all__" for t in targets):
            try:
                names |= set(ast.literal_eval(node.value))
            except ValueError:
                pass
            node.value = ast.Constant(None)
    return names


def _registered(func: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    """Decorated by a registration call (``@register_reader(...)``, ``@register(...)``)."""
    for deco in func.decorator_list:
        target = deco.func if isinstance(deco, ast.Call) else deco
        name = target.attr if isinstance(target, ast.Attribute) else getattr(target, "id", "")
        if name.startswith("register"):
            return True
    return False


def _definitions(tree: ast.Module, module: str, path: Path) -> list[tuple]:
    local_funcs = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
    found: list[tuple] = []

    def walk(node: ast.AST, prefix: str, cls: str | None) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
                name = child.name
                skip = (name.startswith("__") and name.endswith("__")) or _registered(child) \
                    or _HOOK.fullmatch(name)
                if not skip:
                    found.append((f"{prefix}{name}", name, child.lineno, cls, _uses(child)))
                walk(child, f"{prefix}{name}.", cls)
            elif isinstance(child, ast.ClassDef):
                walk(child, f"{prefix}{child.name}.", child.name)

    walk(tree, "", None)
    # Module-level callables a local factory builds: argument types, value-list parsers.
    for node in tree.body:
        if (isinstance(node, ast.Assign) and len(node.targets) == 1
                and isinstance(node.targets[0], ast.Name) and isinstance(node.value, ast.Call)
                and isinstance(node.value.func, ast.Name) and node.value.func.id in local_funcs):
            name = node.targets[0].id
            found.append((name, name, node.lineno, None, Counter()))
    return found


def _py_files(base: Path) -> list[Path]:
    return sorted(p for p in base.rglob("*.py") if "_build" not in p.parts) if base.exists() else []


def scan(root: Path = ROOT, packages: tuple[str, ...] = PACKAGES,
         ) -> tuple[list[Definition], dict[str, Counter]]:
    """Every definition of ``packages`` under ``root`` and the uses of names, by place."""
    uses = {"package": Counter(), "tests": Counter(), "other": Counter()}
    raw: list[tuple] = []
    public: set[str] = set()
    for pkg in packages:
        for path in _py_files(root / pkg):
            tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
            public |= _strip_all(tree)
            parts = path.relative_to(root).with_suffix("").parts
            module = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
            raw += [(module, path.relative_to(root), d) for d in _definitions(tree, module, path)]
            uses["package"].update(_uses(tree))
    for path in _py_files(root / "tests"):
        uses["tests"].update(_uses(ast.parse(path.read_text(encoding="utf-8"))))
    for base in ("benchmarks", "examples"):
        for path in _py_files(root / base):
            uses["other"].update(_uses(ast.parse(path.read_text(encoding="utf-8"))))
    texts = sorted((root / "examples").rglob("*.ipynb")) if (root / "examples").exists() else []
    for name in DOCS:
        base = root / name
        texts += [base] if base.is_file() else [
            p for p in base.rglob("*") if p.is_file() and "_build" not in p.parts
            and p.suffix in (".md", ".rst", ".py", ".txt", ".ipynb")]
    for path in texts:
        uses["other"].update(_IDENT.findall(path.read_text(encoding="utf-8", errors="replace")))
    defs = []
    for module, path, (qualname, name, line, cls, own) in raw:
        owner = cls if cls is not None else name
        defs.append(Definition(module, qualname, name, path, line,
                               owner in public and not name.startswith("_"), own))
    return defs, uses


def classify(defs: list[Definition], uses: dict[str, Counter]) -> dict[str, list[Definition]]:
    """``dead``: used nowhere; ``test_only``: used by the tests alone."""
    out: dict[str, list[Definition]] = {"dead": [], "test_only": []}
    for d in defs:
        outside = uses["package"][d.name] - d.own[d.name] + uses["other"][d.name]
        if outside > 0:
            continue
        out["dead" if uses["tests"][d.name] == 0 else "test_only"].append(d)
    return out


@pytest.fixture(scope="module")
def found() -> dict[str, list[Definition]]:
    return classify(*scan())


def test_no_function_is_dead(found):
    # main had six: hertzcheck.summary_lines, tangential.steady.rolling_residual,
    # CreepSeries.glassy_only, StandardLinearSolid.fg, the CLI's length_range argument type,
    # and roughness_many (public API nothing exercised; tested below, so kept).
    dead = [d.where() for d in found["dead"]]
    assert not dead, "functions nothing uses:\n" + "\n".join(dead)


def test_internal_functions_are_not_kept_alive_by_their_tests_alone(found):
    # main had two: the CLI's force_range argument type (with units.parse_force_range behind
    # it; every command takes --loads through cli/_values.loads) and sweep.done_keys (a copy
    # of what RowWriter(resume=True).done answers for --resume).
    stray = [d.where() for d in found["test_only"] if not d.public and d.key not in TEST_ONLY]
    assert not stray, ("internal functions only the tests call (use them, remove them, or "
                       "give a reason in TEST_ONLY):\n" + "\n".join(stray))


def test_every_test_only_entry_is_still_one(found):
    # A reason that no longer applies is removed, so the list stays the truth.
    current = {d.key for d in found["test_only"]}
    stale = sorted(set(TEST_ONLY) - current)
    assert not stale, f"TEST_ONLY entries that are used now, or gone: {stale}"


def test_the_scan_sees_a_planted_dead_function(tmp_path):
    # The scan itself against a package whose answer is known.
    pkg = tmp_path / "pkg"
    pkg.mkdir()
    (pkg / "__init__.py").write_text('__all__ = ["api", "unused_api", "Thing"]\n')
    (pkg / "core.py").write_text(
        "import numba\n\n"
        "def _factory(f):\n    return f\n\n"
        "def api():\n    return _helper() + getattr(numba, 'kernel_by_name')\n\n"
        "def unused_api():\n    return 1\n\n"
        "def _helper():\n    return 1\n\n"
        "def _recursive(n):\n    return _recursive(n - 1) if n else 0\n\n"
        "def kernel_by_name():\n    return 2\n\n"
        "def _tested_only():\n    return 3\n\n"
        "bound = _factory(len)\n\n"
        "class Thing:\n"
        "    def __len__(self):\n        return 0\n\n"
        "    @property\n    def size(self):\n        return 0\n\n"
        "    def _repr_html_(self):\n        return ''\n")
    (tmp_path / "tests").mkdir()
    (tmp_path / "tests" / "test_x.py").write_text(
        "from pkg.core import _tested_only, api\n\ndef test():\n    api(); _tested_only()\n")
    result = classify(*scan(tmp_path, ("pkg",)))
    assert sorted(d.qualname for d in result["dead"]) == [
        "Thing.size", "_recursive", "bound", "unused_api"]
    assert sorted((d.qualname, d.public) for d in result["test_only"]) == [
        ("_tested_only", False), ("api", True)]


def test_roughness_many_records_a_failed_file_and_goes_on(tmp_path):
    # Public API (surfmet.roughness.__all__) that nothing exercised: it must do what its
    # module says, one result per file, a failed file recorded in its place.
    from surfmet.data import path
    from surfmet.roughness import roughness_file, roughness_many

    good = str(path("paper_plate.x3p"))
    bad = tmp_path / "broken.x3p"
    bad.write_bytes(b"PK\x03\x04 not a zip")
    rows = roughness_many([good, bad, good])
    assert [r["status"] for r in rows] == ["ok", "error", "ok"]
    assert rows[0] == rows[2] == roughness_file(good)
    assert rows[1]["file"] == str(bad) and rows[1]["error"]
