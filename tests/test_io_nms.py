"""NanoFocus µsurf ``.nms`` reader (the instrument of Alaci et al. 2022).

Truths: the real file's header (nm lateral step, µm height range, raw 0 and 65535 present),
the physics of a confocal image (surface slopes a microscope objective can see), and NMS
files built here from the documented layout.
"""

from __future__ import annotations

import struct

import numpy as np
import pytest
from _refusal import refused_cheaply

import surfmet
from surfmet import SurfmetFormatError
from surfmet._model import Profile, Topography
from surfmet.io import detect_format, read_bytes


def nms_file(raw: np.ndarray, *, f_low: float = 1.0, f_high: float = 3.0, n_low: int = 0,
             n_high: int = 65535, step_nm: tuple[float, float] = (312.5, 312.5),
             intensity: np.ndarray | None = None, dim: int = 1) -> bytes:
    """An OM_MS_2.0 file laid out as the real µsurf file is."""
    r = np.atleast_2d(np.asarray(raw, dtype="<u2"))
    ny, nx = r.shape
    h = bytearray(3468)
    struct.pack_into("<4i2d", h, 0, 2, dim, n_low, n_high, f_low, f_high)
    h[32:41] = b"OM_MS_2.0"
    h[52:73] = b"Confocal Height Image"
    h[1076:1092] = b"2022-02-09T13:25"
    h[1096:1103] = b"Unknown"
    struct.pack_into("<i", h, 1352, 3468)
    struct.pack_into("<2I2d3d", h, 1368, nx, ny, *step_nm, 1.0, 2.0, 3.0)
    struct.pack_into("<i", h, 1416, 0 if intensity is None else 1)
    out = bytes(h) + r.tobytes()
    if intensity is not None:
        out += np.asarray(intensity, dtype=np.uint8).tobytes()
    return out


# ----------------------------------------------------------------------------- real file


@pytest.mark.realdata
def test_nms1_grid_and_nanometre_step(realdata):
    t = surfmet.read(realdata("nms-1.nms"))
    assert isinstance(t, Topography)
    assert (t.nx, t.ny) == (512, 512)
    # The header step is 312.5 in nanometres: a 0.3125 µm pixel, a 160 µm field.
    np.testing.assert_allclose(t.dx, 312.5e-9, rtol=1e-7)
    np.testing.assert_allclose(t.dy, 312.5e-9, rtol=1e-7)
    np.testing.assert_allclose(t.size_x, 160e-6, rtol=1e-7)
    assert t.metadata["height_unit"] == "um"
    assert t.metadata["lateral_unit"] == "nm"
    assert np.all(np.isfinite(t.heights)) and t.nan_fraction == 0.0
    assert t.metadata["format_version"] == "OM_MS_2.0"
    assert t.metadata["date"] == "2022-02-09T13:25"
    assert t.metadata["title"] == "Confocal Height Image"


@pytest.mark.realdata
def test_nms1_height_scale_endpoints(realdata):
    buf = realdata("nms-1.nms").read_bytes()
    t = surfmet.read(realdata("nms-1.nms"))
    f_low, f_high = struct.unpack_from("<2d", buf, 16)
    raw = np.frombuffer(buf, "<u2", count=512 * 512, offset=3468).reshape(512, 512)
    # The file holds both extreme codes: they map exactly to the header's height range.
    assert raw.min() == 0 and raw.max() == 65535
    np.testing.assert_allclose(t.heights[raw == 0], f_low * 1e-6, rtol=1e-15)
    np.testing.assert_allclose(t.heights[raw == 65535], f_high * 1e-6, rtol=1e-15)
    np.testing.assert_allclose(f_high - f_low, 3.318277835845947, rtol=1e-12)
    # Linear in between, with the header's 65535 steps (ST uses 65534).
    i = np.unravel_index(np.argmin(np.abs(raw.astype(int) - 30000)), raw.shape)
    expected = f_low + raw[i] * (f_high - f_low) / 65535
    np.testing.assert_allclose(t.heights[i], expected * 1e-6, rtol=1e-14)


