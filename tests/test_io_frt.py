"""FRT MicroProf reader: the real file (27.4 % undefined points) against the manifest, and
synthetic block files built from the published block layout."""

from __future__ import annotations

import struct

import numpy as np
import pytest
from _peer_metrics import detrend_curvature, st_rq, st_sq

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import read_bytes

# SurfaceTopography's definitions (valid points only) are in _peer_metrics.

# --- The old SurfaceTopography normalisation (by the total number of grid points) -------


def old_sq(h):
    ok = np.isfinite(h)
    mean = np.where(ok, h, 0).sum() / h.size
    return float(np.sqrt((np.where(ok, h - mean, 0) ** 2).sum() / h.size))


def old_rq(h):
    ok = np.isfinite(h)
    mean = np.where(ok, h, 0).sum(axis=1, keepdims=True) / h.shape[1]
    return float(np.sqrt((np.where(ok, h - mean, 0) ** 2).sum() / h.size))


@pytest.fixture
def frt2(realdata):
    return surfmet.read(realdata("frt-2.frt"))


@pytest.mark.realdata
def test_real_file_grid_units_and_undefined_points(frt2):
    t = frt2
    assert (t.nx, t.ny) == (150, 300)
    assert t.nx * t.dx == pytest.approx(0.03, rel=1e-6)
    assert t.ny * t.dy == pytest.approx(0.06, rel=1e-6)
    assert t.dx == pytest.approx(200e-6) and t.dy == pytest.approx(200e-6)
    assert t.metadata["height_unit"] == "m"
    assert t.metadata["vendor"] == "FRT"
    assert t.metadata["serial"] == "SN_1036"
    assert t.metadata["date"].startswith("2023-06-26")
    # undefined: counts outside block 0x0070's [first_valid, last_valid] = [5, 65529]
    assert t.has_nan
    assert t.nan_fraction == pytest.approx(0.2736, abs=5e-4)
    assert t.mask.sum() == 12314
    assert "0x0070" in t.metadata["invalid_rule"]
    assert t.metadata["z_scale"] == pytest.approx(9.765923032319103e-09, rel=1e-12)


@pytest.mark.realdata
def test_real_file_roughness_valid_points_only(frt2):
    # Correct values (valid points only); SurfaceTopography 1.27.1 gives Sq 8.8268e-06.
    h = frt2.heights
    assert st_sq(h) == pytest.approx(8.8268e-06, rel=1e-4)
    assert st_sq(h) == pytest.approx(8.826763181113768e-06, rel=1e-6)
    assert st_rq(h) == pytest.approx(7.663174319074244e-06, rel=1e-6)
    d = detrend_curvature(h, frt2.dx, frt2.dy)
    assert st_sq(d) == pytest.approx(8.688677385181484e-06, rel=1e-5)
    assert st_rq(d) == pytest.approx(7.627057775705950e-06, rel=1e-5)


@pytest.mark.realdata
def test_stored_surfacetopography_values_follow_from_the_old_normalisation(frt2):
    # The values stored in SurfaceTopography's test (1.853335e-05, 1.439208e-05; after the
    # curvature detrend 7.405055e-06, 7.332406e-06) are reproduced by dividing by all
    # 45000 grid points (masked points counted as zeros in the means): a known old bug.
    h = frt2.heights
    assert old_sq(h) == pytest.approx(1.853335e-05, rel=1e-6)
    assert old_rq(h) == pytest.approx(1.439208e-05, rel=1e-6)
    d = detrend_curvature(h, frt2.dx, frt2.dy)
    assert old_sq(d) == pytest.approx(7.405055e-06, rel=1e-4)
    assert old_rq(d) == pytest.approx(7.332406e-06, rel=1e-4)
    # and they are not the correct ones
    assert abs(st_sq(h) / old_sq(h) - 1) > 0.5


# --- Synthetic files ---------------------------------------------------------------------


def block(block_id: int, payload: bytes, version: str) -> bytes:
    size = struct.pack("<I" if version == "1.00" else "<Q", len(payload))
    return struct.pack("<H", block_id) + size + payload


