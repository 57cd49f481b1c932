"""NumPy ``.npy`` (bare height array) and ``.npz`` (surfmet's own archive) formats.

``.npz`` as written by surfmet holds ``kind`` (``"areal"`` or ``"profile"``), ``heights``
(areal, shape (ny, nx)) or ``z`` and optionally ``x`` (profile), ``dx``, ``dy`` and
``metadata`` (a JSON string). All values are SI, so a write/read round trip is exact.

A bare ``.npy`` array carries no unit and no pixel size: it is read as heights in metres
with ``dx = dy = 1`` m, both marked assumed (:class:`surfmet._model.Calibration`);
``height_unit=`` and ``dx=`` / ``dy=`` of :func:`surfmet.read` state them.
"""

from __future__ import annotations

import io
import json
from typing import Any

import numpy as np

from surfmet._model import Profile, Topography
from surfmet.io._binary import MAX_POINTS, format_error
from surfmet.io._calibration import assumed
from surfmet.io._registry import register_reader, register_writer
from surfmet.io._zip import ZIP_MAGIC
from surfmet.units import jsonable

_NPY_MAGIC = b"\x93NUMPY"


def _is_npy(buf: bytes) -> bool:
    return buf.startswith(_NPY_MAGIC)


def _is_surfmet_npz(buf: bytes) -> bool:
    # An .npz is a zip whose members end in .npy; x3p files are zips too, so look for our
    # member names in the central directory rather than at the zip signature alone.
    return buf.startswith(ZIP_MAGIC) and b"kind.npy" in buf[-4096:]


def _check_header(buf: bytes, name: str) -> tuple[tuple[int, ...], bool, np.dtype, int, int]:
    """(shape, fortran order, dtype, count, data offset) of a .npy header.

    np.load trusts the shape in the header; shapes the bytes cannot hold are refused here,
    before numpy tries to allocate them."""
    try:
        f = io.BytesIO(buf)
        version = np.lib.format.read_magic(f)
        if version == (1, 0):
            shape, fortran, dtype = np.lib.format.read_array_header_1_0(f)
        else:
            shape, fortran, dtype = np.lib.format.read_array_header_2_0(f)
    except Exception as exc:
        raise format_error(name, "npy", f"unreadable header ({exc})") from None
    count = int(np.prod(shape, dtype=np.int64)) if shape else 1
    if count > MAX_POINTS or count * dtype.itemsize > len(buf) - f.tell():
        raise format_error(
            name, "npy", f"truncated: header says shape {shape} but the file has {len(buf)} bytes"
        )
    return shape, bool(fortran), dtype, count, f.tell()


def _load_npy(buf: bytes, name: str) -> np.ndarray:
    shape, fortran, dtype, count, offset = _check_header(buf, name)
    if dtype.kind not in "fiub" or dtype.hasobject:
        raise format_error(name, "npy", f"heights must be numeric, got {dtype}")
    # a view of the file's bytes, not np.load's copy of them: reading holds the bytes and
    # the float64 heights, never a third copy
    flat = np.frombuffer(buf, dtype=dtype, count=count, offset=offset)
    arr = flat.reshape(shape, order="F" if fortran else "C")
    return arr.astype(np.float64)


@register_reader("npy", extensions=("npy",), description="NumPy array of heights",
                 magic=_is_npy, priority=10)
def decode_npy(buf: bytes, name: str) -> Topography | Profile:
    """Read a bare NumPy array: 2D becomes a Topography, 1D a Profile."""
    z = _load_npy(buf, name)
    z.flags.writeable = False  # the model keeps a read-only float64 array as it is
    md: dict[str, Any] = {"height_unit": "m", "lateral_unit": "", "lateral_calibrated": False,
                          **assumed(True, True)}
    if z.ndim == 2:
        return Topography(z, 1.0, 1.0, md)
    if z.ndim == 1:
        return Profile(z, 1.0, metadata=md)
    raise format_error(name, "npy", f"expected a 1D or 2D array, got shape {z.shape}")


@register_reader("npz", extensions=("npz",), description="surfmet NumPy archive (SI, exact)",
                 magic=_is_surfmet_npz, priority=15)
def decode_npz(buf: bytes, name: str) -> Topography | Profile:
    """Read a ``.npz`` archive written by :func:`encode_npz`."""
    import zipfile

    with zipfile.ZipFile(io.BytesIO(buf)) as zf:
        members = {n.removesuffix(".npy"): n for n in zf.namelist()}
        if "kind" not in members:
            raise format_error(name, "npz", "no 'kind' entry (not written by surfmet)")

        def get(key: str) -> np.ndarray:
            if key not in members:
                raise format_error(name, "npz", f"missing entry {key!r}")
            info = zf.getinfo(members[key])
            if info.file_size > 16 * MAX_POINTS:
                raise format_error(name, "npz", f"entry {key!r} is absurdly large")
            data = zf.read(members[key])
            _check_header(data, name)
            return np.load(io.BytesIO(data), allow_pickle=False)

        kind = str(get("kind"))
        md = json.loads(str(get("metadata"))) if "metadata" in members else {}
        if not isinstance(md, dict):
            raise format_error(name, "npz", "metadata is not a JSON object")
        if kind == "areal":
            return Topography(get("heights"), float(get("dx")), float(get("dy")), md)
        if kind == "profile":
            x = get("x") if "x" in members else None
            return Profile(get("z"), float(get("dx")), x, md)
    raise format_error(name, "npz", f"unknown kind {kind!r}")


@register_writer("npz")
def encode_npz(scan: Topography | Profile) -> bytes:
    """Encode a scan as a ``.npz`` archive; reading it back is bit-exact."""
    out = io.BytesIO()
    md = json.dumps(jsonable(dict(scan.metadata)))
    if isinstance(scan, Topography):
        np.savez_compressed(out, kind=np.array("areal"), heights=scan.heights,
                            dx=np.float64(scan.dx), dy=np.float64(scan.dy), metadata=np.array(md))
    else:
        extra: dict[str, Any] = {"x": scan.x} if scan.x is not None else {}
        np.savez_compressed(out, kind=np.array("profile"), z=scan.z, dx=np.float64(scan.dx),
                            metadata=np.array(md), **extra)
    return out.getvalue()


@register_writer("npy")
def encode_npy(scan: Topography | Profile) -> bytes:
    """Encode the heights alone (metres) as a ``.npy`` file; pixel sizes are lost."""
    out = io.BytesIO()
    np.save(out, scan.heights if isinstance(scan, Topography) else scan.z)
    return out.getvalue()
