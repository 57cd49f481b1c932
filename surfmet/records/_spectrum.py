"""JSON record of a surface's spectrum (``surfmet spectrum``, ``flat-contact``): every
dimensional value with its unit."""

from __future__ import annotations

import math
from typing import Any

from surfmet.units import quantity as _q


def spectrum_record(s: Any) -> dict[str, Any]:
    """JSON-ready description of a :class:`surfmet.mechanics.spectrum.Spectrum` (every dimensional
    value with a unit)."""
    from surfmet.mechanics.spectrum import RESOLUTION_DEPENDENT

    sm = s.summits
    rec: dict[str, Any] = {
        "periodic": s.periodic,
        "periodic_detected": s.settings.get("periodic_detected"),
        "window": s.settings.get("window"),
        "hurst": {"value": s.hurst.hurst,
                  "q_range": [_q(s.hurst.q_range[0], "rad/m"),
                              _q(s.hurst.q_range[1], "rad/m")],
                  "wavelength_range": [_q(2 * math.pi / s.hurst.q_range[1], "m"),
                                       _q(2 * math.pi / s.hurst.q_range[0], "m")],
                  "fit_residual_rms_decades": s.hurst.residual_rms},
        "roll_off": {"q": _q(s.roll_off, "rad/m"),
                     "wavelength": _q(2 * math.pi / s.roll_off if s.roll_off else None,
                                        "m")},
        "short_cutoff": {"q": _q(s.short_cutoff, "rad/m"),
                         "wavelength": _q(2 * math.pi / s.short_cutoff
                                            if s.short_cutoff else None, "m")},
        "noise_floor": {"q": _q(s.noise_floor, "rad/m"),
                        "wavelength": _q(2 * math.pi / s.noise_floor
                                         if s.noise_floor else None, "m")},
        "h_rms": {"spectrum": _q(s.h_rms, "m"), "real_space": _q(s.h_rms_real, "m")},
        "slope_rms": {"spectrum": _q(s.slope_rms, ""),
                      "real_space": _q(s.slope_rms_real, "")},
        "curvature_rms": {"spectrum": _q(s.curvature_rms, "1/m"),
                          "real_space": _q(s.curvature_rms_real, "1/m")},
        "moments": {"m0": _q(sm.m0, "m^2"), "m2": _q(sm.m2, ""), "m4": _q(sm.m4, "1/m^2")},
        "nayak_alpha": sm.alpha,
        "summits": {"density": _q(sm.density, "1/m^2"), "radius": _q(sm.radius, "m"),
                    "sigma_s": _q(sm.sigma_s, "m"), "mean_height": _q(sm.mean_height, "m"),
                    "gw_product": sm.gw_product},
        "plasticity_index": s.plasticity,
        "resolution_dependent": list(RESOLUTION_DEPENDENT),
        "notes": ([] if 0.0 < s.hurst.hurst < 1.0 else
                  [f"H = {s.hurst.hurst:.3g} lies outside (0, 1): the fitted band is not "
                   "self-affine (a form, a filter or a single dominant wavelength)"]),
        "caveats": list(s.settings.get("caveats", [])),
        "psd": {"q": {"value": s.psd.q.tolist(), "unit": "rad/m"},
                "C": {"value": s.psd.C.tolist(), "unit": "m^4"}},
    }
    return rec


def spectrum_command_record(file: str, s: Any, levelling: str,
                            preparation: Any) -> dict[str, Any]:
    """The record ``surfmet spectrum FILE --json`` emits for one scan (and the report
    carries): the file, its levelling and preparation, :func:`spectrum_record`, and the
    materials when the plasticity index was asked for."""
    from surfmet.records._preparation import flat_preparation_record

    rec = {"file": file, "levelling": levelling,
           "scan_preparation": flat_preparation_record(preparation),
           **spectrum_record(s)}
    if s.materials is not None:
        rec["materials"] = s.materials.names
        rec["e_star"] = {"value": s.materials.e_star, "unit": "Pa"}
        rec["hardness"] = {"value": s.materials.hardness, "unit": "Pa"}
    return rec


def profile_psd_record(fit: Any) -> dict[str, Any]:
    """The report's record of the PSD fit drawn for a profile
    (:func:`surfmet.psd.fit_hurst` on the roughness profile; None when it failed)."""
    return {"of": "the roughness profile over the evaluation length", "window": "hann",
            "hurst": None if fit is None else {
                "value": fit.hurst,
                "q_range": [{"value": fit.q_range[0], "unit": "rad/m"},
                            {"value": fit.q_range[1], "unit": "rad/m"}]}}
