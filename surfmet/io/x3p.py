"""ISO 25178-72 / ISO 5436-2 XML ``.x3p`` files: the reader.

An X3P file is a zip archive holding (schema ``iso5436_2.xsd`` of the openGPS project,
http://www.opengps.eu/2008/ISO5436_2):

* ``main.xml``: ``Record1`` (revision, ``FeatureType`` SUR / PRF / PCL and the axes CX, CY,
  CZ with ``AxisType`` I = incremental or A = absolute, ``DataType`` I = int16, L = int32,
  F = float32, D = float64, ``Increment`` and ``Offset`` in metres), the optional
  ``Record2`` (date, creator, instrument manufacturer / model / serial / version,
  calibration date, probing system, comment), ``Record3`` (``MatrixDimension`` SizeX,
  SizeY, SizeZ and a ``DataLink`` to the binary point data with its MD5, optionally a
  ``ValidPointsLink`` with its MD5; or an inline ``DataList`` of ``Datum`` elements) and
  ``Record4`` (name of the checksum file of ``main.xml``);
* ``bindata/*.bin``: the points, little endian, x fastest, then y, then z;
* an optional valid-points file: a packed bit array, least significant bit first, one bit
  per point, 1 = valid (openGPS ``ValidBuffer``);
* ``md5checksum.hex``: ``md5sum`` output for ``main.xml``.

Real coordinates are ``offset + value * increment``; for an incremental axis the increment
is the pixel size. Invalid points are those cleared in the valid-points file and, for
float data, NaN; they become NaN. Integer data types are **signed** (the schema says int16
and int32; SurfaceTopography 1.27 reads them as unsigned, which turns negative heights
into large positive ones).

Only gridded data are read: ``SUR`` becomes a :class:`~surfmet._model.Topography` and
``PRF`` (a matrix of N x 1 x 1) a :class:`~surfmet._model.Profile`. Point clouds (``PCL``),
absolute x/y axes and multi-layer matrices (SizeZ > 1) are refused with a clear message.

Guards: ``main.xml`` larger than :data:`MAX_XML_BYTES` or carrying a DOCTYPE/ENTITY
declaration is refused (no entity-expansion bombs); a binary member whose declared size
differs from what the header implies, or whose declared size is more than a deflate stream
can expand to, is refused before anything is allocated (no zip bombs); MD5 checksums are
verified (``verify_checksum=False`` skips that).

The writer lives in :mod:`surfmet.io.x3p_writer`.
"""

from __future__ import annotations

import hashlib
import math
import re
import zipfile
from typing import Any
from xml.etree import ElementTree as ET

import numpy as np

from surfmet._errors import SurfmetFormatError
from surfmet._model import Profile, Topography
from surfmet.io._binary import MAX_POINTS, check_grid, check_step, format_error
from surfmet.io._registry import register_reader
from surfmet.io._zip import ZIP_MAGIC, open_zip, read_member

FORMAT = "x3p"
# main.xml of a real file is a few kB; 16 MB of XML is never a header.
MAX_XML_BYTES = 16 * 2**20
# A DataList holds one XML element per point: cap it well below the binary limit.
_MAX_DATALIST_POINTS = 10_000_000

DTYPES: dict[str, np.dtype] = {
    "I": np.dtype("<i2"),
    "L": np.dtype("<i4"),
    "F": np.dtype("<f4"),
    "D": np.dtype("<f8"),
}


def _is_x3p(buf: bytes) -> bool:
    # npz files are zips too: require the main.xml member name, which sits in the local
    # header of the first member (openGPS writes it first) or in the central directory.
    return buf[:4] == ZIP_MAGIC and (b"main.xml" in buf[:1024] or b"main.xml" in buf[-65536:])


def _fail(name: str, problem: str) -> SurfmetFormatError:
    return format_error(name, FORMAT, problem)


def _local(tag: str) -> str:
    return tag.rsplit("}", 1)[-1]


def _child(elem: ET.Element | None, tag: str) -> ET.Element | None:
    if elem is None:
        return None
    for c in elem:
        if _local(c.tag) == tag:
            return c
    return None


def _text(elem: ET.Element | None, tag: str) -> str | None:
    c = _child(elem, tag)
    if c is None:
        return None
    return (c.text or "").strip()


def _float(elem: ET.Element | None, tag: str, name: str, where: str) -> float | None:
    t = _text(elem, tag)
    if t is None or t == "":
        return None
    try:
        v = float(t)
    except ValueError:
        raise _fail(name, f"{where}/{tag} {t!r} is not a number") from None
    if not math.isfinite(v):
        raise _fail(name, f"{where}/{tag} is {t!r}, not a finite number")
    return v


