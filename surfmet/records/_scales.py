"""The JSON record of ``surfmet scales`` (:mod:`surfmet.scale_dependent`).

Distances and wavevectors on the analysis grid; ``null`` where no measurement contributes.
Per measurement: its bandwidth, its reliability cut-off and where it came from, the
distance from which it is reliable, its own curves and, per grid point, whether it votes
(``contributes_slope``, ``contributes_curvature``, ``contributes_vbm`` on the distance
grid; ``contributes_psd`` on ``psd.q``, the PSD's own log bins of q).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from surfmet.scale_dependent import DIRECTION_WORDS, ScaleAnalysis


def scales_record(a: ScaleAnalysis) -> dict[str, Any]:
    """The JSON record of ``surfmet scales`` (SI, every value with its unit)."""

    def q(values: Any, unit: str) -> dict[str, Any]:
        return {"value": [None if not np.isfinite(v) else float(v) for v in values],
                "unit": unit}

    votes = {k: a.contributors(k) for k in ("slope", "curvature", "vbm", "psd")}
    band = a.psd_band()
    return {
        "scale_dependent": {"distance": q(a.distance, "m"), "rms_slope": q(a.rms_slope, ""),
                            "rms_curvature": q(a.rms_curvature, "1/m"),
                            "points_per_decade": a.per_decade,
                            "direction": {"value": a.direction,
                                          "meaning": DIRECTION_WORDS[a.direction]}},
        "height_difference_acf": {"distance": q(a.distance, "m"), "A": q(a.acf, "m^2")},
        "variable_bandwidth": {"bandwidth": q(a.distance, "m"),
                               "rms_height": q(a.vbm_rms_height, "m")},
        "psd": {"q": q(a.q, "rad/m"), "C": q(a.psd, "m^3"),
                "window": "periodic hann (mean square 1), after the container's levelling "
                          "(none stated: mean removed); maps: mean of the rows",
                "bins_per_decade": a.psd_per_decade,
                "averaging": "contact.engineering's: each measurement's DFT values below its "
                             "cut-off, bin-averaged in log bins of q, then an equal vote per "
                             "measurement in each bin (q averaged too)",
                "measured_band": None if band is None else q(band, "rad/m")},
        "measurements": [{
            "file": m.file, "kind": m.kind, "pixel": {"value": m.pixel, "unit": "m"},
            "size": {"value": m.size, "unit": "m"},
            "reliability_cutoff": {"value": m.cutoff, "unit": "m"},
            "cutoff_source": m.cutoff_source,
            "reliable_from": {"value": m.reliable_from, "unit": "m"},
            "tip_radius": {"value": m.tip_radius, "unit": "m"},
            "rms_slope": q(np.sqrt(m.variance_slope), ""),
            "rms_curvature": q(np.sqrt(m.variance_curvature), "1/m"),
            **{f"contributes_{k}": [bool(v) for v in votes[k][i]] for k in votes},
        } for i, m in enumerate(a.measurements)],
    }
