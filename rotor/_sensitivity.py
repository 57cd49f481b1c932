"""Every assumption's weight on the rotor verdict, and the experiment that would settle it.

:func:`sensitivity_table` changes one assumption at a time and says what becomes of the
verdict's code, the offset, the ``lambda`` it needs at the slope used and the least
``lambda`` it needs with the friction arm at its bound (:mod:`rotor._arm`):

- the slope (0.5-1.5 deg: the paper says only "smaller than one degree");
- the centre of mass's offset ``xi_G`` (the paper does not print it): the asymmetric group's
  load contrast +-20 %;
- mass and axial inertia: the paper's analytic values (M = 0.954 kg, J = 1.632e-4 kg m²)
  and its CAD values (0.958 kg, 1.644e-4 kg m²) against the parts' own;
- the frame rate: times are frame indices over ``fps``, so every acceleration scales as
  ``fps**2`` (a 120 /s camera running at 119.88 /s, or off by 1 %);
- the collar's unbalance clearance (17.5 µm from an H7/g6 fit, and 150 µm);
- run order: a drift of the launch offsets in the column order, fitted within the groups
  and extrapolated between the blocks;
- the paper's swapped labels: its text's phi_s is Table 3's asymmetric group, so reading the
  columns with the text's labels flips the offset's sign and with it the sign of
  ``lambda - 1``.

None of these refits the frames: the shared-track and lane tests do not depend on them (the
frame rate scales the times, and with them chi² and the noise alike; the labels are
symmetric), so the code stays and only the mechanics move.

:func:`settling_experiment` gives the launches per group that tell ``lambda = 4/3`` from 1
(90 % power, 2 % two-sided, at the measured launch spread) for friction arms at the bound, at
20 µm and at 5 µm, on the paper's loads and on a larger load contrast (2.6 / 6.7 N); and the
straightedge check the named cause implies: the plate's concave sag that the asymmetric
group's decay would need, ``Delta theta L / 8``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from rotor._arm import arm_bound, load_contrast
from rotor._mechanics import G_STANDARD
from rotor._rig import Rig, RigGroup, launches_needed, solve_lambda
from rotor._track import track_acceleration

__all__ = ["Experiment", "ExperimentRow", "Sensitivity", "asymmetric_group",
           "sensitivity_table", "settling_experiment", "with_contrast"]

PAPER_ANALYTIC = (0.954, 1.632e-4)
"""The paper's analytic mass (kg) and axial inertia (kg m²), Section 2.2."""
PAPER_CAD = (0.958, 1.644e-4)
"""The paper's CAD mass and axial inertia (Fig. 10)."""
CLEARANCES = (17.5e-6, 150e-6)
"""Collar unbalance offsets (m): half an H7/g6 fit's largest clearance, and a loose one."""
LARGER_CONTRAST = (6.7, 2.6)
"""Ball loads (N) of an asymmetric collar with a larger contrast."""


@dataclass(frozen=True)
class Sensitivity:
    """One assumption changed: ``assumption`` and its ``setting``; the verdict's ``code``;
    the ``offset`` (rad/s², interval ``ci_low``-``ci_high``); ``lambda_needed`` at the slope
    used; ``lambda_bound`` (``low``/``high`` over the interval) with the arm at its bound;
    ``note``.

    See Also
    --------
    sensitivity_table : builds them.

    Examples
    --------
    >>> import numpy as np
    >>> from rotor import judge_table, paper_rig, sensitivity_table, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> verdict = judge_table(table3(), groups, fps=120.0, step=np.pi / 2, rig=paper_rig(),
    ...                       permutation=False)
    >>> row = sensitivity_table(verdict)[0]
    >>> print(row.assumption, row.code, f"{row.offset:.2f} rad/s²")
    as given undetermined -0.20 rad/s²
    """

    assumption: str
    setting: str
    code: str
    offset: float
    ci_low: float
    ci_high: float
    lambda_needed: float
    lambda_bound: float
    lambda_bound_low: float
    lambda_bound_high: float
    note: str = ""