def make_frt(counts: np.ndarray, zscale: float, xrange_: float, yrange_: float, *,
             version: str = "1.00", valid: tuple[int, int] | None = (5, 65529),
             multi: bool = False, intensity_first: bool = True) -> bytes:
    ny, nx = counts.shape
    bpp = 16 if counts.dtype == np.uint16 else 32
    data = counts.astype("<u2" if bpp == 16 else "<i4").tobytes()
    blocks = [
        block(0x0065, b"synthetic\0", version),
        block(0x0066, struct.pack("<III", nx, ny, bpp), version),
        block(0x0067, struct.pack("<dddddI", xrange_, yrange_, 0, 0, 1, 1), version),
        block(0x006C, struct.pack("<Id", 5, zscale), version),
        block(0x0072, struct.pack("<III", 1687796545, 1687797050, 505), version),
    ]
    if valid is not None:
        blocks.append(block(0x0070, struct.pack("<II", *valid), version))
    if multi:
        topo = struct.pack("<IIII", 0x0004, nx, ny, bpp) + data
        inten = struct.pack("<IIII", 0x0002, nx, ny, 16) + np.full(nx * ny, 700, "<u2").tobytes()
        images = inten + topo if intensity_first else topo + inten
        blocks.append(block(0x007D, struct.pack("<HHHH", 2, 0, 4, 0) + images, version))
    else:
        blocks.append(block(0x000B, data, version))
    return b"FRTM_GLIDERV" + version.encode() + struct.pack("<H", len(blocks)) + b"".join(blocks)


@pytest.mark.parametrize("seed, version, multi", [(0, "1.00", False), (1, "1.01", True),
                                                   (2, "1.00", True)])
def test_synthetic_holes_scale_and_channel(seed, version, multi):
    rng = np.random.default_rng(seed)
    ny, nx = int(rng.integers(3, 30)), int(rng.integers(3, 30))
    counts = rng.integers(100, 60000, (ny, nx)).astype(np.uint16)
    holes = rng.random((ny, nx)) < rng.uniform(0.05, 0.4)
    holes[0, 0] = False
    counts[holes] = rng.choice([1, 2, 3, 65530, 65535], size=int(holes.sum()))
    zscale = float(rng.uniform(1e-9, 1e-8))
    buf = make_frt(counts, zscale, 1e-3, 2e-3, version=version, multi=multi)
    t = read_bytes(buf, name="s.frt")
    assert t.metadata["format"] == "frt"
    np.testing.assert_array_equal(t.mask, holes)
    np.testing.assert_allclose(t.heights[~holes], counts[~holes] * zscale, rtol=1e-15)
    assert (t.dx, t.dy) == pytest.approx((1e-3 / nx, 2e-3 / ny))
    assert t.metadata["channel"] == "topography"
    assert t.metadata["file_version"] == version


def test_synthetic_int32_without_valid_range_uses_count_one():
    rng = np.random.default_rng(7)
    counts = rng.integers(-50000, 50000, (6, 9)).astype(np.int32)
    counts[2, 3] = 1
    counts[4, 4] = 2  # a legitimate height: no range block to call it undefined
    t = read_bytes(make_frt(counts, 1e-9, 1e-3, 1e-3, valid=None))
    assert t.mask.sum() == 1 and t.mask[2, 3]
    assert "no block 0x0070" in t.metadata["invalid_rule"]
    assert t.heights[4, 4] == pytest.approx(2e-9)


def test_intensity_channel_is_refused_and_channel_selects_topography():
    counts = np.full((4, 5), 1000, np.uint16)
    buf = make_frt(counts, 1e-9, 1e-3, 1e-3, multi=True, intensity_first=True)
    t = read_bytes(buf)
    assert t.heights[0, 0] == pytest.approx(1e-6)
    assert read_bytes(buf, channel=1).heights[0, 0] == pytest.approx(1e-6)
    with pytest.raises(SurfmetFormatError, match="intensity"):
        read_bytes(buf, channel=0)
    with pytest.raises(SurfmetFormatError, match="channel 5"):
        read_bytes(buf, channel=5)


def test_damaged_blocks():
    counts = np.full((4, 5), 1000, np.uint16)
    buf = make_frt(counts, 1e-9, 1e-3, 1e-3)
    with pytest.raises(SurfmetFormatError, match="truncated"):
        read_bytes(buf[:-7])
    no_scale = buf.replace(struct.pack("<H", 0x006C), struct.pack("<H", 0x00FE), 1)
    with pytest.raises(SurfmetFormatError, match="0x006c"):
        read_bytes(no_scale)
    with pytest.raises(SurfmetFormatError, match="version"):
        read_bytes(b"FRTM_GLIDERV1.07" + buf[16:])


def test_huge_grid_claim_fails_fast():
    counts = np.full((2, 2), 1000, np.uint16)
    buf = bytearray(make_frt(counts, 1e-9, 1e-3, 1e-3))
    at = buf.index(struct.pack("<III", 2, 2, 16))
    buf[at : at + 8] = struct.pack("<II", 100_000, 100_000)
    with pytest.raises(SurfmetFormatError, match=r"absurd|truncated"):
        read_bytes(bytes(buf))
