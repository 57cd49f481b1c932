"""JSON record of the four differences between the rotor's groups (which model, does it fit,
which the verdict uses) and of the two misread rules, the joint model's and the per-test
analysis' (:func:`rotor.differences_table`, :func:`rotor.misread_rules`).
"""

from __future__ import annotations

from typing import Any

from surfmet.mechanics._rotor_argument import MISREAD_WHY
from surfmet.units import quantity

__all__ = ["differences_record"]


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
            "why_they_differ": MISREAD_WHY,
            "joint_without_both": {
                "group_offset": {**quantity(m.offset, "rad/s^2"), "ci_low": m.offset_ci[0],
                                 "ci_high": m.offset_ci[1], "level": o.level},
                "f_statistic": quantity(m.f_statistic, ""),
                "shared_track_outcome_unchanged": bool(
                    (m.f_statistic > v.f_critical) == (not v.shared_track_adequate))}},
    }
