"""Digital Surf ``.sur`` reader.

Truths: the values SurfaceTopography stores and reports for sur-3.sur (MANIFEST.tsv), the
file's own header, and SUR objects built here field by field from the format description,
with known integers, scales, units and non-measured sentinels.
"""

from __future__ import annotations

import struct
import zlib

import numpy as np
import pytest
from _peer_metrics import st_sq
from _refusal import refused_cheaply

import surfmet
from surfmet import SurfmetFormatError
from surfmet._model import Profile, Topography
from surfmet.io import detect_format, read_bytes


def sur_object(points: np.ndarray, *, obj_type: int = 2, bits: int = 32, zmin: int | None = None,
               zmax: int | None = None, special: int = 0, spacing=(1.0, 1.0, 1.0),
               step_units=("um", "um", "um"), z_offset: float = 0.0, n_objects: int = 1,
               compressed: bool = False, streams: int = 1, big_endian: bool = False,
               comment: bytes = b"", n_total: int | None = None, w_size: int = 0,
               date=(2021, 5, 4, 3, 2, 1)) -> bytes:
    """One SUR object (512-byte header + comment + points), laid out per the format table."""
    e = ">" if big_endian else "<"
    pts = np.asarray(points)
    ny, nx = pts.shape if pts.ndim == 2 else (1, pts.size)
    h = bytearray(512)
    h[0:12] = b"DSCOMPRESSED" if compressed else b"DIGITAL SURF"
    struct.pack_into("<H", h, 12, 257 if big_endian else 0)
    struct.pack_into(e + "HHH", h, 14, n_objects, 1, obj_type)
    h[20:50] = b"sample".ljust(30)
    h[50:80] = b"operator".ljust(30)
    struct.pack_into(e + "5H", h, 80, 0, 9, 0, special, 0)
    struct.pack_into(e + "I", h, 94, w_size)
    struct.pack_into(e + "H", h, 98, bits)
    lo = int(pts.min()) if zmin is None else zmin
    hi = int(pts.max()) if zmax is None else zmax
    total = nx * ny if n_total is None else n_total
    struct.pack_into(e + "5i", h, 100, lo, hi, nx, ny, total)
    struct.pack_into(e + "3f", h, 120, *spacing)
    for i, name in enumerate("XYZ"):
        h[132 + 16 * i:148 + 16 * i] = name.encode().ljust(16)
        h[180 + 16 * i:196 + 16 * i] = step_units[i].encode("latin-1").ljust(16)
        h[228 + 16 * i:244 + 16 * i] = step_units[i].encode("latin-1").ljust(16)
    struct.pack_into(e + "3f", h, 276, 1.0, 1.0, 1.0)
    y, mo, d, hh, mi, s = date
    struct.pack_into(e + "7H", h, 306, s, mi, hh, d, mo, y, 0)
    struct.pack_into(e + "HH", h, 334, len(comment), 0)
    struct.pack_into(e + "3f", h, 466, 0.0, 0.0, z_offset)
    raw = pts.astype(f"{e}i{bits // 8}").tobytes()
    if compressed:
        parts = np.array_split(np.frombuffer(raw, np.uint8), streams)
        zipped = [zlib.compress(p.tobytes()) for p in parts]
        data = struct.pack("<I", streams)
        data += b"".join(struct.pack("<II", p.size, len(z)) for p, z in zip(parts, zipped))
        data += b"".join(zipped)
        struct.pack_into(e + "I", h, 324, len(data))
    else:
        data = raw
    return bytes(h) + comment + data


# ----------------------------------------------------------------------------- real file


