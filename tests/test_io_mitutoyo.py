"""Mitutoyo SurfTest .xlsx reader: the real export against SurfaceTopography's test
(test/IO/test_mitutoyo.py, test_read_uniform_2) and the sheet's own printout; small
workbooks built here from the SpreadsheetML layout for the edge cases."""

from __future__ import annotations

import io
import zipfile

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import detect_format, read_bytes

# SurfaceTopography's EXPECTED_CHANNEL_INFO_2: the 23 results the instrument printed.
PRINTED = [("Ra", 3.308, "µm"), ("Rq", 3.959, "µm"), ("Rz", 18.485, "µm"), ("Rp", 8.244, "µm"),
           ("Rv", 10.24, "µm"), ("Rsk", -0.144, ""), ("Rkµ", 2.463, ""), ("Rc", 13.306, "µm"),
           ("RSm", 419.9, "µm"), ("RDq", 0.157, ""), ("Rmr", 0.03, "%"),
           ("Rmr(c)1", 2.911, "%"), ("Rmr(c)2", 5.822, "%"), ("Rdc", 1.828, "µm"),
           ("Rt", 22.233, "µm"), ("Rz1max", 22.062, "µm"), ("Rk", 11.44, "µm"),
           ("Rpk", 2.912, "µm"), ("Rvk", 3.98, "µm"), ("Mr1", 5.822, "%"), ("Mr2", 92.617, "%"),
           ("A1", 8.48, ""), ("A2", 14.69, "")]
RENAMED = {"Rkµ": "Rku", "RDq": "Rdq", "RSm": "Rsm"}
SI = {"µm": 1e-6, "%": 0.01, "": 1.0}


@pytest.fixture(scope="module")
def mit2():
    from conftest import REALDATA, shared_file
    return surfmet.read(shared_file(REALDATA / "mitutoyo_2_mock.xlsx"))


@pytest.mark.realdata
def test_grid_length_and_rms_match_surfacetopography(mit2):
    p = mit2
    assert p.n == 6664
    assert p.is_uniform
    assert p.dx == pytest.approx(1.5e-6, rel=1e-9)
    assert p.n * p.dx == pytest.approx(9996e-6, rel=1e-9)  # ST: physical size 9996 µm
    rms = np.sqrt(np.mean((p.z - p.z.mean()) ** 2))  # ST rms_height_from_profile
    assert rms == pytest.approx(3.96889742e-6, rel=1e-7)
    assert p.metadata["height_unit"] == "µm"
    assert p.metadata["vendor"] == "Mitutoyo"
    assert p.metadata["date"] == "2023-06-20"


@pytest.mark.realdata
def test_the_23_printed_results_in_si(mit2):
    res = mit2.metadata["instrument_results"]
    assert list(res) == [RENAMED.get(k, k) for k, _, _ in PRINTED]
    for key, value, unit in PRINTED:
        q = res[RENAMED.get(key, key)]
        if key in ("A1", "A2"):  # printed in µm·%, stated in m as surfmet's A1, A2
            assert q == {"value": pytest.approx(value * 1e-8, rel=1e-12), "unit": "m"}
        elif unit == "%":  # as surfmet states Mr1, Mr2
            assert q == {"value": value, "unit": "%"}
        else:
            assert q["value"] == pytest.approx(value * SI[unit], rel=1e-12)
            assert q["unit"] == ("m" if unit == "µm" else "")


@pytest.mark.realdata
def test_printed_areas_in_the_units_surfmet_uses(mit2):
    """The printout's A1, A2 (no unit printed) are Rpk Mr1 / 2 and Rvk (100 % - Mr2) / 2
    of its own printed values (ISO 13565-2) to the printed digits: read in metres, they
    equal those products with Mr in % over 100, surfmet's own definition and units."""
    from surfmet.roughness import roughness

    ours = roughness(mit2).parameters  # name -> (value, unit)
    res = mit2.metadata["instrument_results"]
    v = {k: res[k]["value"] for k in ("Rpk", "Rvk", "Mr1", "Mr2", "A1", "A2")}
    assert v["A1"] == pytest.approx(v["Rpk"] * v["Mr1"] / 100 / 2, rel=1e-3)
    assert v["A2"] == pytest.approx(v["Rvk"] * (100 - v["Mr2"]) / 100 / 2, rel=1e-3)
    for key in ("Mr1", "Mr2", "A1", "A2", "Rpk"):
        assert res[key]["unit"] == ours[key][1], key