def asymmetric_group(rig: Rig) -> RigGroup:
    """The group whose ball loads differ most."""
    return max(rig.groups, key=lambda g: abs(g.ball_loads[0] - g.ball_loads[1]))


def with_contrast(rig: Rig, factor: float) -> Rig:
    """The rig with the asymmetric group's load contrast scaled by ``factor`` (its sum
    kept)."""
    a = asymmetric_group(rig)
    mean, half = 0.5 * sum(a.ball_loads), 0.5 * (a.ball_loads[0] - a.ball_loads[1])
    new = replace(a, ball_loads=(mean + factor * half, mean - factor * half))
    return replace(rig, groups=tuple(new if g.name == a.name else g for g in rig.groups))


def _row(v, assumption: str, setting: str, rig: Rig, off: tuple[float, float, float],
         mean: float, slope: float, note: str = "", names: tuple[str, str] | None = None
         ) -> Sensitivity:
    m, s = names or (v.offset.minuend, v.offset.subtrahend)
    b = arm_bound(rig, m, s, slope, mean, *off)
    return Sensitivity(assumption, setting, v.code, off[0], min(off[1:]), max(off[1:]),
                       solve_lambda(off[0], rig, m, s, slope, mean), b.lambda_at_bound,
                       b.lambda_low, b.lambda_high, note)


def _drift(v) -> tuple[float, float]:
    """The launch offsets' drift per launch in column order (rad/s² per launch), fitted
    within the groups (one intercept per group), and its standard error."""
    _, delta, _, _ = v.shared.layout.split(v.shared.x)
    g = v.data.group_of_launch
    idx = np.arange(delta.size, dtype=float)
    design = np.column_stack([idx] + [(g == k).astype(float) for k in np.unique(g)])
    coef, *_ = np.linalg.lstsq(design, delta, rcond=None)
    dof = delta.size - design.shape[1]
    s2 = float(np.sum((design @ coef - delta) ** 2)) / max(dof, 1)
    return float(coef[0]), math.sqrt(s2 * float(np.linalg.inv(design.T @ design)[0, 0]))


def _scaled(rig: Rig, mass: float, inertia: float) -> Rig:
    k = mass / rig.mass
    groups = tuple(replace(g, ball_loads=(g.ball_loads[0] * k, g.ball_loads[1] * k))
                   for g in rig.groups)
    return replace(rig, mass=mass, axial_inertia=inertia, groups=groups)


