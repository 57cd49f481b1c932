"""Parameter sweeps of ball-on-plate contact: loads x plates x balls x materials x positions.

:func:`sweep_items` expands the Cartesian product into :class:`SweepItem` rows, each with a
stable key (its parameters, not its place in the list); :func:`run_item` solves one item
as ``surfmet contact`` or ``surfmet hertz-check`` would and returns a flat row of
``name -> (value, unit)``; :func:`run_sweep` runs them through :func:`surfmet._batch.batch_map`
(local processes by default, serial, or a Dask cluster), so that:

* the rows are bitwise those of the serial run (every item is a fresh call of the same
  top-level function with single-threaded BLAS);
* a failed item becomes a row with ``status = "error"`` and its message, and the sweep goes
  on;
* every finished row is appended to the output files and flushed at once
  (:class:`RowWriter`), whole in every file or in none: CSV (a header, then one line per
  row) and JSON Lines (a header record naming the task and the columns' units, then one
  JSON object per row, every dimensional value as ``{"value", "unit"}``; :func:`header`).
  A sweep that stops, whatever the reason, leaves at most a cut last line; ``resume``
  validates the files (:func:`valid_rows`: one that does not start with that header is
  refused, never rewritten), keeps the rows whole in all of them and runs only the
  rest. The outputs are locked while a run writes them. Rows are written in completion
  order and carry their ``index`` in the product.
"""

from __future__ import annotations

import csv
import io
import itertools
import json
import math
import os
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from surfmet._batch import batch_map as batch_map  # re-exported: the parallel map of run_sweep
from surfmet._errors import SurfmetInputError
from surfmet.mechanics.material_spec import material_pair
from surfmet.mechanics.scan_preparation import SPIKES, spike_mode
from surfmet.records._sweep import sweep_row_record

TASKS = ("contact", "hertz-check")

#: Columns of every row, in order, with their units ("" for dimensionless or text).
BASE_COLUMNS: tuple[tuple[str, str], ...] = (
    ("index", ""), ("key", ""), ("task", ""), ("plate", ""), ("ball", ""),
    ("materials", ""), ("load", "N"), ("radius", "m"), ("position_x", "m"),
    ("position_y", "m"), ("spikes", ""), ("status", ""), ("error", ""), ("caveats", ""),
)
#: The solve record (:class:`contact._record.SolveRecord`) of each row.
SOLVE_COLUMNS: tuple[tuple[str, str], ...] = (
    ("solve_iterations", ""), ("solve_residual", ""), ("solve_converged", ""),
    ("solve_edge_contact", ""),
)
RESULT_COLUMNS: dict[str, tuple[tuple[str, str], ...]] = {
    "contact": (
        ("grid", ""), ("pixel", "m"), ("max_pressure", "Pa"), ("contact_radius", "m"),
        ("effective_radius", "m"), ("approach", "m"), ("real_area", "m^2"), ("n_clusters", ""),
        ("plastic_area", "m^2"), ("hertz_p0", "Pa"), ("hertz_a", "m"), ("warnings", ""),
        *SOLVE_COLUMNS,
    ),
    "hertz-check": (
        ("grid", ""), ("pixel", "m"), ("hertz_holds", ""), ("model", ""), ("alpha", ""),
        ("max_pressure", "Pa"), ("effective_radius", "m"), ("approach", "m"),
        ("yielded_fraction", ""), ("hertz_p0", "Pa"), ("hertz_a", "m"),
        *SOLVE_COLUMNS,
    ),
}


@dataclass(frozen=True)
class SweepItem:
    """One contact problem of a sweep (SI units; file paths as given)."""

    index: int
    task: str
    plate: str | None
    ball: str | None
    materials: str
    load: float
    radius: float
    position: tuple[float, float] | None = None
    grid: int | None = None
    hardness: float | None = None
    spikes: str = SPIKES
    #: :func:`surfmet.read` options of the plate and the ball files (units, channel)
    plate_options: tuple[tuple[str, Any], ...] = ()
    ball_options: tuple[tuple[str, Any], ...] = ()

    @property
    def key(self) -> str:
        """Stable identity of the item: its parameters, independent of its index."""
        pos = None if self.position is None else [repr(float(v)) for v in self.position]
        fields = [self.task, self.plate, self.ball, self.materials,
                  repr(float(self.load)), repr(float(self.radius)), pos, self.grid,
                  None if self.hardness is None else repr(float(self.hardness)),
                  self.spikes]
        if self.plate_options or self.ball_options:  # older keys stay as they were
            fields.append([[list(o) for o in self.plate_options],
                           [list(o) for o in self.ball_options]])
        return json.dumps(fields, separators=(",", ":"), default=repr)


