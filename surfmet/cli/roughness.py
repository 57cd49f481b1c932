"""``surfmet roughness FILE...``: ISO 25178-2 S-parameters or ISO 21920-2 R-parameters."""

from __future__ import annotations

import argparse
import contextlib
import csv
import sys
from typing import Any

from surfmet.cli._common import add_json_flag, check_output, emit_json, log
from surfmet.cli._roughness_options import add_roughness_options, positive_int
from surfmet.cli._roughness_options import roughness_options as _options
from surfmet.cli._scan_options import add_scan_options, read_options, read_scan

EPILOG = """examples:
  surfmet roughness plate.x3p
  surfmet roughness plate.x3p --level plane --json
  surfmet roughness plate.x3p --lc 0.8mm --ls 25um --spikes
  surfmet roughness ball.nms --level sphere
  surfmet roughness plate.x3p --profile row:100 --lc 0.25mm
  surfmet roughness trace.csv --standard iso4287 --lc 2.5mm --n-sampling 4
  surfmet roughness r_profile.csv --lc none --standard iso4287
  surfmet roughness scans/*.x3p --csv table.csv
  surfmet roughness scans/*.x3p --workers 8 --json > table.json
  surfmet roughness scans/*.x3p --scheduler tcp://10.0.0.5:8786 --csv table.csv

Without --ls/--lc an areal scan is evaluated after the form removal only (the S-F
surface); with them, the band of half a nesting index along each border, where the
filter's weights run past the scan, is left out (--edge). A profile gets the λc, λs,
number of sampling lengths and standard its file states (an instrument's export), else an
automatic ISO 4288 cut-off, 5 sampling lengths and ISO 21920-2. --standard iso4287 averages
every per-sampling-length parameter over the sampling lengths as ISO 4287:1997 (and most
instruments' printouts) do; --lc none evaluates an already filtered profile as it is.
Every output states the standard, λc, λs and the number of sampling lengths used, and why.
--spikes removes spikes (reported) before levelling; every result carries an Sq/Sa spike
diagnosis.

Several files run in parallel over local processes (--workers, default: one per CPU), or
on a Dask distributed cluster (--scheduler; the workers must see the same paths). A file
that fails gets an error row and the others go on; the exit status is then 1.
"""


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "roughness",
        help="areal (S) or profile (R) roughness parameters of scan files",
        description="Roughness parameters with the form removal, filters, cut-offs and "
        "spike handling used stated in the output.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("files", nargs="+", metavar="FILE", help="scan file(s)")
    add_scan_options(p)
    add_roughness_options(p, group=False)
    p.add_argument("--workers", type=positive_int, default=None, metavar="N",
                   help="local processes for several files (default: one per CPU; 1 = serial)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="run several files on a Dask distributed cluster, e.g. "
                   "tcp://host:8786 (the workers must see the same paths)")
    out = p.add_mutually_exclusive_group()
    add_json_flag(out)
    out.add_argument("--csv", metavar="OUT", default=None,
                     help="write one row per file to OUT ('-' for stdout)")
    p.set_defaults(func=run)
    return p


def _display(value: Any, unit: str) -> str:
    from surfmet.units import format_quantity

    return format_quantity(value, unit, digits=5)


def _print_table(rec: dict[str, Any]) -> None:
    print(f"file  {rec['file']}")
    s = rec["settings"]
    filters = ", ".join(f"{f['kind']}-filter {_display(f['nesting_index']['value'], 'm')} "
                        f"({f['edge']})" for f in s.get("filters", []) or [])
    kind = s.get("kind", "") + (f" ({s['profile_kind']})" if s.get("profile_kind") else "")
    print(f"  kind {kind}, level {s.get('level')}"
          + (f", {filters}" if filters else ""))
    if s.get("edge"):
        print(f"  filter edges ({s['edge']['value']}): {s['edge']['meaning']}")
    cond = s.get("conditions")
    if cond:
        print("  " + _conditions_line(cond))
        if cond["lc"].get("note"):
            print(f"  note: {cond['lc']['note']}")
    elif s.get("standard"):
        print(f"  standard {s['standard']}")
    for sym, q in rec["parameters"].items():
        print(f"  {sym:<6} {_display(q['value'], q['unit'])}")
    sp = s.get("spikes", {})
    if sp.get("removed"):
        print(f"  spikes removed: {sp['count']} ({sp['n_points']} points, "
              f"{100 * sp['fraction']:.3g} %)")
    diag = s.get("spike_diagnosis")
    if diag:
        print(f"  diagnosis: {diag['message']}")
    for note in s.get("notes", []) or []:
        print(f"  note: {note}")
    for caveat in s.get("caveats", []) or []:
        print(f"  CAVEAT: {caveat}")


