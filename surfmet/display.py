"""How scans and results show themselves in a notebook: ``_repr_html_`` and short reprs.

Jupyter calls ``_repr_html_`` on the last value of a cell. A scan shows a small height map
(an inline PNG encoded here with :mod:`zlib`, so that displaying a scan never imports
matplotlib) beside its grid and pixel; a result shows its key numbers with their units,
through the same :func:`surfmet.units.split_quantity` as the command line's text.
"""

from __future__ import annotations

import base64
import html
import struct
import zlib
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from surfmet.units import format_quantity, split_quantity

if TYPE_CHECKING:
    from surfmet.mechanics.ball_contact import BallContact
    from surfmet.mechanics.hertz_check import HertzCheck
    from surfmet.model import Profile, Topography
    from surfmet.roughness_result import RoughnessResult

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

    header = struct.pack(">IIBBBBB", grey.shape[1], grey.shape[0], 8, 0, 0, 0, 0)
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


def _range(values: np.ndarray) -> float:
    finite = values[np.isfinite(values)]
    return float(np.ptp(finite)) if finite.size else float("nan")


def topography_html(topo: Topography) -> str:
    """A height map and the scan's grid, pixel, height range and format."""
    rows: list[Row] = [
        ("grid", f"{topo.nx} × {topo.ny}", "points"),
        ("size", f"{format_quantity(topo.size_x, 'm')} × {format_quantity(topo.size_y, 'm')}",
         ""),
        ("pixel", f"{format_quantity(topo.dx, 'm')} × {format_quantity(topo.dy, 'm')}", ""),
        ("height range", _range(topo.heights), "m"),
        ("non-measured", 100 * topo.nan_fraction, "%"),
        ("format", topo.metadata.get("format") or "-", ""),
    ]
    return _side_by_side(_image(topo.heights), quantity_table("Topography", rows))


def profile_html(profile: Profile) -> str:
    """A line of the profile and its points, length, spacing, height range and format."""
    rows: list[Row] = [
        ("points", profile.n, ""),
        ("length", profile.length, "m"),
        ("spacing", profile.dx, "m"),
        ("spacing is", "uniform" if profile.is_uniform else "non-uniform", ""),
        ("height range", _range(profile.z), "m"),
        ("non-measured", 100 * profile.nan_fraction, "%"),
        ("format", profile.metadata.get("format") or "-", ""),
    ]
    return _side_by_side(_profile_svg(profile.positions, profile.z),
                         quantity_table("Profile", rows))


def roughness_html(result: RoughnessResult) -> str:
    """Every parameter of a roughness result with its unit."""
    rows = [(name, value, unit) for name, (value, unit) in result.parameters.items()]
    title = f"Roughness ({result.kind})" + (f": {result.file}" if result.file else "")
    return quantity_table(title, rows)


def roughness_repr(result: RoughnessResult, first: Sequence[str] = ("a", "q", "z")) -> str:
    """``RoughnessResult(areal, 30 parameters: Sa=1.823 µm, Sq=2.416 µm, Sz=243.4 µm)``."""
    prefix = "S" if result.kind == "areal" else "R"
    shown = [f"{prefix}{s}={format_quantity(*result.parameters[prefix + s])}"
             for s in first if prefix + s in result.parameters]
    return (f"RoughnessResult({result.kind}, {len(result.parameters)} parameters"
            + (": " + ", ".join(shown) if shown else "") + ")")


def hertz_check_html(check: HertzCheck) -> str:
    """The verdict and the numbers it rests on: GJM alpha, sigma, load, radius, E*,
    Hertz's and the boundary elements' contact radius and peak pressure."""
    c, res = check.comparison, check.result
    rows: list[Row] = [
        ("verdict", check.verdict, ""),
        ("Hertz holds", "yes" if check.hertz_holds else "no", ""),
        ("GJM alpha", check.alpha, ""),
        ("sigma", check.sigma, "m"),
        ("load", check.load, "N"),
        ("ball radius", check.radius, "m"),
        ("E*", check.e_star, "Pa"),
        ("Hertz contact radius a0", c.hertz.a, "m"),
        ("Hertz peak pressure p0", c.hertz.p0, "Pa"),
        ("BEM contact radius", res.contact_radius, "m"),
        ("BEM peak pressure", c.pmax, "Pa"),
    ]
    return quantity_table("Hertz check", rows)


def hertz_check_repr(check: HertzCheck) -> str:
    """``HertzCheck(verdict='bem', alpha=3.2, load=10 N, radius=20 mm)``."""
    return (f"HertzCheck(verdict={check.verdict!r}, alpha={check.alpha:.4g}, "
            f"load={format_quantity(check.load, 'N')}, "
            f"radius={format_quantity(check.radius, 'm')})")


def ball_contact_html(contact: BallContact) -> str:
    """The solved contact's load, approach, contact radius and area, peak pressure."""
    res = contact.result
    rows: list[Row] = [
        ("load", res.load, "N"),
        ("ball radius", contact.radius, "m"),
        ("E*", res.e_star, "Pa"),
        ("approach", res.approach, "m"),
        ("contact radius", res.contact_radius, "m"),
        ("contact area", res.contact_area, "m^2"),
        ("peak pressure", res.pmax, "Pa"),
        ("grid", f"{res.pressure.shape[1]} × {res.pressure.shape[0]}", "cells"),
    ]
    if res.hertz is not None:
        rows += [("Hertz contact radius a0", res.hertz.a, "m"),
                 ("Hertz peak pressure p0", res.hertz.p0, "Pa")]
    return quantity_table("Ball contact", rows)


def ball_contact_repr(contact: BallContact) -> str:
    """``BallContact(load=10 N, radius=20 mm, contact radius=97.3 µm, pmax=1.2 GPa)``."""
    res = contact.result
    return (f"BallContact(load={format_quantity(res.load, 'N')}, "
            f"radius={format_quantity(contact.radius, 'm')}, "
            f"contact radius={format_quantity(res.contact_radius, 'm')}, "
            f"pmax={format_quantity(res.pmax, 'Pa')})")
