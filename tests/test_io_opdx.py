"""Bruker Dektak OPDx reader: the real profile against its companion text export (values
quoted from SurfaceTopography's opdx-3.txt) and synthetic item trees."""

from __future__ import annotations

import struct

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import read_bytes

# (index, x in m, height in m) from opdx-3.txt, the instrument's own text export
COMPANION = [
    (0, 0.0, 1.3718306e-09),
    (1, 1.6655563e-08, 1.3122408e-09),
    (2, 3.3311126e-08, 1.3172831e-09),
    (999, 1.6638907e-05, -1.8136141e-09),
    (1999, 3.329447e-05, 8.6409162e-09),
    (3000, 4.9966689e-05, 1.4412931e-08),
]


@pytest.fixture
def opdx3(realdata):
    return surfmet.read(realdata("opdx-3.opdx"))


@pytest.mark.realdata
def test_profile_matches_companion_text(opdx3):
    p = opdx3
    assert p.metadata["format"] == "opdx"
    assert p.kind == "profile" and p.n == 3001 and p.is_uniform
    assert p.metadata["height_unit"] == "µm" and p.metadata["lateral_unit"] == "µm"
    assert p.dx == pytest.approx(1.6655563e-08, rel=1e-6)  # 0.0166556 µm
    for i, x, z in COMPANION:
        assert p.positions[i] == pytest.approx(x, rel=1e-6, abs=1e-15)
        assert p.z[i] == pytest.approx(z, rel=1e-6)
    # n * dx = 49.98 µm (the manifest's length); the file's Extent (n - 1) * dx = 49.967 µm
    assert p.length == pytest.approx(49.98e-6, rel=2e-4)
    assert p.nan_fraction == 0.0


@pytest.mark.realdata
def test_metadata(opdx3):
    md = opdx3.metadata
    assert md["instrument"] == "Dektak Profiler"
    assert md["vendor"] == "Bruker"
    assert md["tip_radius"]["value"] == pytest.approx(2e-6)
    assert md["stylus_force"]["value"] == pytest.approx(3e-6 * 9.80665)
    # The FILETIME stamp says 2021-11-02 15:39:13 UTC; the text date "2/11/2021 11:39:13 PM"
    # is day/month in local time (UTC+8), and the data set is named "...2021.11.02...".
    assert md["date"].startswith("2021-11-02T15:39:13")
    assert md["date_text"] == "2/11/2021 11:39:13 PM"
    assert "2021.11.02" in md["data_set"]


# --- a writer of the item tree, from the layout in the module docstring -----------------


def name(s: str) -> bytes:
    b = s.encode()
    return struct.pack("<I", len(b)) + b


def varlen(n: int) -> bytes:
    return b"\x04" + struct.pack("<I", n)


def item(key: str, kind: int, payload: bytes) -> bytes:
    return name(key) + bytes([kind]) + payload


def container(key: str, items: list[bytes], kind: int = 0x7D) -> bytes:
    body = b"".join(items) + name("") + b"\x7f" + b"\xff\xff"
    return item(key, kind, varlen(len(body)) + body)


def string(key: str, s: str) -> bytes:
    b = s.encode()
    return item(key, 0x12, varlen(len(b)) + b)


def qty(key: str, value: float, unit: str, symbol: str) -> bytes:
    body = struct.pack("<d", value) + name(unit) + name(symbol) + b"\0" * 20
    return item(key, 0x13, varlen(len(body)) + body)


def doubles(key: str, values: np.ndarray) -> bytes:
    body = b"\x0d" + struct.pack("<I", values.size) + values.astype("<f8").tobytes()
    return item(key, 0x40, name("double * __ptr64") + varlen(len(body)) + body)


def positions(key: str, x_um: np.ndarray) -> bytes:
    unit = name("Micrometer") + name("µm") + struct.pack("<d", 1e6) + b"\0" * 12
    body = unit + struct.pack("<Q", x_um.size) + x_um.astype("<f8").tobytes()
    return item(key, 0x7C, name("ArrayPosition1D") + varlen(len(body)) + body)


