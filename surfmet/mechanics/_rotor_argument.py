"""The rotor verdict's evidence in words and JSON: the design's permutation p beside the
model's, the friction arm against its physical bound (:mod:`rotor.arm`), the rig
used, and the table of the four differences with the two misread rules
(:mod:`rotor.reconcile`). Called by :mod:`surfmet.mechanics.rotor_verdict`, whose
:func:`~surfmet.mechanics.rotor_verdict.verdict_record` is the one record builder.
"""

from __future__ import annotations

import math
from typing import Any

from surfmet.units import quantity

__all__ = ["argument_lines", "argument_record", "differences_lines", "differences_record",
           "lane_line", "lane_record", "permutation_line", "permutation_record",
           "rig_record", "windows_lines", "windows_record"]

LOWER_BOUND = ("a lower bound on lambda conditional on the slope, not a confidence interval: "
               "a smaller arm (a smaller slope) needs a larger lambda, and lambda -> infinity "
               "as the slope falls to where the rolling torque vanishes")


def _interval(value: float, low: float, high: float, unit: str) -> dict[str, Any]:
    q = quantity(value, unit)
    q.update(ci_low=quantity(low, unit)["value"], ci_high=quantity(high, unit)["value"])
    return q


def permutation_record(v: Any) -> dict[str, Any] | None:
    """``verdict.permutation_p``: the design's exact permutation test."""
    pt = v.permutation
    if pt is None:
        return None
    return {
        "shared_track_f": quantity(pt.f_p, ""), "offset": quantity(pt.offset_p, ""),
        "n_splits": pt.n_splits, "exact": pt.exact, "f_rank": pt.f_rank,
        "smallest_possible": quantity(pt.smallest_p, ""),
        "f_by_split": [quantity(f, "") for f in pt.f_values],
        "offset_by_split": [quantity(o, "rad/s^2") for o in pt.offsets],
        "model_calibrated_p": quantity(v.shared_track_p, ""),
        "weaker_p": quantity(v.weaker_p, ""),
        "over": "the launches' group labels: every split of the launches into groups of the "
                "table's sizes (a split and its mirror counted once), the real one first",
        "wording_follows": "the weaker of the model-calibrated p and this one",
    }


def permutation_line(v: Any) -> str | None:
    pt = v.permutation
    if pt is None:
        return None
    return (f"  the design's own evidence: exact permutation p = {pt.f_p:.2g} for the shared-"
            f"track F (rank {pt.f_rank} of {pt.n_splits} splits of the launches into groups"
            f"{'' if pt.exact else ', sampled'}; the smallest the design allows is "
            f"{pt.smallest_p:.2g}), {pt.offset_p:.2g} for the offset; the wording follows the "
            f"weaker p = {v.weaker_p:.2g}")


def rig_record(rig: Any) -> dict[str, Any] | None:
    """``verdict.rig``: the rig the verdict used."""
    if rig is None:
        return None
    from rotor import paper_rig

    return {
        "source": ("the paper's rotor (analytic mass properties of its printed parts) and "
                   "Table 3's groups" if rig == paper_rig() else "the --rig file"),
        "ball_radius": quantity(rig.ball_radius, "m"), "mass": quantity(rig.mass, "kg"),
        "axial_inertia": quantity(rig.axial_inertia, "kg m^2"),
        "rolling_inertia": quantity(rig.rolling_inertia, "kg m^2"),
        "fps": quantity(rig.fps, "1/s"), "step": quantity(rig.step, "rad"),
        "slope": quantity(rig.slope, "rad"),
        "groups": [{"name": g.name, "columns": list(g.columns),
                    "ball_loads": [quantity(n, "N") for n in g.ball_loads]}
                   for g in rig.groups]}


