"""Sensofar ``.plu`` reader.

Truths: SurfaceTopography's test values for plu-1.plu (MANIFEST.tsv), the continuity of
the real height map (a misaligned read puts the previous row's last samples at the start
of every row), and PLU files built here from the documented layout.
"""

from __future__ import annotations

import struct

import numpy as np
import pytest
from _peer_metrics import detrend_curvature, st_rq, st_sq
from _refusal import refused_cheaply

import surfmet
from surfmet import SurfmetFormatError
from surfmet._model import Profile, Topography
from surfmet.io import detect_format, read_bytes


def plu_file(z_um: np.ndarray, *, mppx: float = 1.5, mppy: float = 2.0, mtype: int = 3,
             layer_grid: tuple[int, int] | None = None, n_layers: int = 1,
             date: bytes = b"Tue Jan  5 09:08:07 2021", tail: bytes = b"\0" * 16) -> bytes:
    """A PLU file laid out per Gwyddion's sensofar.c description."""
    z = np.atleast_2d(np.asarray(z_um, dtype=np.float32))
    ny, nx = z.shape
    b = bytearray(500)
    b[0:len(date)] = date
    struct.pack_into("<I", b, 128, 1609837687)
    b[132:138] = b"(None)"
    struct.pack_into("<3I7f", b, 388, ny, nx, nx, 1.0, mppx, mppy, 0.0, 0.0, 1.0, 0.0)
    struct.pack_into("<5I", b, 428, mtype, 0, 0, 14, 3)
    struct.pack_into("<5I d f 2I", b, 448, ny, nx, ny, nx, 1, 0.1, 50.0, 23, 0)
    struct.pack_into("<5B", b, 488, 0, n_layers, 255, 4, 1)
    struct.pack_into("<I", b, 496, 1)
    ly, lx = layer_grid if layer_grid is not None else (ny, nx)
    return bytes(b) + struct.pack("<II", ly, lx) + z.astype("<f4").tobytes() + tail


# ----------------------------------------------------------------------------- real file


@pytest.mark.realdata
def test_plu1_matches_surfacetopography(realdata):
    t = surfmet.read(realdata("plu-1.plu"))
    assert isinstance(t, Topography)
    assert (t.nx, t.ny) == (768, 576)
    np.testing.assert_allclose(t.nx * t.dx * 1e6, 1274.880066, rtol=1e-6)
    np.testing.assert_allclose(t.ny * t.dy * 1e6, 956.160049, rtol=1e-6)
    assert t.metadata["height_unit"] == "um"
    assert t.nan_fraction == 0.0
    h_um = t.heights * 1e6
    np.testing.assert_allclose(st_sq(h_um), 2.834391, rtol=1e-6)
    np.testing.assert_allclose(st_rq(h_um), 2.833895, rtol=1e-6)
    d = detrend_curvature(h_um, t.dx, t.dy)
    np.testing.assert_allclose(st_sq(d), 0.01818, rtol=1e-4)
    np.testing.assert_allclose(st_rq(d), 0.018167, rtol=1e-4)
    assert t.metadata["date"] == "2023-03-10T16:35:59"
    assert t.metadata["vendor"] == "Sensofar"
    assert t.metadata["measurement_type"] == "topography"


