"""The demo's output folder: recognising a previous demo output, writing ``summary.json``.

A demo run may overwrite only what a previous demo run wrote there; anything else in the
folder makes it refuse, before any work.
"""

from __future__ import annotations

import json
import os
from importlib import resources
from pathlib import Path
from typing import Any

from surfmet._errors import SurfmetInputError

#: The marker ``summary.json`` carries, by which a previous demo output is recognised.
GENERATOR = "surfmet demo"
SUMMARY = "summary.json"

#: Every figure the demo can write, in the order of the story.
FIGURES = {
    "plate_height_map": "plate_height_map.png",
    "plate_profile": "plate_profile.png",
    "plate_abbott_firestone": "plate_abbott_firestone.png",
    "psd": "psd.png",
    "ball_form": "ball_form.png",
    "hertz_check": "hertz_check.png",
    "contact_pressure": "contact_pressure.png",
    "rolling": "rolling.png",
    "rotor_verdict": "rotor_verdict.png",
    "rotor_law_of_motion": "rotor_law_of_motion.png",
    "rotor_residuals": "rotor_residuals.png",
}


def data_file(name: str) -> Path:
    """Path of a file shipped in ``surfmet/data``."""
    path = Path(str(resources.files("surfmet").joinpath("data", name)))
    if not path.is_file():
        raise SurfmetInputError(f"the shipped data file {name} is missing from {path.parent}; "
                                "reinstall surfmet")
    return path


def _previous_summary(folder: Path) -> dict[str, Any] | None:
    try:
        data = json.loads((folder / SUMMARY).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return data if isinstance(data, dict) and data.get("generator") == GENERATOR else None


def prepare_output(out_dir: str | os.PathLike) -> Path:
    """Create the output folder, or make a previous demo output ready to be overwritten.

    A folder that exists and is not empty is used only if its ``summary.json`` was written
    by the demo; then the files that summary lists are removed first (nothing else is
    touched). The folder is marked at once (a ``summary.json`` saying the run is under
    way), so that a run that fails half-way can be repeated into the same folder.

    Raises
    ------
    SurfmetInputError
        The path is a file, or a non-empty folder that is not a previous demo output.
    """
    folder = Path(out_dir)
    if folder.exists() and not folder.is_dir():
        raise SurfmetInputError(f"{folder} exists and is not a folder; give another --out")
    if folder.is_dir() and any(folder.iterdir()):
        prev = _previous_summary(folder)
        if prev is None:
            raise SurfmetInputError(
                f"{folder} is not empty and does not look like a previous 'surfmet demo' "
                f"output (no {SUMMARY} written by the demo): refusing to write into it. "
                "Give another --out, or empty the folder."
            )
        # remove what the previous run wrote, by the names it recorded (plain names only)
        for name in (prev.get("figures") or {}).values():
            if isinstance(name, str) and name == Path(name).name and name in FIGURES.values():
                (folder / name).unlink(missing_ok=True)
    try:
        folder.mkdir(parents=True, exist_ok=True)
        write_json(folder / SUMMARY, {"generator": GENERATOR, "status": "running"})
    except OSError as exc:
        raise SurfmetInputError(f"--out {folder}: cannot write there "
                                f"({exc.strerror or type(exc).__name__})") from None
    return folder


def record_failure(path: Path, summary: dict[str, Any], exc: BaseException) -> None:
    """Mark the summary at ``path`` failed, with the reason, in place of "running".

    The partial summary (the figures written so far among it, which a rerun into the
    folder removes) is written whole; where the disk refuses that, a minimal record is
    written over the old file's bytes, which needs no new space. Never raises: the
    caller re-raises ``exc``.
    """
    reason = "interrupted" if isinstance(exc, KeyboardInterrupt) else \
        (str(exc) or type(exc).__name__)
    summary = {**summary, "status": "failed", "error": reason}
    try:
        write_json(path, summary)
        return
    except Exception:  # the disk is full, or the summary will not encode
        pass
    short = json.dumps({"generator": GENERATOR, "status": "failed", "error": reason},
                       ensure_ascii=False) + "\n"
    try:
        with open(path, "r+b") as fh:
            fh.write(short.encode("utf-8"))
            fh.truncate()
    except OSError:
        pass


def write_json(path: Path, obj: Any) -> None:
    """Write ``obj`` as JSON to ``path`` whole or not at all (:mod:`surfmet._atomic`)."""
    from surfmet._atomic import write_text
    from surfmet.units import jsonable

    write_text(path, json.dumps(jsonable(obj), indent=2, ensure_ascii=False, allow_nan=False)
               + "\n")

