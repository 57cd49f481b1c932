"""The demo's surface steps: the shipped scans, row roughness, the plate's areal
parameters with and without spikes, and the ball's radius and form."""

from __future__ import annotations

from typing import Any

import numpy as np

from rotor import BALL_RADIUS as RADIUS
from surfmet.demo._outputs import data_file
from surfmet.demo._settings import LC, PLATE_LEVEL, ROW_PARAMETERS
from surfmet.records._demo import (
    areal_record,
    ball_form_record,
    demo_scans_record,
    row_statistics_record,
)
from surfmet.records._roughness import roughness_record


def load_scans() -> tuple[Any, Any, dict[str, Any]]:
    """The shipped plate and ball scans and their ``surfmet info`` records."""
    import surfmet

    plate = surfmet.read(data_file("paper_plate.x3p"))
    ball = surfmet.read(data_file("paper_ball.x3p"))
    return plate, ball, demo_scans_record({"plate": plate, "ball": ball})


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
    row = int(np.argmin(np.abs(arr["Ra"] - float(np.median(arr["Ra"])))))
    typical = roughness(scan, profile=f"row:{row}", level=level, lc=lc)
    settings = roughness_record(typical)["settings"]
    return row_statistics_record(scan.ny, level, settings, arr, row), typical


def plate_areal(plate: Any) -> tuple[dict[str, Any], Any]:
    """Areal parameters of the levelled plate as scanned and with its spikes removed."""
    from surfmet.roughness import roughness

    which = ("height", "functional")
    raw = roughness(plate, level=PLATE_LEVEL, which=("Sa", "Sq", "Sku"))
    clean = roughness(plate, level=PLATE_LEVEL, spikes=True, which=which)
    return areal_record(raw, clean), clean


def ball_form(ball: Any) -> tuple[dict[str, Any], Any]:
    """Sphere fit of the ball scan, and circle fits of the row and column through its apex."""
    import profiles
    from surfmet._extract import extract_profile
    from surfmet.fitting import fit_sphere

    fit = fit_sphere(ball)
    circles = {}
    iy = min(max(round(fit.center[1] / ball.dy), 0), ball.ny - 1)
    ix = min(max(round(fit.center[0] / ball.dx), 0), ball.nx - 1)
    for key, spec in (("row_circle", f"row:{iy}"), ("column_circle", f"col:{ix}")):
        prof = extract_profile(ball, spec)
        circles[key] = (spec, profiles.fit_circle(np.asarray(prof.positions),
                                                  np.asarray(prof.z)))
    rec = ball_form_record(ball, fit, RADIUS, circles)
    residual = ball.replace(heights=np.asarray(fit.residuals))
    # the form deviation is the fit's own (rec["sphere"]["form_pv"], SphereFit.form_pv)
    return rec, residual

