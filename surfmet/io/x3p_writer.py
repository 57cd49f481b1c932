"""ISO 25178-72 / ISO 5436-2 XML ``.x3p`` files: the writer.

The format is described in :mod:`surfmet.io.x3p` (the reader). The writer stores SUR or PRF
data as float64 (``D``, or float32 ``F`` on request when exact), NaN for non-measured points
plus a valid-points file when there are any, and writes both MD5 checksums; reading its
output returns bit-identical heights, the same NaN positions, dx, dy and units.
"""

from __future__ import annotations

import datetime as _dt
import hashlib
import io
import re
import zipfile
from typing import Any
from xml.sax.saxutils import escape

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography
from surfmet._version import __version__
from surfmet.io._registry import register_writer
from surfmet.io.x3p import FORMAT

NAMESPACE = "http://www.opengps.eu/2008/ISO5436_2"
REVISION = "ISO5436 - 2000"
_PROBING_TYPES = ("Contacting", "NonContacting", "Software")
_DATE_RE = re.compile(r"^\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2}(\.\d+)?(Z|[+-]\d{2}:\d{2})?$")
# Fixed member time stamps: the same scan always gives the same bytes.
_STAMP = (1980, 1, 1, 0, 0, 0)


def _xml_date(value: Any) -> str:
    """An xsd:dateTime for Record2: the scan's own date when it is one, else now (UTC)."""
    if isinstance(value, str):
        text = value.strip()
        if _DATE_RE.match(text):
            return text
        try:
            return _dt.datetime.fromisoformat(text).replace(microsecond=0).isoformat()
        except ValueError:
            pass
    return _dt.datetime.now(_dt.timezone.utc).replace(microsecond=0).isoformat()


def _token(value: Any, default: str) -> str:
    text = " ".join(str(value).split()) if value not in (None, "") else default
    return escape(text)


def _grid(scan: Topography | Profile) -> tuple[str, int, int, np.ndarray, float]:
    """FeatureType, nx, ny, heights and y increment of a scan."""
    if isinstance(scan, Topography):
        return "SUR", scan.nx, scan.ny, scan.heights, scan.dy
    if isinstance(scan, Profile):
        if not scan.is_uniform:
            raise SurfmetInputError(
                "x3p writer: a non-uniformly sampled profile cannot be written with an "
                "incremental x axis; resample it first"
            )
        return "PRF", scan.n, 1, scan.z, scan.dx
    raise SurfmetInputError("x3p writer needs a Topography or a Profile")


def _point_bytes(z: np.ndarray, ztype: str) -> bytes:
    """The little-endian point data; float32 only when it loses nothing."""
    if ztype not in ("D", "F"):
        raise SurfmetInputError(f"x3p writer: dtype must be 'D' or 'F', not {ztype!r}")
    zarr = np.ascontiguousarray(z, dtype="<f8" if ztype == "D" else "<f4")
    if ztype == "F":
        back = zarr.astype(np.float64)
        same = (back == np.asarray(z)) | (np.isnan(back) & np.isnan(np.asarray(z)))
        if not same.all():
            raise SurfmetInputError(
                "x3p writer: dtype='F' would round heights that are not float32 values; "
                "round them first (np.float32) or keep dtype='D'"
            )
    return zarr.tobytes()


def _default_comment(md: dict[str, Any]) -> str:
    parts = [str(md[k]) for k in ("comment",) if md.get(k)]
    if md.get("format") and md.get("format") != FORMAT:
        parts.append(f"converted by surfmet {__version__} from {md['format']}")
    if md.get("source"):
        # The file name only: a full path would leak the writer's directory layout.
        parts.append(f"source: {str(md['source']).replace(chr(92), '/').rsplit('/', 1)[-1]}")
    return "; ".join(parts)


def _record1(feature: str, dx: float, dy: float, ztype: str) -> list[str]:
    return [
        "  <Record1>",
        f"    <Revision>{REVISION}</Revision>",
        f"    <FeatureType>{feature}</FeatureType>",
        "    <Axes>",
        "      <CX>",
        "        <AxisType>I</AxisType>",
        "        <DataType>D</DataType>",
        f"        <Increment>{float(dx)!r}</Increment>",
        "        <Offset>0</Offset>",
        "      </CX>",
        "      <CY>",
        "        <AxisType>I</AxisType>",
        "        <DataType>D</DataType>",
        f"        <Increment>{float(dy)!r}</Increment>",
        "        <Offset>0</Offset>",
        "      </CY>",
        "      <CZ>",
        "        <AxisType>A</AxisType>",
        f"        <DataType>{ztype}</DataType>",
        "      </CZ>",
        "    </Axes>",
        "  </Record1>",
    ]


