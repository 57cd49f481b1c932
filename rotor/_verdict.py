"""The paper's question answered once: is the difference between the two groups of a rotor
table evidence that ``M_r`` is not linear in ``N``, and if not, what made it?

:func:`judge_table` fits all launches jointly (:mod:`rotor._joint`), tests one shared
track against group-specific ones (the F statistic's null distribution calibrated by
simulation, :mod:`rotor._tables`, ``verdict_calibration.json``), and gives one code:

- ``undetermined``: no shared track explains both groups (they did not run under the same
  conditions: another lane, slope, launch direction or run-in state), so the offset cannot be
  laid to rolling friction; what differs (trend or waviness) and where is said;
- ``difference``: a constant offset on a shared track, ``|offset| / stderr`` beyond Student's
  t at 2 % two-sided (its false-alarm rate measured on simulated tables without an offset);
- ``no_difference``: the groups agree on a shared track: nothing here contradicts
  ``lambda = 1``.

With a rig (:mod:`rotor._rig`) the offset becomes a torque, a change of slope and the
``lambda`` it needs, with the largest offset ``lambda = 4/3`` could give and the launches per
group that would tell 4/3 from 1; and a budget of confounds (:mod:`rotor._confounds`).
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np
from scipy.stats import t as student_t

from contact._errors import ContactInputError
from contact._materials import Material
from rotor._arm import ArmBound, arm_bound
from rotor._confounds import Confound, confound_budget
from rotor._joint import (
    GroupOffset,
    JointFit,
    TableData,
    fit_table,
    group_offset,
    prepare_table,
    shared_track_f,
)
from rotor._lanes import LaneTest, lane_test, lane_words
from rotor._mechanics import G_STANDARD
from rotor._permutation import PermutationTest, permutation_test
from rotor._rig import (
    UPPER_SLOPE,
    Rig,
    launches_needed,
    offset_for_lambda,
    slope_lower_bound,
    solve_lambda,
)
from rotor._track import track_acceleration, track_basis
from rotor._windows import WindowedDifference, windowed_difference

__all__ = ["CODES", "ExponentNeeded", "RotorVerdict", "TrackDifference",
           "judge_table", "verdict_calibration"]

CODES = ("no_difference", "difference", "undetermined")
CALIBRATION_FILE = Path(__file__).with_name("verdict_calibration.json")


@lru_cache(maxsize=1)
def verdict_calibration() -> dict:
    """The simulation calibration (``benchmarks/rotor_verdict_calibration.py``).

    Returns
    -------
    dict
        The calibration as stored (``verdict_calibration.json``, package data): the prior,
        the tables simulated, the shared-track test's critical F and the offset test's rule.

    See Also
    --------
    judge_table : uses it.

    Examples
    --------
    >>> from rotor import verdict_calibration
    >>> cal = verdict_calibration()
    >>> test = cal["shared_track_test"]
    >>> print(test["level"], f"critical F = {test['critical_f']:.2f}")
    0.02 critical F = 3.75
    """
    return json.loads(CALIBRATION_FILE.read_text())


@dataclass(frozen=True)
class TrackDifference:
    """How the group-specific tracks differ (minuend - subtrahend): ``trend`` (rad/s² per m
    of track, the straight line through the joint model's difference) with its
    ``trend_stderr``, ``waviness_rms`` (rad/s², what the trend leaves), ``length`` the track
    covered (m), and ``windows``: the model-free windowed difference
    (:mod:`rotor._windows`) beside it.

    ``start``/``end`` (the polynomial's value at the release and the last mark, rad/s²) and
    ``regions`` ((start, end) m where it exceeds two standard errors) are end values of a
    polynomial, where it is least constrained: kept for the record, never the headline."""

    trend: float
    waviness_rms: float
    regions: tuple[tuple[float, float], ...]
    start: float
    end: float
    length: float
    trend_stderr: float = math.nan
    windows: WindowedDifference | None = None
    curve: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None
    """``(x m, difference rad/s², stderr rad/s²)`` along the track: the figure's band."""


@dataclass(frozen=True)
class ExponentNeeded:
    """What ``lambda`` the offset needs at ``slope`` (rad; ``slope_basis`` says whether it was
    given or assumed), over the offset's interval; ``offset_lambda_4_3``: the largest offset
    ``lambda = 4/3`` gives there (rad/s²); ``launches``: launches per group that tell 4/3 from
    1 with 90 % power at 2 %; ``slope_lower_bound``: the slope the mean acceleration needs."""

    value: float
    ci_low: float
    ci_high: float
    slope: float
    slope_basis: str
    slope_lower_bound: float
    offset_lambda_4_3: float
    launches: int | None


@dataclass(frozen=True)
class RotorVerdict:
    """The answer: ``code`` (one of :data:`CODES`) and ``sentence``, with everything behind it.

    See Also
    --------
    judge_table : builds it.

    Examples
    --------
    Table 3: the asymmetric rotor is slower by about 0.2 rad/s², but no shared track explains
    both groups, so the paper's question stays open:

    >>> import numpy as np
    >>> from rotor import judge_table, paper_rig, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> verdict = judge_table(table3(), groups, fps=120.0, step=np.pi / 2, rig=paper_rig(),
    ...                       permutation=False)
    >>> print(verdict.code, verdict.shared_track_adequate)
    undetermined False
    >>> print(verdict.sentence.split(":")[0])
    undetermined
    """

    code: str
    sentence: str
    offset: GroupOffset
    shared_track_adequate: bool
    shared_track_p: float
    f_statistic: float
    f_critical: float
    difference: TrackDifference | None
    exponent: ExponentNeeded | None
    confounds: tuple[Confound, ...]
    mean_acceleration: float
    data: TableData
    shared: JointFit
    groupwise: JointFit
    rig: Rig | None
    permutation: PermutationTest | None = None
    arm: ArmBound | None = None
    lanes: LaneTest | None = None

    @property
    def weaker_p(self) -> float:
        """The weaker of the model-calibrated and the design's permutation p of the shared
        track test: the one the wording follows."""
        if self.permutation is None or not math.isfinite(self.permutation.f_p):
            return self.shared_track_p
        return max(self.shared_track_p, self.permutation.f_p)

    @property
    def misread_rows(self) -> tuple[tuple[str, int], ...]:
        bad = self.data.mask & ~self.shared.used
        return tuple((self.data.names[i], int(self.data.k[i, j])) for i, j in np.argwhere(bad))


def _p_text(p: float) -> str:
    """``= p``, or ``<= p`` at the calibration's floor (no simulated null table beyond)."""
    floor = 1.0 / (len(verdict_calibration()["shared_track_test"]["null_f_sorted"]) + 1)
    return f"<= {floor:.2g} (the calibration's floor)" if p <= floor else f"= {p:.2g}"


def _p_value(f: float) -> float:
    null = verdict_calibration()["shared_track_test"]["null_f_sorted"]
    return (1 + sum(v >= f for v in null)) / (len(null) + 1)


def _difference(data: TableData, fit: JointFit, mi: int, si: int,
                radius: float) -> TrackDifference:
    """The minuend's model acceleration minus the subtrahend's along the track."""
    lay = fit.layout
    s = np.linspace(0.0, float(np.max(data.angles)), 241)
    beta, delta, _, _ = lay.split(fit.x)
    g = data.group_of_launch
    d = (delta[g == mi].mean() + track_acceleration(s, beta[mi], lay.span)
         - delta[g == si].mean() - track_acceleration(s, beta[si], lay.span))
    m, nb = lay.degree, lay.n_tracks * lay.degree
    grad = np.zeros((s.size, lay.n_params))
    vals = track_basis(s, lay.span, m)[0]
    grad[:, mi * m : (mi + 1) * m] = vals
    grad[:, si * m : (si + 1) * m] = -vals
    grad[:, nb : nb + lay.n_launches] = np.where(g == mi, 1.0 / np.sum(g == mi), 0.0) - np.where(
        g == si, 1.0 / np.sum(g == si), 0.0)
    scale = max(fit.chi2 / max(fit.n_used - lay.n_params, 1), 1.0)
    se = np.sqrt(np.maximum(np.einsum("ij,jk,ik->i", grad, fit.cov, grad) * scale, 0.0))
    x = s * radius
    coef = np.polyfit(x, d, 1)
    wav = float(np.sqrt(np.mean((d - np.polyval(coef, x)) ** 2)))
    # the trend is a linear functional of the parameters: its row of the line's pseudo-inverse
    slope_row = np.linalg.pinv(np.column_stack([x, np.ones_like(x)]))[0] @ grad
    trend_se = math.sqrt(max(float(slope_row @ fit.cov @ slope_row) * scale, 0.0))
    out = np.abs(d) > 2 * se
    regions, start = [], None
    for i, flag in enumerate(out):
        if flag and start is None:
            start = i
        if start is not None and (not flag or i == out.size - 1):
            end = i if flag else i - 1
            regions.append((float(x[start]), float(x[end])))
            start = None
    return TrackDifference(float(coef[0]), wav, tuple(regions), float(d[0]), float(d[-1]),
                           float(x[-1]), trend_se, frame_windows(data, fit, mi, si, radius),
                           (x, d, se))


WINDOWS = 4
"""Windows the track is cut into for the model-free accelerations (six marks each on the
paper's 25-row table: three parameters and three degrees of freedom per launch)."""


def frame_windows(data: TableData, fit: JointFit, mi: int, si: int, radius: float,
                  n_windows: int = WINDOWS) -> WindowedDifference:
    """The model-free windowed difference of groups ``mi - si`` from the frames alone, each
    launch's rows placed on the track by ``fit``'s release point (its used rows, their
    reading noise).

    Parameters
    ----------
    data : TableData
        The launches (:func:`prepare_table`).
    fit : JointFit
        A fit of :func:`fit_table` (its release points, used rows and noise).
    mi, si : int
        The groups (indices into ``data.group_names``): minuend and subtrahend.
    radius : float
        The rolling radius (m) that turns angles into track length.
    n_windows : int
        Windows along the track.

    Returns
    -------
    WindowedDifference
        The difference window by window (rad/s²) at track positions in m.

    See Also
    --------
    local_accelerations

    Examples
    --------
    >>> import numpy as np
    >>> from rotor import fit_table, frame_windows, prepare_table, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> data = prepare_table(table3(), groups, 120.0, np.pi / 2)
    >>> shared, groupwise = fit_table(data)
    >>> windows = frame_windows(data, groupwise, 1, 0, 0.02)
    >>> print(windows.centres.size, f"first window {windows.difference[0]:.1f} rad/s²")
    4 first window 0.0 rad/s²
    """
    _, _, phi0, _ = fit.layout.split(fit.x)
    rows = [np.flatnonzero(fit.used[i]) for i in range(data.times.shape[0])]
    return windowed_difference([data.angles[i, r] - phi0[i] for i, r in enumerate(rows)],
                               [data.times[i, r] for i, r in enumerate(rows)],
                               [fit.sigma[i, r] for i, r in enumerate(rows)],
                               data.group_of_launch, mi, si, radius, n_windows)


def _exponent(rig: Rig, off: GroupOffset, mean_acc: float) -> ExponentNeeded:
    low = slope_lower_bound(rig, mean_acc)
    slope, basis = (rig.slope, "given") if rig.slope is not None else (
        max(UPPER_SLOPE, low), "assumed: the paper's slopes are under 1 degree")
    args = (rig, off.minuend, off.subtrahend, slope, mean_acc)
    lam = [solve_lambda(v, *args) for v in (off.value, off.ci_low, off.ci_high)]
    lo, hi = (min(lam[1], lam[2]), max(lam[1], lam[2])) if not any(map(math.isnan, lam[1:])) \
        else (math.nan, math.nan)
    eff = offset_for_lambda(4 / 3, *args)
    return ExponentNeeded(lam[0], lo, hi, slope, basis, low, eff,
                          launches_needed(eff, off.launch_sd))


def judge_table(columns: Mapping[str, Sequence[float]], groups: Mapping[str, Sequence[str]],
                *, fps: float, step: float, k: Sequence[int] | None = None,
                rig: Rig | None = None,
                mechanisms: Mapping[str, float] | None = None,
                permutation: bool = True,
                materials: tuple[Material, Material] | None = None) -> RotorVerdict:
    """The verdict on a table: ``groups`` ({name: columns}, two groups; the offset is the
    second minus the first), ``rig`` for the exponent, the arm bound and the confounds,
    ``mechanisms`` ({name: implied offset, rad/s²}) to put into the confound budget;
    ``permutation``: also the design's exact permutation test (a refit per split).

    Parameters
    ----------
    columns : Mapping of str to sequence of float
        The frame indices of each launch (column).
    groups : Mapping of str to sequence of str
        Exactly two groups, ``{name: its columns}``.
    fps, step : float
        Frame rate (1/s) and the angle between marks (rad).
    k : sequence of int, optional
        The row numbers (default 1, 2, ...).
    rig : Rig, optional
        The rotor and its groups (:func:`paper_rig`): needed for the exponent, the arm
        bound and the confound budget.
    mechanisms : Mapping of str to float, optional
        Other mechanisms' implied offsets (rad/s²) for the confound budget.
    permutation : bool
        Also run the exact permutation test.
    materials : (Material, Material), optional
        The ball's and the plate's materials for the confound budget's lateral creep
        (default the rig's stated E* and materials, else the paper's steel ball on
        aluminium, :func:`rotor._confounds.creep_moduli`).

    Returns
    -------
    RotorVerdict
        ``code`` (``difference``, ``no_difference`` or ``undetermined``), its sentence and
        the evidence behind it.

    Raises
    ------
    ContactInputError
        Not exactly two groups, or columns the table cannot use.

    See Also
    --------
    analyse_table : the law of motion of each launch on its own.
    arm_bound : the friction arm against the contact radius.

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of Rolling
       Friction Moment on the Normal Force for Elastic Materials", Materials 15 (2022) 2518,
       Eqs. (47)-(49).

    Examples
    --------
    The paper's Table 3, the asymmetric group minus the symmetric one:

    >>> import numpy as np
    >>> from rotor import judge_table, paper_rig, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> verdict = judge_table(table3(), groups, fps=120.0, step=np.pi / 2, rig=paper_rig(),
    ...                       permutation=False)
    >>> offset = verdict.offset
    >>> print(offset.minuend, "-", offset.subtrahend, f"= {offset.value:.1f} rad/s²")
    as - s = -0.2 rad/s²
    >>> print(verdict.code)
    undetermined
    """
    data = prepare_table(columns, groups, fps, step, k)
    if len(data.group_names) != 2:
        raise ContactInputError(f"the verdict compares two groups; the table has "
                                f"{len(data.group_names)} ({', '.join(data.group_names)})")
    shared, groupwise = fit_table(data)
    cal = verdict_calibration()
    f = shared_track_f(shared, groupwise)
    f_crit = float(cal["shared_track_test"]["critical_f"])
    adequate = bool(f <= f_crit)
    off = group_offset(data, shared, minuend=1, subtrahend=0)
    diff = None if adequate else _difference(data, groupwise, 1, 0,
                                             rig.ball_radius if rig else 0.02)
    beta, delta, _, _ = shared.layout.split(shared.x)
    s = np.linspace(0.0, float(np.max(data.angles)), 241)
    prof = track_acceleration(s, beta[0], shared.layout.span)
    mean_acc = float(np.mean(delta) + np.mean(prof))
    t_crit = float(student_t.ppf(0.5 + cal["offset_test"]["t_level"] / 2, max(off.dof, 1)))
    lanes = lane_test(shared, groupwise, data)
    # launches on lanes of their own are not groups differing: undetermined only when the
    # groups' tracks differ beyond the noise and beyond the launches' own variation
    code = "undetermined" if not adequate and lanes.groups_differ else (
        "difference" if abs(off.t_statistic) > t_crit else "no_difference")
    exponent = _exponent(rig, off, mean_acc) if rig is not None else None
    arm = None if rig is None else arm_bound(rig, off.minuend, off.subtrahend, exponent.slope,
                                             mean_acc, off.value, off.ci_low, off.ci_high)
    confounds: tuple[Confound, ...] = ()
    if rig is not None:
        smallest = 0.0 if off.ci_low <= 0 <= off.ci_high else min(abs(off.ci_low),
                                                                  abs(off.ci_high))
        confounds = confound_budget(rig, off.value, max(smallest, 1e-300), exponent.slope,
                                    mean_acc, float(np.ptp(prof)), float(np.max(s)),
                                    off.minuend, off.subtrahend, mechanisms,
                                    materials=materials)
    perm = permutation_test(data, shared, groupwise) if permutation else None
    sentence = _sentence(code, off, f, _p_value(f), diff, exponent, rig, perm, arm)
    if not adequate:
        body = sentence.split(": ", 1)[1]
        body = body.replace("the groups agree on a shared track", "the groups' offsets agree")
        body = body.replace("a constant offset on a shared track",
                            "a constant offset between the groups")
        sentence = lane_words(code, lanes, f) + body
    return RotorVerdict(code, sentence, off, adequate, _p_value(f), f, f_crit, diff, exponent,
                        confounds, mean_acc, data, shared, groupwise, rig, perm, arm, lanes)


BLOCK_CAVEAT = ("with each group filmed as one block (the groups one after the other), a "
                "session effect (run-in, lane, slope reset) cannot be told from the collar's "
                "position")
"""What a block design cannot separate (said wherever the groups are compared)."""


def _design_p(p: float, perm: PermutationTest, what: str) -> str:
    smallest = " (the smallest the design allows)" if p <= perm.smallest_p * (1 + 1e-9) else ""
    return (f"the design's exact permutation p = {p:.2g}{smallest} for the {what} over the "
            f"{perm.n_splits} splits of the launches into groups"
            f"{'' if perm.exact else ' (sampled)'}")


def _level_text(level: float) -> str:
    return f"{level * 100:g} %"


def _shared_track_clause(f: float, p: float, perm: PermutationTest | None) -> str:
    """The shared-track test in words that follow the weaker of the model's calibrated p and
    the design's permutation p."""
    level = float(verdict_calibration()["shared_track_test"]["level"])
    model = f"F = {f:.1f}, calibrated p {_p_text(p)}"
    if perm is None or not math.isfinite(perm.f_p):
        return f"the paper's constant-offset model is rejected: no shared track explains both " \
               f"groups ({model})"
    design = _design_p(perm.f_p, perm, "shared-track F")
    if max(p, perm.f_p) <= level:
        return (f"the paper's constant-offset model is rejected: no shared track explains both "
                f"groups ({model}; {design})")
    return (f"the paper's constant-offset model is rejected by the joint model, not by the "
            f"design alone: no shared track explains both groups under the model ({model}), "
            f"but {design}, so the launches' own evidence cannot reach {_level_text(level)}")


def window_clause(w: WindowedDifference | None) -> str:
    """What the frames alone say (the model-free windows), and where they cannot resolve the
    difference."""
    if w is None or not np.any(np.isfinite(w.difference)):
        return ""
    ok = np.isfinite(w.stderr)
    band = f"{2 * np.min(w.stderr[ok]):#.2g}-{2 * np.max(w.stderr[ok]):#.2g} rad/s²"
    head = (f"; read off the frames alone ({w.difference.size} windows of "
            f"{w.window_length * 1e3:.0f} mm, no track model) the trend is "
            f"{w.trend:+#.2g} ± {w.trend_stderr:#.2g} rad/s² per m")
    res = w.resolved
    if not np.any(res):
        return (f"{head} and no window's difference exceeds its two standard errors "
                f"({band}): the frames alone cannot resolve the difference")
    where = ", ".join(f"{(c - w.window_length / 2) * 1e3:.0f}-"
                      f"{(c + w.window_length / 2) * 1e3:.0f} mm" for c in w.centres[res])
    return (f"{head}; the difference exceeds two standard errors at {where} only (two "
            f"standard errors {band}): the frames cannot resolve it elsewhere")


def _sentence(code: str, off: GroupOffset, f: float, p: float, diff: TrackDifference | None,
              exponent: ExponentNeeded | None, rig: Rig | None,
              perm: PermutationTest | None = None, arm: ArmBound | None = None) -> str:
    pair = f"{off.minuend} - {off.subtrahend}"
    ci = f"[{off.ci_low:+.3f}, {off.ci_high:+.3f}] rad/s² ({off.level:.0%})"
    if code == "undetermined":
        length = diff.length
        kind = "trend" if abs(diff.trend) * length > 2 * diff.waviness_rms else "waviness"
        return (f"undetermined: {_shared_track_clause(f, p, perm)}; the groups' accelerations "
                f"differ by a {kind} along the track "
                f"({pair}: trend {diff.trend:+.3g} ± {diff.trend_stderr:#.2g} rad/s² per m over "
                f"{length * 1e3:.0f} mm in the joint model, waviness {diff.waviness_rms:.3f} "
                f"rad/s² rms){window_clause(diff.windows)}; "
                f"{BLOCK_CAVEAT}, so the offset {off.value:+.3f} rad/s² cannot be laid to "
                f"rolling friction.")
    if code == "no_difference":
        tail = ""
        if exponent is not None:
            tail = (f" At the slope used, lambda = 4/3 would give at most "
                    f"{exponent.offset_lambda_4_3:+.4f} rad/s²; telling it from 1 needs "
                    f"{exponent.launches or 'more than 100000'} launches per group.")
        return (f"no_difference: the groups agree on a shared track ({pair} = {off.value:+.3f} "
                f"rad/s², {ci}): nothing here contradicts lambda = 1.{tail}")
    text = (f"difference: a constant offset on a shared track, {pair} = {off.value:+.3f} rad/s² "
            f"{ci}")
    if perm is not None:
        level = float(verdict_calibration()["shared_track_test"]["level"])
        text += f" ({_design_p(perm.offset_p, perm, 'offset')}"
        text += (f"; the design alone cannot show it at {_level_text(level)})"
                 if perm.offset_p > level else ")")
    if rig is not None and exponent is not None:
        torque = off.value * rig.rolling_inertia
        dslope = torque / (rig.mass * G_STANDARD * rig.ball_radius)
        lam = (f"lambda = {exponent.value:.3g} [{exponent.ci_low:.3g}, {exponent.ci_high:.3g}]"
               if math.isfinite(exponent.value) else "no lambda in 0.05-20")
        text += (f", a torque of {torque:+.3g} N m or a slope change of "
                 f"{math.degrees(dslope):+.3g} deg; at a slope of "
                 f"{math.degrees(exponent.slope):.3g} deg ({exponent.slope_basis}) it needs {lam}")
        if arm is not None and math.isfinite(arm.lambda_at_bound):
            text += (f"; with the friction arm at its bound (the contact radius "
                     f"{arm.arm_bound * 1e6:.0f} µm) at least lambda = {arm.lambda_at_bound:.3g}")
    return text + f"; {BLOCK_CAVEAT}."