def _conditions_line(cond: dict[str, Any]) -> str:
    from surfmet._profile_roughness import FROM_DEFAULT_PEAK
    from surfmet.units import format_length

    def length(block: dict[str, Any]) -> str:
        v = block.get("value")
        text = "none" if v is None else format_length(v)
        if block.get("applied") is False:
            text += " (already applied)"
        return f"{text} ({block['why']})"

    std = cond["standard"]
    n = cond["n_sampling"]
    rk = cond.get("rk_line")
    el = cond.get("element_start")
    return (f"standard {std['name']} ({std['why']}); λc {length(cond['lc'])}; "
            f"λs {length(cond['ls'])}; {n['value']} sampling lengths ({n['why']})"
            + (f"; Rk construction {rk['value']} ({rk['why']})" if rk else "")
            + (f"; profile elements paired {el['value']} ({el['why']})"
               if el and (el["value"] != "peak" or el["why"] != FROM_DEFAULT_PEAK) else ""))


def _condition_cells(rec: dict[str, Any]) -> list[str]:
    cond = rec.get("settings", {}).get("conditions")
    if not cond:
        std = rec.get("settings", {}).get("standard", "")
        return [std, "", "", "", ""]

    def num(v: Any) -> str:
        return "" if v is None else repr(float(v))

    why = "; ".join(f"{k}: {cond[k]['why']}" for k in ("standard", "lc", "ls", "n_sampling"))
    return [cond["standard"]["value"], num(cond["lc"]["value"]), num(cond["ls"]["value"]),
            str(cond["n_sampling"]["value"]), why]


def record_caveats(rec: dict[str, Any]) -> list[str]:
    """A record's caveats for its CSV row: the result's own, and the spike diagnosis when it
    suspects spikes (the text's warning that a few heights dominate Sq and Sz)."""
    s = rec.get("settings", {})
    out = list(s.get("caveats", []) or [])
    diag = s.get("spike_diagnosis") or {}
    if diag.get("suspected") and diag.get("message"):
        out.append(diag["message"])
    return out


def _write_csv(records: list[dict[str, Any]], out: str) -> None:
    symbols: list[str] = []
    units: dict[str, str] = {}
    for rec in records:
        for sym, q in rec.get("parameters", {}).items():
            if sym not in units:
                symbols.append(sym)
                units[sym] = q["unit"]
    from surfmet._atomic import atomic_open
    from surfmet.units import csv_column, valid_text

    cols = (["file", "status", "error", "standard", csv_column("lc", "m"), csv_column("ls", "m"),
             "n_sampling", "conditions", "caveats"] + [csv_column(s, units[s]) for s in symbols])

    with (contextlib.nullcontext(sys.stdout) if out == "-"
          else atomic_open(out, "w", newline="", encoding="utf-8")) as fh:
        w = csv.writer(fh)
        w.writerow(cols)
        for rec in records:
            params = rec.get("parameters", {})
            row = [valid_text(rec["file"]), rec["status"], valid_text(rec.get("error", "")),
                   *_condition_cells(rec),
                   " | ".join(record_caveats(rec))]
            for sym in symbols:
                v = params.get(sym, {}).get("value")
                row.append("" if v is None else repr(float(v)))
            w.writerow(row)


def run(args: argparse.Namespace) -> int:
    from functools import partial

    from surfmet._batch import batch_map
    from surfmet._measurements import Measurement, expand_measurements, read_measurement
    from surfmet.roughness import roughness, roughness_file

    check_output(args.csv if args.csv != "-" else None, "--csv")
    opts = _options(args)
    # a container holds several measurements: each is evaluated and gets its record
    items = expand_measurements(args.files)
    if len(items) == 1 and not args.csv:
        # One file: errors propagate, so the CLI prints one line and exits 1.
        item = items[0]
        scan = (read_measurement(item, **read_options(args))
                if isinstance(item, Measurement) else read_scan(item, args))
        res = roughness(scan, **opts)
        from surfmet.records._roughness import roughness_record

        rec = {"file": str(item), "status": "ok", **roughness_record(res)}
        if args.json:
            emit_json([rec])  # one shape whatever the number of files: a list of records
        else:
            _print_table(rec)
        return 0
    # roughness_file returns error rows itself; batch_map adds rows for dead workers
    records = batch_map(partial(roughness_file, read_options=read_options(args), **opts),
                        items, workers=args.workers,
                        scheduler=args.scheduler, desc="roughness")
    failed = [r for r in records if r["status"] != "ok"]
    for r in failed:
        msg = r["error"]
        log(f"surfmet: error: {msg if msg.startswith(r['file']) else r['file'] + ': ' + msg}")
    if args.csv:
        _write_csv(records, args.csv)
    elif args.json:
        emit_json(records)
    else:
        for rec in records:
            if rec["status"] == "ok":
                _print_table(rec)
    return 1 if failed else 0