def argument_record(v: Any, rough: Any = None) -> dict[str, Any]:
    """The arm fields of ``verdict``: ``friction_arm``, ``arm_bound`` (with the rough
    contact's extent, a :class:`~surfmet.mechanics.rotor_rough_bound.RoughArmBound`, where
    given), ``lambda_at_arm_bound``, ``slope_lambda_4_3`` (and ``arm_lambda_4_3``)."""
    b = v.arm
    if b is None:
        return {"friction_arm": None, "arm_bound": None, "lambda_at_arm_bound": None,
                "slope_lambda_4_3": None, "arm_lambda_4_3": None}
    ends = "at the offset's interval ends nearer to and farther from zero"
    d = _deciding(v, rough)  # the lambda at the bound is at the radius that decides
    return {
        "friction_arm": {"arm": quantity(b.friction_arm, "m"), "lambda": 1,
                         "slope": quantity(b.slope, "rad"),
                         "ratio_to_bound": quantity(b.arm_ratio, ""),
                         "formula": "s_r = (M g R sin(theta) - eps_mean (J + M R^2)) / sum N"},
        "arm_bound": {"radius": quantity(b.arm_bound, "m"), "basis": b.bound_basis,
                      "load": quantity(b.bound_load, "N"), "group": b.bound_group,
                      "e_star": quantity(b.e_star, "Pa"), **_rough_record(rough, b)},
        "lambda_at_arm_bound": {
            "lambda": {**_interval(d.lambda_at_bound, d.lambda_low, d.lambda_high, ""),
                       "level": v.offset.level},
            "interval": "over the offset's interval, at the slope where s_r = a",
            "meaning": LOWER_BOUND, "slope": quantity(d.slope_at_bound, "rad"),
            "radius": quantity(d.arm_bound, "m"), "basis": d.bound_basis,
            "slope_lambda_infinite": quantity(d.slope_lambda_infinite, "rad")},
        "slope_lambda_4_3": {"slope": _interval(b.slope_4_3, b.slope_4_3_low,
                                                b.slope_4_3_high, "rad"), "interval": ends},
        "arm_lambda_4_3": {"arm": _interval(b.arm_4_3, b.arm_4_3_low, b.arm_4_3_high, "m"),
                           "interval": ends},
    }


def _deciding(v: Any, rough: Any) -> Any:
    if rough is None:
        return v.arm
    from surfmet.mechanics.rotor_rough_bound import deciding_bound

    return deciding_bound(v, rough)


def _rough_record(rough: Any, b: Any) -> dict[str, Any]:
    if rough is None:
        return {}
    from surfmet.mechanics.rotor_rough_bound import rough_bound_record

    return rough_bound_record(rough, b.friction_arm)


def _rough_lines(rough: Any, b: Any) -> list[str]:
    if rough is None:
        return []
    from surfmet.mechanics.rotor_rough_bound import rough_bound_line

    return rough_bound_line(rough, b.friction_arm)


def _deg(x: float) -> str:
    return f"{math.degrees(x):.3g} deg" if math.isfinite(x) else "none (beyond 90 deg)"


def argument_lines(v: Any, rough: Any = None) -> list[str]:
    """The arm argument in words (after the exponent's line; the rough contact's extent
    after the friction arm's line, where given)."""
    b, rig = v.arm, v.rig
    if b is None:
        return []
    verdict = ("impossible: the normal force's resultant lies inside the contact, s_r <= a"
               if b.arm_ratio > 1 else "inside the bound")
    if rough is not None:
        verdict += " (by Hertz's radius alone)"
    d = _deciding(v, rough)
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


def differences_record(v: Any, analysis: Any) -> dict[str, Any]:
    """``verdict.differences`` and ``verdict.misread_rules`` for a table's verdict and its
    per-test analysis."""
    from rotor import differences_table, misread_rules

    o = v.offset
    rows = []
    for d in differences_table(v, analysis):
        rows.append({"label": d.label, "model": d.model,
                     "difference": {**quantity(d.value, "rad/s^2"),
                                    "stderr": quantity(d.stderr, "rad/s^2")["value"],
                                    "ci_low": quantity(d.ci_low, "rad/s^2")["value"],
                                    "ci_high": quantity(d.ci_high, "rad/s^2")["value"]},
                     "where": d.where, "model_fits": d.fits, "fit_evidence": d.fit_evidence,
                     "used_by_verdict": d.used_by_verdict, "role": d.role})
    m = misread_rules(v, analysis)
    return {
        "differences": {"of": f"{o.minuend} - {o.subtrahend}", "rows": rows},
        "misread_rules": {
            "joint": [{"column": c, "k": k} for c, k in m.joint],
            "per_test": [{"column": c, "k": k} for c, k in m.per_test],
            "only_per_test": [{"column": c, "k": k, "joint_residual_frames": quantity(r, "frame"),
                               "joint_residual_sigmas": quantity(z, "")}
                              for c, k, r, z in m.only_per_test],
            "only_joint": [{"column": c, "k": k} for c, k in m.only_joint],
            "why_they_differ": _why(),
            "joint_without_both": {
                "group_offset": {**quantity(m.offset, "rad/s^2"), "ci_low": m.offset_ci[0],
                                 "ci_high": m.offset_ci[1], "level": o.level},
                "f_statistic": quantity(m.f_statistic, ""),
                "shared_track_outcome_unchanged": bool(
                    (m.f_statistic > v.f_critical) == (not v.shared_track_adequate))}},
    }


