"""Guarded zip access for the zip-based formats (Mitutoyo .xlsx; the x3p reader has its own).

A member's declared size is checked against a limit and against what deflate can expand
to before anything is decompressed, so a zip bomb or a corrupted central directory fails
with one :class:`~surfmet.errors.SurfmetFormatError` line.
"""

from __future__ import annotations

import io
import zipfile
import zlib

from surfmet.errors import SurfmetFormatError
from surfmet.io._binary import format_error

ZIP_MAGIC = b"PK\x03\x04"
# Deflate cannot expand data by more than about 1032:1; a member claiming more is lying.
_MAX_DEFLATE_RATIO = 1100


def open_zip(buf: bytes, name: str, fmt: str) -> zipfile.ZipFile:
    """The archive in ``buf``; a format error if it is not a readable zip."""
    try:
        return zipfile.ZipFile(io.BytesIO(buf))
    except (zipfile.BadZipFile, OSError, ValueError, EOFError) as exc:
        raise format_error(
            name, fmt, f"not a readable zip archive: truncated or corrupted ({exc})"
        ) from None


def read_member(zf: zipfile.ZipFile, member: str, name: str, fmt: str, limit: int) -> bytes:
    """The bytes of ``member`` after checking its declared sizes (at most ``limit``)."""

    def fail(problem: str) -> SurfmetFormatError:
        return format_error(name, fmt, problem)

    try:
        info = zf.getinfo(member)
    except KeyError:
        raise fail(f"the archive has no member {member!r}") from None
    if info.file_size > limit:
        raise fail(f"member {member!r} is absurdly large ({info.file_size} bytes)")
    if info.compress_type != zipfile.ZIP_STORED and \
            info.file_size > _MAX_DEFLATE_RATIO * info.compress_size + 1024:
        raise fail(f"member {member!r} claims more bytes than compression allows "
                   "(zip bomb or corrupted archive)")
    try:
        with zf.open(info) as f:
            data = f.read(info.file_size + 1)
    except (zipfile.BadZipFile, zlib.error, EOFError, OSError, RuntimeError,
            NotImplementedError, ValueError) as exc:
        raise fail(f"cannot extract {member!r} ({exc})") from None
    if len(data) != info.file_size:
        raise fail(f"member {member!r} is truncated or corrupted")
    return data


def member_names(buf: bytes) -> bytes:
    """The first and last 64 KiB of a zip, where member names sit (for magic checks)."""
    return buf[:65536] + buf[-65536:]
