"""One file, one answer: every real file × every entry point that shows a number for it.

Issue 34, "The principle": every question has one function that answers it (file →
prepared data → numbers) and every entry point calls it, so the numbers are EQUAL, not
close. The matrix runs each file in ``../shared/realdata`` through

* the Python API: :func:`surfmet.roughness.roughness` (what ``surfmet roughness FILE
  --json`` prints for one file) and the spectrum command's
  :func:`surfmet.mechanics.spectrum.scan_spectrum`;
* ``surfmet roughness FILE... --json`` (the batch path, :func:`surfmet._batch.batch_map`);
* ``surfmet report FILE... --json`` (its per-scan ``info``, ``roughness`` and
  ``spectrum`` records);
* ``surfmet show FILE --json`` (the record of the surface it draws; the 2D view, which
  draws the same evaluated surface as the 3D one);
* ``surfmet spectrum FILE --json`` and ``surfmet info FILE --json``;

and asserts that every record equals the API's, key for key and to the last bit (through
the same JSON the commands print). A scan that an entry point refuses must be refused by
every entry point with the same one-line message; an internal error anywhere fails.

How the files are treated: every file in the directory must be listed in MANIFEST.tsv and
joins the matrix (a new file joins it by being there). A profile has no spectrum (the
spectrum command refuses it, and the report draws no areal PSD for it). A container
(:data:`CONTAINERS`) is compared where the entry points read the same measurement; what
they do not share is named there. Every CLI command either joins the matrix
(:data:`IN_MATRIX`) or is listed in :data:`NO_NUMBER_FOR_FILES` with the reason, so a new
command fails :func:`test_every_command_joins_the_matrix_or_says_why_not` until it is
placed. Each entry point runs once per file (module-scoped fixtures): about half a minute.
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import io
import json
import os

import pytest
from conftest import REALDATA

from surfmet.cli import build_parser, main

pytestmark = pytest.mark.realdata

#: the commands in the matrix, and what each is held against
IN_MATRIX = {
    "roughness": "its records against roughness(file) (API), report's and show's",
    "report": "its info, roughness and spectrum records against info, roughness, spectrum",
    "show": "the roughness record of the surface it draws against roughness(file)",
    "spectrum": "its record against the report's spectrum and scan_spectrum (API)",
    "info": "its record against the report's info",
}
#: the commands outside the matrix: they show no number for a file as it is, or no other
#: entry point shows their numbers
NO_NUMBER_FOR_FILES = {
    "formats": "lists the readers and writers; reads no scan",
    "rotor": "reads a table of frame indices, not a scan",
    "demo": "runs on the bundled paper pair only; it takes no FILE",
    "fit": "the fitted sphere or circle: no other entry point shows it for a file",
    "scales": "the scale-dependent slopes and curvatures: no other entry point shows them",
    "hertz-check": "needs a ball radius, a load and materials that no file states; the "
                   "report's Hertz check equals its record in tests/test_report.py::"
                   "test_hertz_options_on_the_command_line",
    "contact": "a contact at a load and materials the user gives; no file states them",
    "sweep": "contacts over loads and materials the user gives; no file states them",
    "rolling": "rolling resistance at loads and materials the user gives",
    "rolling-contact": "a rolling contact at a load, materials and friction the user gives",
    "adhesion": "an adhesive contact at a work of adhesion the user gives",
    "flat-contact": "contacts at pressures and materials the user gives",
}
#: containers of several measurements, and how the matrix treats them
CONTAINERS = {
    "container-2.zip": "a contact.engineering container of three measurements: the "
                       "roughness command and the report give one record each (named "
                       "CONTAINER:MEMBER), show and the API the one surfmet.read gives "
                       "(the first); spectrum averages the PSDs of all, which no other "
                       "entry point shows, and info lists them all where the report's "
                       "section describes its own measurement",
}


def _files() -> list[str]:
    if not REALDATA.is_dir():
        return []
    return sorted(p.name for p in REALDATA.iterdir()
                  if p.is_file() and p.name != "MANIFEST.tsv" and not p.name.startswith("."))


FILES = _files()


def _path(name: str) -> str:
    return os.path.relpath(REALDATA / name)


def _as_printed(obj):
    """``obj`` through the JSON the commands print (surfmet.cli._common.emit_json)."""
    from surfmet.units import jsonable

    return json.loads(json.dumps(jsonable(obj), allow_nan=False))


def _run(argv: list[str]) -> tuple[int, str, str]:
    """The command's exit status, stdout (its JSON without the ``inputs`` record, which
    echoes the command line and so differs by entry point by design) and stderr."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main(argv)
    text = out.getvalue()
    if "--json" in argv and text.strip():  # a batch with a failed file exits 1 with JSON
        text = json.dumps(without_inputs(json.loads(text)))
    return rc, text, err.getvalue()


