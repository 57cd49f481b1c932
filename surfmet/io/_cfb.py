"""Microsoft Compound File Binary (OLE2) streams, read from [MS-CFB] (Microsoft Open
Specifications, "Compound File Binary File Format"), for the MountainsMap ``.mnt`` reader.

A 512-byte header (signature ``D0 CF 11 E0 A1 B1 1A E1``, sector size 2^``0x1E``, mini
sector size 2^``0x20``, FAT sector count, first directory sector, mini-stream cut-off,
first mini-FAT sector, first DIFAT sector) and sectors of 512 (version 3) or 4096
(version 4) bytes, sector ``n`` at ``(n + 1) x size``. The FAT chains the sectors of each
stream; the first 109 FAT sector numbers sit in the header's DIFAT, the rest in chained
DIFAT sectors. Directory entries are 128 bytes (UTF-16 name, type 2 = stream, start sector,
size); streams shorter than the cut-off live in 64-byte mini sectors of the root entry's
stream, chained by the mini FAT. Every chain is bounded, so a corrupted file cannot loop.
"""

from __future__ import annotations

import struct
from typing import NoReturn

import numpy as np

from surfmet.errors import SurfmetFormatError

SIGNATURE = b"\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1"
_END = 0xFFFFFFFA  # sector numbers from here on are markers (end of chain, free, FAT, DIFAT)


class CompoundFile:
    """The streams of a compound file, by name (the directory tree is flattened)."""

    def __init__(self, buf: bytes, name: str, fmt: str) -> None:
        self.buf, self.name, self.fmt = buf, name, fmt
        if buf[:8] != SIGNATURE or len(buf) < 512:
            self.fail("not a compound (OLE2) file")
        shift, mini_shift = struct.unpack_from("<HH", buf, 0x1E)
        if shift not in (9, 12) or mini_shift != 6:
            self.fail(f"sector size 2^{shift} / mini sector 2^{mini_shift} is not valid")
        self.size, self.mini = 1 << shift, 1 << mini_shift
        (_, nfat, dir_start, _, self.cutoff, minifat_start, _, difat_start,
         ndifat) = struct.unpack_from("<9I", buf, 0x28)
        self.nsectors = max(0, (len(buf) - self.size) // self.size)
        self.fat = self._fat(nfat, difat_start, ndifat)
        self.entries = self._directory(dir_start)
        root = self.entries[0] if self.entries else None
        if root is None or root[1] != 5:
            self.fail("the directory has no root entry")
        self.ministream = self._chain_bytes(root[2], root[3])
        self.minifat = np.frombuffer(self._chain_bytes(minifat_start, None), "<u4")

    def fail(self, problem: str) -> NoReturn:
        raise SurfmetFormatError(f"{self.name}: {self.fmt} file: {problem}")

    def _sector(self, n: int) -> bytes:
        if n >= self.nsectors:
            self.fail(f"sector {n} lies outside the file (truncated?)")
        start = (n + 1) * self.size
        return self.buf[start:start + self.size]

    def _fat(self, nfat: int, difat_start: int, ndifat: int) -> np.ndarray:
        difat = list(struct.unpack_from("<109I", self.buf, 0x4C))
        n = difat_start
        for _ in range(min(ndifat, self.nsectors)):
            if n >= _END:
                break
            words = struct.unpack(f"<{self.size // 4}I", self._sector(n))
            difat += words[:-1]
            n = words[-1]
        secs = [d for d in difat if d < _END][:nfat]
        if len(secs) != nfat:
            self.fail(f"the header announces {nfat} FAT sectors, {len(secs)} are listed")
        return np.frombuffer(b"".join(self._sector(s) for s in secs), "<u4")

    def _chain(self, start: int, table: np.ndarray) -> list[int]:
        out: list[int] = []
        n = start
        while n < _END:
            if n >= table.size or len(out) > table.size:
                self.fail("a sector chain is broken or loops (corrupted file)")
            out.append(n)
            n = int(table[n])
        return out

    def _chain_bytes(self, start: int, size: int | None) -> bytes:
        data = b"".join(self._sector(s) for s in self._chain(start, self.fat))
        if size is not None and len(data) < size:
            self.fail("a stream is shorter than its directory entry says (truncated?)")
        return data if size is None else data[:size]

    def _directory(self, start: int) -> list[tuple[str, int, int, int]]:
        raw = self._chain_bytes(start, None)
        out = []
        for k in range(len(raw) // 128):
            e = raw[128 * k:128 * (k + 1)]
            (nlen,) = struct.unpack_from("<H", e, 64)
            name = e[:max(0, min(nlen, 64) - 2)].decode("utf-16-le", errors="replace")
            start_sector, size = struct.unpack_from("<IQ", e, 116)
            if self.size == 512:
                size &= 0xFFFFFFFF  # version 3: the high word is undefined
            out.append((name, e[66], start_sector, size))
        return out

    def stream(self, stream_name: str) -> bytes:
        """The bytes of the first stream called ``stream_name``."""
        for name, kind, start, size in self.entries:
            if kind != 2 or name != stream_name:
                continue
            if size >= self.cutoff:
                return self._chain_bytes(start, size)
            sectors = self._chain(start, self.minifat)
            data = b"".join(self.ministream[s * self.mini:(s + 1) * self.mini] for s in sectors)
            if len(data) < size:
                self.fail(f"stream {stream_name!r} is truncated")
            return data[:size]
        self.fail(f"the file has no stream {stream_name!r}")
