"""``surfmet roughness`` and ``surfmet fit``: JSON shape, units, CSV, errors."""

from __future__ import annotations

import csv
import io
import json

import numpy as np
import pytest

import surfmet
from surfmet._model import Topography
from surfmet.areal import PARAMETER_UNITS
from surfmet.cli import main


def _run(capsys, *argv):
    rc = main(list(argv))
    out, err = capsys.readouterr()
    return rc, out, err


@pytest.fixture
def scan(tmp_path):
    rng = np.random.default_rng(0)
    _, i = np.mgrid[:96, :128]
    z = 1e-7 * rng.standard_normal((96, 128)) + 1e-4 * i * 1e-6
    path = tmp_path / "plate.npz"
    surfmet.write(Topography(z, 1e-6, 1e-6), path)
    return path


@pytest.fixture
def ball(tmp_path):
    rng = np.random.default_rng(1)
    R, n, dx = 10e-3, 80, 5e-6
    j, i = np.mgrid[:n, :n]
    z = np.sqrt(R**2 - (i * dx - 2e-4) ** 2 - (j * dx - 2e-4) ** 2) + 2e-8 * rng.standard_normal(
        (n, n))
    path = tmp_path / "ball.npz"
    surfmet.write(Topography(z, dx, dx), path)
    return path, R


def test_one_file_json_shape(capsys, scan):
    rc, out, _ = _run(capsys, "roughness", str(scan), "--json")
    assert rc == 0
    rec = json.loads(out)[0]
    assert set(rec) == {"file", "status", "parameters", "settings", "inputs"}
    assert rec["file"] == str(scan)
    for sym, q in rec["parameters"].items():
        assert set(q) == {"value", "unit"}
        assert q["unit"] == PARAMETER_UNITS[sym]
    assert rec["parameters"]["Sa"]["unit"] == "m"
    # Ssk against numpy on the same seeded field with its own least-squares plane removed
    z = surfmet.read(scan).heights
    j, i = np.mgrid[: z.shape[0], : z.shape[1]]
    a = np.column_stack([np.ones(z.size), i.ravel(), j.ravel()])
    d = z.ravel() - a @ np.linalg.lstsq(a, z.ravel(), rcond=None)[0]
    ssk = np.mean(d**3) / np.mean(d**2) ** 1.5
    assert rec["parameters"]["Ssk"]["unit"] == ""
    assert rec["parameters"]["Ssk"]["value"] == pytest.approx(ssk, rel=1e-6, abs=1e-9)
    s = rec["settings"]
    assert s["level"] == "plane" and s["ls"] is None and s["lc"] is None
    assert s["filters"] == [] and s["spikes"] == {"removed": False}
    assert "message" in s["spike_diagnosis"]
    # the plane (a 1e-4 tilt) was removed: Sq is that of the noise
    assert rec["parameters"]["Sq"]["value"] == pytest.approx(1e-7, rel=0.05)


def test_filters_and_spikes_are_recorded(capsys, scan):
    rc, out, _ = _run(capsys, "roughness", str(scan), "--lc", "50um", "--ls", "3um",
                      "--spikes", "--level", "poly:2", "--json")
    assert rc == 0
    s = json.loads(out)[0]["settings"]
    assert s["lc"] == {"value": pytest.approx(50e-6), "unit": "m"}
    assert s["ls"] == {"value": pytest.approx(3e-6), "unit": "m"}
    assert [f["kind"] for f in s["filters"]] == ["S", "L"]
    assert s["filters"][1]["edge"] == "discard" and s["edge"]["value"] == "discard"
    assert s["spikes"]["removed"] is True and s["spikes"]["count"] == 0
    assert s["level"] == "poly:2"


