"""Dektak CSV export: the real file against SurfaceTopography's stored values and the
instrument's own header, plus synthetic exports."""

from __future__ import annotations

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import detect_format, read_bytes


def rms_height_piecewise_linear(x, h):
    # SurfaceTopography's non-uniform Rq: the profile is linear between points;
    # mean and variance are integrals over the length.
    dx, length = np.diff(x), x[-1] - x[0]
    mean = np.sum(dx * (h[1:] + h[:-1])) / (2 * length)
    a, b = h[:-1] - mean, h[1:] - mean
    return float(np.sqrt(np.sum(dx * (a * a + a * b + b * b)) / (3 * length)))


def rms_slope_piecewise_linear(x, h):
    return float(np.sqrt(np.sum(np.diff(h) ** 2 / np.diff(x)) / (x[-1] - x[0])))


@pytest.fixture
def dektak(realdata):
    return surfmet.read(realdata("dektak-1.csv"))


@pytest.mark.realdata
def test_profile_and_surfacetopography_values(dektak):
    p = dektak
    assert p.metadata["format"] == "dektak"
    assert p.kind == "profile" and p.n == 9600
    assert not p.is_uniform
    assert p.metadata["lateral_unit"] == "um" and p.metadata["height_unit"] == "um"
    x = p.positions
    assert x[0] == 0.0 and x[-1] == pytest.approx(1499.8e-6)
    assert p.length == pytest.approx(1499.8e-6)
    # ST stores 4.763596 in µm (its unit for this file) and 0.015448 (dimensionless)
    assert rms_height_piecewise_linear(x, p.z) == pytest.approx(4.763596e-6, rel=1e-6)
    assert rms_slope_piecewise_linear(x, p.z) == pytest.approx(0.015448, rel=1e-5)
    assert p.z[0] == pytest.approx(-0.00933e-6) and p.z[-1] == pytest.approx(16.58112e-6)


@pytest.mark.realdata
def test_header_metadata(dektak):
    md = dektak.metadata
    assert md["tip_radius"] == {"value": pytest.approx(2.5e-6), "unit": "m"}
    assert md["scan_length"]["value"] == pytest.approx(1.5e-3)
    assert md["resolution"]["value"] == pytest.approx(0.156e-6)
    assert md["scan_duration"] == {"value": 32.0, "unit": "s"}
    assert md["measurement_range"]["value"] == pytest.approx(524e-6)
    assert md["stylus_force"]["unit"] == "N"
    assert md["stylus_force"]["value"] == pytest.approx(3e-6 * 9.80665)  # 3.00 mg
    assert md["cursors"]["R"]["position"]["value"] == pytest.approx(100e-6)
    assert md["cursors"]["M"]["position"]["value"] == pytest.approx(1000e-6)
    assert md["scan_parameters"]["Scan Type"] == "Standard Scan"
    # the mean sampling step agrees with the header's resolution to 0.2 %
    assert dektak.dx == pytest.approx(0.156e-6, rel=2e-3)


@pytest.mark.realdata
def test_instrument_results(dektak):
    res = dektak.metadata["instrument_results"]
    assert res["Ra"] == {"value": pytest.approx(5.25e-9), "unit": "m"}
    assert res["Rq"] == {"value": pytest.approx(11.43e-9), "unit": "m"}
    assert res["Skew"] == {"value": pytest.approx(6.96), "unit": ""}
    assert res["RzDin"] == {"value": pytest.approx(49.17e-9), "unit": "m"}
    assert res["ASH"]["value"] == pytest.approx(2.89171e-6)
    assert set(res) == {"Ra", "Rq", "Skew", "RzDin", "Wa", "Wq", "WMaxDev", "ASH"}
    rng = dektak.metadata["evaluation_range"]
    assert rng["start"] == {"value": pytest.approx(468e-6), "unit": "m"}
    assert rng["end"] == {"value": pytest.approx(733e-6), "unit": "m"}
    cur = dektak.metadata["instrument_results_cursors"]["Ra"]
    assert cur["R"]["value"] == pytest.approx(468e-6) and cur["M_width"]["value"] == 0.0


def export(x_um, z, *, zunit="Raw Micrometer", results=True, length=None) -> bytes:
    length = abs(x_um[-1] - x_um[0]) if length is None else length
    lines = ["Scan Parameters", "Scan Type,Standard Scan", "Stylus,Radius: 12.5 µm",
             f"Length,{length:.1f} um", "Force,5 mg", ""]
    if results:
        lines += ["Analytical Results", "Function,R.Cur Pos,R.Cur Width,M.Cur Pos,M.Cur Width,"
                  "Result", "Ra,1.0 um,0.0 um,9.0 um,0.0 um,12.5 nm",
                  "Rq,2.0 um,0.0 um,8.0 um,0.0 um,0.0150 um", ""]
    lines += ["Scan Data", f"Lateral um,{zunit},"]
    lines += [f"{a:.1f},{b:.5f},," for a, b in zip(x_um, z)]
    return "\r\n".join(lines).encode("latin-1")


def test_synthetic_uniform_and_units():
    x = np.arange(50) * 0.2
    z = np.sin(x)
    p = read_bytes(export(x, z, zunit="Total Profile (Å)"), name="s.csv")
    assert p.metadata["format"] == "dektak"
    assert p.is_uniform and p.dx == pytest.approx(0.2e-6)
    np.testing.assert_allclose(p.z, np.round(z, 5) * 1e-10)
    assert p.metadata["height_unit"] == "Å"
    assert p.metadata["tip_radius"]["value"] == pytest.approx(12.5e-6)
    res = p.metadata["instrument_results"]
    assert res["Ra"]["value"] == pytest.approx(12.5e-9)
    assert res["Rq"]["value"] == pytest.approx(15e-9)
    # rows with different cursors: no common evaluation range
    assert "evaluation_range" not in p.metadata


def test_synthetic_rounded_positions_are_non_uniform():
    x = np.arange(40) * 0.156
    p = read_bytes(export(x, np.cos(x), results=False))
    assert not p.is_uniform
    np.testing.assert_allclose(p.positions, np.round(x, 1) * 1e-6, atol=1e-15)
    assert "instrument_results" not in p.metadata


def test_detection_and_damage():
    buf = export(np.arange(10.0), np.zeros(10))
    assert detect_format(buf, "x.csv") == "dektak"
    with pytest.raises(SurfmetFormatError, match="Scan Data"):
        read_bytes(buf[: buf.index(b"Scan Data")], format="dektak")
    backwards = export(np.arange(10.0)[::-1], np.zeros(10))
    with pytest.raises(SurfmetFormatError, match="increase"):
        read_bytes(backwards)
    with pytest.raises(SurfmetFormatError, match="not a number"):
        read_bytes(buf.replace(b"3.0,", b"3.0x,"))
    # cut at a line boundary: only the stated scan length reveals it
    cut = buf[: buf.index(b"\r\n5.0,")]
    with pytest.raises(SurfmetFormatError, match="truncated"):
        read_bytes(cut)
