"""X3P (ISO 25178-72) reader and writer.

Truths: SurfaceTopography's test values for x3p-2 (MANIFEST.tsv), the openGPS sample
KautschukInfiniteFocus.x3p's own header, hand-built archives whose integers, masks and
scales are known, and exact write/read round trips.
"""

from __future__ import annotations

import hashlib
import io
import struct
import zipfile

import numpy as np
import pytest
from _peer_metrics import st_rms_gradient, st_sq
from _refusal import refused_cheaply

import surfmet
from surfmet import SurfmetFormatError
from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography
from surfmet.io import detect_format, encode, read_bytes

NS = "http://www.opengps.eu/2008/ISO5436_2"
OWN_REAL_FILES = ("x3p-2.x3p", "KautschukInfiniteFocus.x3p", "sur-3.sur", "plu-1.plu",
                  "opd-1.opd", "nms-1.nms", "metropro-1.dat")


def make_x3p(data: bytes, nx: int, ny: int, *, dtype: str = "D", feature: str = "SUR",
             dx: str = "1e-6", dy: str = "2e-6", cz_extra: str = "", valid: bytes | None = None,
             cx_type: str = "I", md5: str | None = None, record2: str = "",
             size_z: int = 1, data_name: str = "bindata/data.bin") -> bytes:
    """A minimal X3P archive written by hand from the schema (not by surfmet)."""
    digest = hashlib.md5(data).hexdigest() if md5 is None else md5
    vlink = ""
    if valid is not None:
        vlink = (f"<ValidPointsLink>bindata/valid.bin</ValidPointsLink>"
                 f"<MD5ChecksumValidPoints>{hashlib.md5(valid).hexdigest()}"
                 "</MD5ChecksumValidPoints>")
    xml = f"""<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="{NS}">
<Record1><Revision>ISO5436 - 2000</Revision><FeatureType>{feature}</FeatureType>
<Axes><CX><AxisType>{cx_type}</AxisType><DataType>D</DataType><Increment>{dx}</Increment>
<Offset>0</Offset></CX><CY><AxisType>I</AxisType><DataType>D</DataType>
<Increment>{dy}</Increment><Offset>0</Offset></CY>
<CZ><AxisType>A</AxisType><DataType>{dtype}</DataType>{cz_extra}</CZ></Axes></Record1>
{record2}
<Record3><MatrixDimension><SizeX>{nx}</SizeX><SizeY>{ny}</SizeY><SizeZ>{size_z}</SizeZ>
</MatrixDimension><DataLink><PointDataLink>{data_name}</PointDataLink>
<MD5ChecksumPointData>{digest}</MD5ChecksumPointData>{vlink}</DataLink></Record3>
<Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>
</p:ISO5436_2>""".encode()
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as zf:
        zf.writestr("main.xml", xml)
        zf.writestr(data_name, data)
        if valid is not None:
            zf.writestr("bindata/valid.bin", valid)
        zf.writestr("md5checksum.hex", f"{hashlib.md5(xml).hexdigest()} *main.xml\n")
    return out.getvalue()


def roundtrip(scan):
    return read_bytes(encode(scan, "x3p"), name="rt.x3p")


def assert_bit_identical(a: np.ndarray, b: np.ndarray) -> None:
    assert a.shape == b.shape
    np.testing.assert_array_equal(np.isnan(a), np.isnan(b))
    ok = ~np.isnan(a)
    assert np.array_equal(a[ok].view(np.uint64), b[ok].view(np.uint64))


# ----------------------------------------------------------------------------- real files


@pytest.mark.realdata
def test_x3p2_matches_surfacetopography(realdata):
    t = surfmet.read(realdata("x3p-2.x3p"))
    assert isinstance(t, Topography)
    assert (t.nx, t.ny) == (650, 650)
    np.testing.assert_allclose(t.nx * t.dx, 8.29767313942749e-05, rtol=1e-6)
    np.testing.assert_allclose(t.ny * t.dy, 0.0002044783737930349, rtol=1e-6)
    assert t.metadata["height_unit"] == "m" and t.metadata["lateral_unit"] == "m"
    assert t.nan_fraction == 0.0
    np.testing.assert_allclose(st_sq(t.heights), 7.728033273597876e-08, rtol=1e-6)
    np.testing.assert_allclose(st_rms_gradient(t.heights, t.dx, t.dy), 0.062070073998443276,
                               rtol=1e-6)
    md = t.metadata
    # ST composes "Model (Manufacturer, version Version)".
    st_name = f"{md['instrument']} ({md['vendor']}, version {md['instrument_version']})"
    assert st_name == "Mountains Map Technology Software (DIGITAL SURF, version 6.2)"
    assert md["vendor"] == "DIGITAL SURF"
    assert md["data_type"] == "D" and md["feature_type"] == "SUR"
    assert "instrument_serial" not in md  # "not available" in the file
    np.testing.assert_allclose(md["x_offset"], 7.65614218798151e-005)


