"""Wyko / Bruker Vision ``.opd`` reader.

Truths: SurfaceTopography's test values for opd-1.opd (MANIFEST.tsv), the raw values of the
file read here directly from their offsets, and OPD files built here from the documented
block-directory layout, including block types that surfalize cannot handle.
"""

from __future__ import annotations

import struct

import numpy as np
import pytest
from _refusal import refused_cheaply

import surfmet
from surfmet import SurfmetFormatError
from surfmet._model import Topography
from surfmet.io import detect_format, read_bytes


def opd_file(blocks: list[tuple[str, int, bytes]], *, extra_entries: int = 2) -> bytes:
    """An OPD file: 2 bytes, a directory of 24-byte entries, then the blocks in order."""
    n = len(blocks) + 1 + extra_entries
    head = b"\x01\x00" + b"Directory".ljust(16, b"\0") + struct.pack("<HIH", 1, 24 * n, 0xFFFF)
    entries = b"".join(name.encode().ljust(16, b"\0") + struct.pack("<HIH", t, len(d), 0)
                       for name, t, d in blocks)
    entries += (b"\0" * 16 + struct.pack("<HIH", 0, 0, 0)) * extra_entries
    return head + entries + b"".join(d for _, _, d in blocks)


def array_block(values: np.ndarray, dtype: str) -> bytes:
    """Columns (x) of y values, as the OPD array block stores them."""
    nx, ny = values.shape
    a = np.asarray(values, dtype=dtype)
    return struct.pack("<HHH", nx, ny, a.dtype.itemsize) + a.tobytes()


def basic_blocks(data: bytes, *, wavelength: float = 600.0, pixel_mm: float = 0.002,
                 extra: list | None = None) -> list[tuple[str, int, bytes]]:
    blocks = [
        ("PrimaryData2D", 15, b"\x12\x01\x03Raw"),
        ("Wavelength", 7, struct.pack("<f", wavelength)),
        ("Pixel_size", 7, struct.pack("<f", pixel_mm)),
        ("Raw", 3, data),
        ("Date", 5, b"12/31/2019\0"),
        ("Time", 5, b"23:59:30"),
    ]
    return blocks + (extra or [])


# ----------------------------------------------------------------------------- real file


@pytest.mark.realdata
def test_opd1_matches_surfacetopography(realdata):
    t = surfmet.read(realdata("opd-1.opd"))
    assert isinstance(t, Topography)
    assert (t.nx, t.ny) == (640, 480)
    np.testing.assert_allclose(t.nx * t.dx * 1e3, 0.125909140, rtol=1e-6)
    np.testing.assert_allclose(t.ny * t.dy * 1e3, 0.094431855, rtol=1e-6)
    md = t.metadata
    # ST's height_scale_factor is in mm per stored unit.
    np.testing.assert_allclose(md["height_scale_factor"] * 1e3, 0.0005772949829101563,
                               rtol=1e-12)
    np.testing.assert_allclose(md["wavelength"], 577.2949829101562e-9, rtol=1e-12)
    assert md["lateral_unit"] == "mm"
    assert md["date"] == "2015-07-07T16:19:48"
    assert md["measurement_mode"] == "PSI" and md["data_kind"] == "Surface Height"
    # Type-15 blocks (which make surfalize 0.19 fail) are present and tolerated.
    assert 15 in md["block_types"]
    assert np.count_nonzero(np.isnan(t.heights)) == 116
    np.testing.assert_allclose(t.nan_fraction, 0.0004, atol=5e-5)


@pytest.mark.realdata
def test_opd1_heights_are_raw_times_scale_at_known_points(realdata):
    buf = realdata("opd-1.opd").read_bytes()
    t = surfmet.read(realdata("opd-1.opd"))
    # The Raw array block starts at offset 24020 (after the 24000-byte directory and the
    # three 4-byte float blocks): 640 columns of 480 float32.
    assert struct.unpack_from("<HHH", buf, 24020) == (640, 480, 4)
    raw = np.frombuffer(buf, "<f4", count=640 * 480, offset=24026).reshape(640, 480)
    scale = 577.2949829101562e-9
    for x, y in ((0, 0), (639, 0), (0, 479), (321, 123)):
        v = float(raw[x, 479 - y])
        if v < 1e38:
            np.testing.assert_allclose(t.heights[y, x], v * scale, rtol=1e-12)
    assert np.array_equal(np.isnan(t.heights), (raw >= 1e38).T[::-1, :])