def sweep_items(*, task: str, loads: Sequence[float], radius: float,
                plates: Sequence[Any] = (None,), balls: Sequence[Any] = (None,),
                materials: Sequence[str] = ("steel,aluminium",),
                positions: Sequence[tuple[float, float] | None] = (None,),
                grid: int | None = None, hardness: float | None = None,
                spikes: Any = SPIKES, plate_options: dict[str, Any] | None = None,
                ball_options: dict[str, Any] | None = None) -> list[SweepItem]:
    """The Cartesian product plates x balls x materials x positions x loads, in that
    nesting order (loads vary fastest)."""
    if task not in TASKS:
        raise SurfmetInputError(f"task must be one of {', '.join(TASKS)}, got {task!r}")
    loads = [float(v) for v in loads]
    if not loads or not all(math.isfinite(v) and v > 0 for v in loads):
        raise SurfmetInputError("loads must be positive forces in N")
    if not (math.isfinite(radius) and radius > 0):
        raise SurfmetInputError(f"the ball radius must be positive, got {radius!r}")
    if grid is not None and grid < 8:
        raise SurfmetInputError("the grid needs at least 8 cells per side")
    for pair in materials:  # every pair before any work, not item by item
        material_pair(pair)
    spikes = spike_mode(spikes)
    # paths may come as pathlib objects; an item holds them as text (its key is JSON)
    plates = [None if p is None else os.fspath(p) for p in (plates or (None,))]
    balls = [None if b is None else os.fspath(b) for b in (balls or (None,))]
    combos = itertools.product(plates, balls, materials, positions,
                               loads)
    return [SweepItem(index=k, task=task, plate=pl, ball=bl, materials=m, load=w,
                      radius=float(radius), position=pos, grid=grid, hardness=hardness,
                      spikes=spikes, plate_options=tuple(sorted((plate_options or {}).items())),
                      ball_options=tuple(sorted((ball_options or {}).items())))
            for k, (pl, bl, m, pos, w) in enumerate(combos)]


def _base(item: SweepItem) -> dict[str, tuple[Any, str]]:
    px, py = (None, None) if item.position is None else item.position
    return {"index": (item.index, ""), "key": (item.key, ""), "task": (item.task, ""),
            "plate": (item.plate, ""), "ball": (item.ball, ""),
            "materials": (item.materials, ""), "load": (item.load, "N"),
            "radius": (item.radius, "m"), "position_x": (px, "m"), "position_y": (py, "m"),
            "spikes": (item.spikes, "")}