@pytest.mark.realdata
def test_nms1_slopes_are_those_of_a_microscope_image(realdata):
    # With 312.5 nm pixels the rms slope is a few percent, what a confocal objective sees.
    # Read as millimetres (SurfaceTopography 1.27.1) the slopes would be ~1e-8: flatter
    # than any real surface over a 160 m field.
    t = surfmet.read(realdata("nms-1.nms"))
    gx = np.diff(t.heights, axis=1) / t.dx
    gy = np.diff(t.heights, axis=0) / t.dy
    rms_slope = np.sqrt(np.mean(gx**2) / 2 + np.mean(gy**2) / 2)
    assert 1e-3 < rms_slope < 1.0


@pytest.mark.realdata
def test_nms1_truncation_and_corruption(realdata):
    buf = realdata("nms-1.nms").read_bytes()
    for cut in (20, 40, 1370, 3000, 3468, 100_000, 3468 + 2 * 512 * 512 + 10, len(buf) - 1):
        with pytest.raises(SurfmetFormatError):
            read_bytes(buf[:cut], format="nms", name="cut.nms")
    for offset, fmt, value, message in ((0, "<i", 4, "data type"),
                                        (12, "<i", 0, "range"),
                                        (16, "<d", float("inf"), "height range"),
                                        (1352, "<i", 4000, "header size"),
                                        (1376, "<d", -312.5, "step")):
        bad = bytearray(buf)
        struct.pack_into(fmt, bad, offset, value)
        with pytest.raises(SurfmetFormatError, match=message):
            read_bytes(bytes(bad), format="nms", name="bad.nms")


# ----------------------------------------------------------------------------- synthetic


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_zero_intensity_points_are_not_measured(seed):
    rng = np.random.default_rng(seed)
    ny, nx = rng.integers(2, 30, size=2)
    raw = rng.integers(0, 65536, size=(ny, nx))
    intensity = rng.integers(1, 256, size=(ny, nx))
    holes = rng.random((ny, nx)) < rng.uniform(0.05, 0.5)
    holes[0, 0] = False
    intensity[holes] = 0
    buf = nms_file(raw, f_low=-2.0, f_high=6.0, intensity=intensity, step_nm=(500.0, 250.0))
    assert detect_format(buf) == "nms"
    t = read_bytes(buf, name="s.nms")
    np.testing.assert_array_equal(np.isnan(t.heights), holes)
    expected = (-2.0 + raw * 8.0 / 65535) * 1e-6
    np.testing.assert_allclose(t.heights[~holes], expected[~holes], rtol=1e-13)
    assert (t.dx, t.dy) == pytest.approx((500e-9, 250e-9), rel=1e-15)
    assert t.metadata["non_measured_points"] == holes.sum()


def test_raw_range_offset_and_profiles():
    raw = np.array([[100, 200, 300]])
    t = read_bytes(nms_file(raw, n_low=100, n_high=300, f_low=0.0, f_high=2.0, dim=0),
                   name="p.nms")
    assert isinstance(t, Profile)
    np.testing.assert_allclose(t.z, [0.0, 1e-6, 2e-6], atol=1e-20)


def test_signature_required():
    buf = bytearray(nms_file(np.zeros((2, 2))))
    buf[32:38] = b"XX_MS_"
    from surfmet.io.nms import _is_nms
    assert not _is_nms(bytes(buf))
    with pytest.raises(SurfmetFormatError, match="OM_MS_"):
        read_bytes(bytes(buf), format="nms", name="sig.nms")


def test_tiny_file_claiming_huge_grid():
    buf = bytearray(nms_file(np.zeros((2, 2))))
    struct.pack_into("<2I", buf, 1368, 40000, 40000)
    refused_cheaply(buf, name="huge.nms", match=r"truncated|absurd")