def _int(elem: ET.Element | None, tag: str, name: str, where: str) -> int:
    t = _text(elem, tag)
    if t is None:
        raise _fail(name, f"{where}/{tag} is missing")
    try:
        return int(t)
    except ValueError:
        raise _fail(name, f"{where}/{tag} {t!r} is not an integer") from None


def _read_member(zf: zipfile.ZipFile, member: str, name: str, expected: int | None,
                 limit: int, what: str) -> bytes:
    """:func:`surfmet.io._zip.read_member` for X3P: sizes ``expected`` from main.xml."""
    return read_member(zf, member, name, FORMAT, limit, what=what, expected=expected,
                       implied_by="main.xml")


def _check_md5(data: bytes, expected: str | None, name: str, what: str) -> None:
    if not expected:
        return
    got = hashlib.md5(data).hexdigest()
    if got.lower() != expected.strip().lower():
        raise _fail(
            name,
            f"MD5 checksum of {what} is {got}, main.xml says {expected.strip()}: the data "
            "are corrupted (pass verify_checksum=False to read them anyway)",
        )


def _parse_xml(raw: bytes, name: str) -> ET.Element:
    head = raw[:65536]
    if b"<!DOCTYPE" in head or b"<!ENTITY" in raw:
        raise _fail(name, "main.xml declares a DOCTYPE/ENTITY, which X3P never needs; refused")
    try:
        return ET.fromstring(raw)
    except ET.ParseError as exc:
        raise _fail(name, f"main.xml is not well-formed XML ({exc})") from None


def _axis(axes: ET.Element | None, tag: str, name: str) -> dict[str, Any]:
    a = _child(axes, tag)
    if a is None:
        raise _fail(name, f"Record1/Axes/{tag} is missing")
    where = f"Record1/Axes/{tag}"
    return {
        "type": (_text(a, "AxisType") or "").upper(),
        "dtype": (_text(a, "DataType") or "").upper() or None,
        "increment": _float(a, "Increment", name, where),
        "offset": _float(a, "Offset", name, where),
    }


def _record2(root: ET.Element) -> dict[str, Any]:
    md: dict[str, Any] = {}
    r2 = _child(root, "Record2")
    if r2 is None:
        return md
    for key, tag in (("date", "Date"), ("creator", "Creator"),
                     ("calibration_date", "CalibrationDate"), ("comment", "Comment")):
        v = _text(r2, tag)
        if v:
            md[key] = v
    inst = _child(r2, "Instrument")
    if inst is not None:
        unknown = {"", "unknown", "not available", "n/a"}
        manufacturer = _text(inst, "Manufacturer")
        model = _text(inst, "Model")
        serial = _text(inst, "Serial")
        version = _text(inst, "Version")
        if manufacturer and manufacturer.lower() not in unknown:
            md["vendor"] = manufacturer
        if model and model.lower() not in unknown:
            md["instrument"] = model
        elif "vendor" in md:
            md["instrument"] = md["vendor"]
        if serial and serial.lower() not in unknown:
            md["instrument_serial"] = serial
        if version and version.lower() not in unknown:
            md["instrument_version"] = version
    probe = _child(r2, "ProbingSystem")
    if probe is not None:
        t = _text(probe, "Type")
        ident = _text(probe, "Identification")
        if t:
            md["probing_system_type"] = t
        if ident and ident.lower() not in ("unknown", "not available", "n/a"):
            md["probing_system"] = ident
    return md


def _open_header(zf: zipfile.ZipFile, name: str
                 ) -> tuple[bytes, ET.Element, ET.Element, ET.Element]:
    """``main.xml`` raw and parsed, with its Record1 and Record3."""
    if "main.xml" not in zf.namelist():
        raise _fail(name, "the zip archive has no main.xml (not an X3P file)")
    raw_xml = _read_member(zf, "main.xml", name, None, MAX_XML_BYTES, "header")
    root = _parse_xml(raw_xml, name)
    if _local(root.tag) != "ISO5436_2":
        raise _fail(name, f"main.xml root element is {_local(root.tag)!r}, not ISO5436_2")
    r1 = _child(root, "Record1")
    r3 = _child(root, "Record3")
    if r1 is None or r3 is None:
        raise _fail(name, "main.xml lacks Record1 or Record3")
    return raw_xml, root, r1, r3