def run_item(item: SweepItem) -> dict[str, tuple[Any, str]]:
    """Solve one item; the row of :data:`BASE_COLUMNS` and the task's result columns.

    Raises whatever the solve raises (:func:`run_sweep` turns it into an error row).
    """
    import surfmet

    row = _base(item)
    plate = surfmet.read(item.plate, **dict(item.plate_options)) if item.plate else None
    ball = surfmet.read(item.ball, **dict(item.ball_options)) if item.ball else None
    row["caveats"] = (_scan_caveats(plate=plate, ball=ball), "")
    if item.task == "hertz-check":
        from surfmet.mechanics.hertz_check import hertz_check
        from surfmet.records._hertz import hertz_check_solve

        chk = hertz_check(plate, radius=item.radius, load=item.load,
                          materials=item.materials, ball=ball, hardness=item.hardness,
                          grid=item.grid, offset=item.position,
                          spikes=item.spikes)
        c, res = chk.comparison, chk.result
        model = chk.hierarchy.verdict if chk.hierarchy is not None else None
        row.update({
            "grid": (int(res.shape[1]), ""), "pixel": (float(res.dx), "m"),
            "hertz_holds": (bool(c.hertz_holds), ""), "model": (model, ""),
            "alpha": (float(c.alpha), ""), "max_pressure": (float(c.pmax), "Pa"),
            "effective_radius": (float(c.effective_radius), "m"),
            "approach": (float(c.approach), "m"),
            "yielded_fraction": (float(c.plastic_fraction), ""),
            "hertz_p0": (float(c.hertz.p0), "Pa"), "hertz_a": (float(c.hertz.a), "m"),
            **_solve_columns(hertz_check_solve(chk)),
        })
    else:
        from surfmet.mechanics.ball_contact import ball_contact

        sol = ball_contact(plate, ball, radius=item.radius, load=item.load,
                           materials=item.materials, hardness=item.hardness, grid=item.grid,
                           offset=item.position, spikes=item.spikes)
        res = sol.result
        row.update({
            "grid": (int(res.shape[1]), ""), "pixel": (float(res.dx), "m"),
            "max_pressure": (float(res.pmax), "Pa"),
            "contact_radius": (float(res.contact_radius), "m"),
            "effective_radius": (float(res.effective_radius), "m"),
            "approach": (float(res.approach), "m"),
            "real_area": (float(res.contact_area), "m^2"),
            "n_clusters": (int(res.n_clusters), ""),
            "plastic_area": (float(res.plastic_area), "m^2"),
            "hertz_p0": (float(res.hertz.p0), "Pa"), "hertz_a": (float(res.hertz.a), "m"),
            "warnings": ("; ".join(sol.warnings), ""),
            **_solve_columns(res.solve),
        })
    row["status"] = ("ok", "")
    row["error"] = (None, "")
    return row


def _scan_caveats(**scans: Any) -> str | None:
    """The units each scan's file does not state (assumed) or the user stated, as the
    command's text and JSON give them (:meth:`surfmet._model.Calibration.caveats`), each
    named by its body; ``; ``-joined as the ``warnings`` column, None when there are none."""
    out = [f"{body}: {c}" for body, scan in scans.items() if scan is not None
           for c in scan.calibration.caveats()]
    return "; ".join(out) or None


def _solve_columns(rec: Any) -> dict[str, tuple[Any, str]]:
    """The row's solve-record columns (:data:`SOLVE_COLUMNS`)."""
    return {"solve_iterations": (int(rec.iterations), ""),
            "solve_residual": (float(rec.residual), ""),
            "solve_converged": (bool(rec.converged), ""),
            "solve_edge_contact": (bool(rec.edge_contact), "")}


def error_row(item: SweepItem, message: str) -> dict[str, tuple[Any, str]]:
    """The row of a failed item: its parameters, ``status = "error"`` and the message
    (less the advice to accept a truncated result, which a sweep cannot)."""
    from contact._record import TRUNCATED_ADVICE

    message = message.replace(TRUNCATED_ADVICE, "")
    row = _base(item)
    row["status"] = ("error", "")
    row["error"] = (message, "")
    return row


def columns(task: str) -> tuple[tuple[str, str], ...]:
    """All columns of a task's rows, with units."""
    return BASE_COLUMNS + RESULT_COLUMNS[task]