def sensitivity_table(v) -> tuple[Sensitivity, ...]:
    """The verdict ``v`` (:class:`rotor._verdict.RotorVerdict`, with a rig) under
    each assumption changed in turn; the first row is the verdict as given.

    Parameters
    ----------
    v : RotorVerdict
        A verdict of :func:`judge_table` with a rig.

    Returns
    -------
    tuple of Sensitivity
        One row per assumption changed (slope, load contrast, mass and inertia, frame
        rate, collar clearance, run order, labels); empty without a rig.

    See Also
    --------
    settling_experiment

    Examples
    --------
    A smaller slope leaves a smaller friction torque, so the same offset needs a larger
    exponent:

    >>> import numpy as np
    >>> from rotor import judge_table, paper_rig, sensitivity_table, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> verdict = judge_table(table3(), groups, fps=120.0, step=np.pi / 2, rig=paper_rig(),
    ...                       permutation=False)
    >>> for row in sensitivity_table(verdict)[:4]:
    ...     print(row.setting[:8], f"lambda {row.lambda_needed:.1f}")
    slope 1  lambda 2.6
    0.5 deg  lambda 4.2
    0.75 deg lambda 3.1
    1.5 deg  lambda 2.1
    """
    rig, o, e = v.rig, v.offset, v.exponent
    if rig is None or e is None:
        return ()
    off, mean, slope = (o.value, o.ci_low, o.ci_high), v.mean_acceleration, e.slope
    rows = [_row(v, "as given", f"slope {math.degrees(slope):.3g} deg ({e.slope_basis})",
                 rig, off, mean, slope)]
    for deg in (0.5, 0.75, 1.5):
        th = math.radians(deg)
        rows.append(_row(v, "slope", f"{deg:g} deg", rig, off, mean, th,
                         "the arm bound's lambda is at the slope where s_r = a: unchanged"))
    for f in (0.8, 1.2):
        rows.append(_row(v, "xi_G", f"load contrast x {f:g} (xi_G x {f:g})",
                         with_contrast(rig, f), off, mean, slope))
    for what, (mm, jj) in (("analytic", PAPER_ANALYTIC), ("CAD", PAPER_CAD)):
        rows.append(_row(v, "mass and inertia", f"paper's {what}: M = {mm:g} kg, "
                         f"J = {jj:.4g} kg m²", _scaled(rig, mm, jj), off, mean, slope))
    for fps in (rig.fps * 0.999, rig.fps * 0.99):
        k = (fps / rig.fps) ** 2
        rows.append(_row(v, "frame rate", f"{fps:.5g} /s (accelerations x {k:.4f})", rig,
                         tuple(x * k for x in off), mean * k, slope))
    unb = next((c.equivalent_acceleration for c in v.confounds
                if c.name == "collar_unbalance"), math.nan)
    need = CLEARANCES[0] * abs(o.value) / unb if unb > 0 else math.nan
    for e_c in CLEARANCES:
        rows.append(_row(v, "collar clearance", f"e = {e_c * 1e6:g} µm", rig, off, mean,
                         slope, f"unbalance's mean over the track {unb * e_c / CLEARANCES[0]:.3g}"
                         f" rad/s²; the offset would need e = {need * 1e6:.0f} µm"))
    d, d_se = _drift(v)
    g = v.data.group_of_launch
    gap = float(np.mean(np.flatnonzero(g == 1)) - np.mean(np.flatnonzero(g == 0)))
    for sign, order in ((1, "the columns' order (as first)"), (-1, "s first")):
        shift = sign * gap * d
        rows.append(_row(v, "run order", f"{order}, drift removed", rig,
                         tuple(x - shift for x in off), mean, slope,
                         f"drift {d:+.3g} ± {d_se:.2g} rad/s² per launch within the groups; "
                         f"{shift:+.3g} rad/s² between the blocks"))
    rows.append(_row(v, "labels", "the text's phi_s/phi_a (swapped: as <-> s)", rig,
                     (-off[0], -off[2], -off[1]), mean, slope,
                     "the offset's sign flips, and with it the sign of lambda - 1: it would "
                     "need 0 < lambda < 1, where no power law reaches it (N1^lambda + "
                     "N2^lambda - 2 Ns^lambda vanishes at 0 and 1 and stays small between)"))
    return tuple(rows)


@dataclass(frozen=True)
class ExperimentRow:
    """``arm`` (m) on ``loads`` (text), the offset ``lambda = 4/3`` makes (rad/s²) and the
    launches per group that tell it from 1 (None: more than 100000)."""

    arm: float
    arm_basis: str
    loads: str
    offset_4_3: float
    launches: int | None


@dataclass(frozen=True)
class Experiment:
    """The experiment that would settle it: ``rows``, the plate's ``sag`` (m) and the
    ``slope_change`` (rad) the asymmetric group's decay implies over ``length`` (m), at
    ``launch_sd`` (rad/s²), ``power`` and ``alpha``.

    See Also
    --------
    settling_experiment : builds it.

    Examples
    --------
    >>> import numpy as np
    >>> from rotor import judge_table, paper_rig, settling_experiment, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> verdict = judge_table(table3(), groups, fps=120.0, step=np.pi / 2, rig=paper_rig(),
    ...                       permutation=False)
    >>> experiment = settling_experiment(verdict)
    >>> print(len(experiment.rows), f"launch spread {experiment.launch_sd:.3f} rad/s²")
    6 launch spread 0.037 rad/s²
    """

    rows: tuple[ExperimentRow, ...]
    slope_change: float
    length: float
    sag: float
    launch_sd: float
    power: float = 0.9
    alpha: float = 0.02


