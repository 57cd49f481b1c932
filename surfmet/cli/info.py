"""``surfmet info FILE``: what a scan file holds."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.cli._common import add_json_flag, emit_json
from surfmet.units import format_length


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "info",
        help="format, grid, pixel size and metadata of a scan file",
        description="Print the format, kind, grid, pixel size, non-measured fraction and "
        "metadata of a scan file.",
        epilog="examples:\n  surfmet info scan.nms\n  surfmet info scan.x3p --json\n"
        "  surfmet info export.txt --format asc",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("file", help="scan file (format detected from its content)")
    p.add_argument("--format", help="force a reader (see 'surfmet formats')")
    add_json_flag(p)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    import surfmet

    scan = surfmet.read(args.file, format=args.format)
    from surfmet.records import scan_record

    rec = scan_record(scan)
    if args.json:
        emit_json(rec)
        return 0
    print(f"file          {rec['file']}")
    print(f"format        {rec['format']}")
    print(f"kind          {rec['kind']}")
    print(f"grid          {scan.nx} x {scan.ny}")
    dy = format_length(scan.dy) if scan.kind == "areal" else "-"
    note = ""
    if not scan.metadata.get("lateral_calibrated", True):
        note = "  (uncalibrated: the file states no lateral unit)"
    print(f"pixel size    {format_length(scan.dx)} x {dy}{note}")
    if scan.kind == "areal":
        print(f"scan size     {format_length(scan.size_x)} x {format_length(scan.size_y)}")
    else:
        sampling = "uniform" if scan.is_uniform else "non-uniform"
        print(f"length        {format_length(scan.length)} ({sampling})")
    print(f"non-measured  {100 * scan.nan_fraction:.3f} %")
    for key, value in rec["metadata"].items():
        text = str(value)
        if len(text) > 100:
            text = text[:97] + "..."
        print(f"  {key}: {text}")
    return 0
