"""The 3D view and the cluster engine are extras (issue 16, item 17): a roughness-only
install has neither, and a command that needs one says which extra to install, in one line
(exit 1), never a traceback. The README's install command installs everything."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import tomllib

import surfmet
from surfmet import Topography
from surfmet.cli import main

ROOT = Path(__file__).resolve().parents[1]


def _pyproject():
    return tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]


def test_heavy_parts_are_extras():
    proj = _pyproject()
    core = " ".join(proj["dependencies"]).lower()
    assert "pyvista" not in core and "dask" not in core and "vtk" not in core
    extras = proj["optional-dependencies"]
    assert any(d.startswith("pyvista") for d in extras["view"])
    assert any(d.startswith("dask[distributed]") for d in extras["dask"])
    assert extras["all"] == ["surfmet[view,dask]"]


def test_readme_installs_everything():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    installs = [ln for ln in readme.splitlines() if "pip install -e" in ln]
    assert installs and all("all" in ln for ln in installs)


def _scan(tmp_path):
    z = np.random.default_rng(17).normal(0, 1e-7, (24, 24))
    return str(surfmet.write(Topography(z, 1e-6, 1e-6), tmp_path / "s.npz"))


def test_show_without_the_view_extra_names_it(tmp_path, monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "pyvista", None)  # import pyvista -> ImportError
    rc = main(["show", _scan(tmp_path), "-o", str(tmp_path / "v.png")])
    err = capsys.readouterr().err
    assert rc == 1 and 'surfmet[view]' in err and len(err.strip().splitlines()) == 1
    # the 2D view needs no extra
    assert main(["show", _scan(tmp_path), "-o", str(tmp_path / "v.png"), "--2d"]) == 0


def test_report_leaves_the_3d_picture_out_without_the_extra(tmp_path, monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "pyvista", None)
    out = tmp_path / "r.html"
    assert main(["report", _scan(tmp_path), "-o", str(out), "--quiet"]) == 0
    assert "3D view" not in out.read_text(encoding="utf-8")


def test_scheduler_without_the_dask_extra_names_it(monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "distributed", None)
    rc = main(["sweep", "--task", "contact", "--radius", "20mm", "--loads", "1N,2N",
               "--grid", "32", "--scheduler", "tcp://127.0.0.1:1", "--json"])
    err = capsys.readouterr().err
    assert rc == 1 and "surfmet[dask]" in err
