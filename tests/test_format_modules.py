"""The format list: every name in ``surfmet.io.FORMAT_MODULES`` is a module that registers a
format, and a misspelt or missing name fails loudly instead of being skipped."""

import importlib

import pytest

import surfmet.io
from surfmet.io import FORMAT_MODULES, formats

# Modules that register only a writer for a format another module reads.
WRITER_ONLY = {"x3p_writer": "x3p"}


def _registered_by(module: str) -> list:
    full = f"surfmet.io.{module}"
    return [
        spec for spec in formats().values()
        if getattr(spec.decode, "__module__", None) == full
        or getattr(spec.encode, "__module__", None) == full
    ]


@pytest.mark.parametrize("module", FORMAT_MODULES)
def test_every_listed_module_registers_a_format_with_a_magic_check(module):
    importlib.import_module(f"surfmet.io.{module}")
    specs = _registered_by(module)
    assert specs, f"surfmet.io.{module} registers no format"
    if module in WRITER_ONLY:
        assert [s.name for s in specs] == [WRITER_ONLY[module]]
        assert specs[0].encode.__module__ == f"surfmet.io.{module}"
        return
    for spec in specs:
        # A reader with no content check is found by extension only: a renamed file is lost.
        assert spec.magic is not None, f"{spec.name} ({module}) has no magic-byte check"
        assert spec.magic(b"") is False  # cheap and never raises, even on nothing


def test_the_list_names_every_format_module_in_the_package():
    # The other direction: a reader written but left out of the list is never registered.
    from pathlib import Path

    on_disk = {
        p.stem for p in Path(surfmet.io.__file__).parent.glob("*.py")
        if not p.stem.startswith("_")
    }
    infrastructure = {"registry", "writing", "sources", "calibration"}
    assert on_disk - infrastructure == set(FORMAT_MODULES)


@pytest.mark.parametrize("typo", ["x3pp", "mitutoyo_", "netCDF"])
def test_a_misspelt_entry_fails_loudly(monkeypatch, typo):
    # main skipped a name whose module did not exist, so the format vanished in silence.
    monkeypatch.setattr(surfmet.io, "FORMAT_MODULES", (*FORMAT_MODULES, typo))
    with pytest.raises(ModuleNotFoundError, match=rf"FORMAT_MODULES names '{typo}'.*misspelt"):
        formats()
    with pytest.raises(ModuleNotFoundError, match=typo):
        surfmet.io.detect_format(b"no format at all", "scan.unknown")


def test_a_module_that_exists_but_imports_something_missing_is_not_renamed(monkeypatch, tmp_path):
    # The loud error names the list only when the listed module itself is absent.
    (tmp_path / "_drift_broken_fmt.py").write_text("import _no_such_dependency_anywhere\n")
    monkeypatch.setattr(surfmet.io, "__path__", [*surfmet.io.__path__, str(tmp_path)])
    monkeypatch.setattr(surfmet.io, "FORMAT_MODULES", (*FORMAT_MODULES, "_drift_broken_fmt"))
    with pytest.raises(ModuleNotFoundError, match="_no_such_dependency_anywhere") as info:
        formats()
    assert "FORMAT_MODULES" not in str(info.value)


def test_every_format_module_is_type_checked():
    # Issue 36 left the readers outside the mypy scope (32 errors); the scope is the
    # package now, so a new reader is checked from its first commit.
    import re
    from pathlib import Path

    root = Path(surfmet.io.__file__).resolve().parents[2]
    text = (root / "pyproject.toml").read_text(encoding="utf-8")  # no tomllib on 3.10
    block = re.search(r"\[tool\.mypy\].*?^files = \[(.*?)^\]", text, re.S | re.M)
    assert block, "pyproject.toml has no [tool.mypy] files"
    files = re.findall(r'^\s*"([^"]+)"', block.group(1), re.M)
    modules = sorted(p.relative_to(root).as_posix()
                     for p in (root / "surfmet" / "io").glob("*.py"))
    unchecked = [m for m in modules
                 if not any(m == f or m.startswith(f.rstrip("/") + "/") for f in files)]
    assert not unchecked, f"outside the mypy scope: {unchecked}"
