"""How scans and results show themselves in a notebook (``_repr_html_``).

Jupyter calls ``_repr_html_`` on the last value of a cell. A scan shows a small height map
(an inline PNG encoded here with :mod:`zlib`, so that displaying a scan never imports
matplotlib) beside its grid and pixel; a result shows its key numbers with their units,
through the same :func:`surfmet.units.split_quantity` as the command line's text. Each
class names its own rows; this module only draws them (it imports none of the classes).
"""

from __future__ import annotations

import base64
import html
import struct
import zlib
from collections.abc import Iterable
from typing import Any

import numpy as np

from surfmet.units import split_quantity

#: A row of a result's table: a name, an SI value (or a text) and its unit.
Row = tuple[str, Any, str]

#: The longest side of the inline height map, in pixels (a 1024² scan is not 4 MB of page).
MAP_PIXELS = 128

_STYLE = "border-collapse:collapse;font-family:sans-serif;font-size:90%"
_CELL = "padding:1px 8px;text-align:left"
_NUMBER = "padding:1px 8px;text-align:right"


def quantity_table(title: str, rows: Iterable[Row]) -> str:
    """An HTML table of ``(name, value, unit)`` rows, each value in its readable unit.

    Numbers are SI floats shown through :func:`surfmet.units.split_quantity` (``1.8e-6``,
    ``"m"`` shows as 1.823 µm); any other value is shown as text with the unit given.
    """
    body = []
    for name, value, unit in rows:
        if isinstance(value, (int, float, np.floating, np.integer)) and not isinstance(
                value, bool):
            number, shown = split_quantity(float(value), unit)
        else:
            number, shown = str(value), unit
        body.append(f"<tr><th style='{_CELL}'>{html.escape(name)}</th>"
                    f"<td style='{_NUMBER}'>{html.escape(number)}</td>"
                    f"<td style='{_CELL}'>{html.escape(shown)}</td></tr>")
    return (f"<table style='{_STYLE}'><caption style='text-align:left'><b>"
            f"{html.escape(title)}</b></caption>{''.join(body)}</table>")


def png_bytes(values: np.ndarray, pixels: int = MAP_PIXELS) -> bytes:
    """A greyscale PNG of a 2-D array (low = dark), at most ``pixels`` on its longer side;
    non-measured points (NaN) are black."""
    z = np.asarray(values, dtype=float)
    step = max(1, -(-max(z.shape) // pixels))
    z = z[::step, ::step]
    finite = np.isfinite(z)
    lo, hi = (np.nanmin(z), np.nanmax(z)) if finite.any() else (0.0, 0.0)
    grey = np.zeros(z.shape, dtype=np.uint8)
    if hi > lo:
        grey[finite] = np.round(30 + 225 * (z[finite] - lo) / (hi - lo)).astype(np.uint8)
    else:
        grey[finite] = 128
    raw = b"".join(b"\x00" + row.tobytes() for row in grey[::-1])  # y up, as a map reads

    def chunk(kind: bytes, data: bytes) -> bytes:
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    shape: tuple[int, ...] = grey.shape
    height, width = shape[0], shape[-1]
    header = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
            + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def _image(values: np.ndarray) -> str:
    data = base64.b64encode(png_bytes(values)).decode("ascii")
    return (f"<img src='data:image/png;base64,{data}' alt='height map' "
            "style='image-rendering:pixelated;width:160px;margin-right:12px'/>")


def _profile_svg(x: np.ndarray, z: np.ndarray, width: int = 240, height: int = 60) -> str:
    keep = np.isfinite(z)
    step = max(1, int(keep.sum()) // 400)
    x, z = x[keep][::step], z[keep][::step]
    if x.size < 2 or np.ptp(x) == 0:
        return ""
    span = np.ptp(z) or 1.0
    px = (x - x.min()) / np.ptp(x) * (width - 2) + 1
    pz = height - 1 - (z - z.min()) / span * (height - 2)
    points = " ".join(f"{a:.1f},{b:.1f}" for a, b in zip(px, pz))
    return (f"<svg width='{width}' height='{height}' style='margin-right:12px'>"
            f"<polyline fill='none' stroke='black' stroke-width='1' points='{points}'/></svg>")


def _side_by_side(picture: str, table: str) -> str:
    return f"<div style='display:flex;align-items:flex-start'>{picture}{table}</div>"


def value_range(values: np.ndarray) -> float:
    """Peak-to-valley of the measured (finite) values; NaN when none is."""
    finite = values[np.isfinite(values)]
    return float(np.ptp(finite)) if finite.size else float("nan")


def map_html(heights: np.ndarray, title: str, rows: Iterable[Row]) -> str:
    """A small height map beside a table of the scan's numbers."""
    return _side_by_side(_image(heights), quantity_table(title, rows))


def line_html(x: np.ndarray, z: np.ndarray, title: str, rows: Iterable[Row]) -> str:
    """A line of a profile beside a table of its numbers."""
    return _side_by_side(_profile_svg(np.asarray(x, float), np.asarray(z, float)),
                         quantity_table(title, rows))
