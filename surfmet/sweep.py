"""Parameter sweeps of ball-on-plate contact: loads x plates x balls x materials x positions.

:func:`sweep_items` expands the Cartesian product into :class:`SweepItem` rows, each with a
stable key (its parameters, not its place in the list); :func:`run_item` solves one item
as ``surfmet contact`` or ``surfmet hertz-check`` would and returns a flat row of
``name -> (value, unit)``; :func:`run_sweep` runs them through :func:`surfmet.batch.batch_map`
(local processes by default, serial, or a Dask cluster), so that:

* the rows are bitwise those of the serial run (every item is a fresh call of the same
  top-level function with single-threaded BLAS);
* a failed item becomes a row with ``status = "error"`` and its message, and the sweep goes
  on;
* every finished row is appended to the output files and flushed at once
  (:class:`RowWriter`): CSV (a header, then one line per row) and JSON Lines (one JSON
  object per line, every dimensional value as ``{"value", "unit"}``). A sweep that stops,
  whatever the reason, leaves files whose every complete line is a valid row; ``resume``
  reads the keys already written and runs only the rest. Rows are written in completion
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

from surfmet.errors import SurfmetInputError
from surfmet.mechanics.scan_preparation import SPIKES, spike_mode

TASKS = ("contact", "hertz-check")

#: Columns of every row, in order, with their units ("" for dimensionless or text).
BASE_COLUMNS: tuple[tuple[str, str], ...] = (
    ("index", ""), ("key", ""), ("task", ""), ("plate", ""), ("ball", ""),
    ("materials", ""), ("load", "N"), ("radius", "m"), ("position_x", "m"),
    ("position_y", "m"), ("spikes", ""), ("status", ""), ("error", ""),
)
RESULT_COLUMNS: dict[str, tuple[tuple[str, str], ...]] = {
    "contact": (
        ("grid", ""), ("pixel", "m"), ("max_pressure", "Pa"), ("contact_radius", "m"),
        ("effective_radius", "m"), ("approach", "m"), ("real_area", "m^2"), ("n_clusters", ""),
        ("plastic_area", "m^2"), ("hertz_p0", "Pa"), ("hertz_a", "m"), ("warnings", ""),
    ),
    "hertz-check": (
        ("grid", ""), ("pixel", "m"), ("hertz_holds", ""), ("model", ""), ("alpha", ""),
        ("max_pressure", "Pa"), ("effective_radius", "m"), ("approach", "m"),
        ("yielded_fraction", ""), ("hertz_p0", "Pa"), ("hertz_a", "m"),
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

    @property
    def key(self) -> str:
        """Stable identity of the item: its parameters, independent of its index."""
        pos = None if self.position is None else [repr(float(v)) for v in self.position]
        return json.dumps([self.task, self.plate, self.ball, self.materials,
                           repr(float(self.load)), repr(float(self.radius)), pos, self.grid,
                           None if self.hardness is None else repr(float(self.hardness)),
                           self.spikes],
                          separators=(",", ":"))


def sweep_items(*, task: str, loads: Sequence[float], radius: float,
                plates: Sequence[Any] = (None,), balls: Sequence[Any] = (None,),
                materials: Sequence[str] = ("steel,aluminium",),
                positions: Sequence[tuple[float, float] | None] = (None,),
                grid: int | None = None, hardness: float | None = None,
                spikes: Any = SPIKES) -> list[SweepItem]:
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
    spikes = spike_mode(spikes)
    # paths may come as pathlib objects; an item holds them as text (its key is JSON)
    plates = [None if p is None else os.fspath(p) for p in (plates or (None,))]
    balls = [None if b is None else os.fspath(b) for b in (balls or (None,))]
    combos = itertools.product(plates, balls, materials, positions,
                               loads)
    return [SweepItem(index=k, task=task, plate=pl, ball=bl, materials=m, load=w,
                      radius=float(radius), position=pos, grid=grid, hardness=hardness,
                      spikes=spikes)
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
    plate = surfmet.read(item.plate) if item.plate else None
    ball = surfmet.read(item.ball) if item.ball else None
    if item.task == "hertz-check":
        from surfmet.mechanics.hertz_check import hertz_check

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
        })
    row["status"] = ("ok", "")
    row["error"] = (None, "")
    return row


def error_row(item: SweepItem, message: str) -> dict[str, tuple[Any, str]]:
    """The row of a failed item: its parameters, ``status = "error"`` and the message."""
    row = _base(item)
    row["status"] = ("error", "")
    row["error"] = (message, "")
    return row


def columns(task: str) -> tuple[tuple[str, str], ...]:
    """All columns of a task's rows, with units."""
    return BASE_COLUMNS + RESULT_COLUMNS[task]


