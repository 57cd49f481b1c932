"""JSON records of every assumption's weight on the rotor verdict and of the experiment
that would settle the question with the verdict's rig (:func:`rotor.sensitivity_table`,
:func:`rotor.settling_experiment`).
"""

from __future__ import annotations

import math
from typing import Any

from surfmet.mechanics._rotor_sensitivity import (
    EXPERIMENT_DESIGN,
    EXPERIMENT_RECORDS,
    SAG_MEANING,
    experiment_for,
)
from surfmet.units import quantity

__all__ = ["experiment_record", "sensitivity_record"]


def _num(x: float) -> float | None:
    return float(x) if x is not None and math.isfinite(x) else None


def sensitivity_record(v: Any) -> list[dict[str, Any]]:
    """``verdict.sensitivity``: one row per assumption changed."""
    from rotor import sensitivity_table

    return [{"assumption": r.assumption, "setting": r.setting, "code": r.code,
             "offset": {"value": _num(r.offset), "unit": "rad/s^2", "ci_low": _num(r.ci_low),
                        "ci_high": _num(r.ci_high)},
             "lambda_needed": quantity(_num(r.lambda_needed), ""),
             "lambda_at_arm_bound": {"value": _num(r.lambda_bound), "unit": "",
                                     "ci_low": _num(r.lambda_bound_low),
                                     "ci_high": _num(r.lambda_bound_high)},
             "note": r.note} for r in sensitivity_table(v)]


def experiment_record(v: Any) -> dict[str, Any] | None:
    """``verdict.experiment``: what would settle the question with this rig."""
    from rotor import settling_experiment

    e = settling_experiment(v)
    if e is None:
        return None
    return {
        "launches_per_group": [
            {"arm": quantity(r.arm, "m"), "arm_basis": r.arm_basis, "loads": r.loads,
             "offset_lambda_4_3": quantity(r.offset_4_3, "rad/s^2"),
             "launches": r.launches,
             "launches_note": None if r.launches else "more than 100000"} for r in e.rows],
        "for": experiment_for(e),
        "straightedge_check": {
            "slope_change": quantity(e.slope_change, "rad"), "over": quantity(e.length, "m"),
            "concave_sag": quantity(e.sag, "m"),
            "meaning": SAG_MEANING},
        "design": EXPERIMENT_DESIGN,
        "record": list(EXPERIMENT_RECORDS),
    }
