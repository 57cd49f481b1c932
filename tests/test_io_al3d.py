"""Alicona AL3D reader: the real MeasureSuite file against SurfaceTopography's stored values,
and synthetic files (row padding, invalid markers, texture block) built from the layout."""

from __future__ import annotations

import struct

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import read_bytes


def rms_profile_x(h: np.ndarray) -> float:
    # SurfaceTopography's Rq of a map: every line along x loses its own mean, then the rms
    # of all residuals (sum / total number of points).
    r = h - np.nanmean(h, axis=1, keepdims=True)
    return float(np.sqrt(np.nanmean(r**2)))


@pytest.mark.realdata
def test_real_file_matches_surfacetopography(realdata):
    t = surfmet.read(realdata("al3d-1.al3d"))
    assert (t.nx, t.ny) == (200, 296)
    assert t.nx * t.dx == pytest.approx(8.76054e-05, rel=1e-6)
    assert t.ny * t.dy == pytest.approx(0.000129655992, rel=1e-6)
    assert t.dx == pytest.approx(4.38027e-07, rel=1e-9)
    assert t.metadata["height_unit"] == "m"
    assert t.metadata["vendor"] == "Alicona Imaging"
    assert t.metadata["software"] == "MeasureSuite 5.3.6"
    assert t.nan_fraction == 0.0
    h = t.heights
    assert float(np.std(h)) == pytest.approx(7.688266102603082e-06, rel=1e-6)
    assert rms_profile_x(h) == pytest.approx(3.915731160953795e-06, rel=1e-6)
    assert rms_profile_x(h.T) == pytest.approx(6.620846789152015e-06, rel=1e-6)
    # the 4-plane texture fills the rest of the file exactly
    tex = t.metadata["texture"]
    assert tex["planes"] == 4 and tex["complete"]
    assert tex["offset"] + tex["bytes"] == realdata("al3d-1.al3d").stat().st_size


def make_al3d(heights: np.ndarray, dx: float, dy: float, invalid: str = "nan",
              planes: int = 0, pad_byte: bytes = b"\xab", extra_tags: dict | None = None) -> bytes:
    """Encode an AL3D file from the published layout (independent of the reader)."""
    ny, nx = heights.shape
    tags = {"Cols": str(nx), "Rows": str(ny), "PixelSizeXMeter": repr(dx),
            "PixelSizeYMeter": repr(dy), "InvalidPixelValue": invalid,
            "NumberOfPlanes": str(planes), "IconOffset": "0",
            "CreatingApplication": "synthetic 1.0"}
    tags.update(extra_tags or {})
    ntags = len(tags) + 2  # + DepthImageOffset + TextureImageOffset
    depth_offset = 17 + 52 * (ntags + 2) + 256
    stride = (nx * 4 + 7) // 8 * 8
    depth_size = stride * ny
    tex_stride = (nx + 7) // 8 * 8
    tags["DepthImageOffset"] = str(depth_offset)
    tags["TextureImageOffset"] = str(depth_offset + depth_size if planes else 0)

    def tag(k: str, v: str) -> bytes:
        return k.encode().ljust(20, b"\0") + v.encode().ljust(30, b"\0") + b"\r\n"

    out = [b"AliconaImaging\x00\r\n", tag("Version", "1"), tag("TagCount", str(len(tags)))]
    out += [tag(k, v) for k, v in tags.items()]
    out.append(b"\0" * 254 + b"\r\n")
    for row in heights.astype("<f4"):
        out.append(row.tobytes() + pad_byte * (stride - nx * 4))
    out.append(b"\x7f" * (tex_stride * ny * planes))
    buf = b"".join(out)
    assert len(buf) == depth_offset + depth_size + tex_stride * ny * planes
    return buf


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_row_padding_and_invalid_marker(seed):
    rng = np.random.default_rng(seed)
    nx = int(rng.integers(3, 40)) | 1  # odd: every row carries 4 padding bytes
    ny = int(rng.integers(2, 30))
    h = rng.normal(0, 1e-6, (ny, nx)).astype(np.float32).astype(np.float64)
    holes = rng.random((ny, nx)) < rng.uniform(0.02, 0.3)
    holes[0, 0] = False
    marker = "3.000000028082e+15"
    raw = np.where(holes, float(np.float32(3.000000028082e15)), h)
    t = read_bytes(make_al3d(raw, 2e-7, 3e-7, invalid=marker, planes=3), name="x.al3d")
    assert t.metadata["format"] == "al3d"
    assert (t.nx, t.ny) == (nx, ny)
    assert (t.dx, t.dy) == (2e-7, 3e-7)
    np.testing.assert_array_equal(t.mask, holes)
    np.testing.assert_array_equal(t.heights[~holes], h[~holes])
    assert t.metadata["texture"]["planes"] == 3


def test_nan_marker_and_no_holes():
    h = np.arange(12, dtype=float).reshape(3, 4) * 1e-7
    t = read_bytes(make_al3d(h, 1e-6, 1e-6))
    assert not t.has_nan
    np.testing.assert_allclose(t.heights, h, rtol=1e-7)
    h2 = h.copy()
    h2[1, 2] = np.nan
    assert read_bytes(make_al3d(h2, 1e-6, 1e-6)).mask.sum() == 1


def test_truncated_depth_image_is_a_format_error():
    buf = make_al3d(np.ones((5, 6)), 1e-6, 1e-6)
    with pytest.raises(SurfmetFormatError, match="truncated"):
        read_bytes(buf[:-10])


def test_header_damage_is_reported():
    buf = bytearray(make_al3d(np.ones((5, 6)), 1e-6, 1e-6))
    buf[17 + 52 + 50] = ord("X")  # break the CRLF of the TagCount tag
    with pytest.raises(SurfmetFormatError, match="CRLF"):
        read_bytes(bytes(buf))
    bad = make_al3d(np.ones((5, 6)), 1e-6, 1e-6, extra_tags={"Cols": "abc"})
    with pytest.raises(SurfmetFormatError, match="Cols"):
        read_bytes(bad)


@pytest.mark.parametrize("n, problem", [(100000, "absurd"), (40000, "truncated")])
def test_huge_grid_claim_fails_fast(n, problem):
    buf = make_al3d(np.ones((2, 2)), 1e-6, 1e-6, extra_tags={"Cols": str(n), "Rows": str(n)})
    with pytest.raises(SurfmetFormatError, match=problem):
        read_bytes(buf)


def test_signature_is_checked_once():
    assert struct.calcsize("<20s30s2s") == 52
    with pytest.raises(SurfmetFormatError):
        read_bytes(b"AliconaImaging\x00\r\n" + b"\0" * 60, format="al3d")