def without_inputs(obj):
    """A command's JSON less the ``inputs`` echo of its command line (a record, or each of
    a list of records)."""
    if isinstance(obj, list):
        return [without_inputs(o) for o in obj]
    if isinstance(obj, dict):
        return {k: v for k, v in obj.items() if k != "inputs"}
    return obj


def _error_line(err: str) -> str:
    """The message of the one error line a command printed."""
    lines = [ln for ln in err.splitlines() if ln.startswith("surfmet: ")]
    assert len(lines) == 1, err
    return lines[0].split("error: ", 1)[-1]


def _key(function, scan, options: dict) -> tuple:
    """What a pipeline function is handed: the data (heights bit for bit, grid, metadata;
    a path is read first, as the function reads it) and the options that differ from the
    function's defaults. Two entry points share a key only when they hand it the same."""
    import hashlib
    import inspect

    import numpy as np

    from surfmet._measurements import Measurement, read_measurement
    from surfmet._model import Profile, Topography
    from surfmet.io import read

    handed = "data"
    if isinstance(scan, Measurement):  # a container's measurement, as roughness reads it
        scan = read_measurement(scan)
    elif not isinstance(scan, (Topography, Profile)):
        scan = read(scan)
        # roughness(container path) says which measurement it took: not the same answer
        # as that of the data read from it
        handed = "container path" if "container" in scan.metadata else handed
    defaults = {k: p.default for k, p in inspect.signature(function).parameters.items()}
    given = {k: v for k, v in options.items() if k not in defaults or v != defaults[k]}
    z = np.ascontiguousarray(scan.heights if isinstance(scan, Topography) else scan.z)
    digest = hashlib.sha256(z.tobytes())
    if isinstance(scan, Profile) and scan.x is not None:
        digest.update(np.ascontiguousarray(scan.x).tobytes())
    return (handed, type(scan).__name__, z.shape, scan.dx, getattr(scan, "dy", None),
            digest.hexdigest(), json.dumps(_as_printed(dict(scan.metadata)), sort_keys=True),
            json.dumps(given, sort_keys=True, default=repr))


class _NoPixels:
    """The pictures' pixels are no numbers: the matrix builds every figure (its legends
    and captions come from the same result as the records) but does not rasterise it,
    which would take most of its time; tests/test_report.py and tests/test_show.py check
    the pictures themselves."""

    PNG = (b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\x00\x00\x00\x01\x00\x00\x00\x01\x08"
           b"\x06\x00\x00\x00\x1f\x15\xc4\x89\x00\x00\x00\rIDATx\x9cc\xf8\x0f\x00\x00"
           b"\x01\x01\x00\x05\x18\xd8N\x00\x00\x00\x00IEND\xaeB`\x82")

    @staticmethod
    def figure_png(fig, dpi: int = 100) -> bytes:
        from surfmet.plots._style import close

        close(fig)
        return _NoPixels.PNG

    @staticmethod
    def save(fig, path, dpi: int = 120) -> None:
        from pathlib import Path

        Path(path).write_bytes(_NoPixels.PNG)


def _fresh(value):
    """A memoised result as a caller may change it: its dictionaries (settings, records)
    copied; the arrays, which no caller writes, shared."""
    import copy
    import dataclasses

    if isinstance(value, tuple):
        return tuple(_fresh(v) for v in value)
    if isinstance(value, dict):
        return copy.deepcopy(value)
    if dataclasses.is_dataclass(value) and isinstance(getattr(value, "settings", None), dict):
        return dataclasses.replace(value, settings=copy.deepcopy(value.settings))
    return value


@pytest.fixture(scope="module", autouse=True)
def one_computation_per_input():
    """Each pipeline function runs once per distinct input, and no picture is rasterised
    (:class:`_NoPixels`). :func:`roughness` and :func:`scan_spectrum` are memoised on
    :func:`_key`, the data and options they are handed (each caller gets its own copy of
    the result's dictionaries). This keeps the matrix short without weakening it: an entry
    point that levels, filters or prepares the data on its own, or passes other options,
    hands the function another key, is computed on its own and compared; everything after
    the call (records, units, JSON) runs in every entry point."""
    import surfmet.mechanics.spectrum as spectral
    import surfmet.roughness as pipeline

    mp = pytest.MonkeyPatch()
    for module, name in ((pipeline, "roughness"), (spectral, "scan_spectrum")):
        real = getattr(module, name)
        memo: dict[tuple, object] = {}

        def memoised(scan, _real=real, _memo=memo, **options):
            key = _key(_real, scan, options)
            if key not in _memo:
                try:
                    _memo[key] = ("ok", _real(scan, **options))
                except Exception as exc:
                    _memo[key] = ("raised", exc)
            status, value = _memo[key]
            if status == "raised":
                raise value
            return _fresh(value)

        mp.setattr(module, name, memoised)
    import surfmet._report_figures as report_figures
    import surfmet.plots._style as style

    mp.setattr(report_figures, "figure_png", _NoPixels.figure_png)
    mp.setattr(style, "save", _NoPixels.save)
    yield
    mp.undo()


