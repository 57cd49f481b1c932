"""Bounds-checked helpers shared by the readers.

Every size a header states is checked against the bytes that are really there before
anything is allocated, so a 1 KB file claiming a 10^9-point grid fails fast with a clear
:class:`~surfmet._errors.SurfmetFormatError` instead of allocating gigabytes.
"""

from __future__ import annotations

import struct
from typing import Any, NoReturn

import numpy as np

from surfmet._errors import SurfmetFormatError
from surfmet._model import Profile

# Largest grid any reader accepts: 2**31 points is 16 GiB of float64, beyond any instrument.
MAX_POINTS = 2**31
# Deflate (zlib, zip) cannot expand data by more than about 1032:1: a stream or member
# claiming more is lying.
MAX_DEFLATE_RATIO = 1100


def format_error(name: str, fmt: str, problem: str) -> SurfmetFormatError:
    """The error every reader raises for a bad file: ``"<file>: <format> file: <problem>"``."""
    return SurfmetFormatError(f"{name}: {fmt} file: {problem}")


class ByteReader:
    """A cursor over a bytes object whose reads fail with a format error when short.

    Parameters
    ----------
    buf : bytes
        The whole file.
    name : str
        File name, for messages.
    fmt : str
        Format name, for messages.
    """

    def __init__(self, buf: bytes, name: str, fmt: str, pos: int = 0) -> None:
        self.buf = buf
        self.name = name
        self.fmt = fmt
        self.pos = pos

    def __len__(self) -> int:
        return len(self.buf)

    @property
    def remaining(self) -> int:
        """Bytes left after the cursor."""
        return len(self.buf) - self.pos

    def fail(self, problem: str) -> NoReturn:
        """Raise a format error naming the file, the format and the problem."""
        raise format_error(self.name, self.fmt, problem)

    def need(self, n: int, what: str = "data") -> None:
        """Fail unless ``n`` more bytes are available at the cursor."""
        if n < 0:
            self.fail(f"negative size {n} for {what}")
        if self.pos + n > len(self.buf):
            self.fail(
                f"truncated: {what} needs {n} bytes at offset {self.pos}, "
                f"the file has {len(self.buf)}"
            )

    def seek(self, pos: int, what: str = "offset") -> None:
        """Move the cursor to ``pos`` (checked)."""
        if pos < 0 or pos > len(self.buf):
            self.fail(f"{what} {pos} lies outside the file ({len(self.buf)} bytes)")
        self.pos = pos

    def skip(self, n: int, what: str = "field") -> None:
        """Advance by ``n`` bytes (checked)."""
        self.need(n, what)
        self.pos += n

    def bytes(self, n: int, what: str = "field") -> bytes:
        """Read ``n`` raw bytes."""
        self.need(n, what)
        out = self.buf[self.pos : self.pos + n]
        self.pos += n
        return out

    def unpack(self, fmt: str, what: str = "header") -> tuple[Any, ...]:
        """``struct.unpack`` at the cursor, advancing it."""
        size = struct.calcsize(fmt)
        self.need(size, what)
        out = struct.unpack_from(fmt, self.buf, self.pos)
        self.pos += size
        return out

    def unpack_at(self, offset: int, fmt: str, what: str = "header") -> tuple[Any, ...]:
        """``struct.unpack`` at an absolute offset; the cursor does not move."""
        size = struct.calcsize(fmt)
        if offset < 0 or offset + size > len(self.buf):
            self.fail(f"truncated: {what} at offset {offset} needs {size} bytes")
        return struct.unpack_from(fmt, self.buf, offset)

    def cstring(self, n: int, what: str = "text field", encoding: str = "latin-1") -> str:
        """Read a fixed-width, NUL-padded text field."""
        raw = self.bytes(n, what)
        return raw.split(b"\0", 1)[0].decode(encoding, errors="replace").strip()

    def array(self, dtype: Any, count: int, what: str = "height data") -> np.ndarray:
        """Read ``count`` items of ``dtype`` at the cursor into a new array."""
        dt = np.dtype(dtype)
        if count < 0 or count > MAX_POINTS:
            self.fail(f"absurd item count {count} for {what}")
        nbytes = count * dt.itemsize
        self.need(nbytes, what)
        out = np.frombuffer(self.buf, dtype=dt, count=count, offset=self.pos).copy()
        self.pos += nbytes
        return out


