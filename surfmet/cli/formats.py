"""``surfmet formats``: the registered readers and writers."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.cli._common import add_json_flag, emit_json


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "formats",
        help="list the file formats surfmet reads and writes",
        epilog="example:\n  surfmet formats --json",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_json_flag(p)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    from surfmet.io import formats

    specs = sorted(formats().values(), key=lambda s: s.name)
    if args.json:
        emit_json([
            {"name": s.name, "extensions": list(s.extensions), "description": s.description,
             "read": s.decode is not None, "write": s.encode is not None}
            for s in specs
        ])
        return 0
    for s in specs:
        rw = ("r" if s.decode else "-") + ("w" if s.encode else "-")
        print(f"{s.name:<12} {rw}  {','.join(s.extensions):<16} {s.description}")
    return 0
