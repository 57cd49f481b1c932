"""Zygo MetroPro ``.dat`` reader.

Truths: SurfaceTopography's test values for metropro-1.dat (MANIFEST.tsv; Gwyddion agrees
on R = 32768 for phase_res 1), the file's own header, and MetroPro files built here from
the reference guide's layout with known phases and scale factors.
"""

from __future__ import annotations

import struct

import numpy as np
import pytest
from _peer_metrics import detrend_curvature, st_rq, st_sq
from _refusal import refused_cheaply

import surfmet
from surfmet import SurfmetFormatError
from surfmet._model import Topography
from surfmet.io import detect_format, read_bytes

MAGIC = {1: b"\x88\x1b\x03\x6f", 2: b"\x88\x1b\x03\x70", 3: b"\x88\x1b\x03\x71"}


def metropro_file(phase: np.ndarray, *, header_format: int = 1, phase_res: int = 1,
                  scale: float = 0.5, wavelength: float = 632.8e-9, obliquity: float = 1.0,
                  lateral: float = 2e-6, sign: int = 0, buckets: int = 1,
                  intensity_shape: tuple[int, int] | None = None,
                  timestamp: int = 1_600_000_000, serial: int = 40000) -> bytes:
    """A MetroPro file: big-endian header, intensity buckets, then the phase map."""
    ph = np.asarray(phase, dtype=">i4")
    ny, nx = ph.shape
    iy, ix = intensity_shape if intensity_shape is not None else (ny, nx)
    size = 834 if header_format in (1, 2) else 4096
    h = bytearray(size)
    h[0:4] = MAGIC[header_format]
    struct.pack_into(">HIh", h, 4, header_format, size, 1)
    h[12:36] = b"Mon Jan  1 00:00:00 2001"
    struct.pack_into(">3h", h, 42, 9, 2, 1)
    struct.pack_into(">hhHHHhI", h, 48, 0, 0, ix, iy, buckets, 255, 2 * ix * iy * buckets)
    struct.pack_into(">hhHHI", h, 64, 0, 0, nx, ny, 4 * nx * ny)
    struct.pack_into(">i", h, 76, timestamp)
    h[80:92] = b"test comment"
    struct.pack_into(">h6f", h, 162, 0, scale, wavelength, 0.3, obliquity, 10.0, lateral)
    struct.pack_into(">h", h, 218, phase_res)
    struct.pack_into(">h", h, 232, sign)
    struct.pack_into(">hhhhHh", h, 234, nx, ny, 5, 0, serial, 0)
    h[246:256] = b"10X Mirau "
    intens = (np.arange(ix * iy * buckets) % 1000).astype(">u2").tobytes()
    return bytes(h) + intens + ph.tobytes()


# ----------------------------------------------------------------------------- real file


@pytest.mark.realdata
def test_metropro1_matches_surfacetopography(realdata):
    t = surfmet.read(realdata("metropro-1.dat"))
    assert isinstance(t, Topography)
    assert (t.nx, t.ny) == (640, 480)
    np.testing.assert_allclose(t.nx * t.dx, 0.0007028812979115173, rtol=1e-12)
    np.testing.assert_allclose(t.ny * t.dy, 0.000527160973433638, rtol=1e-12)
    md = t.metadata
    assert md["height_unit"] == "m" and md["vendor"] == "Zygo"
    assert t.nan_fraction == 0.0
    np.testing.assert_allclose(st_sq(t.heights), 7.528822204734589e-08, rtol=1e-6)
    np.testing.assert_allclose(st_rq(t.heights), 7.524071e-08, rtol=1e-6)
    d = detrend_curvature(t.heights, t.dx, t.dy)
    np.testing.assert_allclose(st_sq(d), 3.911386124282179e-09, rtol=1e-6)
    np.testing.assert_allclose(st_rq(d), 3.868313e-09, rtol=1e-6)


@pytest.mark.realdata
def test_metropro1_header(realdata):
    md = surfmet.read(realdata("metropro-1.dat")).metadata
    assert md["header_format"] == 1
    assert md["instrument_serial"] == "59407"  # stored as u16 0xE80F
    assert md["date"].startswith("2011-07-23")
    np.testing.assert_allclose(md["wavelength"], 570e-9, rtol=1e-7)
    assert md["phase_res"] == 1 and md["phase_resolution"] == 32768
    assert md["interferometric_scale_factor"] == 0.5 and md["obliquity_factor"] == 1.0
    assert md["objective"] == "20X  Mirau"
    assert md["software_version"] == "8.1.5"