@pytest.mark.realdata
def test_evaluation_conditions_as_printed(mit2):
    ev = mit2.metadata["evaluation_conditions"]
    assert ev["standard"] == "iso4287" and ev["standard_text"] == "ISO 1997"
    assert ev["lc"] == pytest.approx(2.5e-3, rel=1e-12)
    assert ev["ls"] == pytest.approx(8e-6, rel=1e-12)
    assert ev["n_sampling"] == 4
    assert ev["profile"] == "R"
    assert ev["filter"] == "gaussian"


# --- hand-built workbooks -----------------------------------------------------------------

_NS = 'xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main"'
_R = 'xmlns:r="http://schemas.openxmlformats.org/officeDocument/2006/relationships"'


def _sheet(rows: dict[int, dict[str, object]]) -> str:
    out = []
    for r, cells in sorted(rows.items()):
        cs = []
        for col, v in cells.items():
            if isinstance(v, str):
                cs.append(f'<c r="{col}{r}" t="inlineStr"><is><t>{v}</t></is></c>')
            else:
                cs.append(f'<c r="{col}{r}"><v>{v!r}</v></c>')
        out.append(f'<row r="{r}">{"".join(cs)}</row>')
    return f'<worksheet {_NS}><sheetData>{"".join(out)}</sheetData></worksheet>'


def workbook(x, z, results=("Ra 1.000 µm",), conditions=("CUT 0.8mm", "N 5"),
             sheet_name="DATA") -> bytes:
    rows: dict[int, dict[str, object]] = {}
    for i, (a, b) in enumerate(zip(x, z), start=1):
        rows.setdefault(i, {}).update({"E": float(a), "F": float(b)})
    for i, t in enumerate(results, start=1):
        rows.setdefault(i, {})["A"] = t
    for i, t in enumerate(conditions, start=1):
        rows.setdefault(i, {})["B"] = t
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
        zf.writestr("xl/workbook.xml",
                    f'<workbook {_NS} {_R}><sheets><sheet name="{sheet_name}" sheetId="1" '
                    'r:id="rId1"/></sheets></workbook>')
        zf.writestr("xl/_rels/workbook.xml.rels",
                    '<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/'
                    'relationships"><Relationship Id="rId1" Type="worksheet" '
                    'Target="worksheets/sheet1.xml"/></Relationships>')
        zf.writestr("xl/worksheets/sheet1.xml", _sheet(rows))
    return buf.getvalue()


def test_hand_built_uniform_profile_units_from_cutoff_and_results():
    x = np.arange(1, 101) * 0.5e-3  # mm
    z = np.sin(x * 40.0)  # µm
    buf = workbook(x, z)
    assert detect_format(buf, "a.xlsx") == "mitutoyo"
    p = read_bytes(buf, name="a.xlsx")
    assert p.is_uniform and p.n == 100
    assert p.dx == pytest.approx(0.5e-6, rel=1e-9)
    np.testing.assert_allclose(p.z, z * 1e-6, rtol=1e-15)
    ev = p.metadata["evaluation_conditions"]
    assert ev["lc"] == pytest.approx(0.8e-3) and ev["n_sampling"] == 5
    assert "standard" not in ev


def test_hand_built_nonuniform_profile_keeps_positions():
    x = np.cumsum(np.r_[0.001, np.tile([0.001, 0.002], 20)])
    p = read_bytes(workbook(x, np.zeros_like(x) + np.arange(x.size)), name="b.xlsx")
    assert not p.is_uniform
    np.testing.assert_allclose(p.x, (x - x[0]) * 1e-3, rtol=1e-12)


@pytest.mark.parametrize("kwargs, message", [
    ({"sheet_name": "Other"}, "no sheet named DATA"),
    ({"results": ("Rsk -0.1",)}, "height unit is unknown"),
    ({"conditions": ("N 5",)}, "unit of the positions is unknown"),
])
def test_missing_pieces_fail_in_one_line(kwargs, message):
    x = np.arange(1, 11) * 1e-3
    with pytest.raises(SurfmetFormatError, match=message) as info:
        read_bytes(workbook(x, x, **kwargs), name="c.xlsx")
    assert "\n" not in str(info.value)


def test_npz_and_x3p_zips_are_not_mistaken_for_mitutoyo():
    buf = io.BytesIO()
    np.savez(buf, heights=np.zeros((3, 3)))
    assert detect_format(buf.getvalue(), "a.npz") != "mitutoyo"
