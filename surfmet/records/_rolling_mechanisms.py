"""The JSON record of the rolling mechanisms side by side (``surfmet rolling --model all``,
:func:`surfmet.mechanics.viscoelastic_rolling.rolling_mechanisms`): every value with its
unit."""

from __future__ import annotations

from typing import Any

from surfmet.mechanics.viscoelastic_rolling import reaches_offset
from surfmet.records._rolling import sweep_solve
from surfmet.units import quantity

__all__ = ["mechanisms_record"]


def mechanisms_record(rep: Any) -> dict[str, Any]:
    """The record of ``surfmet rolling --model all``
    (:class:`surfmet.mechanics.viscoelastic_rolling.MechanismsReport`): each mechanism's
    moments at the rotor's loads and its sweep, the dominant one, the rotor verdict and its
    group offset, every value with its unit."""
    from contact.viscoelastic._mechanisms import BOUNDS_ONLY
    from surfmet.mechanics._rotor_sensitivity import label_swap_text
    from surfmet.records._rotor_verdict import offset_record

    c = rep.comparison
    name, factor = c.dominant()
    rows = {}
    for m in c.mechanisms:
        rows[m.name] = {
            "moments_at_rotor_loads": quantity(list(m.rotor_moments), "N m"),
            "lambda_eff": quantity(m.sweep.lambda_eff, ""),
            "lambda_ci": quantity(list(m.sweep.lambda_ci), ""),
            "local_lambda_rotor": quantity(m.local_lambda, ""),
            "sweep_loads": quantity(m.sweep.loads, "N"),
            "sweep_moments": quantity(m.sweep.moments, "N m"),
            "raw_second_difference": quantity(
                m.rotor_moments[1] + m.rotor_moments[2] - 2 * m.rotor_moments[0], "N m"),
            "delta_eps": quantity(m.delta_eps, "rad/s^2"),
            "can_explain_offset": bool(reaches_offset(m.delta_eps, rep.verdict.offset)),
            "assumption": m.assumption,
            "ranked": m.name not in BOUNDS_ONLY,
            **sweep_solve(m.sweep),
        }
    return {"model": "all", "mechanisms": rows,
            "rotor_loads": quantity(list(c.rotor_loads), "N"),
            "rolling_inertia": quantity(c.rolling_inertia, "kg m^2"),
            "dominant": name, "dominant_factor": quantity(factor, ""),
            "verdict": {"code": rep.verdict.code, "sentence": rep.verdict.sentence,
                        "label_swap": label_swap_text(rep.verdict)},
            "group_offset": offset_record(rep.verdict),
            "assumptions": {k: quantity(v, _UNITS.get(k, "")) for k, v in
                            c.assumptions.items()},
            "notes": list(rep.notes)}


_UNITS = {"speed": "m/s", "hardness": "Pa", "peak_time": "s",
          "contact_radius_symmetric": "m"}
