"""Igor binary wave reader: the two real files against SurfaceTopography's test/IO/test_ibw.py
(channel names, 20 µm scans, the one-channel file without a name) and against the Asylum
note inside the file (scan size, points); plus hand-built waves from PTN003's layout."""

from __future__ import annotations

import re
import struct

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import detect_format, read_bytes

SPOT_CHANNELS = ["HeightTrace", "HeightRetrace", "AmplitudeTrace", "AmplitudeRetrace",
                 "PhaseTrace", "PhaseRetrace", "NapPotentialTrace", "NapPotentialRetrace"]


def note_field(path, key):
    text = path.read_bytes().decode("latin-1")
    return re.search(rf"(?<![A-Za-z]){key}:([^\r]*)", text).group(1).strip()


@pytest.mark.realdata
def test_kpfm_file_all_channels_20_um(realdata):
    path = realdata("spot_1-1000nm.ibw")
    size = float(note_field(path, "ScanSize"))
    points = int(note_field(path, "ScanPoints"))
    assert size == 2e-5 and points == 256
    for ch in range(8):
        t = surfmet.read(path, channel=ch)
        assert (t.nx, t.ny) == (256, 256)
        # Asylum's delta is the scan size over (points - 1): samples at both edges
        assert t.dx == pytest.approx(size / (points - 1), rel=1e-12)
        assert t.dy == pytest.approx(size / (points - 1), rel=1e-12)
        assert t.nx * t.dx == pytest.approx(2e-5, rel=0.01)  # ST: approx 2e-05
        assert t.metadata["channel"] == SPOT_CHANNELS[ch]
    t = surfmet.read(path)
    assert t.metadata["channels"] == SPOT_CHANNELS
    assert t.metadata["channel"] == "HeightTrace"
    assert t.metadata["height_unit"] == "m"
    assert t.metadata["instrument"] == note_field(path, "MicroscopeModel")
    assert 1e-9 < np.nanstd(t.heights) < 1e-5  # an AFM height map, in metres


@pytest.mark.realdata
def test_one_channel_without_name(realdata):
    t = surfmet.read(realdata("10x10-one_channel_without_name.ibw"))
    assert (t.nx, t.ny) == (10, 10)
    assert t.nx * t.dx == 10.0 and t.ny * t.dy == 10.0  # ST: physical size (10, 10), no unit
    assert t.metadata["channels"] == ["no name (1)"]
    assert t.metadata["units_missing"] and not t.metadata["lateral_calibrated"]


def wave(values: np.ndarray, order: str = "<", units: bytes = b"nm", labels=()) -> bytes:
    """A version-5 wave of float64 layers (nlayers, ny, nx), checksum filled in."""
    nl, ny, nx = values.shape
    data = values.astype(order + "f8").tobytes()
    lab = b"".join(s.encode().ljust(32, b"\0") for s in ("", *labels)) if labels else b""
    wh = bytearray(320)
    struct.pack_into(order + "i", wh, 12, values.size)
    struct.pack_into(order + "h", wh, 16, 4)
    struct.pack_into(order + "4i", wh, 68, nx, ny, nl if nl > 1 else 0, 0)
    struct.pack_into(order + "4d", wh, 84, 2e-3, 3e-3, 1.0, 1.0)
    wh[148:152] = units.ljust(4, b"\0")
    wh[152:156] = b"mm".ljust(4, b"\0")
    bh = bytearray(64)
    struct.pack_into(order + "hhiiii4i4iiii", bh, 0, 5, 0, 320 + len(data), 0, 0, 0,
                     0, 0, 0, 0, 0, 0, len(lab), 0, 0, 0, 0)
    s = int(np.frombuffer(bytes(bh + wh), order + "i2").astype(np.int64).sum())
    struct.pack_into(order + "h", bh, 2, (-s) & 0xFFFF if (-s) & 0xFFFF < 32768
                     else ((-s) & 0xFFFF) - 65536)
    return bytes(bh + wh) + data + lab


@pytest.mark.parametrize("order", ["<", ">"])
def test_hand_built_wave_both_byte_orders(order):
    rng = np.random.default_rng(3)
    v = rng.normal(size=(2, 4, 5))
    buf = wave(v, order, labels=("Amplitude", "HeightRetrace"))
    assert detect_format(buf, "w.bin") == "ibw"
    t = read_bytes(buf, name="w.ibw")
    assert t.metadata["channel"] == "HeightRetrace"
    # x fastest, rows flipped: row 0 is the last stored row
    np.testing.assert_array_equal(t.heights, v[1, ::-1, :] * 1e-9)
    assert t.dx == pytest.approx(2e-6) and t.dy == pytest.approx(3e-6)


def test_damaged_waves_fail_in_one_line():
    buf = wave(np.zeros((1, 4, 5)))
    for bad in (buf[:300], buf[:-16]):
        with pytest.raises(SurfmetFormatError) as info:
            read_bytes(bad, name="w.ibw", format="ibw")
        assert "\n" not in str(info.value)
    with pytest.raises(SurfmetFormatError, match="not a length"):
        read_bytes(wave(np.zeros((1, 4, 5)), units=b"V"), name="w.ibw")
