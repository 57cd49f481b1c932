"""``--height-unit``, ``--pixel`` and ``--channel``: what every command that reads a scan
takes, for files that do not state their units or hold several channels.

One definition here, one call per command (:func:`add_scan_options`), one place where each
command reads its scans (:func:`read_scan`, :func:`read_options`). They are
:func:`surfmet.read`'s ``height_unit=``, ``dx=`` / ``dy=`` and ``channel=``.

The rules, the same in every command:

* ``--height-unit`` and ``--pixel`` state what a file does not. A file that states its own
  unit keeps it: the same value given for it is accepted, a different one refused (one of
  the two is wrong). What is stated this way is printed as "stated by the user"; what
  neither the file nor the user states is printed as "assumed", with what was assumed.
* ``--channel`` picks a data set, channel or container measurement, by index or name; a
  file with a single channel refuses it.
* Commands with a plate and a ball apply the three options to both scans, and take
  ``--plate-height-unit``, ``--ball-pixel``... for one body alone (each replaces the
  shared option for that body): two files from two instruments rarely share their gaps.
* Commands that read several files apply them to every file.
"""

from __future__ import annotations

import argparse
import os
import re
from typing import Any

from surfmet import units
from surfmet._errors import SurfmetInputError

_BARE = re.compile(r"^\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*$")


def parse_pixel(text: str) -> tuple[float, float | None]:
    """``DX`` or ``DX,DY`` (lengths with their units) in metres; DY None when not given."""
    parts = [p.strip() for p in str(text).split(",")]
    if len(parts) not in (1, 2) or not all(parts):
        raise SurfmetInputError(f"a pixel size is DX or DX,DY (e.g. 1um or 1um,2um), got "
                                f"{text!r}")
    out = []
    for part in parts:
        if _BARE.match(part):
            raise SurfmetInputError(f"pixel size {part!r} has no unit: write it with one, "
                                    f"e.g. {part}um")
        value = units.parse_length(part)
        if not value > 0:
            raise SurfmetInputError(f"pixel size {part!r} must be positive")
        out.append(value)
    return out[0], (out[1] if len(out) == 2 else None)


def parse_height_unit(text: str) -> str:
    """A length unit name (``nm``, ``µm``, ``um``, ``mm``, ``m``)."""
    units.length_factor(text)  # an unknown unit: one line naming the accepted ones
    return text.strip()


def parse_channel(text: str) -> int | str:
    """A channel index (``0``, ``1``...) or name."""
    text = text.strip()
    if not text:
        raise SurfmetInputError("a channel is an index (0, 1...) or a name")
    return int(text) if text.isdigit() else text


def _argtype(parse: Any, what: str) -> Any:
    def convert(text: str) -> Any:
        try:
            return parse(text)
        except SurfmetInputError as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None

    convert.__name__ = what  # argparse names the type in its messages
    return convert


def _add(group: Any, prefix: str, whose: str) -> None:
    dest = prefix.replace("-", "_")
    alone = bool(prefix)  # a body's own option: say only what differs from the shared one
    group.add_argument(f"--{prefix}height-unit", dest=f"{dest}height_unit", metavar="UNIT",
                       type=_argtype(parse_height_unit, "height unit"),
                       help=f"--height-unit for {whose} alone" if alone else
                       "unit of the heights, for a file that states none (nm, µm, mm, m); "
                       "a file that states a different one is refused")
    group.add_argument(f"--{prefix}pixel", dest=f"{dest}pixel", metavar="DX[,DY]",
                       type=_argtype(parse_pixel, "pixel size"),
                       help=f"--pixel for {whose} alone" if alone else
                       "pixel size with its unit, for a file that states none (1um, or "
                       "1um,2um for dx,dy)")
    group.add_argument(f"--{prefix}channel", dest=f"{dest}channel", metavar="N|NAME",
                       type=_argtype(parse_channel, "channel"),
                       help=f"--channel for {whose} alone" if alone else
                       "channel, data set or container measurement (index or name; "
                       "default the first)")


