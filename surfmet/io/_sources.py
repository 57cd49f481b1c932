"""Where a scan's bytes come from: a path, a bytes object or a binary file-like object.

:func:`source_bytes` gives the bytes with the names messages and metadata give them, and
refuses, before reading a byte, a path that cannot be a scan file or whose reading cannot
fit in memory.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import BinaryIO

from surfmet._errors import SurfmetFormatError, SurfmetInputError

__all__ = ["READ_BYTES_PER_FILE_BYTE", "Source", "source_bytes"]

#: What :func:`surfmet.io.read` takes: a path, the file's bytes, or a binary file-like
#: object.
Source = str | os.PathLike[str] | bytes | bytearray | memoryview | BinaryIO


def source_bytes(source: Source) -> tuple[bytes, str, str | None]:
    """The bytes of a path, a bytes object or a binary stream, the name that messages give
    it, and the name to record as ``metadata["source"]`` (None for bare bytes).

    Raises
    ------
    SurfmetFormatError
        A file that cannot be read (missing, a directory, a device, too large for memory)
        or a stream whose ``read()`` fails.
    SurfmetInputError
        A source that is neither a path, bytes nor a binary stream.
    """
    if isinstance(source, (bytes, bytearray, memoryview)):
        return bytes(source), "<bytes>", None
    if hasattr(source, "read"):
        label = getattr(source, "name", None)
        name = os.fsdecode(label) if isinstance(label, (str, bytes, os.PathLike)) else "<stream>"
        try:
            buf = source.read()
        except (OSError, ValueError) as exc:  # ValueError: a closed file
            raise SurfmetFormatError(f"{name}: cannot read the stream ({exc})") from None
        if not isinstance(buf, (bytes, bytearray, memoryview)):
            raise SurfmetInputError(f"{name}: the stream gives {type(buf).__name__}, not bytes: "
                                    "open the file in binary mode ('rb')")
        return bytes(buf), name, (name if name != "<stream>" else None)
    if not isinstance(source, (str, os.PathLike)):
        raise SurfmetInputError(f"cannot read a scan from a {type(source).__name__}: give a "
                                "path, bytes or a binary file-like object")
    p = Path(source)
    _check_readable(p)
    try:
        buf = p.read_bytes()
    except FileNotFoundError:
        raise SurfmetFormatError(f"{p}: no such file") from None
    except IsADirectoryError:
        raise SurfmetFormatError(f"{p}: is a directory, not a scan file") from None
    except OSError as exc:
        raise SurfmetFormatError(f"{p}: cannot read the file ({exc.strerror or exc})") from None
    return buf, str(p), str(p)


#: Reading holds the file's bytes and the decoded float64 heights (at least as many bytes
#: as the file, 4 x for 16-bit data) and the validity masks at once: the least a read
#: needs, in file sizes (2.4 measured with tracemalloc on a 200 MB float64 .npy).
READ_BYTES_PER_FILE_BYTE = 2.5


def _check_readable(p: Path) -> None:
    """Refuse, before reading a byte, what cannot be a scan file (a device such as
    /dev/zero, a pipe, a socket: they never end) and a file whose reading cannot fit in the
    memory available now (:func:`contact._sysmem.available_bytes`, planned at its
    ``SAFETY`` fraction, as the solvers plan)."""
    import stat

    from contact._sysmem import SAFETY, available_bytes

    try:
        st = p.stat()
    except OSError:
        return  # read_bytes says what is wrong (no such file, permission...)
    if stat.S_ISDIR(st.st_mode):
        return
    if not stat.S_ISREG(st.st_mode):
        raise SurfmetFormatError(f"{p}: not a regular file (a device, a pipe or a socket "
                                 "never ends): give a scan file")
    need = int(READ_BYTES_PER_FILE_BYTE * st.st_size)
    avail = available_bytes()
    if avail is not None and need > SAFETY * avail:
        raise SurfmetFormatError(
            f"{p}: reading this {st.st_size / 2**20:.4g} MB file needs at least "
            f"{need / 2**20:.4g} MB of memory, but only {avail / 2**20:.4g} MB is available "
            f"({100 * SAFETY:.0f} % of it may be used): free memory or crop the scan")
