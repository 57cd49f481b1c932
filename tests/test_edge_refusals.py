"""Input the commands met as internal errors (exit 2), tracebacks or misleading lines: each
is now one line, exit 1, before the work (issue 34, items 8 and 17)."""

from __future__ import annotations

import json
import os
import resource
import signal
import struct
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

from contact._errors import ContactInputError, ContactMemoryError
from contact._hertz import hertz_cylinder, hertz_sphere
from surfmet.cli import main

ROOT = Path(__file__).resolve().parents[1]
PLATE = str(ROOT / "surfmet" / "data" / "paper_plate.x3p")
REAL = ROOT.parent / "shared" / "realdata"
IBW = REAL / "10x10-one_channel_without_name.ibw"
OPDX = REAL / "opdx-3.opdx"


def _line(capsys) -> str:
    out = capsys.readouterr()
    err = [ln for ln in out.err.splitlines() if ln.strip()]
    assert len(err) == 1, err
    assert "internal error" not in err[0] and "Traceback" not in out.err
    return err[0]


def _cli(args: list[str], **kw) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "surfmet", *args], cwd=ROOT,
                          capture_output=True, text=True, timeout=300, **kw)


@pytest.mark.parametrize("option", [["--load", "1e-320N", "--radius", "20mm"],
                                    ["--load", "5N", "--radius", "1e-320m"]])
def test_a_subnormal_load_or_radius_is_one_line(option, capsys):
    """main: ZeroDivisionError in contact/_hertz.py, exit 2."""
    assert main(["contact", *option, "--materials", "steel,aluminium"]) == 1
    assert "too small to compute with" in _line(capsys)


def test_the_hertz_engine_raises_its_own_error():
    """Inputs the engine cannot compute with are ContactInputError (main: a division by
    zero for a subnormal input, and for representable inputs whose solution underflows)."""
    with pytest.raises(ContactInputError, match="too small"):
        hertz_sphere(0.02, 1e-320, 1e11)
    with pytest.raises(ContactInputError, match="out of range"):
        hertz_sphere(1e-300, 1e-300, 1e11)  # a = (3 W R / 4E*)^(1/3) underflows
    with pytest.raises(ContactInputError, match="out of range"):
        hertz_cylinder(1e-300, 1e-300, 1e11)
    h = hertz_sphere(0.02, 10.0, 1e11)  # Johnson's closed form, unchanged
    assert h.a == pytest.approx((3 * 10.0 * 0.02 / 4e11) ** (1 / 3), rel=1e-15)


def _ibw_with_pixel(tmp_path: Path, value: float) -> Path:
    """A copy of the real 10x10 wave with sfA[0] (the x delta) set to ``value`` and the
    header checksum made good again (PTN003: the 16-bit sum of both headers is zero)."""
    buf = bytearray(IBW.read_bytes())
    order = "<" if struct.unpack_from("<h", buf)[0] == 5 else ">"
    struct.pack_into(order + "d", buf, 64 + 84, value)
    struct.pack_into(order + "h", buf, 2, 0)
    total = int(np.frombuffer(bytes(buf[:384]), dtype=order + "i2").astype(np.int64).sum())
    struct.pack_into(order + "H", buf, 2, (-total) & 0xFFFF)
    out = tmp_path / "tiny_pixel.ibw"
    out.write_bytes(bytes(buf))
    return out


@pytest.mark.skipif(not IBW.exists(), reason="needs ../shared/realdata")
def test_an_ibw_with_a_subnormal_pixel_is_refused_by_every_command(tmp_path, capsys):
    """main: info showed "4.941e-315 nm", roughness died of a ZeroDivisionError."""
    f = str(_ibw_with_pixel(tmp_path, 5e-324))
    for cmd in (["info", f], ["roughness", f]):
        assert main(cmd) == 1
        line = _line(capsys)
        assert "tiny_pixel.ibw" in line and "too small to be a pixel size" in line


