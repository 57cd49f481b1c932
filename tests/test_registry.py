"""The reader registry: detection, error wrapping, validation, the formats the issue names."""

import numpy as np
import pytest

import surfmet
from surfmet import SurfmetFormatError, Topography
from surfmet.io import detect_format, encode, formats, read_bytes
from surfmet.io._registry import register_reader

# Every format issue 2 names must have a registered reader.
REQUIRED_READERS = {
    "x3p", "sur", "plu", "opd", "nms", "metropro", "al3d", "frt", "sdf", "asc", "gwy",
    "dektak", "opdx", "hfm", "xyz", "npy", "npz",
}


def test_every_required_format_is_registered():
    missing = REQUIRED_READERS - set(formats())
    assert not missing, f"no reader for {sorted(missing)}"
    assert formats()["x3p"].encode is not None and formats()["npz"].encode is not None


def test_unknown_and_empty_files(tmp_path):
    junk = tmp_path / "junk.bin"
    junk.write_bytes(b"\x01\x02\x03 this is nothing known" * 10)
    with pytest.raises(SurfmetFormatError, match=r"junk\.bin"):
        surfmet.read(junk)
    empty = tmp_path / "empty.x3p"
    empty.write_bytes(b"")
    with pytest.raises(SurfmetFormatError, match="empty"):
        surfmet.read(empty)
    with pytest.raises(SurfmetFormatError, match="no such file"):
        surfmet.read(tmp_path / "absent.nms")
    with pytest.raises(SurfmetFormatError, match="directory"):
        surfmet.read(tmp_path)


def test_extension_fallback_and_explicit_format(tmp_path):
    t = Topography(np.arange(12.0).reshape(3, 4), 1e-6, 1e-6)
    data = encode(t, "npz")
    assert detect_format(data, "whatever.dat") == "npz"  # magic beats the extension
    p = tmp_path / "scan.npz"
    surfmet.write(t, p)
    back = surfmet.read(p, format="npz")
    assert np.array_equal(back.heights, t.heights)
    assert back.metadata["format"] == "npz" and back.metadata["source"] == str(p)


def test_reader_damage_becomes_format_error():
    @register_reader("_test_broken", extensions=("tbroken",), description="test only")
    def broken(buf, name):
        return np.zeros(3)[10]  # an IndexError from deep inside numpy

    with pytest.raises(SurfmetFormatError, match="IndexError"):
        read_bytes(b"abc", format="_test_broken", name="f.tbroken")


def test_all_nan_and_inf_rejected():
    @register_reader("_test_nan", extensions=("tnan",), description="test only")
    def all_nan(buf, name):
        return Topography(np.full((3, 3), np.nan), 1e-6, 1e-6)

    @register_reader("_test_inf", extensions=("tinf",), description="test only")
    def with_inf(buf, name):
        h = np.zeros((3, 3))
        h[1, 1] = np.inf
        return Topography(h, 1e-6, 1e-6)

    with pytest.raises(SurfmetFormatError, match="all NaN"):
        read_bytes(b"x", format="_test_nan")
    with pytest.raises(SurfmetFormatError, match="infinite"):
        read_bytes(b"x", format="_test_inf")


def test_npz_round_trip_exact(tmp_path):
    rng = np.random.default_rng(7)
    h = rng.normal(size=(33, 17)) * 1e-6
    h[rng.random(h.shape) < 0.1] = np.nan
    t = Topography(h, 0.3125e-6, 0.5e-6, {"instrument": "synthetic", "n": 3})
    p = surfmet.write(t, tmp_path / "a.npz")
    back = surfmet.read(p)
    assert np.array_equal(back.heights, t.heights, equal_nan=True)
    assert back.dx == t.dx and back.dy == t.dy
    assert back.metadata["instrument"] == "synthetic" and back.metadata["n"] == 3


def test_loading_does_not_import_analysis():
    import subprocess
    import sys

    code = (
        "import sys, surfmet, surfmet.io; surfmet.io.formats();"
        "bad = [m for m in ('numba', 'matplotlib', 'pyvista', 'skimage', 'dask', 'contact',"
        " 'profiles', 'surfmet.areal', 'scipy.optimize') if m in sys.modules];"
        "print(','.join(bad))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "", f"loading pulled in: {out.stdout.strip()}"


def test_unknown_reader_option_is_an_input_error():
    from surfmet import SurfmetInputError

    data = encode(Topography(np.ones((2, 2)), 1e-6, 1e-6), "npy")
    with pytest.raises(SurfmetInputError, match="no option"):
        read_bytes(data, format="npy", colour="red")
    assert read_bytes(data, format="npy", dx=2e-6).dx == 2e-6