def _offset_4_3(rig: Rig, minuend: str, subtrahend: str, arm: float) -> float:
    sym = min(rig.groups, key=lambda g: abs(g.ball_loads[0] - g.ball_loads[1]))
    return arm * sum(sym.ball_loads) * load_contrast(rig, minuend, subtrahend, 4 / 3) / \
        rig.rolling_inertia


def _decay(v) -> tuple[float, float]:
    """The asymmetric group's own change of acceleration over the track (rad/s², its
    group-specific track's straight line) and the track's length (m)."""
    rig, gw = v.rig, v.groupwise
    gi = v.data.group_names.index(asymmetric_group(rig).name)
    beta, _, _, _ = gw.layout.split(gw.x)
    s = np.linspace(0.0, float(np.max(v.data.angles)), 241)
    b = beta[gi if beta.shape[0] > 1 else 0]
    x = s * rig.ball_radius
    slope = np.polyfit(x, track_acceleration(s, b, gw.layout.span), 1)[0]
    return float(slope * x[-1]), float(x[-1])


def settling_experiment(v) -> Experiment | None:
    """What would settle the question with this rig (``v`` with a rig).

    Parameters
    ----------
    v : RotorVerdict
        A verdict of :func:`judge_table` with a rig.

    Returns
    -------
    Experiment or None
        For friction arms at the bound, 20 µm and 5 µm, on the rig's loads and on a larger
        load contrast: the offset ``lambda = 4/3`` makes and the launches per group that
        tell it from 1; None without a rig.

    See Also
    --------
    sensitivity_table

    Examples
    --------
    At the contact-radius arm the paper's loads need hundreds of launches per group; a
    larger load contrast needs a handful:

    >>> import numpy as np
    >>> from rotor import judge_table, paper_rig, settling_experiment, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> verdict = judge_table(table3(), groups, fps=120.0, step=np.pi / 2, rig=paper_rig(),
    ...                       permutation=False)
    >>> rows = settling_experiment(verdict).rows
    >>> print(rows[0].loads, rows[0].launches)
    5.36/3.97 N against 4.67/4.67 N 433
    >>> print(rows[3].loads, rows[3].launches)
    6.7/2.6 N against 4.65/4.65 N 8
    """
    rig, o = v.rig, v.offset
    if rig is None or v.arm is None:
        return None
    rows = []
    a_g = asymmetric_group(rig)
    sym = next(g for g in rig.groups if g.name != a_g.name)
    total = sum(LARGER_CONTRAST)
    big = replace(rig, groups=tuple(
        replace(g, ball_loads=LARGER_CONTRAST) if g.name == a_g.name
        else replace(g, ball_loads=(total / 2, total / 2)) for g in rig.groups))
    for r, loads in ((rig, f"{a_g.ball_loads[0]:.3g}/{a_g.ball_loads[1]:.3g} N against "
                           f"{sym.ball_loads[0]:.3g}/{sym.ball_loads[1]:.3g} N"),
                     (big, f"{LARGER_CONTRAST[0]:g}/{LARGER_CONTRAST[1]:g} N against "
                           f"{total / 2:.3g}/{total / 2:.3g} N")):
        for arm, basis in ((v.arm.arm_bound, "at the bound (the contact radius)"),
                           (20e-6, "20 µm"), (5e-6, "5 µm")):
            eff = _offset_4_3(r, o.minuend, o.subtrahend, arm)
            rows.append(ExperimentRow(arm, basis, loads, eff, launches_needed(eff, o.launch_sd)))
    d_eps, length = _decay(v)
    d_theta = abs(d_eps) * rig.rolling_inertia / (rig.mass * G_STANDARD * rig.ball_radius)
    return Experiment(tuple(rows), d_theta, length, d_theta * length / 8.0, o.launch_sd)