def _feature_type(r1: ET.Element, name: str) -> str:
    feature = (_text(r1, "FeatureType") or "").upper()
    if feature == "PCL":
        raise _fail(
            name,
            "FeatureType PCL (unordered point cloud) is not supported: surfmet reads "
            "gridded areal (SUR) and profile (PRF) data only",
        )
    if feature not in ("SUR", "PRF"):
        raise _fail(name, f"unknown FeatureType {feature!r} (expected SUR, PRF or PCL)")
    return feature


def _axes(r1: ET.Element, name: str) -> tuple[dict[str, Any], dict[str, Any], dict[str, Any]]:
    """The CX, CY, CZ axes, checked to describe gridded data with a known z type."""
    axes = _child(r1, "Axes")
    cx, cy, cz = (_axis(axes, t, name) for t in ("CX", "CY", "CZ"))
    for tag, ax in (("CX", cx), ("CY", cy)):
        if ax["type"] != "I":
            raise _fail(
                name,
                f"{tag} AxisType is {ax['type']!r}: only incremental (I) x/y axes, i.e. "
                "gridded data, are supported",
            )
    if cz["type"] != "A":
        raise _fail(name, f"CZ AxisType must be 'A' (absolute), got {cz['type']!r}")
    if cz["dtype"] not in DTYPES:
        raise _fail(name, f"CZ DataType {cz['dtype']!r} is not one of I, L, F, D")
    return cx, cy, cz


def _matrix_size(r3: ET.Element, feature: str, name: str) -> tuple[int, int]:
    mdim = _child(r3, "MatrixDimension")
    if mdim is None:
        if _child(r3, "ListDimension") is not None:
            raise _fail(name, "Record3 holds an unordered list (ListDimension); only "
                              "matrix (gridded) data are supported")
        raise _fail(name, "Record3/MatrixDimension is missing")
    nx = _int(mdim, "SizeX", name, "Record3/MatrixDimension")
    ny = _int(mdim, "SizeY", name, "Record3/MatrixDimension")
    nz = _int(mdim, "SizeZ", name, "Record3/MatrixDimension")
    if nz != 1:
        raise _fail(name, f"SizeZ is {nz}: multi-layer matrices are not supported")
    nx, ny = check_grid(nx, ny, name, FORMAT)
    if feature == "PRF" and ny != 1:
        raise _fail(name, f"a PRF feature must have SizeY = 1, got {ny}")
    return nx, ny


def _point_data(zf: zipfile.ZipFile, r3: ET.Element, n: int, dtype: np.dtype, name: str,
                verify_checksum: bool, md: dict[str, Any]
                ) -> tuple[np.ndarray, np.ndarray | None]:
    """The raw point values and the valid-point mask (None: all valid), linked or inline."""
    link = _child(r3, "DataLink")
    if link is None:
        dlist = _child(r3, "DataList")
        if dlist is None:
            raise _fail(name, "Record3 has neither DataLink nor DataList")
        return _datalist(dlist, n, dtype, name)
    member = _text(link, "PointDataLink")
    if not member:
        raise _fail(name, "Record3/DataLink/PointDataLink is empty")
    data = _read_member(zf, member, name, n * dtype.itemsize, MAX_POINTS * 8, "point data")
    if verify_checksum:
        _check_md5(data, _text(link, "MD5ChecksumPointData"), name, member)
    raw = np.frombuffer(data, dtype=dtype, count=n)
    vlink = _text(link, "ValidPointsLink")
    if not vlink:
        return raw, None
    vdata = _read_member(zf, vlink, name, (n + 7) // 8, MAX_POINTS // 8 + 1,
                         "valid-points file")
    if verify_checksum:
        _check_md5(vdata, _text(link, "MD5ChecksumValidPoints"), name, vlink)
    bits = np.unpackbits(np.frombuffer(vdata, np.uint8), bitorder="little")
    md["valid_points_file"] = vlink
    return raw, bits[:n].astype(bool)


def _heights(raw: np.ndarray, valid: np.ndarray | None, cz: dict[str, Any]) -> np.ndarray:
    """``offset + value * increment`` in float64, NaN where invalid or not finite."""
    inc = cz["increment"]
    off = cz["offset"]
    with np.errstate(invalid="ignore", over="ignore"):  # signalling NaNs, overflow
        z = raw.astype(np.float64)
        if inc is not None and inc != 1.0:
            z = z * inc
        if off is not None and off != 0.0:
            z = z + off
    bad = ~np.isfinite(z)
    if valid is not None:
        bad |= ~valid
    if bad.any():
        z[bad] = np.nan
    return z


