"""The rotor verdict (:mod:`rotor._verdict`) as every entry point shows it: computed
once per table, printed first by ``surfmet rotor``, carried by ``surfmet rolling --model
all``, the demo and the report, in the same words and numbers.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Mapping, Sequence
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING

from surfmet._errors import SurfmetInputError
from surfmet._frames import read_frames_table

if TYPE_CHECKING:
    from rotor import LawOfMotionAnalysis, Rig, RotorVerdict
    from surfmet.mechanics.rotor_rough_bound import RoughArmBound

__all__ = ["column_groups", "judge", "label_swap_text", "load_rig", "paper_verdict",
           "read_frames_table", "shared_track_p_text", "table_verdict", "verdict_figure",
           "verdict_lines", "verdict_plot_path"]


def load_rig(path: str | Path) -> Rig:
    """A :class:`rotor.Rig` from a rig JSON file (one line on any error).

    Parameters
    ----------
    path : str or Path
        The rig JSON file (the rotor's geometry, its groups and the plate).

    Returns
    -------
    rotor.Rig
        The rig.

    Raises
    ------
    SurfmetInputError
        No such file, not JSON, or a rig the engine refuses.

    See Also
    --------
    table_verdict : takes ``rig_path``.

    Examples
    --------
    >>> from surfmet.mechanics.rotor_verdict import load_rig
    >>> load_rig("no-such-rig.json")
    Traceback (most recent call last):
    ...
    surfmet._errors.SurfmetInputError: --rig no-such-rig.json: no such file
    """
    from contact._errors import ContactInputError
    from rotor import rig_from_mapping

    try:
        data = json.loads(Path(path).read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise SurfmetInputError(f"--rig {path}: no such file") from None
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise SurfmetInputError(f"--rig {path}: not a JSON rig file ({exc})") from None
    try:
        return rig_from_mapping(data)
    except ContactInputError as exc:
        raise SurfmetInputError(f"--rig {path}: {exc}") from None


def column_groups(names: Sequence[str]) -> dict[str, list[str]]:
    """Groups from the column names' prefixes (``as1, as2`` -> ``as``), in order of first
    appearance.

    Parameters
    ----------
    names : sequence of str
        Column names.

    Returns
    -------
    dict of str to list of str
        Prefix -> its columns.

    Examples
    --------
    >>> from surfmet.mechanics.rotor_verdict import column_groups
    >>> column_groups(["as1", "as2", "s1", "s2", "s3"])
    {'as': ['as1', 'as2'], 's': ['s1', 's2', 's3']}
    """
    out: dict[str, list[str]] = {}
    for n in names:
        out.setdefault(re.sub(r"\d+$", "", n) or n, []).append(n)
    return out


def judge(cols: Mapping[str, Sequence[float]], ks: Sequence[int] | None, *, fps: float,
          step: float, rig: Rig | None = None, mechanisms: Mapping[str, float] | None = None
          ) -> RotorVerdict:
    """The verdict on a table; with a rig its groups, fps and step, else the column prefixes.

    Parameters
    ----------
    cols : mapping of str to sequence of float
        Column name -> frame index per row.
    ks : sequence of int or None
        Row numbers (default 1, 2, ...).
    fps, step : float
        Frame rate (1/s) and mark step (rad).
    rig : rotor.Rig, optional
        The rig: its groups, and the lambda outputs and confounds.
    mechanisms : mapping of str to float, optional
        Contact mechanisms' accelerations to weigh as confounds.

    Returns
    -------
    rotor.RotorVerdict
        The verdict.

    Raises
    ------
    SurfmetInputError
        A table without two groups of two launches.

    See Also
    --------
    table_verdict : chooses the rig the way ``surfmet rotor`` does.

    Examples
    --------
    >>> import numpy as np
    >>> from surfmet.mechanics.rotor_verdict import judge
    >>> phi = np.arange(12) * np.pi / 2
    >>> t = (-1.0 + np.sqrt(1.0 + 2 * 2.0 * phi)) / 2.0
    >>> judge({"s1": np.round(1000 + 120 * t)}, None, fps=120.0, step=np.pi / 2)
    Traceback (most recent call last):
    ...
    surfmet._errors.SurfmetInputError: ...
    """
    from contact._errors import ContactInputError
    from rotor import judge_table

    groups = ({g.name: list(g.columns) for g in rig.groups} if rig is not None
              else column_groups(list(cols)))
    if rig is not None:
        fps, step = rig.fps, rig.step
    try:
        return judge_table(cols, groups, fps=fps, step=step, k=ks, rig=rig,
                           mechanisms=mechanisms)
    except ContactInputError as exc:
        raise SurfmetInputError(str(exc)) from None


@lru_cache(maxsize=1)
def paper_verdict() -> RotorVerdict:
    """The verdict on the paper's Table 3 with the paper's rig (cached: one answer).

    Returns
    -------
    rotor.RotorVerdict
        The verdict on Table 3 of Alaci et al. (2022): the group offset, the shared-track
        test, the lambda needed, the confounds.

    See Also
    --------
    table_verdict, verdict_lines

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of Rolling
       Friction Moment on the Normal Force for Elastic Materials", Materials 15 (2022) 2518,
       Table 3.

    Examples
    --------
    >>> from surfmet.mechanics.rotor_verdict import paper_verdict
    >>> verdict = paper_verdict()
    >>> verdict.code
    'undetermined'
    """
    from rotor import paper_rig
    from surfmet.data import path as data_path

    ks, cols = read_frames_table(data_path("table3_frames.tsv"))
    rig = paper_rig()
    return judge(cols, ks, fps=rig.fps, step=rig.step, rig=rig)


def _p_floor() -> float:
    from rotor import verdict_calibration

    return 1.0 / (len(verdict_calibration()["shared_track_test"]["null_f_sorted"]) + 1)


def _p_shown(p: float) -> str:
    floor = _p_floor()
    return (f"<= {floor:.2g} (the calibration's floor)" if p <= floor * (1 + 1e-9)
            else f"= {p:.3g}")


def shared_track_p_text(v: RotorVerdict) -> str:
    """The shared-track test's calibrated p in words, as the verdict's text and its JSON
    (``shared_track.p_text``) say it: at most the calibration's floor where it reaches it.

    Parameters
    ----------
    v : rotor.RotorVerdict
        The verdict.

    Returns
    -------
    str
        ``"calibrated p = 0.0123"`` or ``"calibrated p <= 0.0083 (the calibration's floor)"``.

    Examples
    --------
    >>> from surfmet.mechanics.rotor_verdict import paper_verdict, shared_track_p_text
    >>> shared_track_p_text(paper_verdict())
    "calibrated p <= 0.0083 (the calibration's floor)"
    """
    return f"calibrated p {_p_shown(v.shared_track_p)}"


def _rejected(v: RotorVerdict) -> str:
    """REJECTED, said as the model's alone when the design's permutation p is weaker than
    the test's level (the wording follows the weaker p)."""
    from rotor import verdict_calibration

    level = float(verdict_calibration()["shared_track_test"]["level"])
    return "REJECTED" if v.weaker_p <= level else "REJECTED by the model (not by the design)"


def verdict_lines(v: RotorVerdict, analysis: LawOfMotionAnalysis | None = None,
                  rough: RoughArmBound | None = None) -> list[str]:
    """The verdict in words, first thing every entry point prints.

    Parameters
    ----------
    v : RotorVerdict
        The verdict.
    analysis : rotor.LawOfMotionAnalysis, optional
        The table's per-test analysis (:func:`rotor.analyse_table`): adds,
        after a blank line, the table of the four differences and the two misread rules
        (as :func:`surfmet.records._rotor_verdict.verdict_record` adds their JSON).
    rough : surfmet.mechanics.rotor_rough_bound.RoughArmBound, optional
        The scanned contact's extent, after the friction arm's line.

    Returns
    -------
    list of str
        The headline first, then one line per finding.

    See Also
    --------
    surfmet.records._rotor_verdict.verdict_record : the same as JSON.

    Examples
    --------
    >>> from surfmet.mechanics.rotor_verdict import paper_verdict, verdict_lines
    >>> print(verdict_lines(paper_verdict())[0])
    VERDICT  undetermined: the groups' tracks differ more than the launches' within a group do ...
    """
    lines = _verdict_text(v, rough)
    if analysis is not None:
        from surfmet.mechanics._rotor_argument import differences_lines

        lines += ["", *differences_lines(v, analysis)]
    return lines


def _verdict_text(v: RotorVerdict, rough: RoughArmBound | None = None) -> list[str]:
    o = v.offset
    lines = [f"VERDICT  {v.sentence}",
             f"  group offset {o.minuend} - {o.subtrahend} {o.value:+.4f} rad/s², "
             f"{o.level:.0%} CI [{o.ci_low:+.4f}, {o.ci_high:+.4f}] (launch-to-launch sd "
             f"{o.launch_sd:.4f} rad/s², t on {o.dof} dof)",
             f"  shared track ({v.shared.layout.degree}-term profile): "
             f"{'adequate' if v.shared_track_adequate else _rejected(v)}, F = {v.f_statistic:.2f} "
             f"(critical {v.f_critical:.2f} at 2 %), {shared_track_p_text(v)}"]
    from surfmet.mechanics._rotor_argument import (
        argument_lines,
        lane_line,
        permutation_line,
        windows_lines,
    )

    lines += [x for x in (lane_line(v), permutation_line(v)) if x]
    lines += windows_lines(v)
    if v.misread_rows:
        lines.append("  misread rows left out by the joint model: "
                     + ", ".join(f"{c} k={k}" for c, k in v.misread_rows))
    e = v.exponent
    if e is None:
        lines.append("  (no rig: the lambda outputs and the confounds need --rig RIG.json)")
        return lines
    lam = (f"{e.value:.3g} [{e.ci_low:.3g}, {e.ci_high:.3g}]" if math.isfinite(e.value)
           else "none in 0.05-20")
    lines += [f"  lambda needed at slope {math.degrees(e.slope):.3g} deg ({e.slope_basis}; the "
              f"mean acceleration needs >= {math.degrees(e.slope_lower_bound):.3g} deg): {lam} "
              f"(conditional on the slope)",
              *argument_lines(v, rough),
              f"  largest offset lambda = 4/3 gives there: {e.offset_lambda_4_3:+.4f} rad/s²; "
              f"launches per group to tell 4/3 from 1 (90 % power, 2 %): "
              f"{e.launches if e.launches is not None else 'more than 100000'}",
              "  confounds (equivalent acceleration, rad/s²; can it make the offset?):"]
    for c in v.confounds:
        lines.append(f"    {c.name:32s} {c.equivalent_acceleration:10.3g}  "
                     f"{'yes' if c.can_explain else 'no '}  ({c.assumption})")
    from surfmet.mechanics._rotor_sensitivity import (
        experiment_lines,
        label_swap_text,
        sensitivity_lines,
    )

    swap = label_swap_text(v)
    return lines + ([f"  labels: {swap}"] if swap else []) + sensitivity_lines(v) + \
        experiment_lines(v)


def verdict_plot_path(plot: str | Path) -> str:
    """Where ``--plot PATH`` puts the verdict's figure: ``PATH_verdict`` beside it.

    Parameters
    ----------
    plot : str or Path
        The ``--plot`` path of the command.

    Returns
    -------
    str
        The verdict figure's path.

    Examples
    --------
    >>> from surfmet.mechanics.rotor_verdict import verdict_plot_path
    >>> verdict_plot_path("out/fig.png")
    'out/fig_verdict.png'
    """
    p = Path(plot)
    return str(p.with_name(p.stem + "_verdict" + p.suffix))


def table_verdict(ks: Sequence[int], cols: Mapping[str, Sequence[float]], *, paper: bool,
                  fps: float, step: float, rig_path: str | None = None
                  ) -> tuple[RotorVerdict | None, list[str]]:
    """The verdict ``surfmet rotor`` prints, and notes: the paper's rig for the paper's table,
    the rig file when given, else groups from the column prefixes and no rig (None when such
    a table has no two groups of two launches: the per-launch analysis still stands).

    Parameters
    ----------
    ks : sequence of int
        Row numbers.
    cols : mapping of str to sequence of float
        Column name -> frame index per row.
    paper : bool
        The table is the paper's Table 3 (use the paper's rig).
    fps, step : float
        Frame rate (1/s) and mark step (rad).
    rig_path : str, optional
        A rig JSON file (:func:`load_rig`).

    Returns
    -------
    (RotorVerdict or None, list of str)
        The verdict and the notes on how it was reached.

    Raises
    ------
    SurfmetInputError
        An unreadable rig file.

    See Also
    --------
    paper_verdict, judge, verdict_lines

    Examples
    --------
    The paper's Table 3 with the paper's rig and frame rate:

    >>> import csv
    >>> from rotor import FPS, MARK_STEP
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.rotor_verdict import table_verdict
    >>> with open(path("table3_frames.tsv")) as f:
    ...     rows = list(csv.DictReader(f, delimiter="\\t"))
    >>> ks = [int(r["k"]) for r in rows]
    >>> cols = {c: [float(r[c]) for r in rows] for c in rows[0] if c != "k"}
    >>> verdict, notes = table_verdict(ks, cols, paper=True, fps=FPS, step=MARK_STEP)
    >>> verdict.code, notes
    ('undetermined', [])
    """
    from rotor import FPS, MARK_STEP, paper_rig

    if rig_path:
        return judge(cols, ks, fps=fps, step=step, rig=load_rig(rig_path)), []
    if paper:
        if fps == FPS and step == MARK_STEP:
            return paper_verdict(), []
        return judge(cols, ks, fps=fps, step=step, rig=paper_rig()), []
    notes = ["no --rig: groups from the column names; the lambda outputs and the confounds "
             "are left out"]
    try:
        return judge(cols, ks, fps=fps, step=step), notes
    except SurfmetInputError as exc:
        return None, [*notes, f"no verdict: {exc}"]


def verdict_figure(v: RotorVerdict, path: str | Path) -> None:
    """Local accelerations from the frames against track position, per group, with the
    joint model; and the lambda needed against the assumed slope.

    Parameters
    ----------
    v : RotorVerdict
        The verdict.
    path : str or Path
        The image file to write.

    See Also
    --------
    verdict_plot_path : where the commands put it.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> from surfmet.mechanics.rotor_verdict import paper_verdict, verdict_figure
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     out = pathlib.Path(tmp) / "verdict.png"
    ...     verdict_figure(paper_verdict(), out)
    ...     print(out.stat().st_size > 10_000)
    True
    """
    from surfmet.plots.rotor_verdict import draw_verdict

    draw_verdict(v, path)


def label_swap_text(v: RotorVerdict) -> str | None:
    """What the paper's swapped labels do (its φ_s/φ_a columns name the other group, which
    flips the sign of λ − 1), for the paper's rig; None for another rig.

    Parameters
    ----------
    v : rotor.RotorVerdict
        The verdict.

    Returns
    -------
    str or None
        The sentence every entry point prints beside the verdict.

    Examples
    --------
    >>> from surfmet.mechanics.rotor_verdict import label_swap_text, paper_verdict
    >>> "label" in label_swap_text(paper_verdict())
    True
    """
    from surfmet.mechanics._rotor_sensitivity import label_swap_text as text

    return text(v)
