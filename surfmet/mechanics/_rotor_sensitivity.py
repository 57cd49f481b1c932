"""Every assumption's weight on the rotor verdict, the experiment that would settle it, and
the paper's swapped labels, in words and JSON (:mod:`rotor.sensitivity`). Called by
:mod:`surfmet.mechanics.rotor_verdict`, so every entry point says them.
"""

from __future__ import annotations

import math
from typing import Any

from surfmet.units import quantity

__all__ = ["LABEL_SWAP", "experiment_lines", "experiment_record", "label_swap_text",
           "sensitivity_lines", "sensitivity_record"]

LABEL_SWAP = ("the paper's text labels its parabolas the other way round: its 'symmetric' "
              "phi_s fits Table 3's asymmetric columns and its phi_a the symmetric ones; the "
              "verdict reads Table 3's column labels (the asymmetric rotor slower, as the "
              "text also says); read with the text's labels the offset's sign flips, and "
              "with it the sign of lambda - 1")
"""What every entry point says about the paper's swapped phi_s/phi_a labels."""

def label_swap_text(v: Any) -> str | None:
    """The label swap, for the paper's rig and Table 3's groups; None for other rigs."""
    if v.rig is None:
        return None
    from rotor import paper_rig

    return LABEL_SWAP if v.rig == paper_rig() else None


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


def _lam(x: float) -> str:
    return f"{x:.3g}" if math.isfinite(x) else "none"


def sensitivity_lines(v: Any) -> list[str]:
    """The sensitivity table in words."""
    from rotor import sensitivity_table

    rows = sensitivity_table(v)
    if not rows:
        return []
    out = ["  every assumption's weight (code; offset rad/s²; lambda needed at the slope; "
           "least lambda with the arm at its bound, over the offset's interval):"]
    for r in rows:
        out.append(f"    {r.assumption + ': ' + r.setting:66s} {r.code:13s} "
                   f"{r.offset:+.3f}  {_lam(r.lambda_needed):>5s}  {_lam(r.lambda_bound)} "
                   f"[{_lam(r.lambda_bound_low)}, {_lam(r.lambda_bound_high)}]"
                   + (f"  ({r.note})" if r.note else ""))
    return out


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
        "for": f"lambda 4/3 told from 1 with {e.power * 100:g} % power at {e.alpha * 100:g} % "
               f"(two-sided), launch spread {e.launch_sd:.3g} rad/s²",
        "straightedge_check": {
            "slope_change": quantity(e.slope_change, "rad"), "over": quantity(e.length, "m"),
            "concave_sag": quantity(e.sag, "m"),
            "meaning": "the sag the asymmetric group's decay implies were the plate's shape "
                       "its cause (Delta theta L / 8): a straightedge along the lane shows "
                       "it or not"},
        "design": "both collar positions on one lane, interleaved in a randomised run order "
                  "(drawn before the session)",
        "record": ["alpha and beta at the lane (to 0.01 deg)",
                   "xi_G (both scales' readings for each collar position)",
                   "the run order and the time of each launch",
                   "the lane (lateral position of the release)"],
    }


def experiment_lines(v: Any) -> list[str]:
    """The experiment that would settle it, in words."""
    rec = experiment_record(v)
    if rec is None:
        return []
    out = [f"  the experiment that would settle it ({rec['for']}):"]
    for r in rec["launches_per_group"]:
        n = r["launches"] if r["launches"] else "more than 100000"
        out.append(f"    arm {r['arm']['value'] * 1e6:6.1f} µm ({r['arm_basis']}), loads "
                   f"{r['loads']}: lambda = 4/3 gives {r['offset_lambda_4_3']['value']:+.4f} "
                   f"rad/s², {n} launches per group")
    sc = rec["straightedge_check"]
    out += [f"    straightedge check: the asymmetric group's decay, were the plate's shape its "
            f"cause, means the slope falls {math.degrees(sc['slope_change']['value']):.2f} deg "
            f"over {sc['over']['value']:.2f} m, a concave sag of "
            f"{sc['concave_sag']['value'] * 1e3:.2f} mm",
            f"    design: {rec['design']}; record {', '.join(rec['record'])}"]
    return out