def check_grid(nx: Any, ny: Any, name: str, fmt: str, available: int | None = None,
               itemsize: int = 1) -> tuple[int, int]:
    """Validate a grid size from a header.

    Parameters
    ----------
    nx, ny : int or str or None
        Points along x and y, as the header gives them (None or text that is no integer is
        refused).
    available : int, optional
        Bytes (or, with ``itemsize=1``, items) that the file really holds for the data; the
        grid must fit in it.
    itemsize : int
        Bytes per point in the file.

    Returns
    -------
    (nx, ny) as Python ints.
    """
    try:
        nx, ny = int(nx), int(ny)
    except (TypeError, ValueError, OverflowError):
        raise SurfmetFormatError(
            f"{name}: {fmt} file: grid size {nx!r} x {ny!r} is not an integer"
        ) from None
    if nx <= 0 or ny <= 0:
        raise format_error(name, fmt, f"grid size {nx} x {ny} has no points")
    if nx * ny > MAX_POINTS:
        raise format_error(name, fmt, f"absurd grid size {nx} x {ny}")
    if available is not None and nx * ny * itemsize > available:
        raise SurfmetFormatError(
            f"{name}: {fmt} file: truncated: header says {nx} x {ny} points "
            f"({nx * ny * itemsize} bytes) but only {available} bytes of data follow"
        )
    return nx, ny


def check_step(value: float, name: str, fmt: str, what: str = "pixel size") -> float:
    """Validate a positive, finite lateral step (already in metres)."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise format_error(name, fmt, f"{what} {value!r} is not a number") from None
    if not (np.isfinite(v) and v > 0):
        raise format_error(name, fmt, f"{what} {value!r} is not a positive length")
    return v


def positions_profile(z: np.ndarray, x: np.ndarray, step: float, rtol: float,
                      metadata: dict[str, Any]) -> Profile:
    """A profile of heights ``z`` at increasing positions ``x`` (m): uniform at ``step`` when
    no step between the positions differs from it by more than ``rtol * step``, else with
    the positions kept (from ``x[0]``)."""
    if np.max(np.abs(np.diff(x) - step)) <= rtol * step:
        return Profile(z, step, metadata=metadata)
    return Profile(z, step, x - x[0], metadata=metadata)


def channel_index(names: list[str], channel: int | str, r: ByteReader,
                  what: str = "channel") -> int:
    """The index a user's ``channel`` names: a name (case-insensitive, first match) or an
    index (a string of digits counts as an index); fails with a format error otherwise."""
    if isinstance(channel, str) and not channel.lstrip("-").isdigit():
        for i, n in enumerate(names):
            if n.lower() == channel.lower():
                return i
        r.fail(f"no {what} named {channel!r}; {what}s: {names}")
    index = int(channel)
    if not 0 <= index < len(names):
        r.fail(f"{what} {index} does not exist: the file holds {len(names)}")
    return index


def decode_text(buf: bytes) -> str:
    """Decode text files: UTF-8 (with or without BOM), else Latin-1 (never fails)."""
    try:
        return buf.decode("utf-8-sig")
    except UnicodeDecodeError:
        return buf.decode("latin-1")


def looks_like_text(buf: bytes, n: int = 2048) -> bool:
    """True if the start of ``buf`` holds no NUL bytes and mostly printable characters."""
    head = buf[:n]
    if not head or b"\0" in head:
        return False
    printable = sum(1 for b in head if b in b"\t\r\n" or 32 <= b < 127 or b >= 160)
    return printable / len(head) > 0.95