def test_several_files_json_and_csv(capsys, scan, tmp_path):
    bad = tmp_path / "broken.x3p"
    bad.write_bytes(b"PK\x03\x04 not really a zip")
    rc, out, err = _run(capsys, "roughness", str(scan), str(bad), str(scan), "--json")
    assert rc == 1  # one file failed
    recs = json.loads(out)
    assert [r["status"] for r in recs] == ["ok", "error", "ok"]
    assert "error" in recs[1] and recs[1]["file"] == str(bad)
    assert err.count("\n") == 1 and "broken.x3p" in err
    out_csv = tmp_path / "t.csv"
    rc, _, _ = _run(capsys, "roughness", str(scan), str(bad), "--csv", str(out_csv))
    rows = list(csv.DictReader(io.StringIO(out_csv.read_text())))
    assert rc == 1
    assert rows[0]["status"] == "ok" and float(rows[0]["Sa [m]"]) > 0
    assert rows[1]["status"] == "error" and rows[1]["error"]
    assert list(rows[0])[:10] == ["file", "status", "error", "standard", "lc [m]", "ls [m]",
                                  "n_sampling", "conditions", "caveats", "Sa [m]"]
    assert rows[0]["standard"].startswith("ISO 25178-2")
    assert "Ssk" in rows[0] and "Spd [1/m^2]" in rows[0]


def test_human_table(capsys, scan):
    rc, out, _ = _run(capsys, "roughness", str(scan))
    assert rc == 0 and "Sa" in out and "nm" in out and "diagnosis" in out


@pytest.mark.parametrize("argv, needle", [
    (["roughness", "/nonexistent/scan.x3p"], "scan.x3p"),
    (["roughness", "{scan}", "--lc", "3furlong"], "unit"),
    (["roughness", "{scan}", "--lc", "1mm"], "too small"),
    (["roughness", "{scan}", "--level", "banana"], "banana"),
    (["roughness", "{scan}", "--profile", "row:999"], "row"),
    (["fit", "{scan}", "--shape", "circle"], "--profile"),
])
def test_user_errors_exit_1_with_one_line(capsys, scan, argv, needle):
    argv = [a.replace("{scan}", str(scan)) for a in argv]
    rc, out, err = _run(capsys, *argv)
    assert rc == 1
    assert out == ""
    assert err.count("\n") == 1 and err.startswith("surfmet: error:")
    assert needle in err


def test_fit_sphere_json(capsys, ball):
    path, R = ball
    rc, out, _ = _run(capsys, "fit", str(path), "--shape", "sphere", "--json")
    assert rc == 0
    rec = json.loads(out)
    for key in ("radius", "rms_residual", "radius_uncertainty"):
        assert rec[key]["unit"] == "m" and isinstance(rec[key]["value"], float)
    assert rec["center"]["unit"] == "m" and len(rec["center"]["value"]) == 3
    assert abs(rec["radius"]["value"] - R) < 4 * rec["radius_uncertainty"]["value"]


def test_fit_circle_of_a_row(capsys, ball):
    path, R = ball
    rc, out, _ = _run(capsys, "fit", str(path), "--shape", "circle", "--profile", "row:40",
                      "--loss", "huber", "--json")
    assert rc == 0
    rec = json.loads(out)
    # row 40 is at y = 2e-4 m, through the apex: the section radius is R
    assert rec["radius"]["value"] == pytest.approx(R, rel=0.02)
    assert len(rec["center"]["value"]) == 2 and rec["center"]["unit"] == "m"
    assert rec["radius_uncertainty"]["unit"] == "m"


def test_uncalibrated_units_carry_a_caveat_into_every_output(capsys, realdata, tmp_path):
    # issue 16 item 12: test.gwy states no units; info says so, roughness must too
    path = str(realdata("test.gwy"))
    rc, out, _ = _run(capsys, "roughness", path, "--json")
    assert rc == 0
    caveats = json.loads(out)[0]["settings"]["caveats"]
    assert any("pixel size assumed" in c for c in caveats)
    assert any("height unit" in c for c in caveats)
    rc, out, _ = _run(capsys, "roughness", path)
    assert out.count(" assumed: the file states none") == 2
    table = tmp_path / "t.csv"
    _run(capsys, "roughness", path, "--csv", str(table))
    row = next(csv.DictReader(io.StringIO(table.read_text())))
    assert "pixel size assumed" in row["caveats"]
    # a calibrated file has none
    rc, out, _ = _run(capsys, "roughness", str(realdata("x3p-2.x3p")), "--json")
    assert "caveats" not in json.loads(out)[0]["settings"]