def json_row(row: dict[str, tuple[Any, str]]) -> dict[str, Any]:
    """A row as JSON: every value with a unit as ``{"value", "unit"}``, others plain."""
    return {name: ({"value": v, "unit": u} if u else v) for name, (v, u) in row.items()}


class RowWriter:
    """Appends rows to a CSV and/or a JSON Lines file, one flushed line per row.

    The files are opened (and created) at construction, so that an unwritable path fails
    before any work. With ``resume`` an existing file is appended to (its header kept);
    otherwise it is started afresh.
    """

    def __init__(self, task: str, csv_path: str | Path | None = None,
                 json_path: str | Path | None = None, *, resume: bool = False) -> None:
        self.cols = columns(task)
        self._files: list[Any] = []
        self._csv = self._json = None
        try:
            if csv_path is not None:
                fresh = not (resume and Path(csv_path).exists()
                             and Path(csv_path).stat().st_size > 0)
                self._csv = open(csv_path, "w" if fresh else "a", newline="",
                                 encoding="utf-8")
                self._files.append(self._csv)
                if fresh:
                    self._write_csv_line([f"{n} [{u}]" if u else n for n, u in self.cols])
            if json_path is not None:
                self._json = open(json_path, "a" if resume else "w",
                                  encoding="utf-8")
                self._files.append(self._json)
        except OSError as exc:
            self.close()
            raise SurfmetInputError(f"cannot write the sweep output: {exc}") from None

    def _write_csv_line(self, values: Sequence[Any]) -> None:
        buf = io.StringIO()
        csv.writer(buf, lineterminator="\n").writerow(values)
        # one write call per row: a stop between rows never leaves half a line behind
        self._csv.write(buf.getvalue())
        self._csv.flush()
        os.fsync(self._csv.fileno())

    def write(self, row: dict[str, tuple[Any, str]]) -> None:
        """Append one row to every open file and flush it to disk."""
        if self._csv is not None:
            vals = []
            for name, _ in self.cols:
                v = row.get(name, (None, ""))[0]
                vals.append("" if v is None else (repr(v) if isinstance(v, float) else v))
            self._write_csv_line(vals)
        if self._json is not None:
            self._json.write(json.dumps(json_row(row), allow_nan=False,
                                        default=str) + "\n")
            self._json.flush()
            os.fsync(self._json.fileno())

    def close(self) -> None:
        for f in self._files:
            f.close()
        self._files = []

    def __enter__(self) -> RowWriter:
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()


def done_keys(csv_path: str | Path | None = None,
              json_path: str | Path | None = None) -> set[str]:
    """Keys of the rows already written (ok or error) in existing output files; a last line
    cut short by a stop is ignored."""
    keys: set[str] = set()
    if json_path is not None and Path(json_path).exists():
        for line in Path(json_path).read_text(encoding="utf-8").splitlines():
            try:
                keys.add(json.loads(line)["key"])
            except (ValueError, KeyError, TypeError):
                continue
    if csv_path is not None and Path(csv_path).exists():
        with open(csv_path, newline="", encoding="utf-8") as fh:
            for rec in csv.DictReader(fh):
                if rec.get("key") and rec.get("status") in ("ok", "error"):
                    keys.add(rec["key"])
    return keys


def run_sweep(items: Iterable[SweepItem], *, workers: int | None = None,
              scheduler: Any = None, writer: RowWriter | None = None,
              skip: set[str] | None = None, progress: bool | None = None,
              on_row: Callable[[dict[str, tuple[Any, str]]], Any] | None = None,
              ) -> list[dict[str, tuple[Any, str]]]:
    """Run the items (minus those whose key is in ``skip``); rows in the items' order.

    Each finished row goes to ``writer`` (and ``on_row``) as soon as it arrives.
    """
    from surfmet.batch import batch_map

    todo = [it for it in items if not skip or it.key not in skip]

    def arrived(k: int, row: dict[str, tuple[Any, str]]) -> None:
        if writer is not None:
            writer.write(row)
        if on_row is not None:
            on_row(row)

    return batch_map(run_item, todo, workers=workers, scheduler=scheduler,
                     on_error=error_row, progress=progress, desc="sweep",
                     on_result=arrived)