@pytest.mark.realdata
def test_plu1_alignment_has_no_two_sample_shift(realdata):
    buf = realdata("plu-1.plu").read_bytes()
    t = surfmet.read(realdata("plu-1.plu"))
    h = t.heights * 1e6
    # The two u32 at offset 500 are the layer grid, not heights.
    assert struct.unpack_from("<II", buf, 500) == (576, 768)
    # Reading from offset 500 (surfalize 0.19) starts with those integers as floats.
    shifted = np.frombuffer(buf, "<f4", count=768 * 576, offset=500).astype(float)
    assert abs(shifted[0]) < 1e-30 and abs(shifted[1]) < 1e-30
    shifted = shifted.reshape(576, 768)
    # In our map the left edge is as smooth as the interior: the step between columns 0
    # and 1 and between columns 1 and 2 is like any interior step. A 2-sample shift puts
    # the previous row's end in columns 0-1, which creates a jump between columns 1 and 2.
    interior = np.median(np.abs(np.diff(h[:, 10:-10], axis=1)))
    ours = np.median(np.abs(h[1:, 2] - h[1:, 1]))
    theirs = np.median(np.abs(shifted[1:, 2] - shifted[1:, 1]))
    assert ours < 3 * interior
    assert theirs > 10 * ours
    # And the peers' Sq is matched only by the aligned read.
    np.testing.assert_allclose(st_sq(h), 2.834391, rtol=1e-6)
    assert abs(st_sq(shifted) - 2.834391) / 2.834391 > 1e-3


@pytest.mark.realdata
def test_plu1_truncation_and_corruption(realdata):
    buf = realdata("plu-1.plu").read_bytes()
    for cut in (10, 130, 400, 499, 504, 508, 100_000, 508 + 4 * 768 * 576 - 1):
        with pytest.raises(SurfmetFormatError):
            read_bytes(buf[:cut], format="plu", name="cut.plu")
    bad = bytearray(buf)
    struct.pack_into("<I", bad, 500, 575)  # layer grid disagrees with calibration
    with pytest.raises(SurfmetFormatError, match="differs"):
        read_bytes(bytes(bad), format="plu", name="grid.plu")
    bad = bytearray(buf)
    struct.pack_into("<f", bad, 404, -1.0)  # negative microns per pixel (mppx)
    with pytest.raises(SurfmetFormatError, match="pixel size"):
        read_bytes(bytes(bad), format="plu", name="mpp.plu")


# ----------------------------------------------------------------------------- synthetic


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_non_measured_and_orientation(seed):
    rng = np.random.default_rng(seed)
    ny, nx = rng.integers(2, 25, size=2)
    z = rng.normal(0, 3, size=(ny, nx)).astype(np.float32)
    holes = rng.random((ny, nx)) < rng.uniform(0.05, 0.5)
    holes[0, 0] = False
    z[holes] = 1000001.0
    buf = plu_file(z)
    assert detect_format(buf, "") == "plu"
    t = read_bytes(buf, name="s.plu")
    np.testing.assert_array_equal(np.isnan(t.heights), holes)
    np.testing.assert_array_equal(t.heights[~holes], z[~holes].astype(float) * 1e-6)
    assert (t.dx, t.dy) == pytest.approx((1.5e-6, 2.0e-6), rel=1e-7)
    assert t.metadata["date"] == "2021-01-05T09:08:07"


def test_profile_measurement():
    t = read_bytes(plu_file(np.arange(9.0)[None, :], mtype=1), name="p.plu")
    assert isinstance(t, Profile) and t.n == 9
    np.testing.assert_allclose(t.z, np.arange(9.0) * 1e-6)


def test_image_measurement_is_refused():
    with pytest.raises(SurfmetFormatError, match="no heights"):
        read_bytes(plu_file(np.zeros((3, 3)), mtype=0), name="img.plu")


def test_magic_needs_consistent_grids():
    good = plu_file(np.zeros((4, 5)))
    assert detect_format(good, "") == "plu"
    bad = plu_file(np.zeros((4, 5)), layer_grid=(5, 4))
    assert detect_format(bad, "x.plu") == "plu"  # only the extension says so
    from surfmet.io.plu import _is_plu
    assert not _is_plu(bad)
    assert not _is_plu(b"Fri Mar 10 16:35:59 2023" + b"\0" * 600)


def test_tiny_file_claiming_huge_grid():
    buf = bytearray(plu_file(np.zeros((2, 2))))
    struct.pack_into("<II", buf, 388, 60000, 60000)
    struct.pack_into("<II", buf, 500, 60000, 60000)
    refused_cheaply(buf, format="plu", name="huge.plu", match=r"truncated|absurd")
