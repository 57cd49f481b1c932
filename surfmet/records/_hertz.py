"""JSON records of a Hertz check (``surfmet hertz-check``, the demo, the report): the verdict
with Hertz against the BEM, the model hierarchy, and the details of every criterion."""

from __future__ import annotations

from typing import Any

from surfmet.mechanics.scan_preparation import pixel_source
from surfmet.records._contact import grid_record
from surfmet.records._hertz_adhesion import hertz_adhesion_record
from surfmet.records._preparation import preparation_record
from surfmet.records._solve import solve_record
from surfmet.units import quantity as _q


def hertz_check_record(check: Any) -> dict[str, Any]:
    """The ``hertz-check`` record with exactly the issue's keys (see
    :mod:`surfmet.mechanics.hertz_check`)."""
    c = check.comparison
    hz = c.hertz
    prof = c.profile
    return {
        "hertz_holds": bool(c.hertz_holds),
        "judged": bool(c.judged),
        "alpha": _q(c.alpha, ""),
        "sigma": _q(c.sigma, "m"),
        "hertz": {"a": _q(hz.a, "m"), "delta": _q(hz.delta, "m"), "p0": _q(hz.p0, "Pa")},
        "bem": {
            "pmax": _q(c.pmax, "Pa"),
            "effective_radius": _q(c.effective_radius, "m"),
            "contact_radius": _q(check.result.contact_radius, "m"),
            "approach": _q(c.approach, "m"),
            "area_fraction": _q(c.area_fraction, ""),
            "plastic_fraction": _q(c.plastic_fraction, ""),
        },
        "reasons": list(c.reasons),
        "grid": grid_record(check.result.shape, check.result.dx,
                            pixel_source(check.result.dx, check.scans.pair, check.grid)),
        "scan_preparation": preparation_record(check.scans),
        "warnings": check.warnings,
        "solve": solve_record(hertz_check_solve(check)),
        "radial_profile": {"r": _q(prof.r, "m"), "p_bem": _q(prof.p, "Pa"),
                           "p_hertz": _q(prof.p_hertz, "Pa")},
        **_models(check),
        **_adhesion(check),
    }


def hertz_check_solve(check: Any) -> Any:
    """The solve record of a Hertz check: the elastic solve's, or both solves' combined
    when the elastic-plastic one was made (:func:`contact._record.combine`)."""
    from contact._record import combine

    solves = [r.solve for r in (check.elastic, check.plastic) if r is not None]
    return combine(solves, "normal BEM, elastic then elastic-plastic"
                   if len(solves) > 1 else None)


def _adhesion(check: Any) -> dict[str, Any]:
    """The adhesion section, when a work of adhesion was given."""
    if getattr(check, "adhesion", None) is None:
        return {}
    return {"adhesion": hertz_adhesion_record(check.adhesion)}

def _models(check: Any) -> dict[str, Any]:
    h = check.hierarchy
    if h is None:
        return {}
    models = {
        name: {"effective_radius": _q(m.a_star, "m"), "approach": _q(m.approach, "m"),
               "peak_pressure": _q(m.peak, "Pa"),
               "radial_profile": {"r": _q(m.r, "m"), "p": _q(m.p, "Pa")},
               "radius_error": _q(m.radius_error, ""),
               "profile_error": _q(m.profile_error, "")}
        for name, m in h.models.items()
    }
    out: dict[str, Any] = {"models": models,
                           "verdict": {"model": h.verdict, "reasons": list(h.reasons)}}
    sp = check.summits
    if sp is not None:
        out["summits"] = {
            "density": _q(sp.density, "1/m^2"), "radius": _q(sp.radius, "m"),
            "sigma_s": _q(sp.sigma_s, "m"), "nayak_alpha": _q(sp.alpha, ""),
            "note": "spectral moments m0, m2, m4 of the plate and ball residuals summed "
                    "(independent surfaces); the summit density and radius depend on the "
                    "scans' lateral resolution (m2 and m4 grow as the pixel shrinks)",
        }
    return out

def hertz_check_details(check: Any) -> dict[str, Any]:
    """Inputs, every criterion, the elastic peak pressure, the grid and the notes."""
    c = check.comparison
    return {
        "load": _q(check.load, "N"),
        "radius": _q(check.radius, "m"),
        "materials": {"ball": check.ball_material.name, "plate": check.plate_material.name,
                      "e_star": _q(check.e_star, "Pa")},
        "hardness": _q(c.hardness, "Pa"),
        "sigma_plate": _q(check.scans.sigma_plate, "m"),
        "sigma_ball": _q(check.scans.sigma_ball, "m"),
        "elastic_pmax": _q(c.elastic_pmax, "Pa"),
        "profile_deviation": _q(c.profile_deviation, ""),
        "criteria": [{"name": k.name, "value": k.value, "limit": k.limit,
                      "passed": k.passed, "decisive": k.decisive} for k in c.criteria],
        "grid": {"n": check.result.shape[1], "dx": _q(check.result.dx, "m")},
        "notes": list(check.notes),
    }