@pytest.fixture(scope="module")
def api() -> dict[str, tuple[str, object]]:
    """roughness(file) per file: ("ok", record) or ("error", message)."""
    import surfmet.roughness as pipeline
    from surfmet._errors import user_error_types
    from surfmet.records._roughness import roughness_record

    out: dict[str, tuple[str, object]] = {}
    for name in FILES:
        try:
            res = pipeline.roughness(_path(name))
        except user_error_types() as exc:
            out[name] = ("error", str(exc))
        except Exception as exc:  # an internal error: the file's test says so
            out[name] = ("internal", f"{type(exc).__name__}: {exc}")
        else:
            out[name] = ("ok", _as_printed({"file": _path(name), "status": "ok",
                                            **roughness_record(res)}))
    return out


@pytest.fixture(scope="module")
def api_spectrum() -> dict[str, tuple[str, object]]:
    """scan_spectrum(read(file)) per areal file, as the spectrum command records it."""
    import surfmet
    import surfmet.mechanics.spectrum as spectral
    from surfmet._errors import user_error_types
    from surfmet.records._spectrum import spectrum_command_record

    out: dict[str, tuple[str, object]] = {}
    for name in FILES:
        try:
            s, level, prep = spectral.scan_spectrum(surfmet.read(_path(name)))
        except user_error_types() as exc:
            out[name] = ("error", str(exc))
        else:
            out[name] = ("ok", _as_printed(spectrum_command_record(_path(name), s, level,
                                                                   prep)))
    return out


@pytest.fixture(scope="module")
def cli_roughness() -> dict[str, list[dict]]:
    """``surfmet roughness FILE... --json`` on every file at once: records by file."""
    _, out, _ = _run(["roughness", *map(_path, FILES), "--json", "--workers", "1"])
    by_file: dict[str, list[dict]] = {}
    for rec in json.loads(out):
        by_file.setdefault(str(rec["file"]).split(":")[0], []).append(rec)
    return by_file


@pytest.fixture(scope="module")
def report(tmp_path_factory) -> dict[str, dict]:
    """``surfmet report FILE... --json`` on every file at once: its scans by file."""
    page = tmp_path_factory.mktemp("report") / "all.html"
    _, out, err = _run(["report", *map(_path, FILES), "-o", str(page), "--no-3d", "--json"])
    assert page.is_file(), err  # written whatever failed
    return {s["file"]: s for s in json.loads(out)["scans"]}


def _per_file(argv_of) -> dict[str, tuple[int, object]]:
    out: dict[str, tuple[int, object]] = {}
    for name in FILES:
        rc, text, err = _run(argv_of(name))
        out[name] = (rc, json.loads(text) if rc == 0 else (err if rc == 2 else
                                                            _error_line(err)))
    return out


@pytest.fixture(scope="module")
def show(tmp_path_factory) -> dict[str, tuple[int, object]]:
    d = tmp_path_factory.mktemp("show")
    return _per_file(lambda n: ["show", _path(n), "-o", str(d / f"{n}.png"), "--2d", "--json"])


@pytest.fixture(scope="module")
def spectrum() -> dict[str, tuple[int, object]]:
    return _per_file(lambda n: ["spectrum", _path(n), "--json"])


@pytest.fixture(scope="module")
def info() -> dict[str, tuple[int, object]]:
    return _per_file(lambda n: ["info", _path(n), "--json"])


def test_every_file_is_in_the_manifest_and_the_matrix():
    with (REALDATA / "MANIFEST.tsv").open(encoding="utf-8", newline="") as fh:
        listed = {row["filename"] for row in csv.DictReader(fh, delimiter="\t")}
    assert FILES and set(FILES) == listed
    assert set(CONTAINERS) <= set(FILES)


def test_every_command_joins_the_matrix_or_says_why_not():
    sub = next(a for a in build_parser()._actions
               if isinstance(a, argparse._SubParsersAction))
    commands = set(sub.choices)
    assert not set(IN_MATRIX) & set(NO_NUMBER_FOR_FILES)
    assert commands == set(IN_MATRIX) | set(NO_NUMBER_FOR_FILES), (
        "a command must join the matrix or say why it shows no number for a file: "
        f"{sorted(commands ^ (set(IN_MATRIX) | set(NO_NUMBER_FOR_FILES)))}")