@pytest.mark.realdata
def test_metropro1_phase_res_index_is_not_a_count(realdata):
    # surfalize 0.19 maps phase_res 1 to R = 4096: its heights are exactly 8 times ours,
    # and its Sq 8 times the value SurfaceTopography's test asserts.
    buf = realdata("metropro-1.dat").read_bytes()
    t = surfmet.read(realdata("metropro-1.dat"))
    phase = np.frombuffer(buf, ">i4", count=640 * 480, offset=834 + 614400).reshape(480, 640)
    ours = phase * (0.5 * 1.0 * np.float32(570e-9).item() / 32768)
    np.testing.assert_allclose(t.heights, ours, rtol=1e-12)
    surfalize_sq = st_sq(phase * (0.5 * np.float32(570e-9).item() / 4096))
    np.testing.assert_allclose(surfalize_sq / 7.528822204734589e-08, 8.0, rtol=1e-6)


@pytest.mark.realdata
def test_metropro1_truncation_and_corruption(realdata):
    buf = realdata("metropro-1.dat").read_bytes()
    for cut in (3, 8, 100, 833, 834, 1000, 834 + 614400, len(buf) - 1):
        with pytest.raises(SurfmetFormatError):
            read_bytes(buf[:cut], format="metropro", name="cut.dat")
    for offset, fmt, value, message in ((4, ">H", 3, "contradicts"),
                                        (6, ">I", 4096, "header size"),
                                        (60, ">I", 12, "intensity size"),
                                        (72, ">I", 12, "phase size"),
                                        (218, ">h", 3, "phase_res"),
                                        (168, ">f", -1.0, "wavelength")):
        bad = bytearray(buf)
        struct.pack_into(fmt, bad, offset, value)
        with pytest.raises(SurfmetFormatError, match=message):
            read_bytes(bytes(bad), name="bad.dat")


# ----------------------------------------------------------------------------- synthetic


@pytest.mark.parametrize(("header_format", "phase_res", "resolution"),
                         [(1, 0, 4096), (2, 1, 32768), (3, 2, 131072)])
def test_header_formats_and_phase_resolutions(header_format, phase_res, resolution):
    rng = np.random.default_rng(header_format)
    phase = rng.integers(-10**6, 10**6, size=(7, 9))
    buf = metropro_file(phase, header_format=header_format, phase_res=phase_res,
                        scale=0.5, obliquity=1.25, wavelength=632.8e-9, buckets=2)
    assert detect_format(buf) == "metropro"
    t = read_bytes(buf, name="s.dat")
    wl = float(np.float32(632.8e-9))
    np.testing.assert_allclose(t.heights, phase * 0.5 * 1.25 * wl / resolution, rtol=1e-12)
    assert t.dx == pytest.approx(2e-6, rel=1e-7)
    assert t.metadata["header_format"] == header_format


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_invalid_phase_and_sign(seed):
    rng = np.random.default_rng(seed)
    phase = rng.integers(-5000, 5000, size=(6, 11))
    holes = rng.random(phase.shape) < rng.uniform(0.05, 0.5)
    holes[0, 0] = False
    phase[holes] = 2147483640 + rng.integers(0, 8, size=holes.sum())
    t = read_bytes(metropro_file(phase, sign=1), name="i.dat")
    np.testing.assert_array_equal(np.isnan(t.heights), holes)
    wl = float(np.float32(632.8e-9))
    np.testing.assert_allclose(t.heights[~holes], -phase[~holes] * 0.5 * wl / 32768,
                               rtol=1e-12)


def test_intensity_only_file_is_refused_and_missing_lateral_is_flagged():
    buf = bytearray(metropro_file(np.zeros((2, 2), dtype=int)))
    struct.pack_into(">HHI", buf, 68, 0, 0, 0)
    with pytest.raises(SurfmetFormatError, match="no phase"):
        read_bytes(bytes(buf[:834 + 8]), name="int.dat")
    t = read_bytes(metropro_file(np.ones((2, 2), dtype=int), lateral=0.0), name="nolat.dat")
    assert t.metadata["lateral_calibrated"] is False


def test_tiny_file_claiming_huge_grid():
    buf = bytearray(metropro_file(np.zeros((2, 2), dtype=int)))
    struct.pack_into(">hhHHI", buf, 64, 0, 0, 60000, 60000, (4 * 60000 * 60000) % 2**32)
    refused_cheaply(buf, name="huge.dat")