def add_scan_options(parser: Any, bodies: tuple[str, ...] = ()) -> None:
    """Add ``--height-unit``, ``--pixel``, ``--channel`` (and, for each of ``bodies``,
    ``--BODY-height-unit``... for that body's scan alone)."""
    group = parser.add_argument_group(
        "scan units and channel", "for files that do not state their units (output then "
        "says 'stated by the user'; what no one states is said to be 'assumed') or that "
        "hold several channels")
    if bodies:
        group.description += f"; they apply to every scan, --{bodies[0]}-pixel... to one"
    _add(group, "", "")
    for body in bodies:
        _add(group, f"{body}-", f"the {body} scan")


def read_options(args: argparse.Namespace, body: str | None = None) -> dict[str, Any]:
    """:func:`surfmet.read`'s options from the command line (only those given); for a
    ``body`` (``"plate"``, ``"ball"``), its own options replace the shared ones."""

    def get(name: str) -> Any:
        own = getattr(args, f"{body}_{name}", None) if body else None
        return own if own is not None else getattr(args, name, None)

    out: dict[str, Any] = {}
    if get("height_unit") is not None:
        out["height_unit"] = get("height_unit")
    pixel = get("pixel")
    if pixel is not None:
        out["dx"], dy = pixel
        if dy is not None:
            out["dy"] = dy
    if get("channel") is not None:
        out["channel"] = get("channel")
    return out


def read_scan(path: Any, args: argparse.Namespace, body: str | None = None) -> Any:
    """The scan at ``path`` (None stays None; a scan already read is returned as it is),
    read with the command line's options."""
    if path is None or not isinstance(path, (str, bytes, os.PathLike)):
        return path
    import surfmet

    return surfmet.read(path, format=getattr(args, "format", None),
                        **read_options(args, body))


def read_bodies(args: argparse.Namespace, bodies: tuple[str, ...] = ("plate", "ball")
                ) -> None:
    """Read each body's scan file (``args.plate``, ``args.ball``) in place with the command
    line's options, so that every later use of them sees the scan as the user stated it."""
    for body in bodies:
        if hasattr(args, body):
            setattr(args, body, read_scan(getattr(args, body), args, body))


def scan_caveats(*scans: Any) -> list[str]:
    """Each scan's units that were assumed or stated by the user
    (:meth:`surfmet._model.Calibration.caveats`), prefixed by its file when several scans
    are given; for the ``caveats`` of a command's text and JSON."""
    named = [s for s in scans if s is not None]
    out = []
    for s in named:
        label = s.metadata.get("source") or s.metadata.get("container") or "scan"
        prefix = f"{label}: " if len(named) > 1 else ""
        out.extend(f"{prefix}{c}" for c in s.calibration.caveats())
    return out


def files_caveats(args: argparse.Namespace, files: dict[str, Any]) -> list[str]:
    """Read each file of each body once (``files``: body -> paths or None) with the
    command line's options, so that what a file contradicts is refused before any work;
    their caveats, printed on stderr and returned for the JSON."""
    import sys

    scans = [read_scan(p, args, body) for body, paths in files.items()
             for p in dict.fromkeys(paths or ())]
    caveats = scan_caveats(*scans)
    print_caveats(caveats, sys.stderr)
    return caveats


def print_caveats(caveats: list[str], file: Any = None) -> None:
    """The caveats, one ``CAVEAT:`` line each (on ``file``, default stdout)."""
    for c in caveats:
        print(f"CAVEAT: {c}", file=file)


__all__ = [
    "add_scan_options",
    "files_caveats",
    "parse_channel",
    "parse_height_unit",
    "parse_pixel",
    "print_caveats",
    "read_bodies",
    "read_options",
    "read_scan",
    "scan_caveats",
]
