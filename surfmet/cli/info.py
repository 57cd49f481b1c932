"""``surfmet info FILE``: what a scan file holds, every channel or measurement of it, and
which of its units the file states."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet._model import SOURCE_WORDS, STATED, unit_text
from surfmet.cli._common import add_json_flag, emit_json
from surfmet.cli._scan_options import add_scan_options, read_options
from surfmet.records._scans import channel_record
from surfmet.units import format_length


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "info",
        help="format, grid, pixel size and metadata of a scan file",
        description="Print the format, kind, grid, pixel size, non-measured fraction and "
        "metadata of a scan file, which of its units the file states (and which are "
        "assumed), and every channel or measurement it holds.",
        epilog="examples:\n  surfmet info scan.nms\n  surfmet info scan.x3p --json\n"
        "  surfmet info export.txt --format asc\n"
        "  surfmet info surface.h5 --channel 1 --height-unit um --pixel 78.125nm",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("file", help="scan file (format detected from its content)")
    p.add_argument("--format", help="force a reader (see 'surfmet formats')")
    add_scan_options(p)
    add_json_flag(p)
    p.set_defaults(func=run)
    return p


def _pixel(scan: Any) -> str:
    if scan.kind == "areal":
        return f"{format_length(scan.dx)} x {format_length(scan.dy)}"
    return format_length(scan.dx)


def _line(index: Any, label: str, rec: dict[str, Any] | None, error: str | None,
          scan: Any = None) -> str:
    head = f"  {index!s:>3} {label[:28]:28s}"
    if error:
        return f"{head} not read: {error}"
    cal = scan.calibration
    said = [f"{w} {SOURCE_WORDS[s]}" for w, s in (("height unit", cal.height),
                                                  ("pixel", cal.lateral)) if s != STATED]
    note = f" ({', '.join(said)})" if said else ""
    return (f"{head} {rec['kind']} {scan.nx} x {scan.ny}, pixel {_pixel(scan)}, heights "
            f"in {unit_text(cal.height_unit)}{note}")


def run(args: argparse.Namespace) -> int:
    import surfmet

    scan = surfmet.read(args.file, format=args.format, **read_options(args))
    from surfmet.file_info import channel_listing, info_record

    cal = scan.calibration
    listing = channel_listing(args.file, scan, args.format, read_options(args))
    rec = info_record(args.file, scan, listing=listing)
    if args.json:
        emit_json(rec)
        return 0
    print(f"file          {rec['file']}")
    print(f"format        {rec['format']}")
    print(f"kind          {rec['kind']}")
    print(f"grid          {scan.nx} x {scan.ny}")
    dy = format_length(scan.dy) if scan.kind == "areal" else "-"
    print(f"pixel size    {format_length(scan.dx)} x {dy}  ({SOURCE_WORDS[cal.lateral]})")
    print(f"height unit   {unit_text(cal.height_unit)}  ({SOURCE_WORDS[cal.height]})")
    if scan.kind == "areal":
        print(f"scan size     {format_length(scan.size_x)} x {format_length(scan.size_y)}")
    else:
        sampling = "uniform" if scan.is_uniform else "non-uniform"
        print(f"length        {format_length(scan.length)} ({sampling})")
    print(f"non-measured  {100 * scan.nan_fraction:.3f} %")
    for caveat in cal.caveats():
        print(f"CAVEAT: {caveat}")
    if listing:
        word = "measurements" if rec["format"] == "ce" else "channels"
        print(f"{word:13s} {len(listing)} (this one: {scan.metadata.get('channel')}; "
              "--channel picks another)")
        for c, label, s, err in listing:
            print(_line(c, label, None if s is None else channel_record(s), err, s))
    for key, value in rec["metadata"].items():
        if key in _SHOWN_ABOVE:  # the lines above state them, in the text's units
            continue
        text = _metadata_text(value)
        if len(text) > 100:
            text = text[:97] + "..."
        print(f"  {key}: {text}")
    return 0


#: metadata the header lines already state (units, their sources, the channel listing)
_SHOWN_ABOVE = frozenset({"height_unit", "lateral_unit", "lateral_calibrated",
                          "height_unit_source", "lateral_unit_source", "channels",
                          "channel_grids"})


def _metadata_text(value: Any) -> str:
    """A metadata value as text: a quantity ``{"value", "unit"}`` as the one formatter
    writes it (``8.786 nm``, not ``{'value': 8.78e-09, 'unit': 'm'}``)."""
    from surfmet.units import format_quantity

    if isinstance(value, dict) and set(value) == {"value", "unit"} and isinstance(
            value["value"], (int, float)) and not isinstance(value["value"], bool):
        return format_quantity(float(value["value"]), str(value["unit"]), 6)
    if isinstance(value, dict):  # e.g. a region's x, y, width: each as above
        return "{" + ", ".join(f"{k}: {_metadata_text(v)}" for k, v in value.items()) + "}"
    return str(value)