@pytest.mark.realdata
def test_sur3_grid_units_and_non_measured(realdata):
    t = surfmet.read(realdata("sur-3.sur"))
    assert isinstance(t, Topography)
    assert (t.nx, t.ny) == (512, 512)
    np.testing.assert_allclose(t.nx * t.dx, 0.151319552, rtol=1e-6)
    np.testing.assert_allclose(t.ny * t.dy, 0.151319552, rtol=1e-6)
    np.testing.assert_allclose(t.dx, 295.546e-6, rtol=1e-9)
    assert t.metadata["height_unit"] == "m"
    assert t.metadata["lateral_unit"] == "nm"
    assert np.count_nonzero(np.isnan(t.heights)) == 233009
    np.testing.assert_allclose(t.nan_fraction, 0.889, atol=5e-4)
    assert t.metadata["vendor"] == "Digital Surf"
    assert t.metadata["date"] == "2023-06-22T10:08:53"


@pytest.mark.realdata
def test_sur3_sq_valid_points_and_the_old_surfacetopography_number(realdata):
    t = surfmet.read(realdata("sur-3.sur"))
    # Installed ST 1.27.1 (valid points only) gives 0.0011132 (manifest, 5 digits).
    np.testing.assert_allclose(st_sq(t.heights), 0.0011132, rtol=5e-5)
    # The value stored in ST's test, 0.0019200491394179297, is the rms of all 262144 grid
    # values with the non-measured sentinels (zmin - 2 = -2 steps of 1 nm) counted as
    # heights and the z offset not applied: the old reader did not honour the flag.
    md = t.metadata
    step = md["z_spacing"]
    raw_heights = np.where(np.isnan(t.heights), (md["zmin_raw"] - 2) * step,
                           t.heights - md["z_offset"])
    old = np.sqrt(np.mean((raw_heights - raw_heights.mean()) ** 2))
    np.testing.assert_allclose(old, 0.0019200491394179297, rtol=1e-9)
    # Equivalently (to 1e-6): valid points only, but normalised by the total grid size,
    # which is not translation invariant: adding the z offset changes it.
    v = (t.heights - md["z_offset"])[np.isfinite(t.heights)]
    n = t.heights.size
    total_norm = np.sqrt(np.sum(v**2) / n - (np.sum(v) / n) ** 2)
    np.testing.assert_allclose(total_norm, 0.0019200491394179297, rtol=1e-6)
    w = t.heights[np.isfinite(t.heights)]
    shifted = np.sqrt(np.sum(w**2) / n - (np.sum(w) / n) ** 2)
    assert abs(shifted - total_norm) / total_norm > 0.1


