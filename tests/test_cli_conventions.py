"""Conventions every subcommand keeps: examples in --help, valid JSON on stdout with logs on
stderr, exit codes 0 / 1 (user error) / 2 (internal error), ``python -m surfmet``, a
versioned ``__version__``, a light ``surfmet --help``."""

from __future__ import annotations

import argparse
import importlib.metadata
import json
import re
import subprocess
import sys

import numpy as np
import pytest

import surfmet
from surfmet._model import Topography
from surfmet.cli import build_parser, main


def _subparsers() -> dict[str, argparse.ArgumentParser]:
    parser = build_parser()
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            return dict(action.choices)
    raise AssertionError("surfmet has no subcommands")


SUBS = _subparsers()

# A valid --json invocation of every subcommand that has --json ({scan}, {ball}, {tmp},
# {frames} are filled in by the test). A new subcommand must add its line here.
INVOCATIONS = {
    "info": ["info", "{scan}", "--json"],
    "formats": ["formats", "--json"],
    "roughness": ["roughness", "{scan}", "--json"],
    "fit": ["fit", "{ball}", "--shape", "sphere", "--json"],
    "contact": ["contact", "--radius", "20mm", "--load", "10N", "--materials",
                "steel,aluminium", "--grid", "32", "--json"],
    "hertz-check": ["hertz-check", "{scan}", "--radius", "1mm", "--load", "20mN",
                    "--materials", "steel,aluminium", "--json"],
    "rolling": ["rolling", "--radius", "20mm", "--materials", "steel,aluminium",
                "--loads", "1N:10N:3", "--grid", "64", "--json"],
    "rotor": ["rotor", "{frames}", "--json"],
    "show": ["show", "{scan}", "-o", "{tmp}/view.png", "--2d", "--json"],
    "report": ["report", "{scan}", "-o", "{tmp}/report.html", "--no-3d", "--json"],
    "demo": ["demo", "--out", "{tmp}/demo", "--quick", "--json"],
    "spectrum": ["spectrum", "{scan}", "--json"],
    "scales": ["scales", "{scan}", "--json"],
    "adhesion": ["adhesion", "--radius", "10um", "--e-star", "1GPa", "--work-of-adhesion",
                 "50mJ/m2", "--range", "2nm", "--grid", "32", "--steps", "10", "--json"],
    "sweep": ["sweep", "--radius", "20mm", "--loads", "5N", "--grid", "32", "--workers", "1",
              "--json"],
    "flat-contact": ["flat-contact", "{scan}", "--e-star", "1GPa", "--pressures", "1MPa",
                     "--json"],
    "rolling-contact": ["rolling-contact", "--radius", "20mm", "--load", "5N", "--materials",
                        "steel,aluminium", "--mu", "0.3", "--grid", "16", "--json"],
}


@pytest.fixture
def files(tmp_path):
    rng = np.random.default_rng(0)
    scan = surfmet.write(Topography(rng.standard_normal((48, 64)) * 1e-7, 1e-6, 1e-6),
                         tmp_path / "plate.npz")
    R, n, dx = 10e-3, 60, 5e-6
    j, i = np.mgrid[:n, :n]
    z = np.sqrt(R**2 - (i * dx - 1.5e-4) ** 2 - (j * dx - 1.5e-4) ** 2)
    ball = surfmet.write(Topography(z + 1e-8 * rng.standard_normal((n, n)), dx, dx),
                         tmp_path / "ball.npz")
    # frame indices of a rotor under constant acceleration from rest (120 fps, 90° marks)
    k = np.arange(1, 13)
    frames = np.rint(120 * np.sqrt((k - 1) * np.pi / 3.0)).astype(int)
    tsv = tmp_path / "frames.tsv"
    tsv.write_text("k\tas1\n" + "".join(f"{a}\t{b}\n" for a, b in zip(k, frames)))
    return {"scan": str(scan), "ball": str(ball), "tmp": str(tmp_path), "frames": str(tsv)}


def _fill(argv, files):
    return [a.format(**files) for a in argv]


def _no_nan(text: str):
    def refuse(const):
        raise AssertionError(f"{const} is not JSON")

    return json.loads(text, parse_constant=refuse)


@pytest.mark.parametrize("name", sorted(SUBS))
def test_help_shows_examples(name):
    text = SUBS[name].format_help()
    assert re.search(r"^examples?:", text, re.M | re.I), f"'surfmet {name} --help' has no examples"
    assert f"surfmet {name}" in text.split("xample", 1)[1], "the examples use the command"


def test_every_json_subcommand_has_an_invocation_here():
    with_json = {n for n, p in SUBS.items() if "--json" in p.format_usage()}
    missing = with_json - set(INVOCATIONS)
    assert not missing, f"add a --json invocation to INVOCATIONS for: {sorted(missing)}"


# the demo's run (about 30 s) is a campaign: the default suite keeps the demo's JSON test
# (tests/test_demo.py), and every other command's convention here
@pytest.mark.parametrize("name", [
    pytest.param(n, marks=pytest.mark.campaign) if n == "demo" else n
    for n in sorted(INVOCATIONS)])