def test_diagnosis_and_table_agree_and_no_spike_advice_after_removal(capsys, tmp_path):
    # issue 16 item 13: (1) a profile's table said Rku 79.6 and its diagnosis 79.9 (about
    # the sample mean instead of the mean line); (2) after --spikes removed spikes the
    # diagnosis still advised "--spikes"
    from surfmet._model import Profile

    rng = np.random.default_rng(12)
    z = 1e-8 * rng.standard_normal(4000) + 3e-9  # a mean off the mean line
    z[rng.choice(4000, 30, replace=False)] += 2e-7
    path = tmp_path / "spiky_profile.npz"
    surfmet.write(Profile(z, 0.5e-6), path)
    rc, out, _ = _run(capsys, "roughness", str(path), "--lc", "none", "--level", "none",
                      "--json")
    assert rc == 0
    rec = json.loads(out)[0]
    rku = rec["parameters"]["Rku"]["value"]
    # numpy truth: the kurtosis about the mean line (z = 0), as ISO defines Rku
    assert rku == pytest.approx(np.mean(z**4) / np.mean(z**2) ** 2, rel=1e-9)
    diag = rec["settings"]["spike_diagnosis"]
    assert f"Rku = {rku:.3g}" in diag["message"]
    # an areal scan with wide pits that are not spikes: they stay after --spikes
    j, i = np.mgrid[:120, :120]
    zz = 1e-8 * rng.standard_normal((120, 120))
    for cj, ci in ((30, 30), (80, 90), (60, 20)):
        zz[(j - cj) ** 2 + (i - ci) ** 2 < 36] -= 2e-6
    zz[rng.integers(0, 120, 20), rng.integers(0, 120, 20)] += 3e-6
    scan = tmp_path / "pits.npz"
    surfmet.write(Topography(zz, 1e-6, 1e-6), scan)
    rc, out, _ = _run(capsys, "roughness", str(scan), "--spikes", "--json")
    assert rc == 0
    s = json.loads(out)[0]["settings"]
    assert s["spikes"]["count"] > 0 and s["spike_diagnosis"]["suspected"]
    assert "--spikes" not in s["spike_diagnosis"]["message"]
    assert "after removing" in s["spike_diagnosis"]["message"]


def test_areal_default_leaves_out_the_filter_edges_and_gets_the_closed_form_sq(capsys,
                                                                               tmp_path):
    # three plane waves between λc/6 and λc/2 on a 2.5 λc scan: after the L-filter each
    # keeps 1 - exp(-π (α λc / λ)²) of its amplitude (ISO 16610-61), so the S-L surface is
    # known in closed form at every point; Sq over the area the output keeps must be its
    # rms there (issue 18: the kept edge bands made Sq about 2 % low)
    from surfmet.areal._filters import ALPHA

    n, dx, lc = 500, 4e-6, 0.8e-3
    y, x = np.mgrid[:n, :n] * dx
    rng = np.random.default_rng(3)
    z = np.zeros((n, n))
    filtered = np.zeros((n, n))
    for lam, amp in ((0.2e-3, 1e-6), (0.4e-3, 0.7e-6), (0.13e-3, 0.5e-6)):
        th, ph = rng.uniform(0, np.pi), rng.uniform(0, 2 * np.pi)
        wave = np.sin(2 * np.pi * (x * np.cos(th) + y * np.sin(th)) / lam + ph)
        z += amp * wave
        filtered += amp * (1 - np.exp(-np.pi * (ALPHA * lc / lam) ** 2)) * wave
    path = tmp_path / "waves.npz"
    surfmet.write(Topography(z, dx, dx), path)
    rc, out, _ = _run(capsys, "roughness", str(path), "--lc", "0.8mm", "--level", "none",
                      "--json")
    assert rc == 0
    rec = json.loads(out)[0]
    band = rec["settings"]["filters"][0]["discarded_points_each_edge"]["rows"]
    assert band == 100  # λc/2 = 400 µm = 100 points
    inner = filtered[band:n - band, band:n - band]
    assert rec["parameters"]["Sq"]["value"] == pytest.approx(inner.std(), rel=1e-3)
    assert "left out" in rec["settings"]["edge"]["meaning"]
    # keeping the bands with the moment correction misses the whole surface's Sq by > 1 %
    rc, out, _ = _run(capsys, "roughness", str(path), "--lc", "0.8mm", "--level", "none",
                      "--edge", "moment", "--json")
    kept = json.loads(out)[0]["parameters"]["Sq"]["value"]
    assert kept < 0.99 * filtered.std()


