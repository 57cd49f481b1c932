"""The licence, the changelog, the type markers and the classifiers ship with the package."""

from __future__ import annotations

from pathlib import Path

import pytest

tomllib = pytest.importorskip("tomllib")  # Python >= 3.11

ROOT = Path(__file__).resolve().parents[1]


def _project() -> dict:
    with open(ROOT / "pyproject.toml", "rb") as fh:
        return tomllib.load(fh)


def test_licence_file_is_mit_and_shipped():
    text = (ROOT / "LICENSE").read_text(encoding="utf-8")
    assert text.startswith("MIT License")
    assert "surfmet developers" in text and "2026" in text
    project = _project()["project"]
    assert project["license"] == "MIT"
    assert "LICENSE" in project["license-files"]


def test_changelog_names_the_current_version():
    from surfmet._version import __version__

    text = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    assert "## Unreleased" in text
    assert f"## {__version__}" in text


def test_classifiers_as_the_anchors_have_them():
    project = _project()["project"]
    classifiers = project["classifiers"]
    for prefix in ("Development Status ::", "Intended Audience ::", "Operating System ::",
                   "Programming Language :: Python :: 3.1", "Topic :: Scientific/Engineering"):
        assert any(c.startswith(prefix) for c in classifiers), prefix
    # the SPDX expression states the licence; setuptools >= 77 refuses a licence classifier
    assert not any(c.startswith("License ::") for c in classifiers)
    # no project URL until the project has a public address: an invented one would mislead
    assert "urls" not in project


def test_type_markers_ship_in_every_package():
    data = _project()["tool"]["setuptools"]["package-data"]
    for package in ("surfmet", "contact", "profiles", "rotor"):
        assert (ROOT / package / "py.typed").is_file()
        assert "py.typed" in data[package]
