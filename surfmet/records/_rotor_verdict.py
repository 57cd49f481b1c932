"""JSON record of the rotor verdict (:func:`rotor.judge_table`): the one ``verdict`` object
``surfmet rotor --json``, the demo, the report and ``surfmet rolling --model all`` carry. Its
parts: the group offset, the shared-track test and its calibration, the track difference and
its model-free windows, the lane and permutation tests, the rig, the friction arm
(:mod:`surfmet.records._rotor_arm`), every assumption's weight and the settling experiment
(:mod:`surfmet.records._rotor_sensitivity`), and with the per-test analysis the four
differences (:mod:`surfmet.records._rotor_differences`).
"""

from __future__ import annotations

import math
from typing import Any

from surfmet.mechanics._rotor_sensitivity import label_swap_text
from surfmet.mechanics.rotor_verdict import shared_track_p_text
from surfmet.records._rotor_arm import argument_record
from surfmet.records._rotor_differences import differences_record
from surfmet.records._rotor_sensitivity import experiment_record, sensitivity_record
from surfmet.units import quantity

__all__ = ["lane_record", "offset_record", "permutation_record", "rig_record",
           "verdict_record", "windows_record"]


def offset_record(v: Any) -> dict[str, Any]:
    """The group offset as an interval quantity (the one JSON form every entry point uses)."""
    o = v.offset
    return {"value": o.value, "unit": "rad/s^2", "ci_low": o.ci_low, "ci_high": o.ci_high,
            "level": o.level, "minuend": o.minuend, "subtrahend": o.subtrahend}


def _calibration_record() -> dict[str, Any]:
    from rotor import verdict_calibration

    cal = verdict_calibration()
    st, ot = cal["shared_track_test"], cal["offset_test"]
    return {
        "tables": cal["tables"], "generated_by": cal["generated_by"],
        "shared_track_false_alarm": quantity(st["false_alarm_held_out"], ""),
        "shared_track_power_group_specific_tracks": quantity(st["power_group_specific_tracks"],
                                                             ""),
        "difference_false_alarm_zero_offset": quantity(ot["false_alarm_zero_offset"], ""),
        "difference_rate_lambda_4_3": quantity(ot["difference_rate_lambda_4_3"], ""),
        "difference_power_by_offset": [
            {"abs_offset": quantity(r["abs_offset_rad_s2"], "rad/s^2"), "tables": r["n"],
             "rate": quantity(r["rate"], "")} for r in ot["power_by_offset"]],
    }


def verdict_record(v: Any, analysis: Any = None, rough: Any = None) -> dict[str, Any]:
    """The JSON ``verdict`` object, the one record builder every entry point calls: every
    value a quantity with its unit (the group offset and the exponent as interval
    quantities).

    Parameters
    ----------
    v : RotorVerdict
        The verdict.
    analysis : rotor.LawOfMotionAnalysis, optional
        The table's per-test analysis (:func:`rotor.analyse_table`): adds
        the table of the four differences and the two misread rules.
    rough : surfmet.mechanics.rotor_rough_bound.RoughArmBound, optional
        The scanned contact's extent: added to ``arm_bound`` beside the Hertz radius.

    Returns
    -------
    dict
        The JSON object, every value ``{"value": v, "unit": u}``.

    See Also
    --------
    surfmet.mechanics.rotor_verdict.verdict_lines : the same in words.

    Examples
    --------
    >>> from surfmet.mechanics.rotor_verdict import paper_verdict
    >>> from surfmet.records._rotor_verdict import verdict_record
    >>> record = verdict_record(paper_verdict())
    >>> record["code"], record["group_offset"]["unit"]
    ('undetermined', 'rad/s^2')
    """
    rec = _verdict_record(v)
    rec["shared_track"]["p_text"] = shared_track_p_text(v)
    rec["permutation_p"] = permutation_record(v)
    rec["lane_test"] = lane_record(v)
    rec["rig"] = rig_record(v.rig)
    rec.update(argument_record(v, rough))
    rec.update(_sensitivity_fields(v))
    if analysis is not None:
        rec.update(differences_record(v, analysis))
    return rec


