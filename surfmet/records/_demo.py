"""The JSON records of the demo's steps (:mod:`surfmet.demo`): the shipped scans, the
roughness of their rows, the plate's areal parameters, the ball's form, the Hertz check
with the paper's values, the rotor's loads and the timings; every value with its unit.
The demo computes, this module writes what it computed (the rotor step's record is
:mod:`surfmet.records._demo_rotor`)."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from surfmet.records._scans import fit_record, scan_record
from surfmet.units import quantity

__all__ = ["areal_record", "ball_form_record", "demo_hertz_record", "demo_scans_record",
           "loads_record", "row_statistics_record", "seconds", "table2_record"]


def demo_scans_record(scans: dict[str, Any]) -> dict[str, Any]:
    """The ``surfmet info`` record of each shipped scan (``{"plate": scan, ...}``), its
    file by name only and without its metadata."""
    rec = {}
    for name, scan in scans.items():
        d = scan_record(scan)
        d["file"] = Path(str(d["file"])).name if d["file"] else None
        d["nan_fraction"] = quantity(d["nan_fraction"], "")
        d.pop("metadata")
        rec[name] = d
    return rec


def row_statistics_record(rows: int, level: str, settings: dict[str, Any],
                          values: dict[str, np.ndarray], typical_row: int) -> dict[str, Any]:
    """R-parameters of every row (``values``: parameter -> one value per row, m): their
    median and quartiles, the settings of the typical row's record (with their units, as
    the command's JSON gives them) and which row is typical."""
    return {
        "rows": rows,
        # the record's settings carry their units ({value, unit}), as the CLI's JSON does
        "settings": {"level": level, "lc": settings.get("lc"),
                     "evaluation_length": settings.get("evaluation_length"),
                     "filter": settings.get("filter")},
        "median": {k: quantity(float(np.median(v)), "m") for k, v in values.items()},
        "quartiles": {k: quantity(np.percentile(v, [25, 75]), "m") for k, v in values.items()},
        "typical_row": typical_row,
    }


def areal_record(raw: Any, clean: Any) -> dict[str, Any]:
    """The plate's areal parameters as scanned (``raw``) and with its spikes removed
    (``clean``), both :class:`surfmet._roughness_result.RoughnessResult`."""
    from surfmet.records._roughness import roughness_record

    sp = clean.spike_report
    return {
        "as_scanned": {
            "parameters": roughness_record(raw)["parameters"],
            "sq_over_sa": quantity(raw.value("Sq") / raw.value("Sa"), ""),
            "spikes_suspected": bool(raw.spike_diagnosis.suspected),
            "diagnosis": raw.spike_diagnosis.message,
        },
        "spikes_removed": {"count": int(sp.count), "points": int(sp.n_points),
                           "threshold": quantity(sp.threshold, "m")},
        "cleaned": {
            "parameters": roughness_record(clean)["parameters"],
            "sq_over_sa": quantity(clean.value("Sq") / clean.value("Sa"), ""),
            "gaussian_sq_over_sa": quantity(math.sqrt(math.pi / 2), ""),
        },
    }


def ball_form_record(ball: Any, fit: Any, nominal: float,
                     circles: dict[str, tuple[str, Any]]) -> dict[str, Any]:
    """The ball's sphere fit against its ``nominal`` radius (m), and the circle fits of
    the profiles through its apex (``{"row_circle": (spec, CircleFit), ...}``)."""
    dev = fit.radius - nominal
    rec: dict[str, Any] = {"nominal_radius": quantity(nominal, "m"),
                           "sphere": fit_record(ball, "sphere"),
                           "radius_minus_nominal": quantity(dev, "m"),
                           "radius_minus_nominal_in_uncertainties":
                               quantity(dev / fit.radius_uncertainty, "")}
    for key, (spec, c) in circles.items():
        rec[key] = {"profile": spec, "radius": quantity(c.radius, "m"),
                    "radius_uncertainty": quantity(c.radius_uncertainty, "m")}
    return rec


def demo_hertz_record(check: Any, paper: dict[str, float]) -> dict[str, Any]:
    """The Hertz check's record with its details (each criterion's number a dimensionless
    quantity) and the paper's approach and contact radius (``paper``: ``delta``, ``a``, m)."""
    from surfmet.records._hertz import hertz_check_details, hertz_check_record

    rec = hertz_check_record(check)
    details = hertz_check_details(check)
    # each criterion's number as a dimensionless quantity (a ratio or a fraction)
    details["criteria"] = [
        {"name": c["name"], "measured": quantity(c["value"], ""),
         "limit": quantity(c["limit"], ""), "passed": c["passed"], "decisive": c["decisive"]}
        for c in details["criteria"]
    ]
    rec["details"] = details
    rec["paper"] = {"delta": quantity(paper["delta"], "m"), "a": quantity(paper["a"], "m")}
    return rec


def loads_record(loads: dict[str, float]) -> dict[str, Any]:
    """Named loads (N)."""
    return {k: quantity(v, "N") for k, v in loads.items()}


def table2_record(table: dict[str, dict[str, float]]) -> dict[str, Any]:
    """The paper's Table 2 means (m) per scan and parameter."""
    return {k: {p: quantity(v, "m") for p, v in d.items()} for k, d in table.items()}


def seconds(dt: float) -> dict[str, Any]:
    """A duration (s)."""
    return quantity(dt, "s")
