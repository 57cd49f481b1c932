"""Gwyddion GWY reader: gwyfile's test file (no units) and synthetic containers written from
the documented serialisation, with every component type."""

from __future__ import annotations

import struct

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import read_bytes
from surfmet.io.gwy import load


@pytest.mark.realdata
def test_gwyfile_test_file_without_units(realdata):
    t = surfmet.read(realdata("test.gwy"))
    assert t.metadata["format"] == "gwy"
    # gwyfile: data.shape == (128, 128) (yres, xres), data[0][0], data[44][33], rel 1e-5
    assert t.heights.shape == (128, 128)
    assert t.heights[0][0] == pytest.approx(0.00082494, rel=1e-5)
    assert t.heights[44][33] == pytest.approx(0.00085301, rel=1e-5)
    assert t.heights[33][44] != pytest.approx(0.00085301, rel=1e-5)  # index order matters
    assert t.metadata["title"] == "Test"
    # empty si units: numbers kept as they are, flagged as uncalibrated
    assert t.metadata["units_missing"] is True
    assert t.metadata["lateral_calibrated"] is False
    assert t.metadata["height_unit"] == ""
    assert (t.dx, t.dy) == (1.0, 1.0)  # xreal = 128 over xres = 128, taken as metres
    assert t.nan_fraction == 0.0


# --- a serialiser written from the GWY format documentation ------------------------------


def _obj(type_name: str, components: list[tuple[str, str, object]]) -> bytes:
    body = b"".join(_comp(*c) for c in components)
    return type_name.encode() + b"\0" + struct.pack("<I", len(body)) + body


def _comp(name: str, code: str, value: object) -> bytes:
    head = name.encode() + b"\0" + code.encode()
    if code == "b":
        return head + bytes([1 if value else 0])
    if code == "c":
        return head + value
    if code in "iqd":
        return head + struct.pack("<" + code, value)
    if code == "s":
        return head + value.encode() + b"\0"
    if code == "o":
        return head + value
    if code in "CIQD":
        arr = np.asarray(value, {"C": "u1", "I": "<i4", "Q": "<i8", "D": "<f8"}[code])
        return head + struct.pack("<I", arr.size) + arr.tobytes()
    if code == "S":
        return head + struct.pack("<I", len(value)) + b"".join(s.encode() + b"\0" for s in value)
    if code == "O":
        return head + struct.pack("<I", len(value)) + b"".join(value)
    raise AssertionError(code)


def unit(s: str) -> bytes:
    return _obj("GwySIUnit", [("unitstr", "s", s)])


def field(data: np.ndarray, xreal: float, yreal: float, xy: str, z: str) -> bytes:
    ny, nx = data.shape
    return _obj("GwyDataField", [
        ("xres", "i", nx), ("yres", "i", ny), ("xreal", "d", xreal), ("yreal", "d", yreal),
        ("xoff", "d", 1e-6), ("yoff", "d", 0.0),
        ("si_unit_xy", "o", unit(xy)), ("si_unit_z", "o", unit(z)),
        ("data", "D", data.ravel()),
    ])


def container(items: list[tuple[str, str, object]]) -> bytes:
    return b"GWYP" + _obj("GwyContainer", items)


@pytest.fixture
def two_channels():
    rng = np.random.default_rng(11)
    current = rng.normal(size=(5, 6))
    topo = rng.normal(size=(7, 4)) * 1e-8
    buf = container([
        ("/0/data", "o", field(current, 6e-6, 5e-6, "m", "A")),
        ("/0/data/title", "s", "Current"),
        ("/1/data", "o", field(topo, 4e-6, 14e-6, "m", "m")),
        ("/1/data/title", "s", "Topo"),
        ("/1/data/visible", "b", True),
        ("/1/meta/char", "c", b"x"),
        ("/1/meta/count", "q", 2**40),
        ("/1/meta/ints", "I", [1, 2, 3]),
        ("/1/meta/longs", "Q", [4, 5]),
        ("/1/meta/bytes", "C", [7, 8, 9]),
        ("/1/meta/names", "S", ["a", "bc"]),
        ("/1/meta/objs", "O", [unit("V"), unit("s")]),
        ("/1/data/log", "o", _obj("GwyStringList", [("strings", "S", ["import"])])),
    ])
    return buf, current, topo


def test_every_component_type_parses(two_channels):
    buf, _, _ = two_channels
    c = load(buf)
    assert c.type_name == "GwyContainer"
    assert c["/1/meta/count"] == 2**40
    assert list(c["/1/meta/ints"]) == [1, 2, 3]
    assert list(c["/1/meta/longs"]) == [4, 5]
    assert list(c["/1/meta/bytes"]) == [7, 8, 9]
    assert c["/1/meta/names"] == ["a", "bc"]
    assert [o["unitstr"] for o in c["/1/meta/objs"]] == ["V", "s"]
    assert c["/1/data/visible"] is True and c["/1/meta/char"] == b"x"


def test_first_height_channel_is_chosen(two_channels):
    buf, _, topo = two_channels
    t = read_bytes(buf, name="two.gwy")
    assert t.metadata["channel"] == 1 and t.metadata["title"] == "Topo"
    np.testing.assert_array_equal(t.heights, topo)
    assert (t.dx, t.dy) == pytest.approx((1e-6, 2e-6))
    assert t.metadata["lateral_calibrated"] is True and t.metadata["height_unit"] == "m"
    assert t.metadata["x_offset"] == {"value": pytest.approx(1e-6), "unit": "m"}
    assert [c["title"] for c in t.metadata["channels"]] == ["Current", "Topo"]


def test_channel_option(two_channels):
    buf, _, topo = two_channels
    np.testing.assert_array_equal(read_bytes(buf, channel="Topo").heights, topo)
    np.testing.assert_array_equal(read_bytes(buf, channel=1).heights, topo)
    with pytest.raises(SurfmetFormatError, match="'A' values, not heights"):
        read_bytes(buf, channel=0)
    with pytest.raises(SurfmetFormatError, match="no channel 'Phase'"):
        read_bytes(buf, channel="Phase")


def test_only_non_height_channels_is_an_error():
    buf = container([("/0/data", "o", field(np.ones((3, 3)), 1e-6, 1e-6, "m", "V"))])
    with pytest.raises(SurfmetFormatError, match="no channel holds heights"):
        read_bytes(buf)


def test_damage_and_huge_claims():
    buf = container([("/0/data", "o", field(np.ones((3, 4)), 1e-6, 1e-6, "m", "m"))])
    assert read_bytes(buf).shape == (3, 4)
    with pytest.raises(SurfmetFormatError, match="truncated"):
        read_bytes(buf[:-5])
    # a data array claiming 10^10 doubles in a small file fails before allocating
    big = bytearray(buf)
    at = big.index(b"data\0D") + 6
    big[at : at + 4] = struct.pack("<I", 2**32 - 1)
    with pytest.raises(SurfmetFormatError, match="truncated"):
        read_bytes(bytes(big))
    # xres x yres disagreeing with the array
    bad = bytearray(buf)
    at = bad.index(b"xres\0i") + 6
    bad[at : at + 4] = struct.pack("<i", 100000)
    with pytest.raises(SurfmetFormatError, match="holds 12 values"):
        read_bytes(bytes(bad))
    with pytest.raises(SurfmetFormatError, match="Gwyddion 1"):
        read_bytes(b"GWYO" + buf[4:], format="gwy")
