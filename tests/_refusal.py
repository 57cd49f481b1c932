"""A reader must refuse a tiny file that claims a huge grid before it allocates the grid."""

from __future__ import annotations

import tracemalloc
from typing import Any

import pytest

from surfmet._errors import SurfmetFormatError
from surfmet.io import read_bytes


def refused_cheaply(data: bytes | bytearray, name: str, *, match: str | None = None,
                    limit: float = 20e6, **kwargs: Any) -> pytest.ExceptionInfo:
    """Read ``data`` expecting a format error (matching ``match``), and assert that Python's
    allocations peaked below ``limit`` bytes on the way; return the error's info."""
    data = bytes(data)
    tracemalloc.start()
    try:
        with pytest.raises(SurfmetFormatError, match=match) as info:
            read_bytes(data, name=name, **kwargs)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < limit, f"{name}: peak {peak / 2**20:.0f} MiB for a {len(data)}-byte file"
    return info