class RowWriter:
    """Appends rows to a CSV and/or a JSON Lines file, each row whole or not at all.

    The outputs are locked (:func:`surfmet._atomic.output_lock`: a second run on the same
    file is refused) and opened (created) at construction, so that an unwritable path
    fails before any work. Each row goes to every file in one write per file, flushed to
    disk; a write the disk refuses is undone in every file (they keep exactly the rows
    before it) and raised as one :class:`~surfmet._errors.SurfmetWriteError`.

    With ``resume`` the existing files are validated first (:func:`valid_rows`): a line
    cut short by a stop and anything after it are dropped, and a row that reached only
    one of the two files is dropped from the other, so that both hold the same rows;
    their keys are :attr:`done`. Otherwise the files are started afresh.
    """

    def __init__(self, task: str, csv_path: str | Path | None = None,
                 json_path: str | Path | None = None, *, resume: bool = False) -> None:
        import contextlib

        from surfmet._atomic import output_lock

        self.cols = columns(task)
        self.done: set[str] = set()
        self._paths = {"csv": csv_path, "json": json_path}
        self._files: dict[str, Any] = {}
        self._locks = contextlib.ExitStack()
        _distinct(csv_path, json_path)
        try:
            for path in (csv_path, json_path):
                if path is not None:
                    self._locks.enter_context(output_lock(path))
            if resume:
                self.done = _restore(self.cols, csv_path, json_path)
            for kind, path in self._paths.items():
                if path is None:
                    continue
                keep = resume and Path(path).exists()
                self._files[kind] = open(path, "ab" if keep else "wb", buffering=0)
                if not (keep and Path(path).stat().st_size > 0):
                    _append(self._files[kind], header(kind, self.cols).encode("utf-8"))
        except OSError as exc:
            self.close()
            raise SurfmetInputError(f"cannot write the sweep output: {exc}") from None
        except BaseException:
            self.close()
            raise

    def write(self, row: dict[str, tuple[Any, str]]) -> None:
        """Append one row to every open file and flush it to disk (all or nothing)."""
        from surfmet._errors import SurfmetWriteError
        from surfmet.units import jsonable

        texts = {}
        if "csv" in self._files:
            vals = []
            for name, _ in self.cols:
                v = row.get(name, (None, ""))[0]
                vals.append("" if v is None else (repr(v) if isinstance(v, float) else v))
            texts["csv"] = _csv_line(vals)
        if "json" in self._files:
            texts["json"] = json.dumps(jsonable(sweep_row_record(row)), allow_nan=False) + "\n"
        marks = {kind: self._files[kind].seek(0, os.SEEK_END) for kind in texts}
        try:
            for kind, text in texts.items():
                _append(self._files[kind], text.encode("utf-8"))
        except OSError as exc:
            for kind, pos in marks.items():  # undo the row in every file
                try:
                    self._files[kind].truncate(pos)
                except OSError:
                    continue
            raise SurfmetWriteError(
                f"cannot write row {row.get('index', ('?', ''))[0]} of the sweep to "
                f"{self._paths[kind]}: {exc.strerror or exc}; the files hold every row "
                "before it: free some space and run again with --resume") from None

    def close(self) -> None:
        for f in self._files.values():
            f.close()
        self._files = {}
        self._locks.close()

    def __enter__(self) -> RowWriter:
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()


def _distinct(csv_path: str | Path | None, json_path: str | Path | None) -> None:
    """Refuse one file given for both outputs (by any of its names): the two formats
    would interleave in it, and its lock would seem held by another run."""
    from surfmet._atomic import real_target

    if csv_path is None or json_path is None:
        return
    same = real_target(csv_path) == real_target(json_path)
    if not same and Path(csv_path).exists() and Path(json_path).exists():
        same = os.path.samefile(csv_path, json_path)  # two hard links of one file
    if same:
        raise SurfmetInputError(
            f"--csv {csv_path} and --json {json_path} are the same file: give each "
            "output its own file")


def header(kind: str, cols: Sequence[tuple[str, str]]) -> str:
    """The first line of a sweep's output file, which marks it as a sweep's and names its
    task and columns: the CSV's column names with units in brackets; in JSON Lines one
    record ``{"surfmet_sweep": {"task": ..., "columns": {name: unit}}}`` (``""`` for a
    dimensionless or text column), the rows following it."""
    if kind == "csv":
        return _csv_line([f"{n} [{u}]" if u else n for n, u in cols])
    task = next((t for t in TASKS if columns(t) == tuple(cols)), None)
    return json.dumps({"surfmet_sweep": {"task": task, "columns": dict(cols)}},
                      separators=(", ", ": ")) + "\n"


def _check_header(kind: str, path: str | Path, cols: Sequence[tuple[str, str]],
                  text: str) -> str:
    """The rows' part of an existing output ``text`` (complete lines), after checking
    that it is a sweep's output of this task: empty, or a header cut short by a stop, is a
    fresh file; any other first line is refused, so that ``--resume`` never rewrites a
    file a sweep did not write."""
    head = header(kind, cols)
    if text.startswith(head):
        return text[len(head):]
    raw = Path(path).read_bytes().decode("utf-8", errors="replace")
    if not text and head.startswith(raw):
        return ""
    task = next((t for t in TASKS if columns(t) == tuple(cols)), "this")
    what = "CSV" if kind == "csv" else "JSON Lines"
    raise SurfmetInputError(
        f"{path}: not the {what} output of a {task} sweep (its first line is not the header "
        "such a sweep writes): give another file or leave out --resume")


