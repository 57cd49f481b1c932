"""``surfmet sweep``: contact or hertz-check over loads x plates x balls x materials x positions."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.cli._common import (
    add_quiet_flag,
    add_spikes_argument,
    log,
    positive_length,
    pressure,
    show_progress,
)
from surfmet.cli._scan_options import add_scan_options, files_caveats, read_options
from surfmet.cli._values import VALUES_METAVAR, loads, positions, values_help

EPILOG = """examples:
  surfmet sweep --task hertz-check --plates plate.x3p --balls ball.x3p --radius 20mm \\
      --loads 1N:100N:5 --materials steel,aluminium --csv sweep.csv
  surfmet sweep --task contact --plates a.x3p b.x3p --radius 20mm --loads 5N,10N \\
      --materials steel,aluminium --materials steel,copper --positions 0:0,0.2mm:0 \\
      --json sweep.jsonl --workers 2
  surfmet sweep ... --scheduler tcp://10.0.0.5:8786 --csv sweep.csv
  surfmet sweep ... --csv sweep.csv --resume      # after a stop: run only the rest

Every item is a fresh solve with single-threaded BLAS, so the rows are bitwise those of
the serial run whatever the engine (--workers 1, local processes, or Dask). A failed item
gets its own row (status error, with the message) and the sweep goes on. Rows are
appended and flushed as they finish: CSV with units in the headers, and JSON Lines (a
first record {"surfmet_sweep": {"task", "columns": {name: unit}}}, then one object per
row, values as {"value", "unit"}), each row whole in every file or in none.
--resume first checks the files: one that does not start with a sweep's header is
refused and left as it is; a row cut short by a stop (or a full disk) is dropped,
and so is a row that reached only one of --csv and --json; then it runs every item
whose row is not in all of them. Two runs never write one file at once (a lock, taken
on the file itself, whichever name or link reaches it).
--positions are apex offsets x:y from the middle of the scans.
"""


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "sweep",
        help="contact or hertz-check over loads x scans x materials x track positions",
        description="Run many ball-on-plate contact problems in parallel (local processes "
        "or Dask), one row per item, written as each finishes.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--task", choices=("contact", "hertz-check"), default="contact")
    p.add_argument("--plates", nargs="+", metavar="FILE", default=None,
                   help="plate scans (default: a smooth plate)")
    p.add_argument("--balls", nargs="+", metavar="FILE", default=None,
                   help="ball scans (default: a smooth ball)")
    p.add_argument("--radius", type=positive_length, required=True, metavar="L")
    p.add_argument("--loads", type=loads, required=True, metavar=VALUES_METAVAR,
                   help=values_help("loads", "5N,10N"))
    p.add_argument("--materials", action="append", metavar="BALL,PLATE",
                   help="a material pair; repeat for several (default steel,aluminium)")
    p.add_argument("--positions", type=positions, default=None, metavar="X:Y,...",
                   help="apex offsets from the middle of the scans (default the middle)")
    p.add_argument("--hardness", type=pressure, default=None, metavar="P",
                   help="cap the pressure (contact) / the flow pressure (hertz-check)")
    p.add_argument("--grid", type=int, default=None, metavar="N",
                   help="cells per side (default: the scans' own pixel)")
    add_scan_options(p, ("plate", "ball"))
    add_spikes_argument(p)
    p.add_argument("--workers", type=int, default=None, metavar="N",
                   help="local processes (default: one per CPU; 1 = serial)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="run on a Dask distributed cluster, e.g. tcp://host:8786")
    p.add_argument("--csv", default=None, metavar="OUT.csv", help="rows as CSV")
    add_quiet_flag(p)
    p.add_argument("--json", nargs="?", const="-", default=None, metavar="OUT.jsonl",
                   help="rows as JSON Lines in OUT.jsonl, written as they finish; without "
                   "OUT, one JSON document with all rows on stdout at the end")
    p.add_argument("--resume", action="store_true",
                   help="skip the items already in --csv/--json and append the rest")
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    from surfmet._errors import SurfmetInputError
    from surfmet.sweep import RowWriter, run_sweep, sweep_items

    if args.csv is None and args.json is None:
        raise SurfmetInputError("give --csv OUT and/or --json [OUT] for the rows")
    to_stdout = args.json == "-"
    json_path = None if to_stdout else args.json
    if to_stdout and args.resume:
        raise SurfmetInputError("--resume needs the rows in a file: --json OUT or --csv OUT")
    if args.workers is not None and args.workers < 1:
        raise SurfmetInputError("--workers must be at least 1")
    if args.scheduler is not None:
        from surfmet._batch import check_scheduler

        check_scheduler(args.scheduler)  # before the files are touched
    items = sweep_items(task=args.task, loads=args.loads, radius=args.radius,
                        plates=args.plates or [None], balls=args.balls or [None],
                        materials=args.materials or ["steel,aluminium"],
                        positions=args.positions or [None], grid=args.grid,
                        hardness=args.hardness, spikes=args.spikes,
                        plate_options=read_options(args, "plate"),
                        ball_options=read_options(args, "ball"))
    # each file read once here: a unit it contradicts is refused before any solve
    caveats = files_caveats(args, {"plate": args.plates, "ball": args.balls})
    with RowWriter(args.task, args.csv, json_path, resume=args.resume) as writer:
        skip = writer.done
        todo = sum(1 for it in items if it.key not in skip)
        if skip:
            log(f"resume: {len(items) - todo} of {len(items)} items already written")
        rows = run_sweep(items, workers=args.workers, scheduler=args.scheduler,
                         writer=writer, skip=skip, progress=show_progress(args))
    failed = [r for r in rows if r["status"][0] == "error"]
    if to_stdout:
        from surfmet.cli._common import emit_json
        from surfmet.records._sweep import sweep_row_record

        emit_json({"task": args.task, "rows": [sweep_row_record(r) for r in rows],
                   "caveats": caveats})
    log(f"{len(rows)} items run, {len(failed)} failed"
        + (f" (first: {failed[0]['error'][0]})" if failed else ""))
    return 1 if failed else 0