def _record2(md: dict[str, Any], date: str, comment: str) -> list[str]:
    probing = md.get("probing_system_type")
    if probing not in _PROBING_TYPES:
        probing = "Software"
    lines = ["  <Record2>", f"    <Date>{escape(date)}</Date>"]
    if md.get("creator"):
        lines.append(f"    <Creator>{_token(md['creator'], '')}</Creator>")
    lines += [
        "    <Instrument>",
        f"      <Manufacturer>{_token(md.get('vendor'), 'unknown')}</Manufacturer>",
        f"      <Model>{_token(md.get('instrument'), 'unknown')}</Model>",
        f"      <Serial>{_token(md.get('instrument_serial'), 'not available')}</Serial>",
        f"      <Version>{_token(md.get('instrument_version'), f'surfmet {__version__}')}"
        "</Version>",
        "    </Instrument>",
        f"    <CalibrationDate>{escape(_xml_date(md.get('calibration_date', date)))}"
        "</CalibrationDate>",
        "    <ProbingSystem>",
        f"      <Type>{probing}</Type>",
        f"      <Identification>{_token(md.get('probing_system'), 'surfmet')}"
        "</Identification>",
        "    </ProbingSystem>",
        f"    <Comment>{escape(str(comment))}</Comment>",
        "  </Record2>",
    ]
    return lines


def _record3(nx: int, ny: int, data: bytes, valid_bin: bytes | None) -> list[str]:
    lines = [
        "  <Record3>",
        "    <MatrixDimension>",
        f"      <SizeX>{nx}</SizeX>",
        f"      <SizeY>{ny}</SizeY>",
        "      <SizeZ>1</SizeZ>",
        "    </MatrixDimension>",
        "    <DataLink>",
        "      <PointDataLink>bindata/data.bin</PointDataLink>",
        f"      <MD5ChecksumPointData>{hashlib.md5(data).hexdigest().upper()}"
        "</MD5ChecksumPointData>",
    ]
    if valid_bin is not None:
        lines += [
            "      <ValidPointsLink>bindata/valid.bin</ValidPointsLink>",
            "      <MD5ChecksumValidPoints>"
            f"{hashlib.md5(valid_bin).hexdigest().upper()}</MD5ChecksumValidPoints>",
        ]
    lines += ["    </DataLink>", "  </Record3>"]
    return lines


def _archive(xml: bytes, data: bytes, valid_bin: bytes | None) -> bytes:
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", compression=zipfile.ZIP_DEFLATED) as zf:
        # main.xml first, so that magic detection finds it in the first local header.
        zf.writestr(zipfile.ZipInfo("main.xml", _STAMP), xml, zipfile.ZIP_DEFLATED)
        zf.writestr(zipfile.ZipInfo("bindata/data.bin", _STAMP), data, zipfile.ZIP_DEFLATED)
        if valid_bin is not None:
            zf.writestr(zipfile.ZipInfo("bindata/valid.bin", _STAMP), valid_bin,
                        zipfile.ZIP_DEFLATED)
        zf.writestr(zipfile.ZipInfo("md5checksum.hex", _STAMP),
                    f"{hashlib.md5(xml).hexdigest()} *main.xml\n".encode("ascii"),
                    zipfile.ZIP_DEFLATED)
    return out.getvalue()


@register_writer(FORMAT)
def encode(scan: Topography | Profile, **options: Any) -> bytes:
    """Encode a scan as X3P (float ``D`` or ``F`` data, SUR for areal, PRF for profiles).

    Parameters
    ----------
    scan : Topography or Profile
        A uniformly sampled scan (non-uniform profiles have no X3P incremental axis).
    **options
        ``date`` (ISO 8601 text for Record2, default the scan's ``date`` metadata or now),
        ``comment`` (default built from the metadata), ``dtype`` (``"D"``, float64, the
        default; or ``"F"``, float32, half the size, accepted only when every height is
        exactly representable in float32, so that the round trip stays exact).

    Returns
    -------
    bytes
        The zip archive.
    """
    unknown = set(options) - {"date", "comment", "dtype"}
    if unknown:
        raise SurfmetInputError(f"x3p writer: unknown option(s) {sorted(unknown)}")
    md = dict(scan.metadata)
    feature, nx, ny, z, dy = _grid(scan)
    ztype = str(options.get("dtype", "D")).upper()
    data = _point_bytes(z, ztype)
    invalid = np.isnan(np.asarray(z)).ravel()
    valid_bin = None
    if invalid.any():
        valid_bin = np.packbits(~invalid, bitorder="little").tobytes()
    date = _xml_date(options.get("date", md.get("date")))
    comment = options.get("comment")
    if comment is None:
        comment = _default_comment(md)
    lines = [
        '<?xml version="1.0" encoding="UTF-8" standalone="no" ?>',
        f'<p:ISO5436_2 xmlns:p="{NAMESPACE}" '
        'xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" '
        f'xsi:schemaLocation="{NAMESPACE} {NAMESPACE}/ISO5436_2.xsd">',
        *_record1(feature, scan.dx, dy, ztype),
        *_record2(md, date, comment),
        *_record3(nx, ny, data, valid_bin),
        "  <Record4>",
        "    <ChecksumFile>md5checksum.hex</ChecksumFile>",
        "  </Record4>",
        "</p:ISO5436_2>",
        "",
    ]
    return _archive("\n".join(lines).encode("utf-8"), data, valid_bin)


__all__ = ["NAMESPACE", "REVISION", "encode"]