def test_json_has_one_shape_for_one_file_or_several(capsys, scan):
    """A list of per-file records whatever the number of files, so that a script reading
    ``roughness *.x3p --json`` does not break when the glob matches one file (main: an
    object for one file, a list for several)."""
    rc, one, _ = _run(capsys, "roughness", str(scan), "--json")
    assert rc == 0
    rc, two, _ = _run(capsys, "roughness", str(scan), str(scan), "--json", "--workers", "1")
    assert rc == 0
    one, two = json.loads(one), json.loads(two)
    assert isinstance(one, list) and len(one) == 1 and len(two) == 2
    assert one[0] == two[0] == two[1]


def _flip_exponent_bit(path, index):
    """Flip bit 62 (the exponent's top bit) of float64 number ``index`` of a .npy file."""
    raw = bytearray(path.read_bytes())
    start = len(raw) - 8 * int(np.load(path).size) + 8 * index
    raw[start + 7] ^= 0x40  # little-endian: byte 7 holds the sign and the top exponent bits
    path.write_bytes(bytes(raw))


def test_one_flipped_bit_is_refused_not_summarised(tmp_path, capsys):
    """Issue 25 item 12: one flipped exponent bit turns a 2 µm height into ~1e302 m; the
    reader flags the file (it still reads, and writes back exactly) and the analysis
    refuses it in one line (exit 1) instead of printing Sa = 2e301 m and "Sq n/a" with
    exit 0."""
    z = np.random.default_rng(5).normal(scale=1e-6, size=(32, 32)) + 2e-6
    path = tmp_path / "flipped.npy"
    np.save(path, z)
    _flip_exponent_bit(path, 100)
    assert abs(np.load(path).ravel()[100]) > 1e300  # the premise: one damaged height
    assert main(["roughness", str(path)]) == 1
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "peak to valley" in err and "damaged" in err
    assert "peak to valley" in surfmet.read(path).metadata["height_range"]
    # an intact file of the same heights carries no flag
    np.save(path, z)
    assert "height_range" not in surfmet.read(path).metadata


def test_heights_beyond_any_surface_are_refused_by_the_statistics():
    """Issue 25 items 11-12: a Topography built in memory with heights x 1e300 is refused
    by the parameters themselves (no OverflowError, no non-finite Sq)."""
    from surfmet._errors import SurfmetInputError
    from surfmet.roughness import roughness

    z = np.random.default_rng(6).normal(size=(32, 32)) * 1e294
    with pytest.raises(SurfmetInputError, match="not a surface measurement"):
        roughness(Topography(z, 1e-6, 1e-6))


def test_a_ball_levelled_by_a_plane_is_said_to_be_dominated_by_its_form(capsys):
    """Issue 25 item 6: the paper's ball read with the default plane gives Sa ~ 124 µm of
    spherical cap; the output says a curved form dominates and how to remove it, and says
    nothing of the kind once the sphere is removed, nor for the (flat) paper plate."""
    from pathlib import Path

    data = Path(surfmet.__file__).parent / "data"
    assert main(["roughness", str(data / "paper_ball.x3p"), "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)[0]
    caveats = rec["settings"].get("caveats", [])
    assert any("a curved form dominates" in c and "--level sphere" in c for c in caveats)
    assert rec["parameters"]["Sa"]["value"] > 50e-6  # the premise: Sa is the cap's
    for argv in (["paper_ball.x3p", "--level", "sphere"], ["paper_plate.x3p"]):
        assert main(["roughness", str(data / argv[0]), *argv[1:], "--json"]) == 0
        rec = json.loads(capsys.readouterr().out)[0]
        assert not any("form dominates" in c for c in rec["settings"].get("caveats", []))
