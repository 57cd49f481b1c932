"""``surfmet.read`` on a path, on the file's bytes and on a binary stream gives one scan.

contact.engineering's web app reads uploads as binary streams; every real instrument file in
``../shared/realdata`` is read three ways here (path, ``bytes`` with the format detected
from the magic bytes alone, ``io.BytesIO`` with ``format=``), and the heights (NaN-aware)
and the metadata must be the same as the path's, bar the record of where they came from.
"""

from __future__ import annotations

import io

import numpy as np
import pytest
from conftest import REALDATA
from test_io_smd import profile_file

import surfmet
from surfmet._errors import SurfmetFormatError, SurfmetInputError
from surfmet._model import Profile, Topography
from surfmet.io import encode, read_container

pytestmark = pytest.mark.realdata

FILES = sorted(p.name for p in REALDATA.iterdir()
               if p.is_file() and p.name != "MANIFEST.tsv" and not p.name.startswith(".")) \
    if REALDATA.is_dir() else []

# where a scan came from: the path, or the container's file name, which bytes do not have
_WHERE = ("source", "container")


def _values(scan: Topography | Profile) -> np.ndarray:
    return scan.heights if isinstance(scan, Topography) else scan.z


def _same(a: Topography | Profile, b: Topography | Profile) -> None:
    assert type(a) is type(b)
    assert np.array_equal(_values(a), _values(b), equal_nan=True)
    if isinstance(a, Profile):
        assert np.array_equal(a.x, b.x)
    else:
        assert (a.dx, a.dy) == (b.dx, b.dy)
    strip = lambda s: {k: v for k, v in s.metadata.items() if k not in _WHERE}  # noqa: E731
    assert repr(strip(a)) == repr(strip(b))


@pytest.mark.parametrize("name", FILES)
def test_bytes_and_stream_read_as_the_path(name, realdata):
    path = realdata(name)
    from_path = surfmet.read(path)
    fmt = from_path.metadata["format"]
    buf = path.read_bytes()
    from_bytes = surfmet.read(buf)  # no name: the magic bytes alone tell the format
    assert from_bytes.metadata["format"] == fmt
    _same(from_path, from_bytes)
    assert "source" not in from_bytes.metadata
    _same(from_path, surfmet.read(io.BytesIO(buf), format=fmt))
    _same(from_path, surfmet.read(memoryview(buf), format=fmt))
    with open(path, "rb") as fh:  # an open file: its name is the source
        from_file = surfmet.read(fh)
    _same(from_path, from_file)
    assert from_file.metadata["source"] == str(path)


def test_container_reads_from_bytes_and_streams(realdata):
    path = realdata("container-2.zip")
    whole = read_container(path)
    buf = path.read_bytes()
    for source in (buf, io.BytesIO(buf)):
        scans = read_container(source)
        assert len(scans) == len(whole) == 3
        for a, b in zip(whole, scans):
            _same(a, b)
    # a measurement other than the first, through the reader's own option
    _same(surfmet.read(path, channel=2), surfmet.read(io.BytesIO(buf), channel=2))


@pytest.mark.parametrize("fmt", ["npy", "npz", "x3p"])
def test_written_formats_read_back_from_streams(fmt, tmp_path):
    topo = Topography(np.arange(12.0).reshape(3, 4) * 1e-7, 1e-6, 2e-6)
    buf = encode(topo, fmt)
    path = tmp_path / f"t.{fmt}"
    path.write_bytes(buf)
    from_path = surfmet.read(path)
    np.testing.assert_array_equal(from_path.heights, topo.heights)
    _same(from_path, surfmet.read(buf))
    _same(from_path, surfmet.read(io.BytesIO(buf), format=fmt))


def test_text_formats_from_streams(tmp_path):
    xyz = b"".join(b"%g %g %g\n" % (i * 1e-6, j * 1e-6, (i + 2 * j) * 1e-8)
                   for j in range(3) for i in range(4))
    smd = profile_file(np.round(np.sin(np.arange(50) * 0.1), 6))
    for fmt, buf in (("xyz", xyz), ("smd", smd)):
        path = tmp_path / f"t.{fmt}"
        path.write_bytes(buf)
        from_path = surfmet.read(path)
        _same(from_path, surfmet.read(io.BytesIO(buf), format=fmt))
        _same(from_path, surfmet.read(bytearray(buf), format=fmt))


def test_errors_name_the_bytes_or_the_stream(realdata):
    buf = realdata("plu-1.plu").read_bytes()[:300]  # truncated
    with pytest.raises(SurfmetFormatError) as exc:
        surfmet.read(buf)
    assert str(exc.value).startswith("<bytes>: ") and "\n" not in str(exc.value)
    with pytest.raises(SurfmetFormatError) as exc:
        surfmet.read(io.BytesIO(buf))
    assert str(exc.value).startswith("<stream>: ")
    named = io.BytesIO(b"no scan here")
    named.name = "upload.xyz"
    with pytest.raises(SurfmetFormatError) as exc:
        surfmet.read(named)
    assert str(exc.value).startswith("upload.xyz: ") and "\n" not in str(exc.value)
    with pytest.raises(SurfmetFormatError, match=r"^<bytes>: unknown file format"):
        surfmet.read(b"\x00\x01 not a scan")
    with pytest.raises(SurfmetFormatError, match=r"^<bytes>: the file is empty"):
        surfmet.read(b"")
    with pytest.raises(SurfmetInputError, match="binary mode"):
        surfmet.read(io.StringIO("1 2 3"))
    with pytest.raises(SurfmetInputError, match="cannot read a scan from a int"):
        surfmet.read(3)
    closed = io.BytesIO(b"x")
    closed.close()
    with pytest.raises(SurfmetFormatError, match="cannot read the stream"):
        surfmet.read(closed)