def _axes_metadata(cx: dict[str, Any], cy: dict[str, Any], cz: dict[str, Any]
                   ) -> dict[str, Any]:
    md: dict[str, Any] = dict(height_unit="m", lateral_unit="m", lateral_calibrated=True,
                              data_type=cz["dtype"])
    if cz["dtype"] in ("I", "L"):
        md["z_increment"] = 1.0 if cz["increment"] is None else cz["increment"]
    for key, ax in (("x_offset", cx), ("y_offset", cy), ("z_offset", cz)):
        if ax["offset"] is not None:
            md[key] = ax["offset"]
    return md


@register_reader(FORMAT, extensions=("x3p",),
                 description="ISO 25178-72 XML 3D surface profile (X3P, zip + XML)",
                 magic=_is_x3p, priority=20)
def decode(buf: bytes, name: str, verify_checksum: bool = True) -> Topography | Profile:
    """Read an X3P file.

    Parameters
    ----------
    buf : bytes
        The whole file.
    name : str
        File name, for messages.
    verify_checksum : bool
        Check the MD5 sums of the point data, the valid-points file and ``main.xml``.

    Returns
    -------
    Topography (FeatureType SUR) or Profile (FeatureType PRF), heights in metres.
    """
    with open_zip(buf, name, FORMAT) as zf:
        raw_xml, root, r1, r3 = _open_header(zf, name)
        md: dict[str, Any] = {"format": FORMAT}
        revision = _text(r1, "Revision")
        if revision:
            md["revision"] = revision
        feature = _feature_type(r1, name)
        md["feature_type"] = feature
        cx, cy, cz = _axes(r1, name)
        nx, ny = _matrix_size(r3, feature, name)
        raw, valid = _point_data(zf, r3, nx * ny, DTYPES[cz["dtype"]], name,
                                 verify_checksum, md)
        if verify_checksum:
            _check_xml_checksum(zf, root, raw_xml, name)
        z = _heights(raw, valid, cz)
        if cx["increment"] is None:
            raise _fail(name, "CX has no Increment (pixel size)")
        dx = check_step(cx["increment"], name, FORMAT, "x increment (pixel size)")
        md.update(_record2(root))
        md.update(_axes_metadata(cx, cy, cz))
        if feature == "PRF":
            if cy["increment"] is not None:
                md["y_increment"] = cy["increment"]
            return Profile(z, dx, metadata=md)
        if cy["increment"] is None:
            raise _fail(name, "CY has no Increment (pixel size)")
        dy = check_step(cy["increment"], name, FORMAT, "y increment (pixel size)")
        return Topography(z.reshape(ny, nx), dx, dy, md)


def _datalist(dlist: ET.Element, n: int, dtype: np.dtype, name: str
              ) -> tuple[np.ndarray, np.ndarray]:
    # Inline data: one Datum per point, holding the absolute-axis value (z here); an empty
    # Datum marks an invalid point.
    if n > _MAX_DATALIST_POINTS:
        raise _fail(name, f"an inline DataList of {n} points is absurd")
    values = np.zeros(n, dtype=np.float64)
    valid = np.ones(n, dtype=bool)
    count = 0
    for d in dlist:
        if _local(d.tag) != "Datum":
            continue
        if count >= n:
            raise _fail(name, f"DataList holds more than the {n} points of the matrix")
        t = (d.text or "").strip()
        if not t:
            valid[count] = False
        else:
            parts = t.split(";")
            if len(parts) != 1:
                raise _fail(name, f"Datum {count} {t!r} has {len(parts)} coordinates; "
                                  "incremental x/y axes store z only")
            try:
                values[count] = float(parts[0])
            except ValueError:
                raise _fail(name, f"Datum {count} {t!r} is not a number") from None
        count += 1
    if count != n:
        raise _fail(name, f"DataList holds {count} points but the matrix has {n}")
    if dtype.kind in "iu":
        info = np.iinfo(dtype)
        ok = values[valid]
        if np.any(ok != np.round(ok)) or np.any((ok < info.min) | (ok > info.max)):
            raise _fail(name, f"DataList values do not fit the integer data type {dtype}")
    return values, valid


def _check_xml_checksum(zf: zipfile.ZipFile, root: ET.Element, raw_xml: bytes,
                        name: str) -> None:
    r4 = _child(root, "Record4")
    member = _text(r4, "ChecksumFile") if r4 is not None else None
    if not member or member not in zf.namelist():
        return
    text = _read_member(zf, member, name, None, 4096, "checksum file")
    m = re.match(rb"\s*([0-9a-fA-F]{32})", text)
    if m is None:
        raise _fail(name, f"checksum file {member!r} holds no MD5 sum")
    _check_md5(raw_xml, m.group(1).decode("ascii"), name, "main.xml")


__all__ = ["DTYPES", "MAX_XML_BYTES", "decode"]
