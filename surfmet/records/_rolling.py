"""JSON records of rolling resistance (``surfmet rolling``, the demo): one track's sweep, or
several track positions and the exponent of their mean moment."""

from __future__ import annotations

from typing import Any

from surfmet.mechanics.scan_preparation import pixel_source
from surfmet.records._preparation import preparation_record
from surfmet.records._solve import solve_record
from surfmet.units import quantity


def rolling_record(rep: Any) -> dict[str, Any]:
    """The ``rolling`` record of a :class:`surfmet.mechanics.rolling_resistance.RollingReport`."""
    s = rep.sweep
    st = dict(s.settings)
    settings = {
        "radius": quantity(rep.radius, "m"),
        "materials": {"ball": rep.ball_material.name, "plate": rep.plate_material.name},
        "e_star": quantity(st.get("e_star"), "Pa"),
        "hardness": quantity(st.get("hardness"), "Pa"),
        "alpha_h": quantity(st.get("alpha_h"), ""),
        "displacement_share": quantity(st.get("share"), ""),
        "kinematics": st.get("kinematics"),
        "band": quantity(st.get("band"), ""),
        "grid": st.get("grid"),
        "dx": quantity(st.get("dx"), "m"),
        "pixel_source": pixel_source(st["dx"], None if rep.scans is None else
                                     rep.scans.pair, rep.grid),
        "sigma": quantity(rep.scans.sigma if rep.scans is not None else 0.0, "m"),
        "confidence": quantity(s.fit.confidence if s.fit is not None else None, ""),
        "forces": quantity(s.forces, "N"),
        "notes": list(rep.notes),
        **({"microslip": st["microslip"]} if "microslip" in st else {}),
    }
    if rep.scans is not None:
        settings["scan_preparation"] = preparation_record(rep.scans)
    return {
        "lambda_eff": quantity(s.lambda_eff, ""),
        "lambda_ci": quantity(list(s.lambda_ci), ""),
        "loads": quantity(s.loads, "N"),
        "moments": quantity(s.moments, "N m"),
        "local_lambda": quantity(s.local_lambda, ""),
        "model": s.model,
        "settings": settings,
        **sweep_solve(s),
    }


def sweep_solve(sweep: Any) -> dict[str, Any]:
    """``{"solve": record}`` of a rolling sweep's contact solves (:attr:`contact._rolling.
    RollingSweep.solve`), or nothing for a sweep in closed form."""
    rec = sweep.solve
    return {} if rec is None else {"solve": solve_record(rec)}


def tracks_record(rep: Any) -> dict[str, Any]:
    """The ``rolling --positions`` record of a
    :class:`surfmet.mechanics.rolling_resistance.TrackReport`."""
    rows = []
    for t in rep.tracks:
        row: dict[str, Any] = {"offset": quantity(None if t["offset"] is None
                                                  else list(t["offset"]), "m")}
        if t.get("error"):
            row["error"] = t["error"]
        else:
            row.update({"moments": quantity(t["moments"], "N m"),
                        "lambda_eff": quantity(t["lambda"], "")})
        rows.append(row)
    return {"lambda_eff": quantity(rep.lambda_eff, ""),
            "lambda_ci": quantity(None if rep.fit is None else list(rep.fit.ci), ""),
            "loads": quantity(rep.loads, "N"),
            "mean_moments": quantity(rep.mean_moments, "N m"), "tracks": rows}


def visco_rolling_record(rep: Any) -> dict[str, Any]:
    """The record of ``surfmet rolling --model viscoelastic``
    (:class:`surfmet.mechanics.viscoelastic_rolling.ViscoRollingReport`): the sweep, its
    fit and settings, every value with its unit."""
    s = rep.sweep
    st = s.settings
    return {
        "model": "viscoelastic",
        "lambda_eff": quantity(s.lambda_eff, ""),
        "lambda_ci": quantity(list(s.lambda_ci), ""),
        "loads": quantity(s.loads, "N"),
        "moments": quantity(s.moments, "N m"),
        "rolling_resistance_coefficient": quantity(s.forces / s.loads, ""),
        "local_lambda": quantity(s.local_lambda, ""),
        "settings": {"radius": quantity(rep.radius, "m"),
                     "speed": quantity(st["speed"], "m/s"),
                     "bodies": [repr(b) for b in rep.bodies],
                     "grid": st["grid"], "dx": quantity(st["dx"], "m"),
                     "roughness": st["roughness"], "notes": list(rep.notes)},
        **sweep_solve(s),
    }