@pytest.mark.parametrize("name", FILES)
def test_one_file_one_answer(name, api, api_spectrum, cli_roughness, report, show, spectrum,
                             info):
    path = _path(name)
    status, expected = api[name]
    assert status != "internal", f"roughness({name}): internal error {expected}"
    if name in CONTAINERS:
        pytest.skip("held against per measurement in test_a_container_one_answer_each")
    sec = report[path]
    rc_show, shown = show[name]
    assert rc_show != 2, f"show {name}: {shown}"
    if status == "error":
        # refused: everywhere, in the same words
        assert sec["status"] == "error" and sec["error"] == expected
        assert (rc_show, shown) == (1, expected)
        assert [(r["status"], r["error"]) for r in cli_roughness[path]] == \
            [("error", expected)]
        return
    assert sec["status"] == "ok", sec.get("error")
    assert sec["roughness"] == expected
    assert rc_show == 0 and shown["roughness"] == expected
    assert cli_roughness[path] == [expected]
    rc_info, rec = info[name]
    assert rc_info == 0 and sec["info"] == rec
    kind = expected["settings"]["kind"]
    rc_spec, spec = spectrum[name]
    assert rc_spec != 2, f"spectrum {name}: {spec}"
    if kind == "profile":
        assert "spectrum" not in sec  # no areal PSD on a profile's page
        return
    sp_status, sp_expected = api_spectrum[name]
    if sp_status == "error":
        assert sec["spectrum"] == {"error": sp_expected}
        assert (rc_spec, spec) == (1, sp_expected)
    else:
        assert sec["spectrum"] == sp_expected
        assert (rc_spec, spec) == (0, sp_expected)


@pytest.mark.parametrize("name", sorted(CONTAINERS))
def test_a_container_one_answer_each(name, api, cli_roughness, report, show):
    """A container: the roughness command's record of each measurement is the report's
    section of it, and the one show draws (and says it draws) is the API's."""
    path = _path(name)
    records = cli_roughness[path]
    assert len(records) > 1 and all(r["status"] == "ok" for r in records)
    # one record per measurement, named CONTAINER:MEMBER with the container's own data
    # files, as the zip lists them (was: each name rebuilt from itself, which could only
    # check the prefix)
    import zipfile

    with zipfile.ZipFile(REALDATA / name) as zf:
        members = [m for m in zf.namelist()
                   if m != "meta.yml" and not m.upper().startswith("LICENSE")]
    assert [r["file"] for r in records] == [f"{path}:{m}" for m in members]
    for r in records:
        sec = report[r["file"]]
        assert sec["status"] == "ok" and sec["roughness"] == r
    rc_show, shown = show[name]
    assert rc_show == 0 and shown["measurement"]["name"] == records[0]["file"]
    assert shown["roughness"] == records[0]
    status, expected = api[name]
    assert status == "ok" and expected["parameters"] == records[0]["parameters"]
    # the API's result of a container path says which measurement it is, first
    api_settings, rec_settings = dict(expected["settings"]), dict(records[0]["settings"])
    api_notes, rec_notes = api_settings.pop("notes"), rec_settings.pop("notes")
    assert api_settings == rec_settings and api_notes[1:] == rec_notes
    assert api_notes[0].startswith("measurement 0 ")


#: evaluation options that change a file's numbers, each run through every entry point
#: that takes the shared roughness options (surfmet.cli._roughness_options)
OPTION_CASES = {
    "mitutoyo_2_mock.xlsx": (("--element-start", "peak"),
                             ("--standard", "iso21920", "--element-start", "first-crossing")),
}


@pytest.mark.parametrize(("name", "argv"), [(n, a) for n, cases in OPTION_CASES.items()
                                            for a in cases])
def test_an_option_gives_one_answer_everywhere(name, argv, tmp_path):
    """The option reaches the API's keyword through roughness, report and show alike: the
    same record everywhere, and not the record without it (so it took effect)."""
    import surfmet.roughness as pipeline
    from surfmet.records._roughness import roughness_record

    path = _path(name)
    kwargs = {o.lstrip("-").replace("-", "_"): v for o, v in zip(argv[::2], argv[1::2])}
    expected = _as_printed({"file": path, "status": "ok",
                            **roughness_record(pipeline.roughness(path, **kwargs))})
    plain = _as_printed(roughness_record(pipeline.roughness(path)))
    assert expected["parameters"]["Rsm"] != plain["parameters"]["Rsm"]
    _, out, err = _run(["roughness", path, *argv, "--json", "--workers", "1"])
    assert json.loads(out) == [expected], err
    _, out, err = _run(["report", path, *argv, "-o", str(tmp_path / "r.html"), "--no-3d",
                        "--json"])
    assert json.loads(out)["scans"][0]["roughness"] == expected, err
    rc, out, err = _run(["show", path, *argv, "-o", str(tmp_path / "s.png"), "--2d",
                         "--json"])
    assert rc == 0 and json.loads(out)["roughness"] == expected, err