def test_flat_contact_refuses_pressures_beyond_e_star_before_solving(capsys):
    """--e-star 1Pa: main ran both solves and died of a TypeError printing them. (A bare
    --e-star 1 is now refused for lacking its unit, the pressure rule.)"""
    assert main(["flat-contact", PLATE, "--e-star", "1Pa", "--pressures", "1MPa:10MPa:2",
                 "--quiet"]) == 1
    line = _line(capsys)
    assert "not below E* = 1 Pa" in line and "reach 10 MPa" in line


def test_adhesion_refuses_a_grid_that_cannot_fit(capsys):
    """main: MemoryError for a 74.5 GiB array (exit 2) after the set-up."""
    assert main(["adhesion", "--radius", "10um", "--e-star", "1GPa", "--work-of-adhesion",
                 "50mJ/m2", "--range", "2nm", "--grid", "100000"]) == 1
    line = _line(capsys)
    assert "100000 x 100000 cells" in line and "the largest grid that fits" in line


def test_the_adhesion_estimate_is_below_the_measured_peaks():
    """The guard refuses only what would not fit: at 256^2 its estimate is below the
    peaks measured there (143 MB with 4 steps, 172 MB with 40: contact/adhesion/memory)."""
    from contact.adhesion.memory import check_adhesion_memory, estimate_adhesion_bytes

    assert estimate_adhesion_bytes(256 ** 2, 4) < 143e6
    assert estimate_adhesion_bytes(256 ** 2, 40) < 172e6
    assert check_adhesion_memory(256, steps=40, available=10**9) < 172e6
    with pytest.raises(ContactMemoryError, match="largest grid that fits is"):
        check_adhesion_memory(4096, steps=40, available=10**9)


def test_show_refuses_an_unknown_colormap_before_reading(capsys):
    """main: KeyError/ValueError from matplotlib after the scan was read and levelled."""
    assert main(["show", PLATE, "-o", "x.png", "--cmap", "nosuch"]) == 1
    line = _line(capsys)
    assert "'nosuch' is not a colormap" in line and "viridis" in line


@pytest.mark.parametrize("extra", [[], ["--2d"]])
def test_show_names_the_output_the_user_gave(extra, tmp_path, capsys):
    """main: 'Format part-1a2b3c4d is not supported', the temporary file's suffix."""
    out = tmp_path / "noext"
    assert main(["show", PLATE, "-o", str(out), *extra]) == 1
    line = _line(capsys)
    assert "noext: has no suffix" in line and "part-" not in line
    assert list(tmp_path.iterdir()) == []


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="needs /dev/full")
@pytest.mark.parametrize("json_flag", [[], ["--json"]])
def test_stdout_to_a_full_disk_is_one_line(json_flag):
    """main: "internal error: OSError: [Errno 28]", exit 2."""
    with open("/dev/full", "w") as full:
        run = subprocess.run([sys.executable, "-m", "surfmet", "info", PLATE, *json_flag],
                             cwd=ROOT, stdout=full, stderr=subprocess.PIPE, text=True,
                             timeout=120)
    err = run.stderr.strip().splitlines()
    assert run.returncode == 1 and len(err) == 1, run.stderr
    assert "No space left on device" in err[0] and "internal error" not in err[0]


def test_a_malformed_scheduler_is_refused_before_connecting(tmp_path):
    """main: the line, then 20 s later a Client.__del__ traceback at exit."""
    pytest.importorskip("distributed")
    out = tmp_path / "s.csv"
    run = _cli(["sweep", "--radius", "20mm", "--loads", "5N", "--grid", "16",
                "--scheduler", "not a url", "--csv", str(out)])
    assert run.returncode == 1, run.stderr
    lines = run.stderr.strip().splitlines()
    assert len(lines) == 1 and "'not a url' is not a Dask scheduler address" in lines[0]
    assert "Traceback" not in run.stderr and not out.exists()


