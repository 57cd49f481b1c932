"""Guarded zip access for the zip-based formats (X3P, Mitutoyo .xlsx).

A member's declared size is checked against a limit and against what deflate can expand
to before anything is decompressed, so a zip bomb or a corrupted central directory fails
with one :class:`~surfmet._errors.SurfmetFormatError` line.
"""

from __future__ import annotations

import io
import zipfile
import zlib

from surfmet._errors import SurfmetFormatError
from surfmet.io._binary import MAX_DEFLATE_RATIO, format_error

ZIP_MAGIC = b"PK\x03\x04"


def open_zip(buf: bytes, name: str, fmt: str) -> zipfile.ZipFile:
    """The archive in ``buf``; a format error if it is not a readable zip."""
    try:
        return zipfile.ZipFile(io.BytesIO(buf))
    except (zipfile.BadZipFile, OSError, ValueError, EOFError) as exc:
        raise format_error(
            name, fmt, f"not a readable zip archive: truncated or corrupted ({exc})"
        ) from None


def read_member(zf: zipfile.ZipFile, member: str, name: str, fmt: str, limit: int, *,
                what: str | None = None, expected: int | None = None,
                implied_by: str = "the header") -> bytes:
    """The bytes of ``member`` after checking its declared sizes; never reads more than needed.

    Parameters
    ----------
    zf : zipfile.ZipFile
        The archive.
    member, name, fmt : str
        The member; the file and its format, for messages.
    limit : int
        Most bytes the member may declare.
    what : str, optional
        The member's role in the format (``"header"``, ``"point data"``), for messages.
    expected : int, optional
        The size ``implied_by`` (the format's header) says the member has.
    """
    label = what or "member"

    def fail(problem: str) -> SurfmetFormatError:
        return format_error(name, fmt, problem)

    try:
        info = zf.getinfo(member)
    except KeyError:
        role = f" ({what})" if what else ""
        raise fail(f"the archive has no member {member!r}{role}") from None
    if info.file_size > limit:
        raise fail(f"{label} {member!r} is absurdly large ({info.file_size} bytes)")
    if info.compress_type == zipfile.ZIP_STORED:
        if info.file_size != info.compress_size:
            raise fail(f"{label} {member!r}: stored member with inconsistent sizes")
    elif info.file_size > MAX_DEFLATE_RATIO * info.compress_size + 1024:
        raise fail(f"{label} {member!r} claims {info.file_size} bytes from "
                   f"{info.compress_size} compressed bytes, more than compression allows "
                   "(zip bomb or corrupted archive)")
    if expected is not None and info.file_size != expected:
        raise fail(f"{label} {member!r} holds {info.file_size} bytes but {implied_by} "
                   f"implies {expected}")
    try:
        with zf.open(info) as f:
            data = f.read(info.file_size + 1)
    except (zipfile.BadZipFile, zlib.error, EOFError, OSError, RuntimeError,
            NotImplementedError, ValueError) as exc:
        # RuntimeError: encrypted member; NotImplementedError: unknown compression method.
        role = f"{what} " if what else ""
        raise fail(f"cannot extract {role}{member!r} ({exc})") from None
    if len(data) != info.file_size:
        raise fail(f"{label} {member!r} is truncated or corrupted")
    return data


def member_names(buf: bytes) -> bytes:
    """The first and last 64 KiB of a zip, where member names sit (for magic checks)."""
    return buf[:65536] + buf[-65536:]