def _csv_line(values: Sequence[Any]) -> str:
    from surfmet.units import valid_text

    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerow(
        [valid_text(v) if isinstance(v, str) else v for v in values])
    return buf.getvalue()


def _append(fh: Any, data: bytes) -> None:
    """Write ``data`` at the end of an unbuffered file and force it to disk."""
    view = memoryview(data)
    while view:
        view = view[fh.write(view):]
    os.fsync(fh.fileno())


def _complete(path: str | Path | None) -> str | None:
    """A file's text up to its last complete line (None when there is no file)."""
    if path is None or not Path(path).exists():
        return None
    text = Path(path).read_bytes().decode("utf-8", errors="replace")
    return text[:text.rfind("\n") + 1]


def _row_ok(key: Any, status: Any) -> bool:
    return isinstance(key, str) and bool(key) and status in ("ok", "error")


def valid_rows(cols: Sequence[tuple[str, str]], csv_path: str | Path | None = None,
               json_path: str | Path | None = None) -> dict[str, dict[str, str]]:
    """The whole rows of existing output files: ``{"csv": {key: line}, "json": {...}}``
    for each file given that exists, in file order.

    A row is whole when its line is complete (ends with a newline), parses, has every
    column (CSV) or is a JSON object, and has a key and a status; the first row that is
    not, and everything after it, is dropped (what a stop or a full disk leaves). A
    repeated key keeps its first row.

    Raises
    ------
    SurfmetInputError
        A file that is not a sweep's output of these columns (:func:`header`).
    """
    out: dict[str, dict[str, str]] = {}
    text = _complete(csv_path)
    if text is not None:
        rows: dict[str, str] = {}
        reader = csv.reader(io.StringIO(_check_header("csv", csv_path, cols, text)))
        names = [n for n, _ in cols]
        key, status = names.index("key"), names.index("status")
        try:
            for rec in reader:
                if len(rec) != len(cols) or not _row_ok(rec[key], rec[status]):
                    break
                rows.setdefault(rec[key], _csv_line(rec))
        except csv.Error:
            pass  # a quoted field cut short: the rows before it stand
        out["csv"] = rows
    text = _complete(json_path)
    if text is not None:
        rows = {}
        for line in _check_header("json", json_path, cols, text).splitlines():
            try:
                rec = json.loads(line)
            except ValueError:
                break
            if not (isinstance(rec, dict) and _row_ok(rec.get("key"), rec.get("status"))):
                break
            rows.setdefault(rec["key"], line + "\n")
        out["json"] = rows
    return out


def _restore(cols: Sequence[tuple[str, str]], csv_path: str | Path | None,
             json_path: str | Path | None) -> set[str]:
    """Rewrite the existing outputs (atomically) with only the rows whole in all of them;
    their keys."""
    from surfmet._atomic import write_text

    found = valid_rows(cols, csv_path, json_path)
    paths = {"csv": csv_path, "json": json_path}
    given = [k for k, p in paths.items() if p is not None]
    done = set.intersection(*(set(found.get(k, {})) for k in given)) if given else set()
    for kind, rows in found.items():
        text = header(kind, cols) + "".join(line for key, line in rows.items() if key in done)
        if Path(paths[kind]).read_text(encoding="utf-8", errors="replace") != text:
            write_text(paths[kind], text)
    return done


def run_sweep(items: Iterable[SweepItem], *, workers: int | None = None,
              scheduler: Any = None, writer: RowWriter | None = None,
              skip: set[str] | None = None, progress: bool | None = None,
              on_row: Callable[[dict[str, tuple[Any, str]]], Any] | None = None,
              ) -> list[dict[str, tuple[Any, str]]]:
    """Run the items (minus those whose key is in ``skip``); rows in the items' order.

    Each finished row goes to ``writer`` (and ``on_row``) as soon as it arrives.
    """
    todo = [it for it in items if not skip or it.key not in skip]

    def arrived(k: int, row: dict[str, tuple[Any, str]]) -> None:
        if writer is not None:
            writer.write(row)
        if on_row is not None:
            on_row(row)

    return batch_map(run_item, todo, workers=workers, scheduler=scheduler,
                     on_error=error_row, progress=progress, desc="sweep",
                     on_result=arrived)