def _why() -> str:
    return ("the joint model flags a row off one shared track by more than 4 sigma and 1.5 "
            "frames, sigma its launch's reading noise estimated from that shared track's "
            "residuals, so a launch the shared track misfits gets a larger sigma and keeps "
            "rows the per-test analysis leaves out; the per-test analysis judges each row by "
            "its exact leave-one-out error under the launch's own flexible model")


def differences_lines(v: Any, analysis: Any) -> list[str]:
    """The table of the four differences and the misread rules, in words."""
    rec = differences_record(v, analysis)
    lines = [f"the four differences ({rec['differences']['of']}, rad/s²): which model, does it "
             f"fit, which the verdict uses",
             f"  {'model':8s} {'difference':>22s}  {'fits':7s} {'verdict':8s} what"]
    for r in rec["differences"]["rows"]:
        d = r["difference"]
        val = f"{d['value']:+.3f} ± {d['stderr']:.3f}"
        if d["ci_low"] is not None:
            val = f"{d['value']:+.3f} [{d['ci_low']:+.3f}, {d['ci_high']:+.3f}]"
        lines.append(f"  {r['model']:8s} {val:>22s}  {r['fit_evidence'].split(':')[0]:7s} "
                     f"{'USED' if r['used_by_verdict'] else '-':8s} {r['label']}; {r['where']}")
        lines.append(f"  {'':8s} {'':22s}  {r['fit_evidence']}")
    m = rec["misread_rules"]

    def rows(xs: list[dict[str, Any]]) -> str:
        return ", ".join(f"{x['column']} k={x['k']}" for x in xs) or "none"

    lines.append(f"  misread rows: the joint model leaves out {len(m['joint'])} "
                 f"({rows(m['joint'])}), the per-test analysis {len(m['per_test'])} "
                 f"({rows(m['per_test'])})")
    for x in m["only_per_test"]:
        lines.append(f"    {x['column']} k={x['k']}: off the shared track by "
                     f"{x['joint_residual_frames']['value']:+.1f} frames = "
                     f"{x['joint_residual_sigmas']['value']:+.1f} sigma there: kept by the "
                     f"joint model")
    j = m["joint_without_both"]
    lines.append(f"    why: {m['why_they_differ']}; with both rules' rows left out the joint "
                 f"model gives {j['group_offset']['value']:+.3f} rad/s² "
                 f"[{j['group_offset']['ci_low']:+.3f}, {j['group_offset']['ci_high']:+.3f}], "
                 f"F = {j['f_statistic']['value']:.1f}: the shared-track test's outcome "
                 f"{'does not change' if j['shared_track_outcome_unchanged'] else 'CHANGES'}")
    return lines


def _num(x: float) -> float | None:
    return float(x) if math.isfinite(x) else None


def windows_record(w: Any) -> dict[str, Any] | None:
    """``verdict.track_difference.windowed``: the model-free windowed accelerations
    (:mod:`rotor.windows`) and where they resolve the difference."""
    if w is None:
        return None

    def group(gw: Any) -> list[dict[str, Any]]:
        return [{"mean": quantity(_num(m), "rad/s^2"), "stderr": quantity(_num(e), "rad/s^2"),
                 "launches": int(n)} for m, e, n in zip(gw.mean, gw.stderr, gw.n, strict=True)]

    return {
        "method": "per launch, per window, a parabola phi(t) = c0 + c1 tau + c2 tau^2 "
                  "through the marks' crossing times (no track model): eps = 2 c2; a "
                  "group's value the launches' mean with the larger of the propagated and "
                  "the scatter's standard error",
        "window_length": quantity(w.window_length, "m"),
        "windows": [{"centre": quantity(float(c), "m"),
                     "difference": quantity(_num(d), "rad/s^2"),
                     "stderr": quantity(_num(e), "rad/s^2"), "resolved": bool(r)}
                    for c, d, e, r in zip(w.centres, w.difference, w.stderr, w.resolved,
                                          strict=True)],
        "minuend": group(w.minuend), "subtrahend": group(w.subtrahend),
        "trend": quantity(_num(w.trend), "rad/s^2/m"),
        "trend_stderr": quantity(_num(w.trend_stderr), "rad/s^2/m"),
        "resolved_anywhere": bool(w.resolved.any()),
    }


