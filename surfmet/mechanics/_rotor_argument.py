"""The rotor verdict's evidence in words: the design's permutation p beside the model's,
the friction arm against its physical bound (:mod:`rotor._arm`), the rig used, the
model-free windows, the lane test, and the table of the four differences with the two
misread rules (:mod:`rotor._reconcile`). Called by :mod:`surfmet.mechanics.rotor_verdict`;
the same evidence as JSON is :mod:`surfmet.records._rotor_verdict` (and the records it
gathers), which reads the sentences shared by both from here.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from surfmet.mechanics.rotor_rough_bound import deciding_bound, rough_bound_line

if TYPE_CHECKING:
    from collections.abc import Iterable

    from rotor import ArmBound, LawOfMotionAnalysis, RotorVerdict
    from surfmet.mechanics.rotor_rough_bound import RoughArmBound

__all__ = ["LOWER_BOUND", "MISREAD_WHY", "argument_lines", "differences_lines", "lane_line",
           "permutation_line", "windows_lines"]

LOWER_BOUND = ("a lower bound on lambda conditional on the slope, not a confidence interval: "
               "a smaller arm (a smaller slope) needs a larger lambda, and lambda -> infinity "
               "as the slope falls to where the rolling torque vanishes")


def permutation_line(v: RotorVerdict) -> str | None:
    pt = v.permutation
    if pt is None:
        return None
    return (f"  the design's own evidence: exact permutation p = {pt.f_p:.2g} for the shared-"
            f"track F (rank {pt.f_rank} of {pt.n_splits} splits of the launches into groups"
            f"{'' if pt.exact else ', sampled'}; the smallest the design allows is "
            f"{pt.smallest_p:.2g}), {pt.offset_p:.2g} for the offset; the wording follows the "
            f"weaker p = {v.weaker_p:.2g}")


def _rough_lines(rough: RoughArmBound | None, b: ArmBound) -> list[str]:
    if rough is None:
        return []
    return rough_bound_line(rough, b.friction_arm)


def _deg(x: float) -> str:
    return f"{math.degrees(x):.3g} deg" if math.isfinite(x) else "none (beyond 90 deg)"


def argument_lines(v: RotorVerdict, rough: RoughArmBound | None = None) -> list[str]:
    """The arm argument in words (after the exponent's line; the rough contact's extent
    after the friction arm's line, where given)."""
    b, rig = v.arm, v.rig
    if b is None or rig is None:  # the arm argument needs the rig (no --rig: no argument)
        return []
    verdict = ("impossible: the normal force's resultant lies inside the contact, s_r <= a"
               if b.arm_ratio > 1 else "inside the bound")
    if rough is not None:
        verdict += " (by Hertz's radius alone)"
    d = deciding_bound(v, rough)
    lam = (f"{d.lambda_at_bound:.3g} [{d.lambda_low:.3g}, {d.lambda_high:.3g}]"
           if math.isfinite(d.lambda_at_bound) else "none in 0.05-20")
    at = f"s_r = a = {d.arm_bound * 1e6:.0f} µm" if d is not b else "s_r = a"
    loads = ", ".join(f"{g.name} {g.ball_loads[0]:.3g}/{g.ball_loads[1]:.3g} N"
                      for g in rig.groups)
    return [
        f"  friction arm s_r = M_r/N (lambda = 1) at slope {_deg(b.slope)}: "
        f"{b.friction_arm * 1e3:.3g} mm = {b.arm_ratio:.2g} x the contact radius "
        f"a = {b.arm_bound * 1e6:.0f} µm (Hertz at group {b.bound_group}'s ball load "
        f"{b.bound_load:.3g} N, E* {b.e_star / 1e9:.3g} GPa): {verdict}",
        *_rough_lines(rough, b),
        f"  lambda at the arm bound ({at}, slope {_deg(d.slope_at_bound)}): {lam} over the "
        f"offset's interval; a lower bound conditional on the slope, not a confidence "
        f"interval (lambda -> infinity as the slope falls to {_deg(d.slope_lambda_infinite)}, "
        f"where the torque vanishes)",
        f"  lambda = 4/3 makes the offset only with s_r = {b.arm_4_3 * 1e3:.3g} mm "
        f"({b.arm_4_3 / d.arm_bound:.2g} x a) on a slope of {_deg(b.slope_4_3)} "
        f"({_deg(b.slope_4_3_low)} to {_deg(b.slope_4_3_high)} over the offset's interval)",
        f"  rig: R = {rig.ball_radius * 1e3:.3g} mm, M = {rig.mass:.4g} kg, "
        f"J = {rig.axial_inertia:.4g} kg m², ball loads {loads}",
    ]


MISREAD_WHY = ("the joint model flags a row off one shared track by more than 4 sigma and 1.5 "
               "frames, sigma its launch's reading noise estimated from that shared track's "
               "residuals, so a launch the shared track misfits gets a larger sigma and keeps "
               "rows the per-test analysis leaves out; the per-test analysis judges each row "
               "by its exact leave-one-out error under the launch's own flexible model")
"""Why the two misread rules differ (the text and the JSON's ``why_they_differ``)."""


def differences_lines(v: RotorVerdict, analysis: LawOfMotionAnalysis) -> list[str]:
    """The table of the four differences and the misread rules, in words."""
    from rotor import differences_table, misread_rules

    o = v.offset
    lines = [f"the four differences ({o.minuend} - {o.subtrahend}, rad/s²): which model, does "
             f"it fit, which the verdict uses",
             f"  {'model':8s} {'difference':>22s}  {'fits':7s} {'verdict':8s} what"]
    for d in differences_table(v, analysis):
        val = f"{d.value:+.3f} ± {d.stderr:.3f}"
        if math.isfinite(d.ci_low):
            val = f"{d.value:+.3f} [{d.ci_low:+.3f}, {d.ci_high:+.3f}]"
        lines.append(f"  {d.model:8s} {val:>22s}  {d.fit_evidence.split(':')[0]:7s} "
                     f"{'USED' if d.used_by_verdict else '-':8s} {d.label}; {d.where}")
        lines.append(f"  {'':8s} {'':22s}  {d.fit_evidence}")
    m = misread_rules(v, analysis)

    def rows(xs: Iterable[tuple[str, int]]) -> str:
        return ", ".join(f"{c} k={k}" for c, k in xs) or "none"

    lines.append(f"  misread rows: the joint model leaves out {len(m.joint)} "
                 f"({rows(m.joint)}), the per-test analysis {len(m.per_test)} "
                 f"({rows(m.per_test)})")
    for c, k, r, z in m.only_per_test:
        lines.append(f"    {c} k={k}: off the shared track by {r:+.1f} frames = {z:+.1f} sigma "
                     f"there: kept by the joint model")
    unchanged = (m.f_statistic > v.f_critical) == (not v.shared_track_adequate)
    lines.append(f"    why: {MISREAD_WHY}; with both rules' rows left out the joint "
                 f"model gives {m.offset:+.3f} rad/s² "
                 f"[{m.offset_ci[0]:+.3f}, {m.offset_ci[1]:+.3f}], "
                 f"F = {m.f_statistic:.1f}: the shared-track test's outcome "
                 f"{'does not change' if unchanged else 'CHANGES'}")
    return lines


def windows_lines(v: RotorVerdict) -> list[str]:
    """The model-free windows in words, one line per window (after the verdict's lines)."""
    d = v.difference
    if d is None or d.windows is None:
        return []
    w = d.windows
    o = v.offset
    lines = [f"  model-free windowed accelerations ({o.minuend} - {o.subtrahend}, rad/s², "
             f"windows of {w.window_length * 1e3:.0f} mm; resolved: beyond two standard "
             f"errors): trend {w.trend:+#.2g} ± {w.trend_stderr:#.2g} rad/s² per m, the "
             f"joint model's {d.trend:+#.3g} ± {d.trend_stderr:#.2g}"]
    for c, dv, e, r in zip(w.centres, w.difference, w.stderr, w.resolved, strict=True):
        lines.append(f"    at {c * 1e3:5.0f} mm  {dv:+8.3f} ± {e:6.3f}  "
                     f"{'resolved' if r else 'not resolved'}")
    return lines


def lane_line(v: RotorVerdict) -> str | None:
    """The lane test in one line (after the shared-track test's)."""
    lt = v.lanes
    if lt is None:
        return None
    return (f"  lane test (do the groups' tracks differ more than the launches' within a "
            f"group?): F = {lt.f:.2f} on {lt.q_g} and {lt.q_l} dof, nominal p = "
            f"{lt.p_nominal:.2g} (critical {lt.p_critical:.2g}, calibrated with launch-level "
            f"lanes in the null): {'yes' if lt.groups_differ else 'no'}; the launches' own "
            f"tracks differ by F = {lt.launch_f:.2f} per parameter over the noise")
