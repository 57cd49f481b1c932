"""Units a file does not state (issue 34, item 5).

``h5-multiple.h5`` states no unit and no pixel; its first data set is the map of
``mi-1.mi`` (256 x 256 points over 20 µm, heights in µm: MANIFEST.tsv), read by an
independent reader. Every output says what was assumed, and ``--height-unit``,
``--pixel`` and ``--channel`` state it on every command that reads a scan.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from surfmet.cli import main

#: mi-1.mi: 256 points over 20 µm (MANIFEST.tsv), so its pixel is 78.125 nm.
MI_PIXEL = "78.125nm"


def _run(capsys, *argv):
    rc = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return rc, out, err


def _params(capsys, *argv):
    rc, out, err = _run(capsys, "roughness", *argv, "--json")
    assert rc == 0, err
    rec = json.loads(out)[0]
    return rec["parameters"], rec["settings"].get("caveats", [])


@pytest.fixture
def h5(realdata):
    return realdata("h5-multiple.h5")


def test_info_says_the_h5_units_are_assumed_in_text_and_json(capsys, h5):
    rc, out, _ = _run(capsys, "info", h5)
    assert rc == 0
    assert "height unit   m  (assumed)" in out
    assert "pixel size    1 m x 1 m  (assumed)" in out
    assert "CAVEAT: height unit assumed: the file states none" in out
    rc, out, _ = _run(capsys, "info", h5, "--json")
    units = json.loads(out)["units"]
    assert units["height_unit"] == {"unit": "m", "source": "assumed", "stated_by": "assumed"}
    assert units["pixel"]["source"] == "assumed"
    assert units["pixel"]["dx"] == {"value": 1.0, "unit": "m"}


def test_roughness_of_h5_says_what_was_assumed_in_text_and_json(capsys, h5):
    rc, out, _ = _run(capsys, "roughness", h5)
    assert rc == 0
    assert "CAVEAT: height unit assumed: the file states none, so its heights are taken as m" \
        in out
    assert "CAVEAT: pixel size assumed" in out
    _, caveats = _params(capsys, h5)
    assert any(c.startswith("height unit assumed") for c in caveats)
    assert any(c.startswith("pixel size assumed") for c in caveats)


def test_height_unit_and_pixel_give_the_numbers_of_the_same_map_in_mi(capsys, h5, realdata):
    # the same map read from mi-1.mi, whose header states µm and 20 µm over 256 points
    mi, mi_caveats = _params(capsys, realdata("mi-1.mi"))
    assert mi_caveats == []
    ours, caveats = _params(capsys, h5, "--height-unit", "um", "--pixel", MI_PIXEL)
    for name in ("Sa", "Sq", "Sz", "Sdq", "Sdr", "Sal"):
        assert ours[name]["unit"] == mi[name]["unit"]
        assert ours[name]["value"] == pytest.approx(mi[name]["value"], rel=1e-9), name
    assert mi["Sa"]["value"] == pytest.approx(2.579e-9, rel=1e-3)  # nm, not mm
    assert caveats and all("stated by the user" in c for c in caveats)
    rc, out, _ = _run(capsys, "roughness", h5, "--height-unit", "µm", "--pixel", MI_PIXEL)
    assert rc == 0
    assert "CAVEAT: height unit stated by the user: the file's heights are in µm" in out
    assert "assumed" not in out


def test_pixel_scales_the_lateral_quantities_as_it_should(capsys, h5):
    # heights fixed, lateral lengths doubled: slopes halve, Sdr (~ slope²) quarters at
    # small slopes, Sal doubles, Spd (per area) quarters; heights do not change
    one, _ = _params(capsys, h5, "--height-unit", "um", "--pixel", "1um")
    two, _ = _params(capsys, h5, "--height-unit", "um", "--pixel", "2um")
    assert two["Sa"]["value"] == pytest.approx(one["Sa"]["value"], rel=1e-12)
    assert two["Sdq"]["value"] == pytest.approx(one["Sdq"]["value"] / 2, rel=1e-12)
    assert two["Sal"]["value"] == pytest.approx(one["Sal"]["value"] * 2, rel=1e-9)
    assert two["Spd"]["value"] == pytest.approx(one["Spd"]["value"] / 4, rel=1e-9)
    # dx, dy apart: the x and y steps are each the user's
    rc, out, _ = _run(capsys, "info", h5, "--pixel", "1um,2um", "--json")
    assert rc == 0
    rec = json.loads(out)
    assert (rec["dx"]["value"], rec["dy"]["value"]) == (pytest.approx(1e-6), pytest.approx(2e-6))
    assert rec["units"]["pixel"]["source"] == "user"


def test_channel_picks_a_data_set(capsys, h5):
    # MANIFEST: two data sets of 256 x 256 and 640 x 480 (nx x ny)
    for channel, grid in (("0", (256, 256)), ("1", (640, 480)), ("dataset2", (640, 480))):
        rc, out, _ = _run(capsys, "info", h5, "--channel", channel, "--json")
        rec = json.loads(out)
        assert rc == 0 and (rec["nx"], rec["ny"]) == grid
    first, _ = _params(capsys, h5)
    second, _ = _params(capsys, h5, "--channel", "1")
    assert second["Sa"]["value"] != first["Sa"]["value"]
    rc, _, err = _run(capsys, "roughness", h5, "--channel", "2")
    assert rc == 1 and err.count("\n") == 1 and "does not exist" in err


def test_a_single_channel_file_and_a_stated_unit_refuse_what_contradicts_them(capsys,
                                                                              realdata):
    x3p = realdata("x3p-2.x3p")
    rc, _, err = _run(capsys, "roughness", x3p, "--channel", "1")
    assert rc == 1 and "single channel" in err and err.count("\n") == 1
    rc, _, err = _run(capsys, "roughness", x3p, "--height-unit", "nm")
    assert rc == 1 and "states its height unit" in err and err.count("\n") == 1
    rc, _, err = _run(capsys, "roughness", x3p, "--pixel", "1um")
    assert rc == 1 and "states its pixel size" in err
    # the unit it states, given again, is no contradiction
    rc, out, _ = _run(capsys, "roughness", x3p, "--height-unit", "m")
    assert rc == 0 and "CAVEAT" not in out
    # a text matrix whose header states metres (after its rad -> m factor): the same rule,
    # and the user's mistake is not reported as a damaged file
    rc, _, err = _run(capsys, "info", realdata("matrix-4.txt"), "--height-unit", "nm")
    assert rc == 1 and "states its height unit (m)" in err and "inconsistent" not in err
    rc, out, _ = _run(capsys, "info", realdata("matrix-4.txt"), "--height-unit", "m")
    assert rc == 0 and "height unit   m  (stated by the file)" in out


def test_pixel_needs_a_unit(capsys, h5):
    rc, _, err = _run(capsys, "roughness", h5, "--pixel", "1")
    assert rc == 1 and "has no unit" in err and err.count("\n") == 1


def test_tmd_says_it_assumes_millimetres(capsys, realdata):
    tmd = realdata("tmd-1.tmd")
    rc, out, _ = _run(capsys, "roughness", tmd)
    assert rc == 0
    assert "CAVEAT: height unit assumed: the file states none, so its heights are taken as mm" \
        in out
    assert "CAVEAT: lateral unit assumed: the file states none, so its lengths are taken as mm" \
        in out
    mm, caveats = _params(capsys, tmd)
    assert len(caveats) == 2 and all("assumed" in c for c in caveats)
    um, caveats = _params(capsys, tmd, "--height-unit", "um")
    assert um["Sa"]["value"] == pytest.approx(mm["Sa"]["value"] / 1000, rel=1e-12)
    assert [c.split(":")[0] for c in caveats] == ["height unit stated by the user",
                                                  "lateral unit assumed"]


def test_info_lists_every_measurement_of_a_container_and_every_data_set(capsys, h5, realdata):
    # MANIFEST: a TEM line scan (.asc), an AFM map (Nanoscope), a stylus profile (.txt)
    rc, out, _ = _run(capsys, "info", realdata("container-2.zip"), "--json")
    listed = json.loads(out)["channels_read"]
    assert [m["kind"] for m in listed] == ["profile", "areal", "profile"]
    assert [m["channel"] for m in listed] == [0, 1, 2]
    rc, out, _ = _run(capsys, "info", realdata("container-2.zip"))
    assert "measurements  3" in out
    assert out.count(" profile ") >= 2 and " areal 512 x 512" in out
    rc, out, _ = _run(capsys, "info", h5, "--json")
    grids = [(m["nx"], m["ny"]) for m in json.loads(out)["channels_read"]]
    assert grids == [(256, 256), (640, 480)]
    # a container measurement is a channel too
    rc, out, _ = _run(capsys, "info", realdata("container-2.zip"), "--channel", "1", "--json")
    assert rc == 0 and json.loads(out)["kind"] == "areal"


def test_a_contact_on_a_bare_array_with_its_units_stated_is_the_contact_on_the_x3p(
        capsys, tmp_path):
    # the bundled plate written as a bare array of micrometres: stating µm and its 5 µm
    # pixel gives the scan the x3p states, so the same contact
    import surfmet

    plate = surfmet.read("surfmet/data/paper_plate.x3p")
    bare = tmp_path / "plate.npy"
    np.save(bare, plate.heights * 1e6)
    common = ["--radius", "20mm", "--load", "10N", "--materials", "steel,aluminium",
              "--json"]
    _, ref, _ = _run(capsys, "hertz-check", "surfmet/data/paper_plate.x3p", *common)
    rc, out, _ = _run(capsys, "hertz-check", bare, "--plate-height-unit", "um",
                      "--plate-pixel", "5um", *common)
    assert rc == 0
    ref, ours = json.loads(ref), json.loads(out)
    for key in ("approach", "contact_radius", "area_fraction"):
        assert ours["bem"][key]["value"] == pytest.approx(ref["bem"][key]["value"], rel=1e-9)
    notes = ours["scan_preparation"]["notes"]
    assert "CAVEAT (plate scan): pixel size stated by the user: 5 µm (the file states none)" \
        in notes


def test_every_reader_marks_what_its_file_states_as_the_manifest_says(realdata):
    # MANIFEST.tsv's height_unit_in_file: "none"/"None" for the files that state no unit;
    # tmd-1's "mm" is SurfaceTopography's reading of a header that has no unit field
    # (surfmet.io.tmd), so it is assumed too. Every other file states both.
    import csv

    import surfmet

    manifest = realdata("MANIFEST.tsv")
    rows = list(csv.DictReader(manifest.open(encoding="utf-8"), delimiter="\t"))
    assert len(rows) == 33
    for row in rows:
        cal = surfmet.read(realdata(row["filename"])).calibration
        unstated = row["height_unit_in_file"] in ("none", "None") or row["filename"] == \
            "tmd-1.tmd"
        expected = "assumed" if unstated else "file"
        assert (cal.height, cal.lateral) == (expected, expected), row["filename"]
        assert bool(cal.caveats()) == unstated, row["filename"]


def test_sweep_refuses_a_contradicted_pixel_before_any_row(capsys, tmp_path):
    out = tmp_path / "rows.csv"
    rc, _, err = _run(capsys, "sweep", "--plates", "surfmet/data/paper_plate.x3p",
                      "--radius", "20mm", "--loads", "10N", "--pixel", "1um", "--csv", out)
    assert rc == 1 and "states its pixel size (5 µm)" in err and err.count("\n") == 1
    assert not out.exists()