def make_profile(z_raw: np.ndarray, scale_um: float, x_um: np.ndarray | None) -> bytes:
    n = z_raw.size
    chan = [qty("Extent", float(n), "Micrometer", "µm"),
            item("NumPoints", 0x0B, struct.pack("<Q", n)),
            qty("DataScale", scale_um, "Micrometer", "µm"), doubles("Array", z_raw)]
    if x_um is not None:
        chan.insert(0, positions("PositionFunction", x_um))
    names = name("vector<wstring>")
    listing = name("Raw")
    meta = [string("DataKind", "Surface Profile"),
            container("1D_Channels", [
                item("Height", 0x42, names + varlen(len(listing)) + listing)]),
            container("MeasurementSettings", [string("InstrumentName", "Synthetic"),
                                              qty("StylusForce", 1.0, "Milligram", "mg")])]
    body = (container("1D_Data", [container("Raw", chan, kind=0x46)]) + container("MetaData", meta)
            + name("") + b"\x7f\xff\xff")
    return b"VCA DATA\x01\x00\x00\x55" + body


def make_map(raw: np.ndarray, scale_um: float, sx_um: float, sy_um: float) -> bytes:
    ny, nx = raw.shape
    data = struct.pack("<II", ny, nx) + raw.astype("<f4").tobytes()
    matrix = item("Matrix", 0x00, name("matrix") + struct.pack("<I", 1) + name("f")
                  + varlen(len(data)) + data)
    chan = [matrix, qty("DataScale", scale_um, "Micrometer", "µm"),
            qty("Dimension1Extent", sy_um, "Micrometer", "µm"),
            qty("Dimension2Extent", sx_um, "Micrometer", "µm")]
    meta = [string("DataKind", "Surface Height"), string("PrimaryData2D", "Height")]
    body = (container("2D_Data", [container("Height", chan, kind=0x47)])
            + container("MetaData", meta) + name("") + b"\x7f\xff\xff")
    return b"VCA DATA\x01\x00\x00\x55" + body


@pytest.mark.parametrize("seed", [0, 1])
def test_synthetic_profile_uniform_and_not(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(5, 200))
    raw = rng.normal(size=n)
    scale = float(rng.uniform(1e-5, 1e-3))
    p = read_bytes(make_profile(raw, scale, np.arange(n) * 0.05), name="s.opdx")
    assert p.metadata["format"] == "opdx" and p.is_uniform
    assert p.dx == pytest.approx(0.05e-6)
    np.testing.assert_allclose(p.z, raw * scale * 1e-6, rtol=1e-12)
    x = np.cumsum(rng.uniform(0.01, 0.1, n))
    q = read_bytes(make_profile(raw, scale, x))
    assert not q.is_uniform
    np.testing.assert_allclose(q.positions, (x - x[0]) * 1e-6, rtol=1e-12, atol=1e-18)
    r = read_bytes(make_profile(raw, scale, None))  # no positions: Extent / NumPoints
    assert r.is_uniform and r.dx == pytest.approx(1e-6)
    assert r.metadata["instrument"] == "Synthetic"


def test_synthetic_map():
    rng = np.random.default_rng(3)
    raw = rng.normal(size=(6, 9)).astype(np.float32)
    t = read_bytes(make_map(raw, 0.01, 18.0, 3.0))
    assert (t.nx, t.ny) == (9, 6)
    assert (t.dx, t.dy) == pytest.approx((2e-6, 0.5e-6))
    np.testing.assert_allclose(t.heights, raw * 0.01e-6, rtol=1e-6)


def test_damage_and_huge_claims():
    buf = make_profile(np.ones(20), 1e-3, np.arange(20.0))
    with pytest.raises(SurfmetFormatError, match="truncated"):
        read_bytes(buf[:-40])
    raw = np.ones((2, 2), np.float32)
    big = bytearray(make_map(raw, 1.0, 1.0, 1.0))
    at = big.index(struct.pack("<II", 2, 2) + raw.tobytes())
    big[at : at + 8] = struct.pack("<II", 100_000, 100_000)
    with pytest.raises(SurfmetFormatError, match=r"absurd|truncated"):
        read_bytes(bytes(big))
    bad_kind = buf.replace(b"\x0b" + struct.pack("<Q", 20), b"\x99" + struct.pack("<Q", 20))
    with pytest.raises(SurfmetFormatError, match="unknown type 0x99"):
        read_bytes(bad_kind)
