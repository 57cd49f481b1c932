"""JSON record of a resolution study (``--resolution-study``): per level the pixel, grid and
quantities with units; per quantity its trend; the verdict from converged quantities."""

from __future__ import annotations

from typing import Any

from surfmet.units import quantity


def study_record(study: Any) -> dict[str, Any]:
    """The study as JSON: per level the pixel, grid and quantities with units; per quantity
    its trend and whether it converged; the verdict from converged quantities only."""
    from surfmet.mechanics.resolution_study import QUANTITIES

    def q(name: str, v: float) -> Any:
        unit = QUANTITIES.get(name, (name, ""))[1]
        return quantity(v, unit) if unit != "1" else v

    levels = []
    for lv in study.levels:
        levels.append({"factor": lv.factor, "pixel": quantity(lv.pixel, "m"), "grid": lv.grid,
                       **{k: q(k, v) for k, v in lv.values.items()}})
    trends = {}
    for name, t in study.trends.items():
        trends[name] = {
            "converged": t.converged, "status": t.status,
            "last_change": t.last_change, "exponent": t.exponent, "order": t.order,
            "extrapolated": q(name, t.extrapolated), "expected": t.expected,
            "values": [q(name, v) for v in t.values],
        }
    out: dict[str, Any] = {
        "criterion": "converged: relative change below 2 % over the last halving of the "
                     "pixel",
        "side": quantity(study.side, "m"),
        "pixels": [quantity(p, "m") for p in study.pixels],
        "levels": levels, "trends": trends,
        "converged": list(study.converged), "keeps_moving": list(study.moving),
        "notes": list(study.notes),
    }
    holds, reasons, left = study.verdict()
    if study.finest.comparison is not None:
        out["verdict"] = {"hertz_holds": holds, "decided": holds is not None,
                          "reasons": list(reasons), "not_used": list(left)}
    return out