def test_sweep_checks_every_material_pair_before_any_item(tmp_path, capsys):
    """main: every item ran and became an error row, the file written, 'N failed'."""
    out = tmp_path / "s.csv"
    assert main(["sweep", "--radius", "20mm", "--loads", "5N,6N", "--grid", "16",
                 "--workers", "1", "--materials", "steel,aluminium", "--materials", "steel",
                 "--csv", str(out)]) == 1
    assert "two names" in _line(capsys) and not out.exists()


def _opdx(tmp_path: Path, name: str, edits: dict[int, float]) -> str:
    buf = bytearray(OPDX.read_bytes())
    for offset, value in edits.items():
        struct.pack_into("<d", buf, offset, value)
    path = tmp_path / name
    path.write_bytes(bytes(buf))
    return str(path)


@pytest.mark.skipif(not OPDX.exists(), reason="needs ../shared/realdata")
def test_a_damaged_opdx_is_one_line_without_numpy_warnings(tmp_path, capsys):
    """Two heights at +-1.7e308 with the height scale at 1.7e308 um overflow (main: numpy
    "overflow encountered in multiply" twice, then the error); the last stored position
    at 1.7e308 um (main: OverflowError in roughness, exit 2)."""
    from surfmet.io.opdx import read_tree

    tree = read_tree(OPDX.read_bytes())
    _, arr, _ = tree["/1D_Data/Raw/Array"]
    _, pos, size = tree["/1D_Data/Raw/PositionFunction"]
    raw = OPDX.read_bytes()
    scale = raw.find(struct.pack("<d", tree["/1D_Data/Raw/DataScale"][0]))
    heights = _opdx(tmp_path, "heights.opdx",
                    {scale: 1.7e308, arr + 5: 1.7e308, arr + 13: -1.7e308})
    position = _opdx(tmp_path, "position.opdx", {pos + size - 8: 1.7e308})
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # a warning fails the command
        for f, words in ((heights, "beyond the float range"),
                         (position, "the stored positions jump")):
            for cmd in ("info", "roughness"):
                assert main([cmd, f]) == 1
                assert words in _line(capsys)


def _full_disk_demo(tmp_path: Path, limit: int) -> dict:
    out = tmp_path / "demo"

    def cap() -> None:
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    # no bytecode written under the cap: a .pyc cut short would break later imports
    env = {**os.environ, "PYTHONDONTWRITEBYTECODE": "1"}
    run = _cli(["demo", "--quick", "--out", str(out)], preexec_fn=cap, env=env)
    errors = [ln for ln in run.stderr.splitlines() if ln.startswith("surfmet:")]
    assert run.returncode == 1 and len(errors) == 1, run.stderr
    assert "File too large" in errors[0]
    return json.loads((out / "summary.json").read_text())


@pytest.mark.slow
def test_a_demo_stopped_by_a_full_disk_says_so_in_its_summary(tmp_path):
    """The first figure does not fit (file size capped): summary.json says failed, with
    the reason (main: "status": "running" for ever)."""
    summary = _full_disk_demo(tmp_path, 20000)  # the partial summary (8.3 kB) fits, the figure not
    assert summary["status"] == "failed" and "File too large" in summary["error"]
    assert summary["scans"]["plate"]["file"] == "paper_plate.x3p"  # the partial summary


def test_a_failure_summary_that_does_not_fit_is_written_in_place(tmp_path, monkeypatch):
    """Where the disk takes no new file, the "running" summary's own bytes are
    overwritten with a short failed record."""
    from surfmet.demo import _outputs as outputs

    path = tmp_path / "summary.json"
    outputs.write_json(path, {"generator": outputs.GENERATOR, "status": "running"})

    def full(*args, **kwargs):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(outputs, "write_json", full)
    outputs.record_failure(path, {"generator": outputs.GENERATOR, "big": "x" * 10**5},
                           OSError(28, "No space left on device"))
    rec = json.loads(path.read_text())
    assert rec["status"] == "failed" and "No space left" in rec["error"]
