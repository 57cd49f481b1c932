"""TIFF image file directories (IFDs), for the TIFF-based formats that keep several pages.

Classic TIFF (TIFF 6.0 specification, section 2): a byte-order mark (``II*\\0`` little,
``MM\\0*`` big endian), the offset of the first IFD, then a chain of IFDs, each a count of
12-byte entries (tag, type, count, value or offset) followed by the offset of the next IFD.
Every offset and count is checked against the file before it is followed, and the chain is
cut at the first loop, so a damaged file fails with one :class:`SurfmetFormatError` line.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass

import numpy as np

from surfmet.io._binary import ByteReader, check_grid

# bytes per value of each TIFF field type
_TYPE_SIZE = {1: 1, 2: 1, 3: 2, 4: 4, 5: 8, 6: 1, 7: 1, 8: 2, 9: 4, 10: 8, 11: 4, 12: 8, 16: 8}
_NUMERIC = {1: "B", 3: "H", 4: "I", 6: "b", 8: "h", 9: "i", 11: "f", 12: "d", 16: "Q"}
_MAX_IFDS = 4096
_SAMPLE_KINDS = {1: "u", 2: "i", 3: "f"}


@dataclass(frozen=True)
class Ifd:
    """One image file directory: ``{tag: (type, count, raw value bytes)}``."""

    order: str
    entries: dict[int, tuple[int, int, bytes]]

    def has(self, tag: int) -> bool:
        return tag in self.entries

    def text(self, tag: int) -> str:
        """An ASCII tag, without its terminating NUL."""
        _, _, raw = self.entries[tag]
        return raw.split(b"\0", 1)[0].decode("utf-8", errors="replace").strip()

    def numbers(self, tag: int) -> tuple[float | int, ...]:
        """The values of a numeric tag (rationals as floats)."""
        kind, count, raw = self.entries[tag]
        if kind in (5, 10):
            pairs = struct.unpack(f"{self.order}{2 * count}{'I' if kind == 5 else 'i'}", raw)
            return tuple(a / b if b else float("nan") for a, b in zip(pairs[::2], pairs[1::2]))
        if kind not in _NUMERIC:
            raise ValueError(f"TIFF tag {tag} of type {kind} is not numeric")
        return struct.unpack(f"{self.order}{count}{_NUMERIC[kind]}", raw)

    def number(self, tag: int) -> float | int:
        return self.numbers(tag)[0]


def is_tiff(buf: bytes) -> bool:
    """True for the classic TIFF byte-order marks (BigTIFF is not read)."""
    return buf[:4] in (b"II*\0", b"MM\0*")


def first_ifd_tags(buf: bytes) -> set[int]:
    """The tag numbers of the first IFD (empty when the bytes do not hold one); for magic
    checks, so it never raises."""
    if not is_tiff(buf) or len(buf) < 8:
        return set()
    order = "<" if buf[:2] == b"II" else ">"
    (pos,) = struct.unpack_from(order + "I", buf, 4)
    if pos + 2 > len(buf):
        return set()
    (n,) = struct.unpack_from(order + "H", buf, pos)
    if pos + 2 + 12 * n > len(buf):
        return set()
    return {struct.unpack_from(order + "H", buf, pos + 2 + 12 * k)[0] for k in range(n)}


def read_ifds(buf: bytes, name: str, fmt: str) -> list[Ifd]:
    """Every IFD of the chain, in file order."""
    r = ByteReader(buf, name, fmt)
    if not is_tiff(buf):
        r.fail("not a TIFF file (no II*/MM* byte-order mark)")
    order = "<" if buf[:2] == b"II" else ">"
    (pos,) = r.unpack_at(4, order + "I", "first IFD offset")
    seen: set[int] = set()
    ifds: list[Ifd] = []
    while pos and pos not in seen:
        if len(ifds) >= _MAX_IFDS:
            r.fail(f"more than {_MAX_IFDS} image directories")
        seen.add(pos)
        (n,) = r.unpack_at(pos, order + "H", "IFD entry count")
        r.unpack_at(pos + 2, f"{12 * n + 4}x", "IFD entries")
        entries = {}
        for k in range(n):
            at = pos + 2 + 12 * k
            tag, kind, count = struct.unpack_from(order + "HHI", buf, at)
            size = _TYPE_SIZE.get(kind, 1) * count
            if size <= 4:
                raw = buf[at + 8:at + 8 + size]
            else:
                (off,) = struct.unpack_from(order + "I", buf, at + 8)
                if off + size > len(buf):
                    r.fail(f"truncated: TIFF tag {tag} points past the end of the file")
                raw = buf[off:off + size]
            entries[tag] = (kind, count, raw)
        ifds.append(Ifd(order, entries))
        (pos,) = struct.unpack_from(order + "I", buf, pos + 2 + 12 * n)
    return ifds


def strip_image(buf: bytes, ifd: Ifd, name: str, fmt: str) -> np.ndarray:
    """The uncompressed single-sample image of ``ifd`` as a (rows, columns) array.

    Reads tags 256/257 (width, length), 258 (bits per sample), 259 (compression, 1 only),
    273/279 (strip offsets and byte counts), 277 (samples per pixel, 1 only) and 339
    (sample format: 1 unsigned, 2 signed, 3 float).
    """
    r = ByteReader(buf, name, fmt)
    for tag in (256, 257, 258, 273, 279):
        if not ifd.has(tag):
            r.fail(f"image directory lacks TIFF tag {tag}")
    if ifd.has(259) and ifd.number(259) != 1:
        r.fail(f"compressed image data (TIFF compression {ifd.number(259)}) is not read")
    if ifd.has(277) and ifd.number(277) != 1:
        r.fail(f"{ifd.number(277)} samples per pixel (one expected)")
    nx, ny = check_grid(ifd.number(256), ifd.number(257), name, fmt)
    bits = int(ifd.number(258))
    kind = _SAMPLE_KINDS.get(int(ifd.number(339)) if ifd.has(339) else 1)
    if kind is None or bits not in (8, 16, 32, 64) or (kind == "f" and bits < 32):
        r.fail(f"unsupported sample layout ({bits} bits, TIFF sample format "
               f"{ifd.number(339) if ifd.has(339) else 1})")
    dtype = np.dtype(f"{ifd.order}{kind}{bits // 8}")
    offsets, counts = ifd.numbers(273), ifd.numbers(279)
    if len(offsets) != len(counts):
        r.fail("strip offsets and strip byte counts differ in number")
    parts = []
    for off, cnt in zip(offsets, counts):
        r.unpack_at(int(off), f"{int(cnt)}x", "image strip")
        parts.append(buf[int(off):int(off) + int(cnt)])
    data = b"".join(parts)
    check_grid(nx, ny, name, fmt, available=len(data), itemsize=dtype.itemsize)
    return np.frombuffer(data, dtype=dtype, count=nx * ny).reshape(ny, nx).copy()
