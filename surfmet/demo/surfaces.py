"""The demo's surface steps: the shipped scans, row roughness, the plate's areal
parameters with and without spikes, and the ball's radius and form."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from rotor import BALL_RADIUS as RADIUS
from surfmet.demo.outputs import data_file
from surfmet.demo.settings import LC, PLATE_LEVEL, ROW_PARAMETERS
from surfmet.units import quantity


def load_scans() -> tuple[Any, Any, dict[str, Any]]:
    """The shipped plate and ball scans and their ``surfmet info`` records."""
    import surfmet
    from surfmet.records import scan_record

    plate = surfmet.read(data_file("paper_plate.x3p"))
    ball = surfmet.read(data_file("paper_ball.x3p"))
    rec = {}
    for name, scan in (("plate", plate), ("ball", ball)):
        d = scan_record(scan)
        d["file"] = Path(str(d["file"])).name if d["file"] else None
        d["nan_fraction"] = quantity(d["nan_fraction"], "")
        d.pop("metadata")
        rec[name] = d
    return plate, ball, rec


def row_statistics(scan: Any, level: str, lc: str = LC) -> tuple[dict[str, Any], Any]:
    """R-parameters of every row: median and quartiles, and the analysis of the row whose
    Ra is nearest the median (for the profile figure).

    The median over rows is the statistic the paper's Table 2 is compared with: a few rows
    of the plate carry spikes, which a mean would let through.
    """
    from surfmet.roughness import roughness

    values: dict[str, list[float]] = {k: [] for k in ROW_PARAMETERS}
    for k in range(scan.ny):
        res = roughness(scan, profile=f"row:{k}", level=level, lc=lc)
        for key in values:
            values[key].append(res.value(key))
    arr = {k: np.asarray(v) for k, v in values.items()}
    med = {k: float(np.median(v)) for k, v in arr.items()}
    row = int(np.argmin(np.abs(arr["Ra"] - med["Ra"])))
    typical = roughness(scan, profile=f"row:{row}", level=level, lc=lc)
    typical_settings = typical.to_json()["settings"]
    rec = {
        "rows": scan.ny,
        # the record's settings carry their units ({value, unit}), as the CLI's JSON does
        "settings": {"level": level, "lc": typical_settings.get("lc"),
                     "evaluation_length": typical_settings.get("evaluation_length"),
                     "filter": typical_settings.get("filter")},
        "median": {k: quantity(v, "m") for k, v in med.items()},
        "quartiles": {k: quantity(np.percentile(v, [25, 75]), "m") for k, v in arr.items()},
        "typical_row": row,
    }
    return rec, typical


def plate_areal(plate: Any) -> tuple[dict[str, Any], Any]:
    """Areal parameters of the levelled plate as scanned and with its spikes removed."""
    from surfmet.roughness import roughness

    which = ("height", "functional")
    raw = roughness(plate, level=PLATE_LEVEL, which=("Sa", "Sq", "Sku"))
    clean = roughness(plate, level=PLATE_LEVEL, spikes=True, which=which)
    sp = clean.spike_report
    rec = {
        "as_scanned": {
            "parameters": raw.to_json()["parameters"],
            "sq_over_sa": quantity(raw.value("Sq") / raw.value("Sa"), ""),
            "spikes_suspected": bool(raw.spike_diagnosis.suspected),
            "diagnosis": raw.spike_diagnosis.message,
        },
        "spikes_removed": {"count": int(sp.count), "points": int(sp.n_points),
                           "threshold": quantity(sp.threshold, "m")},
        "cleaned": {
            "parameters": clean.to_json()["parameters"],
            "sq_over_sa": quantity(clean.value("Sq") / clean.value("Sa"), ""),
            "gaussian_sq_over_sa": quantity(math.sqrt(math.pi / 2), ""),
        },
    }
    return rec, clean


def ball_form(ball: Any) -> tuple[dict[str, Any], Any]:
    """Sphere fit of the ball scan, and circle fits of the row and column through its apex."""
    import profiles
    from surfmet.extract import extract_profile
    from surfmet.fitting import fit_sphere
    from surfmet.records import fit_record

    fit = fit_sphere(ball)
    rec: dict[str, Any] = {"nominal_radius": quantity(RADIUS, "m"),
                           "sphere": fit_record(ball, "sphere")}
    dev = fit.radius - RADIUS
    rec["radius_minus_nominal"] = quantity(dev, "m")
    rec["radius_minus_nominal_in_uncertainties"] = quantity(dev / fit.radius_uncertainty, "")
    iy = min(max(round(fit.center[1] / ball.dy), 0), ball.ny - 1)
    ix = min(max(round(fit.center[0] / ball.dx), 0), ball.nx - 1)
    for key, spec in (("row_circle", f"row:{iy}"), ("column_circle", f"col:{ix}")):
        prof = extract_profile(ball, spec)
        c = profiles.fit_circle(np.asarray(prof.positions), np.asarray(prof.z))
        rec[key] = {"profile": spec, "radius": quantity(c.radius, "m"),
                    "radius_uncertainty": quantity(c.radius_uncertainty, "m")}
    residual = ball.replace(heights=np.asarray(fit.residuals))
    # the form deviation is the fit's own (rec["sphere"]["form_pv"], SphereFit.form_pv)
    return rec, residual