@pytest.mark.realdata
def test_kautschuk_opengps_sample(realdata):
    t = surfmet.read(realdata("KautschukInfiniteFocus.x3p"))
    assert (t.nx, t.ny) == (860, 634)
    np.testing.assert_allclose(t.dx, 2.279984215e-6, rtol=1e-12)
    np.testing.assert_allclose(t.dy, 2.279794519e-6, rtol=1e-12)
    assert t.metadata["data_type"] == "F"
    assert np.count_nonzero(np.isnan(t.heights)) == 5296
    np.testing.assert_allclose(t.nan_fraction, 0.0097, atol=5e-5)
    md = t.metadata
    assert md["vendor"] == "Alicona Imaging GmbH"
    assert md["instrument_serial"] == "H271106000"
    assert md["instrument_version"] == "OpenGPS Export V1.0"
    assert md["date"] == "2009-06-09T13:40:58"
    assert md["comment"] == "Alicona OpenGPS Export"
    assert md["probing_system_type"] == "NonContacting"
    # float32 heights: every finite value is exactly representable in float32.
    v = t.heights[np.isfinite(t.heights)]
    assert np.array_equal(v.astype(np.float32).astype(np.float64), v)


@pytest.mark.realdata
@pytest.mark.parametrize("fname", OWN_REAL_FILES)
def test_real_files_convert_to_x3p_exactly(realdata, fname):
    scan = surfmet.read(realdata(fname))
    back = roundtrip(scan)
    assert type(back) is type(scan)
    assert back.dx == scan.dx
    if isinstance(scan, Topography):
        assert back.dy == scan.dy
        assert_bit_identical(scan.heights, back.heights)
    else:
        assert_bit_identical(scan.z, back.z)
    assert back.metadata["height_unit"] == "m"
    if scan.metadata.get("vendor"):
        assert back.metadata["vendor"] == scan.metadata["vendor"]


# ----------------------------------------------------------------------------- round trips


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_roundtrip_areal_with_hidden_holes(seed):
    rng = np.random.default_rng(seed)
    ny, nx = rng.integers(3, 40, size=2)
    h = rng.normal(0, 10 ** rng.uniform(-9, -4), size=(ny, nx))
    holes = rng.random((ny, nx)) < rng.uniform(0.01, 0.5)
    holes[0, 0] = False
    h[holes] = np.nan
    dx, dy = 10 ** rng.uniform(-8, -3, size=2)
    t = Topography(h, dx, dy, {"instrument": "test & <probe>", "vendor": "ACME"})
    buf = encode(t, "x3p")
    assert detect_format(buf) == "x3p"
    back = read_bytes(buf, name="holes.x3p")
    assert_bit_identical(h, back.heights)
    np.testing.assert_array_equal(back.mask, holes)
    assert (back.dx, back.dy) == (dx, dy)
    assert back.metadata["instrument"] == "test & <probe>"
    # Holes are also flagged in a valid-points file, as the standard provides.
    with zipfile.ZipFile(io.BytesIO(buf)) as zf:
        bits = np.unpackbits(np.frombuffer(zf.read("bindata/valid.bin"), np.uint8),
                             bitorder="little")[: h.size]
    np.testing.assert_array_equal(bits.astype(bool), ~holes.ravel())


def test_roundtrip_profile_prf():
    rng = np.random.default_rng(7)
    z = rng.normal(0, 1e-6, 501)
    z[[3, 77, 400]] = np.nan
    p = Profile(z, 0.5e-6, metadata={"date": "2021-02-11T10:00:00"})
    buf = encode(p, "x3p")
    with zipfile.ZipFile(io.BytesIO(buf)) as zf:
        xml = zf.read("main.xml").decode()
    assert "<FeatureType>PRF</FeatureType>" in xml and "<SizeY>1</SizeY>" in xml
    assert "<Date>2021-02-11T10:00:00</Date>" in xml
    back = read_bytes(buf, name="p.x3p")
    assert isinstance(back, Profile)
    assert_bit_identical(z, back.z)
    assert back.dx == 0.5e-6


