"""JSON record of a flat rough contact (``surfmet flat-contact``): the BEM at each nominal
pressure against the Persson, Greenwood-Williamson and Bush-Gibson-Thomas theories."""

from __future__ import annotations

import math
from typing import Any

from contact._record import combine
from surfmet.records._preparation import flat_preparation_record
from surfmet.records._solve import solve_record
from surfmet.records._spectrum import spectrum_record
from surfmet.units import quantity


def _rel(model: float | None, ref: float) -> float | None:
    if model is None or not (math.isfinite(ref) and ref != 0):
        return None
    return float(model / ref - 1.0)


def flat_contact_record(rep: Any) -> dict[str, Any]:
    """JSON-ready record (every dimensional value with its unit)."""
    s = rep.spectrum
    srec = spectrum_record(s)
    srec.pop("psd")
    bem = rep.bem
    results = []
    for i, pt in enumerate(bem.points):
        row: dict[str, Any] = {
            "pressure": quantity(pt.pressure, "Pa"),
            "bem": {
                "area_fraction": pt.area_fraction,
                "corrected_area_fraction": pt.corrected_area_fraction,
                "mean_gap": quantity(pt.mean_gap, "m"),
                "stiffness": quantity(pt.stiffness, "Pa/m"),
                "n_clusters": pt.n_clusters,
                "max_pressure": quantity(pt.max_pressure, "Pa"),
                "plastic_fraction": pt.plastic_fraction,
                "kappa": float(pt.area_fraction * bem.e_star * s.slope_rms / pt.pressure),
                "kappa_corrected": float(pt.corrected_area_fraction * bem.e_star
                                         * s.slope_rms / pt.pressure),
                "iterations": pt.iterations,
                "converged": pt.converged,
                "solve": solve_record(pt.solve),
            },
        }
        for name, m in rep.models.items():
            a = float(m.area_fraction[i])
            gap = None if m.mean_gap is None else float(m.mean_gap[i])
            k = None if m.stiffness is None else float(m.stiffness[i])
            row[name] = {
                "area_fraction": a,
                "mean_gap": quantity(gap, "m"),
                "stiffness": quantity(k, "Pa/m"),
                "kappa": float(a * bem.e_star * s.slope_rms / pt.pressure),
                "relative_error": {
                    "area_fraction": _rel(a, pt.area_fraction),
                    "mean_gap": _rel(gap, pt.mean_gap),
                    "stiffness": _rel(k, pt.stiffness),
                },
            }
        if rep.adhesion is not None:
            row["adhesive"] = _adhesive_row(rep.adhesion.points[i], pt)
        results.append(row)
    rec = {
        "boundary": "periodic" if bem.periodic else "free",
        "levelling": rep.levelling,
        "grid": {"nx": bem.shape[1], "ny": bem.shape[0], "dx": quantity(bem.dx, "m"),
                 "dy": quantity(bem.dy, "m")},
        "e_star": quantity(bem.e_star, "Pa"),
        "hardness": quantity(bem.hardness, "Pa"),
        "spectrum": srec,
        "scan_preparation": flat_preparation_record(rep.preparation),
        "caveats": [*srec["caveats"], *rep.caveats],
        "results": results,
        "solve": solve_record(bem.solve),
        "notes": [
            *bem.notes,
            "BGT gives the area only (its load-separation law has no closed form)",
            "relative_error = model / BEM - 1; the BEM area counts whole cells, the "
            "corrected area removes the perimeter bias (Yastrebov et al. 2015)",
        ],
    }
    if rep.adhesion is not None:
        rec["adhesion"] = _adhesion_header(rep.adhesion)
    return rec


def _adhesion_header(ad: Any) -> dict[str, Any]:
    """The law and resolution of an adhesive sweep."""
    from surfmet.mechanics.adhesion import interaction_name

    law = ad.law
    return {
        "interaction": interaction_name(law),
        "work_of_adhesion": quantity(law.work, "J/m^2"),
        "range": quantity(law.range, "m"),
        "peak_tension": quantity(law.peak, "Pa"),
        "step_smoothing": quantity(law.smoothing, "m"),
        "process_zone": quantity(ad.process_zone, "m"),
        "process_zone_pixels": quantity(ad.process_zone / ad.dx, ""),
        "warnings": list(ad.warnings),
        "solve": solve_record(combine([pt.solve for pt in ad.points],
                                      "adhesive, per pressure (" + "; ".join(
                                          sorted({pt.solve.method for pt in ad.points}))
                                      + ")")),
        "notes": ["per pressure, 'adhesive' is the periodic adhesive solve and 'bem' the "
                  "non-adhesive one; attractive_pressure is the law's tension averaged over "
                  "the nominal area, touching points included: pressure = repulsive - "
                  "attractive; mean_gap is the mean of the deformed gap over all cells "
                  "(zero where touching: the mean separation, as Tamaas' gap field), "
                  "mean_gap_out_of_contact its mean over the cells apart only"],
    }


def _adhesive_row(a: Any, bare: Any) -> dict[str, Any]:
    """One pressure of an adhesive sweep, with its change from the non-adhesive solve."""
    return {
        "pressure": quantity(a.pressure, "Pa"),
        "contact_area_fraction": quantity(a.area_fraction, ""),
        "mean_gap": quantity(a.mean_gap, "m"),
        "mean_gap_out_of_contact": quantity(a.mean_gap_out_of_contact, "m"),
        "attractive_pressure": quantity(a.attractive_pressure, "Pa"),
        "repulsive_pressure": quantity(a.repulsive_pressure, "Pa"),
        "approach": quantity(a.approach, "m"),
        "relative_change": {"contact_area_fraction": _rel(a.area_fraction, bare.area_fraction),
                            "mean_gap": _rel(a.mean_gap, bare.mean_gap)},
        "solves": a.solves,
        "iterations": a.iterations,
        "solve": solve_record(a.solve),
    }