@pytest.mark.realdata
def test_opd1_truncation_and_corruption(realdata):
    buf = realdata("opd-1.opd").read_bytes()
    for cut in (5, 20, 26, 1000, 24010, 30000, len(buf) // 2, len(buf) - 1):
        with pytest.raises(SurfmetFormatError):
            read_bytes(buf[:cut], format="opd", name="cut.opd")
    bad = bytearray(buf)
    struct.pack_into("<I", bad, 2 + 16 + 2, 24001)  # directory length not a multiple of 24
    with pytest.raises(SurfmetFormatError, match="multiple"):
        read_bytes(bytes(bad), name="dir.opd")
    bad = bytearray(buf)
    struct.pack_into("<f", bad, 24002 + 6, float("nan"))  # Wavelength block value
    with pytest.raises(SurfmetFormatError, match="Wavelength"):
        read_bytes(bytes(bad), name="wl.opd")


# ----------------------------------------------------------------------------- synthetic


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_float_array_invalid_points_and_orientation(seed):
    rng = np.random.default_rng(seed)
    nx, ny = rng.integers(2, 20, size=2)
    cols = rng.normal(0, 0.2, size=(nx, ny)).astype(np.float32)  # in waves
    bad = rng.random((nx, ny)) < rng.uniform(0.05, 0.4)
    bad[0, -1] = False
    cols[bad] = 1e38 if seed % 2 else np.float32(3.4e38)
    buf = opd_file(basic_blocks(array_block(cols, "<f4")))
    assert detect_format(buf) == "opd"
    t = read_bytes(buf, name="f.opd")
    assert t.shape == (ny, nx)
    expected = cols.astype(float).T[::-1, :] * 600e-9
    mask = bad.T[::-1, :]
    np.testing.assert_array_equal(np.isnan(t.heights), mask)
    np.testing.assert_allclose(t.heights[~mask], expected[~mask], rtol=1e-12)
    assert t.dx == pytest.approx(2e-6, rel=1e-6)
    assert t.metadata["date"] == "2019-12-31T23:59:30"


def test_int16_array_with_mult_as_short_and_aspect():
    cols = np.array([[0, 100, 32767], [-5, 32766, 7]], dtype="<i2")
    extra = [("Mult", 6, struct.pack("<h", 4)), ("Aspect", 7, struct.pack("<f", 2.0))]
    blocks = basic_blocks(array_block(cols, "<i2"), extra=extra)
    t = read_bytes(opd_file(blocks), name="i.opd")
    heights = t.heights[::-1, :].T  # back to the file's column layout
    invalid = cols >= 32766
    np.testing.assert_array_equal(np.isnan(heights), invalid)
    np.testing.assert_allclose(heights[~invalid], cols[~invalid] * 600e-9 / 4, rtol=1e-12)
    assert t.dy == pytest.approx(2 * t.dx, rel=1e-12)
    assert t.metadata["mult"] == 4


def test_unknown_block_types_are_tolerated_and_primary_data_is_honoured():
    first = np.ones((3, 2), dtype="<f4")
    second = 2 * np.ones((3, 2), dtype="<f4")
    blocks = [
        ("PrimaryData2D", 15, b"\x12\x01\x05Other"),
        ("Mystery", 99, b"\x00\x01\x02"),
        ("Tagged", 15, b"\x7d\x02\x00\x00"),
        ("Wavelength", 7, struct.pack("<f", 500.0)),
        ("Pixel_size", 7, struct.pack("<f", 0.001)),
        ("RAW_DATA", 3, array_block(first, "<f4")),
        ("Other", 3, array_block(second, "<f4")),
        ("Scan", 8, struct.pack("<d", 1.5)),
        ("Count", 12, struct.pack("<i", -3)),
    ]
    t = read_bytes(opd_file(blocks), name="u.opd")
    np.testing.assert_allclose(t.heights, 2 * 500e-9)
    assert t.metadata["data_block"] == "Other"
    assert t.metadata["unknown_block_types"] == [99]


@pytest.mark.parametrize(("drop", "message"), [("Wavelength", "Wavelength"),
                                               ("Pixel_size", "Pixel_size"),
                                               ("Raw", "height array")])
def test_missing_blocks(drop, message):
    blocks = [b for b in basic_blocks(array_block(np.zeros((2, 2)), "<f4")) if b[0] != drop]
    with pytest.raises(SurfmetFormatError, match=message):
        read_bytes(opd_file(blocks), name="m.opd")


def test_byte_image_is_not_heights_and_sizes_must_agree():
    img = np.zeros((4, 4), dtype=np.uint8)
    with pytest.raises(SurfmetFormatError, match="image"):
        read_bytes(opd_file(basic_blocks(array_block(img, "u1"))), name="img.opd")
    data = bytearray(array_block(np.zeros((4, 4)), "<f4"))
    struct.pack_into("<HH", data, 0, 400, 400)  # grid larger than the block
    with pytest.raises(SurfmetFormatError, match="truncated"):
        read_bytes(opd_file(basic_blocks(bytes(data))), name="size.opd")


def test_tiny_file_claiming_huge_directory_and_grid():
    buf = bytearray(opd_file(basic_blocks(array_block(np.zeros((2, 2)), "<f4"))))
    struct.pack_into("<I", buf, 20, 24 * 60000)
    refused_cheaply(buf, name="huge.opd")