def test_roundtrip_random_float64_bits_and_bytes_stable():
    rng = np.random.default_rng(11)
    bits = rng.integers(0, 2**63 - 1, size=(17, 23), dtype=np.int64).view(np.float64)
    h = np.where(np.isfinite(bits), bits, 1.0)
    h[0, :3] = [5e-324, -0.0, 1.7976931348623157e308]  # subnormal, signed zero, max
    t = Topography(h, 1.2345678901234567e-7, 3.3e-7)
    buf1 = encode(t, "x3p")
    back = read_bytes(buf1, name="bits.x3p")
    assert np.array_equal(back.heights.view(np.uint64), h.view(np.uint64))
    assert back.dx == t.dx and back.dy == t.dy
    buf2 = encode(back, "x3p")
    with zipfile.ZipFile(io.BytesIO(buf1)) as a, zipfile.ZipFile(io.BytesIO(buf2)) as b:
        assert a.read("bindata/data.bin") == b.read("bindata/data.bin")
        assert a.read("bindata/data.bin") == h.astype("<f8").tobytes()


def test_writer_refuses_nonuniform_profile_and_unknown_options():
    p = Profile([1.0, 2.0, 3.0], 1.0, x=[0.0, 1.0, 3.0])
    with pytest.raises(SurfmetInputError, match="non-uniform"):
        encode(p, "x3p")
    with pytest.raises(SurfmetInputError, match="unknown option"):
        encode(Topography(np.zeros((2, 2)), 1.0, 1.0), "x3p", colour="red")


def test_npz_and_x3p_detection_do_not_collide():
    t = Topography(np.arange(6.0).reshape(2, 3), 1e-6, 1e-6)
    assert detect_format(encode(t, "npz")) == "npz"
    assert detect_format(encode(t, "x3p")) == "x3p"


# ------------------------------------------------------------------- reading the standard


def test_int16_is_signed_and_scaled_by_cz_increment_and_offset():
    ints = np.array([[-32768, -1, 0], [1, 1234, 32767]], dtype="<i2")
    buf = make_x3p(ints.tobytes(), 3, 2, dtype="I",
                   cz_extra="<Increment>1e-9</Increment><Offset>5e-6</Offset>")
    t = read_bytes(buf, name="i16.x3p")
    np.testing.assert_allclose(t.heights, 5e-6 + ints * 1e-9, rtol=1e-15)
    assert t.heights[0, 0] < 5e-6  # negative integers stay negative
    assert t.metadata["z_increment"] == 1e-9


def test_int32_without_increment_is_metres():
    ints = np.array([-7, 0, 9, 2**31 - 1], dtype="<i4")
    t = read_bytes(make_x3p(ints.tobytes(), 4, 1, dtype="L"), name="i32.x3p")
    np.testing.assert_array_equal(t.heights, ints[None, :].astype(float))


def test_valid_points_file_masks_points():
    rng = np.random.default_rng(3)
    h = rng.normal(size=(5, 7)).astype("<f4")
    invalid = rng.random(35) < 0.3
    valid = np.packbits(~invalid, bitorder="little").tobytes()
    t = read_bytes(make_x3p(h.tobytes(), 7, 5, dtype="F", valid=valid), name="v.x3p")
    np.testing.assert_array_equal(np.isnan(t.heights).ravel(), invalid)
    np.testing.assert_array_equal(t.heights.ravel()[~invalid],
                                  h.ravel()[~invalid].astype(float))


def test_prf_feature_becomes_profile_and_namespaced_tags_are_read():
    z = np.linspace(0, 1e-6, 9)
    t = read_bytes(make_x3p(z.tobytes(), 9, 1, feature="PRF", dx="2.5e-7"), name="p.x3p")
    assert isinstance(t, Profile) and t.dx == 2.5e-7
    np.testing.assert_array_equal(t.z, z)


def test_record2_metadata():
    r2 = ("<Record2><Date>2020-01-02T03:04:05</Date><Creator>Jane Doe</Creator><Instrument>"
          "<Manufacturer>NanoFocus AG</Manufacturer><Model>unknown</Model><Serial>42</Serial>"
          "<Version>6.4</Version></Instrument><CalibrationDate>2019-12-01T00:00:00"
          "</CalibrationDate><ProbingSystem><Type>NonContacting</Type><Identification>"
          "800xs</Identification></ProbingSystem><Comment>plate 3</Comment></Record2>")
    t = read_bytes(make_x3p(np.zeros(4).tobytes(), 2, 2, record2=r2), name="m.x3p")
    md = t.metadata
    assert md["creator"] == "Jane Doe" and md["date"] == "2020-01-02T03:04:05"
    assert md["vendor"] == "NanoFocus AG" and md["instrument"] == "NanoFocus AG"
    assert md["instrument_serial"] == "42" and md["instrument_version"] == "6.4"
    assert md["probing_system"] == "800xs" and md["comment"] == "plate 3"
    assert md["calibration_date"] == "2019-12-01T00:00:00"


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"feature": "PCL"}, "PCL"),
    ({"cx_type": "A"}, "incremental"),
    ({"dtype": "Q"}, "DataType"),
    ({"size_z": 2}, "SizeZ"),
    ({"md5": "0" * 32}, "MD5"),
    ({"dx": "-1e-6"}, "pixel size"),
    ({"dx": "abc"}, "not a number"),
])
def test_unsupported_or_inconsistent_headers_are_refused(kwargs, message):
    buf = make_x3p(np.zeros(4).tobytes(), 2, 2, **kwargs)
    with pytest.raises(SurfmetFormatError, match=message):
        read_bytes(buf, name="bad.x3p")


