"""Running the demo: the seven steps in order, each reported on stderr and timed, their
records gathered in ``summary.json`` and their figures written to the output folder."""

from __future__ import annotations

import os
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from rotor import HERTZ_CHECK_LOAD
from surfmet.demo import _figures as fig
from surfmet.demo._lawofmotion import rotor_step
from surfmet.demo._mechanics import contact_step, hertz_step, rolling_step, rotor_loads
from surfmet.demo._outputs import (
    GENERATOR,
    SUMMARY,
    prepare_output,
    record_failure,
    write_json,
)
from surfmet.demo._settings import BALL_LEVEL, PAPER_TABLE2_MEAN, PLATE_LEVEL
from surfmet.demo._surfaces import ball_form, load_scans, plate_areal, row_statistics
from surfmet.records._demo import loads_record, seconds, table2_record

STEPS = 7


class _Steps:
    """Numbered, timed steps reported through ``say``; the figures written so far."""

    def __init__(self, out: Path, say: Callable[[str], None]) -> None:
        self.out, self.say = out, say
        self.n, self.name, self.t = 0, "", time.perf_counter()
        self.t_start = self.t
        self.timings: dict[str, Any] = {}
        self.figures: dict[str, str] = {}

    def start(self, name: str, text: str) -> None:
        self.n += 1
        self.name, self.t = name, time.perf_counter()
        self.say(f"step {self.n}/{STEPS}: {text} ...")

    def done(self) -> None:
        dt = time.perf_counter() - self.t
        self.timings[self.name] = seconds(dt)
        self.say(f"  done in {dt:.1f} s")

    def figure(self, key: str, draw: Callable[[Path], Any]) -> None:
        fig.write_figure(self.out, key, draw, self.figures)


def _sayer(progress: bool | Callable[[str], None]) -> Callable[[str], None]:
    if callable(progress):
        return progress
    if progress:
        return lambda line: print(line, file=sys.stderr, flush=True)
    return lambda line: None


def _surfaces(st: _Steps, summary: dict[str, Any], quick: bool) -> tuple[Any, Any]:
    st.start("read", "reading the shipped plate and ball scans (x3p)")
    plate, ball, summary["scans"] = load_scans()
    st.done()

    st.start("roughness", "roughness of every row of both scans, and the plate's areal "
             "parameters")
    rough: dict[str, Any] = {}
    rough["plate_rows"], typical = row_statistics(plate, PLATE_LEVEL)
    rough["ball_rows"], _ = row_statistics(ball, BALL_LEVEL)
    rough["paper_table2_mean"] = table2_record(PAPER_TABLE2_MEAN)
    rough["plate_areal"], clean = plate_areal(plate)
    summary["roughness"] = rough
    st.figure("plate_height_map", lambda p: fig.height_map(
        clean.surface, p, "aluminium plate (stand-in): levelled, spikes removed"))
    row = rough["plate_rows"]["typical_row"]
    st.figure("plate_profile", lambda p: fig.profile(
        typical.analysis, p, f"plate row {row} (Ra nearest the median of all rows)"))
    if not quick:
        st.figure("plate_abbott_firestone", lambda p: fig.abbott(clean, p))
    st.done()

    st.start("ball", "the ball's radius (sphere fit) and form deviation")
    summary["ball"], residual = ball_form(ball)
    st.figure("ball_form", lambda p: fig.height_map(
        residual, p, f"ball minus its best-fit sphere (R = "
        f"{summary['ball']['sphere']['radius']['value'] * 1e3:.3f} mm)"))
    if not quick:
        st.figure("psd", lambda p: fig.psd(clean.surface, residual, p))
    st.done()
    return plate, ball


def _mechanics(st: _Steps, summary: dict[str, Any], plate: Any, ball: Any) -> None:
    st.start("hertz", f"Hertz check at {HERTZ_CHECK_LOAD:g} N (boundary elements on both scans)")
    summary["hertz_check"], check = hertz_step(plate, ball)
    st.figure("hertz_check", check.figure)
    st.done()

    loads = rotor_loads()
    st.start("contact", f"contact at the rotor's load per ball, {loads['symmetric']:.2f} N "
             "(elastic-perfectly-plastic)")
    rec, res = contact_step(check, loads["symmetric"])
    rec["rotor_loads"] = loads_record(loads)
    summary["contact"] = rec
    st.figure("contact_pressure", lambda p: fig.pressure(res, p))
    st.done()

    st.start("rolling", "rolling-resistance sweep, 5 loads from 1 N to 100 N")
    summary["rolling"], rep = rolling_step(plate, ball, "1N:100N:5")
    st.figure("rolling", rep.figure)
    st.done()


def _rotor(st: _Steps, summary: dict[str, Any], quick: bool) -> None:
    st.start("rotor", "law of motion of the rotor (the paper's Table 3)"
             + (": its verdict and the paper's parabolas (--quick)" if quick else ""))
    summary["rotor"], an = rotor_step(quick=quick)
    from surfmet.mechanics.rotor_verdict import paper_verdict, verdict_figure
    from surfmet.records._rotor_verdict import verdict_record

    summary["verdict"] = verdict_record(paper_verdict())
    st.figure("rotor_verdict", lambda p: verdict_figure(paper_verdict(), p))
    if an is not None:
        st.figure("rotor_law_of_motion", lambda p: fig.law_of_motion(an, p))
        st.figure("rotor_residuals", lambda p: fig.residuals(an, p))
    st.done()


def run_demo(
    out_dir: str | os.PathLike = "surfmet_demo",
    *,
    quick: bool = False,
    progress: bool | Callable[[str], None] = True,
) -> dict[str, Any]:
    """Run the demo and write its figures and ``summary.json`` to ``out_dir``.

    Parameters
    ----------
    out_dir : path
        Output folder: created if absent; a non-empty folder must be a previous demo
        output (see :func:`surfmet.demo._outputs.prepare_output`).
    quick : bool
        Leave out the per-test law-of-motion models of Table 3 (most of the run's time;
        :data:`surfmet.demo._lawofmotion.QUICK_LEAVES_OUT`), their two figures and the PSD
        and Abbott–Firestone figures. Every number the quick story prints is the full
        run's, computed the same way (the verdict, the paper's parabolas and the rolling
        sweep included).
    progress : bool or callable
        Report each step on stderr (True), not at all (False), or to ``progress(line)``.

    Returns
    -------
    dict
        The summary, as written to ``summary.json``.
    """
    import surfmet
    from surfmet.units import jsonable

    out = prepare_output(out_dir)
    st = _Steps(out, _sayer(progress))
    summary: dict[str, Any] = {"generator": GENERATOR, "surfmet_version": surfmet.__version__,
                               "status": "running", "quick": bool(quick)}
    try:
        plate, ball = _surfaces(st, summary, quick)
        _mechanics(st, summary, plate, ball)
        _rotor(st, summary, quick)
    except BaseException as exc:  # a full disk, an error, a Ctrl-C: not left "running"
        summary.update(figures=st.figures, timings=st.timings, out_dir=str(out))
        record_failure(out / SUMMARY, summary, exc)
        raise

    total = time.perf_counter() - st.t_start
    summary["figures"] = st.figures
    summary["timings"] = st.timings
    summary["total_time"] = seconds(total)
    summary["out_dir"] = str(out)
    summary["status"] = "complete"
    write_json(out / SUMMARY, summary)
    st.say(f"figures and {SUMMARY} written to {out} ({time.perf_counter() - st.t_start:.0f} s)")
    return jsonable(summary)