@pytest.mark.realdata
def test_sur3_truncation_and_corruption(realdata):
    buf = realdata("sur-3.sur").read_bytes()
    for cut in (11, 100, 300, 511, 512, 1000, len(buf) // 2, len(buf) - 1):
        with pytest.raises(SurfmetFormatError):
            read_bytes(buf[:cut], format="sur", name="cut.sur")
    bad = bytearray(buf)
    struct.pack_into("<H", bad, 98, 24)  # 24 bits per point
    with pytest.raises(SurfmetFormatError, match="bits per point"):
        read_bytes(bytes(bad), name="bits.sur")
    bad = bytearray(buf)
    struct.pack_into("<i", bad, 116, 1234)  # total points inconsistent with the grid
    with pytest.raises(SurfmetFormatError, match="points"):
        read_bytes(bytes(bad), name="count.sur")
    bad = bytearray(buf)
    bad[212:228] = b"furlong".ljust(16)
    with pytest.raises(SurfmetFormatError, match="unit"):
        read_bytes(bytes(bad), name="unit.sur")


# ----------------------------------------------------------------------------- synthetic


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_sentinel_points_become_nan_and_scale_applies(seed):
    rng = np.random.default_rng(seed)
    ny, nx = rng.integers(2, 30, size=2)
    zmin = int(rng.integers(-1000, 1000))
    pts = rng.integers(zmin, zmin + 5000, size=(ny, nx))
    holes = rng.random((ny, nx)) < rng.uniform(0.05, 0.6)
    holes[0, 0] = False
    pts[holes] = zmin - 2
    dz, offset = 2.5, -7.0  # in micrometres
    buf = sur_object(pts, zmin=zmin, special=1, spacing=(0.5, 0.25, dz), z_offset=offset)
    t = read_bytes(buf, name="s.sur")
    np.testing.assert_array_equal(np.isnan(t.heights), holes)
    expected = (pts * dz + offset) * 1e-6
    np.testing.assert_allclose(t.heights[~holes], expected[~holes], rtol=1e-12)
    assert (t.dx, t.dy) == (0.5e-6, 0.25e-6)
    # Without the special-points flag the same value is an ordinary height.
    t2 = read_bytes(sur_object(pts, zmin=zmin, special=0), name="s2.sur")
    assert not t2.has_nan


def test_int16_big_endian_and_units():
    pts = np.array([[-300, 0, 300], [1, 2, 3]])
    buf = sur_object(pts, bits=16, big_endian=True, spacing=(2.0, 3.0, 4.0),
                     step_units=("mm", "\xb5m", "nm"), date=(2020, 2, 29, 23, 59, 58))
    t = read_bytes(buf, name="be.sur")
    np.testing.assert_allclose(t.heights, pts * 4e-9, rtol=1e-12)
    assert (t.dx, t.dy) == (2e-3, 3e-6)
    assert t.metadata["date"] == "2020-02-29T23:59:58"
    assert t.metadata["bits_per_point"] == 16


@pytest.mark.parametrize("streams", [1, 3])
def test_compressed_objects(streams):
    rng = np.random.default_rng(streams)
    pts = rng.integers(-10**6, 10**6, size=(13, 17))
    buf = sur_object(pts, compressed=True, streams=streams, comment=b"hello surf")
    assert detect_format(buf) == "sur"
    t = read_bytes(buf, name="c.sur")
    np.testing.assert_allclose(t.heights, pts * 1e-6, rtol=1e-12)
    assert t.metadata["compressed"] and t.metadata["comment"] == "hello surf"


def test_compressed_bombs_and_corruption_are_refused():
    pts = np.zeros((50, 50), dtype=int)
    buf = bytearray(sur_object(pts, compressed=True))
    # Claim a 10^8-point grid (and raw stream length to match) behind a tiny stream.
    struct.pack_into("<5i", buf, 100, 0, 0, 10**4, 10**4, 10**8)
    struct.pack_into("<I", buf, 516, 4 * 10**8)
    refused_cheaply(buf, name="bomb.sur", match=r"cannot hold|bomb")
    buf = bytearray(sur_object(pts + 5, compressed=True))
    buf[-10:] = b"\xff" * 10
    with pytest.raises(SurfmetFormatError):
        read_bytes(bytes(buf), name="corrupt.sur")


def test_first_height_object_after_an_image():
    image = np.arange(12).reshape(3, 4)
    surface = np.arange(6).reshape(2, 3) * 10
    buf = sur_object(image, obj_type=10, n_objects=2) + sur_object(surface, n_objects=2)
    t = read_bytes(buf, name="multi.sur")
    np.testing.assert_allclose(t.heights, surface * 1e-6)
    assert t.metadata["object_index"] == 1
    with pytest.raises(SurfmetFormatError, match="no height data"):
        read_bytes(sur_object(image, obj_type=12), name="rgb.sur")


def test_profiles_and_gwyddion_style_surfaces():
    p = read_bytes(sur_object(np.arange(7)[None, :], obj_type=1), name="p.sur")
    assert isinstance(p, Profile) and p.n == 7
    # Gwyddion exports surfaces with the profile type: more than one line means areal.
    t = read_bytes(sur_object(np.arange(8).reshape(2, 4), obj_type=1), name="g.sur")
    assert isinstance(t, Topography) and t.shape == (2, 4)


def test_tiny_file_claiming_huge_grid():
    buf = bytearray(sur_object(np.zeros((4, 4), dtype=int)))
    struct.pack_into("<5i", buf, 100, 0, 0, 50000, 40000, 50000 * 40000)
    refused_cheaply(buf, name="huge.sur", match=r"truncated|absurd")


def test_spectral_objects_are_not_heights():
    buf = bytearray(sur_object(np.zeros((2, 2), dtype=int), w_size=5))
    with pytest.raises(SurfmetFormatError):
        read_bytes(bytes(buf), name="spec.sur")