def _sensitivity_fields(v: Any) -> dict[str, Any]:
    """``label_swap``, ``sensitivity`` and ``experiment`` (:mod:`rotor._sensitivity`)."""
    return {"label_swap": label_swap_text(v), "sensitivity": sensitivity_record(v),
            "experiment": experiment_record(v)}


def _verdict_record(v: Any) -> dict[str, Any]:
    o = v.offset
    rec: dict[str, Any] = {
        "code": v.code, "sentence": v.sentence, "group_offset": offset_record(v),
        "group_offset_stderr": quantity(o.stderr, "rad/s^2"), "dof": o.dof,
        "launch_sd": quantity(o.launch_sd, "rad/s^2"),
        "shared_track": {"adequate": v.shared_track_adequate,
                         "p_value": quantity(v.shared_track_p, ""),
                         "f_statistic": quantity(v.f_statistic, ""),
                         "f_critical": quantity(v.f_critical, ""),
                         "track_degree": v.shared.layout.degree},
        "calibration": _calibration_record(),
        "mean_acceleration": quantity(v.mean_acceleration, "rad/s^2"),
        "misread_rows": [{"column": c, "k": k} for c, k in v.misread_rows],
        "lambda_needed": None, "launches_needed": None, "confounds": [],
    }
    d = v.difference
    if d is not None:
        rec["track_difference"] = {
            "trend": quantity(d.trend, "rad/s^2/m"),
            "trend_stderr": quantity(d.trend_stderr, "rad/s^2/m"),
            "waviness_rms": quantity(d.waviness_rms, "rad/s^2"),
            "windowed": windows_record(d.windows),
            "polynomial_end_values": {
                "note": "end values of the joint model's track polynomial, where it is least "
                        "constrained: not robust, never the headline",
                "at_release": quantity(d.start, "rad/s^2"),
                "at_last_mark": quantity(d.end, "rad/s^2"),
                "regions": [{"from": quantity(a, "m"), "to": quantity(b, "m")}
                            for a, b in d.regions]}}
    e = v.exponent
    if e is None:
        rec["note"] = "no rig: the lambda outputs and the confounds need --rig RIG.json"
        return rec
    rec["lambda_needed"] = {"value": e.value, "unit": "", "ci_low": e.ci_low,
                            "ci_high": e.ci_high, "level": o.level}
    rec["lambda_assumptions"] = {
        "slope": quantity(e.slope, "rad"), "slope_basis": e.slope_basis,
        "slope_lower_bound": quantity(e.slope_lower_bound, "rad"),
        "largest_offset_lambda_4_3": quantity(e.offset_lambda_4_3, "rad/s^2")}
    rec["launches_needed"] = e.launches  # a count, plain as every count in the records
    rec["launches_needed_for"] = "lambda 4/3 told from 1 with 90 % power at 2 % (two-sided)"
    rec["confounds"] = [{"name": c.name,
                         "equivalent_acceleration": quantity(c.equivalent_acceleration, "rad/s^2"),
                         "can_explain": c.can_explain, "formula": c.formula,
                         "assumption": c.assumption, "source": c.source,
                         **_moduli(c)}
                        for c in v.confounds]
    return rec


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


def _num(x: float) -> float | None:
    return float(x) if math.isfinite(x) else None


def windows_record(w: Any) -> dict[str, Any] | None:
    """``verdict.track_difference.windowed``: the model-free windowed accelerations
    (:mod:`rotor._windows`) and where they resolve the difference."""
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


def lane_record(v: Any) -> dict[str, Any] | None:
    """``verdict.lane_test``: do the groups' tracks differ more than the launches' within a
    group do (:mod:`rotor._lanes`), with its calibration's held-out rates."""
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


def _moduli(c: Any) -> dict[str, Any]:
    """The lateral creep's elastic constants and their basis (the rig's or the paper's
    pair), as a record's keys; none for the other confounds."""
    m = c.moduli
    if m is None:
        return {}
    return {"moduli": {"e_star": quantity(m.e_star, "Pa"),
                       "shear_modulus": quantity(m.shear, "Pa"), "basis": m.basis}}