def windows_lines(v: Any) -> list[str]:
    """The model-free windows in words, one line per window (after the verdict's lines)."""
    d = v.difference
    w = None if d is None else d.windows
    if w is None:
        return []
    o = v.offset
    lines = [f"  model-free windowed accelerations ({o.minuend} - {o.subtrahend}, rad/s², "
             f"windows of {w.window_length * 1e3:.0f} mm; resolved: beyond two standard "
             f"errors): trend {w.trend:+#.2g} ± {w.trend_stderr:#.2g} rad/s² per m, the "
             f"joint model's {d.trend:+#.3g} ± {d.trend_stderr:#.2g}"]
    for c, dv, e, r in zip(w.centres, w.difference, w.stderr, w.resolved, strict=True):
        lines.append(f"    at {c * 1e3:5.0f} mm  {dv:+8.3f} ± {e:6.3f}  "
                     f"{'resolved' if r else 'not resolved'}")
    return lines


def lane_record(v: Any) -> dict[str, Any] | None:
    """``verdict.lane_test``: do the groups' tracks differ more than the launches' within a
    group do (:mod:`rotor.lanes`), with its calibration's held-out rates."""
    lt = v.lanes
    if lt is None:
        return None
    from rotor import lane_calibration

    cal = lane_calibration()

    def power(rows: list[dict]) -> list[dict[str, Any]]:
        return [{"abs_offset": quantity(r["abs_offset_rad_s2"], "rad/s^2"), "tables": r["n"],
                 "difference_rate": quantity(r["difference_rate"], ""),
                 "true_offset_in_ci_when_difference": quantity(
                     r["true_offset_in_ci_when_difference"], "")}
                for r in rows]

    held = cal["held_out"]
    return {
        "f_statistic": quantity(lt.f, ""), "dof": [lt.q_g, lt.q_l],
        "p_nominal": quantity(lt.p_nominal, ""), "p_critical": quantity(lt.p_critical, ""),
        "calibrated_p": quantity(lt.p, ""), "groups_differ": lt.groups_differ,
        "launch_f": quantity(lt.launch_f, ""),
        "rule": cal["rule"], "prior": cal["prior"], "generated_by": cal["generated_by"],
        "tables": cal["tables"], "split": cal["split"],
        "false_difference_zero_offset": {k: quantity(held[k]["difference"], "")
                                         for k in ("null0", "lane0")},
        "false_undetermined_zero_offset": {k: quantity(held[k]["undetermined"], "")
                                           for k in ("null0", "lane0")},
        "held_out_tables": {k: held[k]["n"] for k in held},
        "power_by_offset_lanes": power(cal["power_by_offset_lanes"]),
        "power_by_offset_no_lanes": power(cal["power_by_offset_no_lanes"]),
        "undetermined_rate_group_tracks": {k: quantity(held[k]["undetermined"], "")
                                           for k in ("track", "lanetrack")},
    }


def lane_line(v: Any) -> str | None:
    """The lane test in one line (after the shared-track test's)."""
    lt = v.lanes
    if lt is None:
        return None
    return (f"  lane test (do the groups' tracks differ more than the launches' within a "
            f"group?): F = {lt.f:.2f} on {lt.q_g} and {lt.q_l} dof, nominal p = "
            f"{lt.p_nominal:.2g} (critical {lt.p_critical:.2g}, calibrated with launch-level "
            f"lanes in the null): {'yes' if lt.groups_differ else 'no'}; the launches' own "
            f"tracks differ by F = {lt.launch_f:.2f} per parameter over the noise")