def test_json_on_stdout_logs_on_stderr(name, files, capsys):
    assert name in SUBS, f"'surfmet {name}' has an invocation here but no subcommand"
    rc = main(_fill(INVOCATIONS[name], files))
    out, err = capsys.readouterr()
    assert rc == 0, err
    data = _no_nan(out)  # the whole of stdout is one JSON document
    assert isinstance(data, (dict, list)) and data
    assert not err.strip().startswith(("{", "[")), "JSON leaked to stderr"
    _check_units_and_inputs(name, data)


def _units(obj, path="$"):
    """Every ``"unit"`` a JSON document states, with where."""
    if isinstance(obj, dict):
        if isinstance(obj.get("unit"), str) and "value" in obj:
            yield path, obj["unit"]
        for k, v in obj.items():
            yield from _units(v, f"{path}.{k}")
    elif isinstance(obj, list):
        for i, v in enumerate(obj):
            yield from _units(v, f"{path}[{i}]")


def _check_units_and_inputs(name, data):
    """Issue 34, items 10 and 13: every unit is in the one vocabulary (was "rad/s²" beside
    "m^2", "1" beside ""), and every record states its inputs."""
    from surfmet.units import JSON_UNITS

    bad = {(p, u) for p, u in _units(data) if u not in JSON_UNITS}
    assert not bad, f"units outside surfmet.units.JSON_UNITS: {sorted(bad)[:5]}"
    if name == "formats":  # takes no input
        return
    for rec in data if isinstance(data, list) else [data]:
        assert isinstance(rec.get("inputs"), dict), f"'surfmet {name} --json' has no inputs"


@pytest.mark.parametrize("argv", [
    ["info", "{tmp}/absent.x3p"],
    ["roughness", "{tmp}/absent.x3p", "--json"],
    ["roughness", "{tmp}/absent.x3p", "{scan}", "--workers", "1"],
    ["fit", "{tmp}/absent.x3p", "--shape", "sphere"],
    ["show", "{tmp}/absent.x3p", "-o", "{tmp}/v.png"],
    ["report", "{tmp}/absent.x3p", "-o", "{tmp}/r.html", "--no-3d"],
    ["roughness", "{scan}", "--workers", "0"],
    ["report", "{scan}", "-o", "{tmp}/r.html", "--load", "-3N", "--radius", "1mm",
     "--materials", "steel,steel"],
    ["show", "{scan}"],  # missing -o
    ["no-such-command"],
])
def test_user_errors_exit_1(argv, files, capsys):
    assert main(_fill(argv, files)) == 1
    out, err = capsys.readouterr()
    assert "Traceback" not in err and "surfmet" in err and "error" in err
    if argv[0] in ("info", "fit", "show") or "--json" in argv:
        assert err.count("\n") == 1 and out == ""


@pytest.mark.parametrize("target, argv", [
    ("surfmet.roughness.roughness", ["roughness", "{scan}"]),
    ("surfmet._render.render_3d", ["show", "{scan}", "-o", "{tmp}/v.png"]),
    ("surfmet.report.render_html", ["report", "{scan}", "-o", "{tmp}/r.html", "--no-3d"]),
])
def test_internal_errors_exit_2(target, argv, files, capsys, monkeypatch):
    def broken(*a, **k):
        raise RuntimeError("a bug")

    module, name = target.rsplit(".", 1)
    monkeypatch.setattr(importlib.import_module(module), name, broken)
    monkeypatch.delenv("SURFMET_DEBUG", raising=False)
    assert main(_fill(argv, files)) == 2
    err = capsys.readouterr().err
    assert "internal error" in err and "RuntimeError: a bug" in err and "Traceback" not in err


def test_python_m_surfmet_and_version():
    run = subprocess.run([sys.executable, "-m", "surfmet", "--version"],
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 0
    assert run.stdout.strip() == f"surfmet {surfmet.__version__}"
    # PEP 440 release (with optional pre/post/dev parts), and the installed metadata agrees
    assert re.fullmatch(r"\d+\.\d+\.\d+((a|b|rc)\d+)?(\.post\d+)?(\.dev\d+)?",
                        surfmet.__version__)
    assert importlib.metadata.version("surfmet") == surfmet.__version__
    run = subprocess.run([sys.executable, "-m", "surfmet"], capture_output=True, text=True,
                         timeout=60)
    assert run.returncode == 1 and "usage" in run.stderr  # no command: help, status 1


def test_cli_stays_light():
    # Building every subcommand's parser (what --help does) loads no heavy library.
    code = ("import sys; from surfmet.cli import build_parser; build_parser(); "
            "print(','.join(m for m in ('matplotlib', 'pyvista', 'vtk', 'dask', "
            "'distributed', 'numba', 'skimage', 'scipy', 'tqdm') if m in sys.modules))")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=60, check=True)
    assert run.stdout.strip() == "", f"surfmet --help pulled in: {run.stdout.strip()}"