def test_checksum_can_be_skipped():
    buf = make_x3p(np.ones(4).tobytes(), 2, 2, md5="0" * 32)
    t = read_bytes(buf, name="x.x3p", verify_checksum=False)
    np.testing.assert_array_equal(t.heights, np.ones((2, 2)))


def test_grid_larger_than_data_is_refused():
    buf = make_x3p(np.zeros(4).tobytes(), 3, 2)
    with pytest.raises(SurfmetFormatError, match="implies"):
        read_bytes(buf, name="short.x3p")


def test_zip_without_main_xml_is_not_x3p():
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w") as zf:
        zf.writestr("data.txt", "hello")
    with pytest.raises(SurfmetFormatError, match=r"main\.xml"):
        read_bytes(out.getvalue(), format="x3p", name="a.zip")


def test_entity_expansion_is_refused():
    bomb = (b'<?xml version="1.0"?><!DOCTYPE x [<!ENTITY a "aaaaaaaaaa">'
            b'<!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;">]><x>&b;</x>')
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w") as zf:
        zf.writestr("main.xml", bomb)
    with pytest.raises(SurfmetFormatError, match="DOCTYPE"):
        read_bytes(out.getvalue(), name="bomb.x3p")


def _patch_central_size(buf: bytes, member: str, size: int) -> bytes:
    """Rewrite the uncompressed size that the central directory declares for a member."""
    b = bytearray(buf)
    pos = b.find(b"PK\x01\x02" + b"\x00" * 0)
    while pos != -1:
        (nlen,) = struct.unpack_from("<H", b, pos + 28)
        if bytes(b[pos + 46:pos + 46 + nlen]) == member.encode():
            struct.pack_into("<I", b, pos + 24, size)
        pos = b.find(b"PK\x01\x02", pos + 4)
    return bytes(b)


def test_lying_member_size_is_refused_without_allocating():
    # A small archive whose central directory claims a 4 GB point file, and a header
    # grid to match: the reader must refuse before decompressing or allocating.
    n = 23_000
    buf = make_x3p(np.zeros(4).tobytes(), n, n)
    buf = _patch_central_size(buf, "bindata/data.bin", 8 * n * n % 2**32)
    refused_cheaply(buf, name="bomb.x3p")


def test_absurd_xml_size_is_refused():
    xml = b"<x>" + b" " * (17 * 2**20) + b"</x>"
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as zf:
        zf.writestr("main.xml", xml)
    with pytest.raises(SurfmetFormatError, match="absurdly large"):
        read_bytes(out.getvalue(), name="big.x3p")


@pytest.mark.realdata
def test_truncation_and_corruption_of_a_real_file(realdata):
    buf = realdata("x3p-2.x3p").read_bytes()
    for cut in (4, 30, 200, 1000, len(buf) // 2, len(buf) - 22, len(buf) - 1):
        with pytest.raises(SurfmetFormatError):
            read_bytes(buf[:cut], format="x3p", name="cut.x3p")
    # Flip bytes inside the compressed point data: CRC or MD5 must catch it.
    bad = bytearray(buf)
    mid = len(bad) // 2
    bad[mid:mid + 8] = bytes(255 - x for x in bad[mid:mid + 8])
    with pytest.raises(SurfmetFormatError):
        read_bytes(bytes(bad), name="flipped.x3p")


def test_float32_writer_is_exact_or_refuses():
    """dtype='F' stores float32; it must round-trip exactly and refuse lossy input."""
    rng = np.random.default_rng(11)
    h = (rng.normal(size=(200, 150)) * 1e-6).astype(np.float32).astype(np.float64)
    h[rng.random(h.shape) < 0.05] = np.nan
    t = Topography(h, 5e-6, 4e-6)
    back = read_bytes(encode(t, "x3p", dtype="F"))
    assert np.array_equal(back.heights, h, equal_nan=True)
    assert back.dx == t.dx and back.dy == t.dy
    with zipfile.ZipFile(io.BytesIO(encode(t, "x3p", dtype="F"))) as zf:
        assert "<DataType>F</DataType>" in zf.read("main.xml").decode()
        assert zf.getinfo("bindata/data.bin").file_size == 4 * h.size
    lossy = Topography(rng.normal(size=(5, 5)) * 1e-6, 1e-6, 1e-6)
    with pytest.raises(SurfmetInputError, match="float32"):
        encode(lossy, "x3p", dtype="F")
