"""``surfmet contact`` end to end: smooth Hertz case, scans, JSON, saved fields, errors."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from contact_synth import rough_surface

import surfmet
from contact import composite_modulus, hertz_sphere, material
from surfmet.cli import main

E_STAR = composite_modulus(material("steel"), material("aluminium"))
KEYS = ("pmax", "contact_radius", "approach", "area_fraction", "load")


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_smooth_case_json(capsys):
    rec = _json(capsys, ["contact", "--radius", "20mm", "--load", "10N",
                         "--materials", "steel,aluminium", "--json"])
    hz = hertz_sphere(0.02, 10.0, E_STAR)
    for key in KEYS:
        assert set(rec[key]) == {"value", "unit"}, key
    assert rec["load"] == {"value": pytest.approx(10.0, rel=1e-10), "unit": "N"}
    assert rec["pmax"]["unit"] == "Pa"
    assert rec["pmax"]["value"] == pytest.approx(hz.p0, rel=1e-4)
    assert rec["contact_radius"]["unit"] == "m"
    assert abs(rec["contact_radius"]["value"] - hz.a) < rec["grid"]["dx"]["value"]
    assert rec["approach"]["value"] == pytest.approx(hz.delta, rel=1e-4)
    assert rec["area_fraction"]["unit"] == ""
    assert rec["converged"] is True and rec["touches_edge"] is False
    assert isinstance(rec["iterations"], int) and rec["iterations"] > 0
    assert rec["hertz"]["a"] == {"value": pytest.approx(hz.a), "unit": "m"}
    assert rec["hertz"]["delta"]["value"] == pytest.approx(0.936e-6, abs=0.5e-9)
    assert rec["hertz"]["p0"]["unit"] == "Pa"


def test_text_output_and_overrides(capsys):
    assert main(["contact", "--radius", "20mm", "--load", "10N", "--grid", "64",
                 "--materials", "steel:E=200GPa:nu=0.29,al:H=1GPa", "--plastic"]) == 0
    out = capsys.readouterr().out
    assert "max pressure" in out and "Hertz p0" in out and "plastic area" in out
    table, inputs = out.split("\ninputs\n")
    assert "200 GPa" not in table  # E* is shown, not E; the inputs echo E as given
    assert "steel (E 200 GPa, ν 0.29" in inputs
    E = composite_modulus(material("steel", E=200e9, nu=0.29), material("aluminium"))
    assert f"{E / 1e9:.4g} GPa" in out


def test_scans_and_saved_fields(tmp_path, capsys):
    dx = 5e-6
    plate_z = rough_surface(192, dx, 0.4e-6, seed=1)
    yy, xx = np.indices(plate_z.shape)
    plate = surfmet.Topography(plate_z + 2e-3 * xx * dx + 1e-5, dx, dx)  # hidden tilt
    n, bdx = 40, 25e-6
    yy, xx = np.indices((n, n))
    r2 = ((xx - 19.5) * bdx) ** 2 + ((yy - 19.5) * bdx) ** 2
    ball = surfmet.Topography(np.sqrt(0.02**2 - r2) + rough_surface(n, bdx, 0.05e-6, 2,
                                                                   corr=50e-6), bdx, bdx)
    surfmet.write(plate, tmp_path / "plate.npz")
    surfmet.write(ball, tmp_path / "ball.npz")
    out = tmp_path / "res.npz"
    rec = _json(capsys, ["contact", "--plate", str(tmp_path / "plate.npz"), "--ball",
                         str(tmp_path / "ball.npz"), "--radius", "20mm", "--load", "10N",
                         "--materials", "steel,aluminium", "--json", "--out", str(out)])
    assert rec["converged"] and not rec["touches_edge"]
    assert rec["load"]["value"] == pytest.approx(10.0, rel=1e-10)
    assert rec["roughness"]["ball_fit_radius"]["value"] == pytest.approx(0.02, rel=0.02)
    # Independent truth: the plate's rms about its own least-squares plane (the CLI levels
    # the scan), combined with the ball roughness. The ball's share of the variance lies
    # between none and all of the 0.05 um generated (its sphere fit and the interpolation
    # from 25 um to 5 um can only lower it). The cross term of two independent fields over
    # the 955 um window, ~(955/50)^2 = 365 independent ball patches, has a sample
    # correlation of at most 3/sqrt(365) = 0.16 (3 sigma): 2 * 0.16 * 0.4 * 0.05 / 0.4^2
    # = 4 % of the variance, 2 % of the rms.
    cols, rows = np.meshgrid(np.arange(192.0), np.arange(192.0))
    design = np.column_stack([np.ones(cols.size), cols.ravel(), rows.ravel()])
    heights = np.asarray(plate.heights).ravel()
    plane, *_ = np.linalg.lstsq(design, heights, rcond=None)
    plate_rms = float(np.sqrt(np.mean((heights - design @ plane) ** 2)))
    composite = rec["roughness"]["composite_rms"]["value"]
    assert plate_rms * 0.98 <= composite <= math.hypot(plate_rms, 0.05e-6) * 1.02
    hz = hertz_sphere(0.02, 10.0, E_STAR)
    assert rec["pmax"]["value"] > hz.p0  # rough: asperity peaks above the Hertz peak
    with np.load(out) as f:
        assert f["pressure"].shape == (rec["grid"]["ny"], rec["grid"]["nx"])
        assert f["pressure"].sum() * float(f["dx"]) * float(f["dy"]) == pytest.approx(10.0)
        assert set(f.files) >= {"pressure", "gap", "displacement", "plastic_displacement", "x",
                                "y", "summary"}
        assert json.loads(str(f["summary"]))["pmax"]["value"] == rec["pmax"]["value"]


def test_smooth_scans_reproduce_hertz(tmp_path, capsys):
    # A flat, tilted plate and an exact spherical cap, through the whole scan pipeline
    # (levelling, sphere fit, pairing) and the solver: no roughness is left, so the answer
    # is Hertz's closed form up to the grid. The scans' pixel dx = 5 um puts a/dx = 27
    # cells on the Hertz radius; the uniform-pressure cells and the collocation at their
    # centres make p0 and delta err by O((dx/a)^2) = 1.3e-3, and the contact area counts
    # whole cells, so the contact radius is known to half a cell.
    dx, n, bdx = 5e-6, 40, 25e-6
    _, cols = np.indices((192, 192))
    plate = surfmet.Topography(2e-3 * cols * dx + 1e-5, dx, dx)
    yy, xx = np.indices((n, n))
    r2 = ((xx - 19.5) * bdx) ** 2 + ((yy - 19.5) * bdx) ** 2
    ball = surfmet.Topography(np.sqrt(0.02**2 - r2), bdx, bdx)
    surfmet.write(plate, tmp_path / "plate.npz")
    surfmet.write(ball, tmp_path / "ball.npz")
    rec = _json(capsys, ["contact", "--plate", str(tmp_path / "plate.npz"), "--ball",
                         str(tmp_path / "ball.npz"), "--radius", "20mm", "--load", "10N",
                         "--materials", "steel,aluminium", "--json"])
    hz = hertz_sphere(0.02, 10.0, E_STAR)
    assert rec["grid"]["dx"]["value"] == pytest.approx(dx)
    assert rec["converged"] and not rec["touches_edge"]
    assert rec["roughness"]["composite_rms"]["value"] < 1e-12  # the forms removed exactly
    assert rec["roughness"]["ball_fit_radius"]["value"] == pytest.approx(0.02, rel=1e-9)
    grid_error = (dx / hz.a) ** 2
    assert rec["pmax"]["value"] == pytest.approx(hz.p0, rel=grid_error)
    assert rec["approach"]["value"] == pytest.approx(hz.delta, rel=grid_error)
    assert abs(rec["contact_radius"]["value"] - hz.a) <= dx / 2


@pytest.mark.parametrize("argv", [
    ["--radius", "20mm", "--load=-1N", "--materials", "steel,aluminium"],
    ["--radius", "20mm", "--load", "10N", "--materials", "steel"],
    ["--radius", "20mm", "--load", "10N", "--materials", "steel,unobtainium"],
    ["--radius", "0mm", "--load", "10N", "--materials", "steel,aluminium"],
    ["--radius", "20mm", "--load", "10N", "--materials", "steel:E=-3GPa,aluminium"],
    ["--radius", "20mm", "--load", "10N", "--materials", "steel,aluminium", "--grid", "4"],
])
def test_user_errors_exit_1_with_one_line(argv, capsys):
    assert main(["contact", *argv]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("surfmet: error:")


def test_all_nan_plate_is_refused(tmp_path, capsys):
    np.save(tmp_path / "nan.npy", np.full((20, 20), np.nan))
    assert main(["contact", "--plate", str(tmp_path / "nan.npy"), "--radius", "20mm",
                 "--load", "10N", "--materials", "steel,aluminium"]) == 1
    assert "error" in capsys.readouterr().err


def test_non_convergence_is_an_error_with_the_residual(capsys):
    assert main(["contact", "--radius", "20mm", "--load", "10N", "--materials",
                 "steel,aluminium", "--max-iter", "1", "--tol", "1e-12", "--grid", "32"]) == 1
    assert "residual" in capsys.readouterr().err


@pytest.mark.realdata
def test_real_plate_scan(realdata, capsys):
    rec = _json(capsys, ["contact", "--plate", str(realdata("plu-1.plu")), "--radius", "20mm",
                         "--load", "10N", "--materials", "steel,aluminium", "--json"])
    assert rec["converged"] and not rec["touches_edge"]
    assert rec["load"]["value"] == pytest.approx(10.0, rel=1e-10)
    assert rec["n_clusters"] > 1
    assert rec["pmax"]["value"] > rec["hertz"]["p0"]["value"]


@pytest.mark.realdata
def test_real_scan_too_small_for_the_contact(realdata, capsys):
    # nms-1 is 160 um wide, narrower than the 274 um Hertz contact
    argv = ["contact", "--plate", str(realdata("nms-1.nms")), "--radius", "20mm", "--load",
            "10N", "--materials", "steel,aluminium"]
    assert main(argv) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert "do not overlap the contact" in err[-1] and "273.6 µm" in err[-1]
    assert len(err[-1]) < 400 and "Traceback" not in "".join(err)
    assert all(line.startswith("note:") for line in err[:-1])
    rec = _json(capsys, [*argv, "--on-edge", "warn", "--json"])
    assert rec["touches_edge"] is True
    assert any("truncated" in note for note in rec["notes"])


def test_one_name_one_radius_across_contact_and_hertz_check(capsys):
    """Issue 25 item 2: ``contact_radius`` is sqrt(A_real/pi) in both commands, and the
    second-moment radius a* is ``effective_radius`` in both, for the same solve."""
    from pathlib import Path

    plate = str(Path(surfmet.__file__).parent / "data" / "paper_plate.x3p")
    common = ["--radius", "20mm", "--load", "10N", "--materials", "steel,aluminium",
              "--grid", "64", "--json"]
    assert main(["contact", "--plate", plate, *common]) == 0
    con = json.loads(capsys.readouterr().out)
    assert main(["hertz-check", plate, "--elastic", *common]) == 0
    chk = json.loads(capsys.readouterr().out)
    bem = chk["bem"]
    # the real-area radius against its definition, in each record
    assert con["contact_radius"]["value"] == pytest.approx(
        math.sqrt(con["contact_area"]["value"] / math.pi), rel=1e-12)
    assert bem["contact_radius"]["value"] == pytest.approx(
        math.sqrt(bem["area_fraction"]["value"]) * chk["hertz"]["a"]["value"], rel=1e-9)
    # same solve, same names, same numbers
    for key in ("contact_radius", "effective_radius"):
        assert con[key]["value"] == pytest.approx(bem[key]["value"], rel=1e-6), key
    # on this rough plate the two radii are different quantities
    assert con["effective_radius"]["value"] > 2 * con["contact_radius"]["value"]
