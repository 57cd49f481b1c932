"""JSON record of the averaged PSD of several measurements as ``surfmet spectrum`` and
``surfmet flat-contact`` use it (:mod:`surfmet.mechanics.all_scales`).

``psd.measured_band`` is the union of the bands over which the measurements contribute
(rad/m, with the wavelengths); ``measurements[i].psd_band`` is each one's, and
``measurements[i].contributes_psd`` says per point of ``psd.q_profile`` who votes (the
rest of each measurement's entry is that of ``surfmet scales``). ``persson`` holds
Persson's area, mean gap and stiffness from the band's isotropic PSD at each pressure.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from surfmet.records._scales import scales_record
from surfmet.units import quantity


def _band(b: tuple[float, float] | None) -> dict[str, Any]:
    if b is None:
        return {"q": quantity(None, "rad/m"), "wavelength": quantity(None, "m")}
    return {"q": {"value": [b[0], b[1]], "unit": "rad/m"},
            "wavelength": {"value": [2 * math.pi / b[1], 2 * math.pi / b[0]], "unit": "m"}}


def all_scales_record(s: Any, curve: Any = None, e_star: float | None = None,
                      hardness: float | None = None) -> dict[str, Any]:
    """Record of an :class:`~surfmet.mechanics.all_scales.AllScalesSpectrum`; with
    ``curve`` (a :class:`contact.roughcontact.ModelCurve`) and ``e_star``, Persson's
    theory on it; with ``e_star`` and ``hardness``, the plasticity index of the band."""
    from contact.roughcontact import plasticity_index

    a = s.analysis
    order = np.argsort(a.q)
    meas = scales_record(a)["measurements"]
    for m, band in zip(meas, s.measurement_bands()):
        m["psd_band"] = _band(band)
        m["contributes_psd"] = [m["contributes_psd"][k] for k in order]
    h = s.hurst
    rec: dict[str, Any] = {
        "psd": {
            "measured_band": _band(s.band),
            "q_profile": quantity(a.q[order], "rad/m"),
            "C_profile": quantity(a.psd[order], "m^3"),
            "q": quantity(s.q, "rad/m"),
            "C_iso": quantity(s.c_iso, "m^4"),
            "window": "hann (non-periodic data), mean removed; maps: mean of the rows",
            "conversion": "C_iso from the averaged profile PSD by the inverse Abel transform "
                          "(Jacobs, Junge & Pastewka 2017), log-log interpolation, power-law "
                          "continuation above the band",
        },
        "h_rms": quantity(s.h_rms, "m"),
        "slope_rms": quantity(s.slope_rms, ""),
        "curvature_rms": quantity(s.curvature_rms, "1/m"),
        "hurst": None if h is None else {
            "value": h.hurst, "q_range": quantity(list(h.q_range), "rad/m"),
            "fit_residual_rms_decades": h.residual_rms},
        "summits": None if s.summits is None else {
            "nayak_alpha": s.summits.alpha, "density": quantity(s.summits.density, "1/m^2"),
            "radius": quantity(s.summits.radius, "m"),
            "sigma_s": quantity(s.summits.sigma_s, "m")},
        "measurements": meas,
        "notes": ["rms values, summit statistics and Persson's theory are those of the "
                  "roughness in the measured band (slope, curvature, summits and the plasticity "
                  "index grow as its shortest wavelength shrinks); scales outside it are not "
                  "included", *s.notes],
    }
    if e_star is not None:
        rec["e_star"] = quantity(e_star, "Pa")
    if e_star is not None and hardness is not None and s.summits is not None:
        rec["hardness"] = quantity(hardness, "Pa")
        rec["plasticity_index"] = plasticity_index(e_star, hardness, s.summits)
    if curve is not None and e_star is not None:
        rec["persson"] = [{
            "pressure": quantity(float(p), "Pa"),
            "area_fraction": float(curve.area_fraction[i]),
            "mean_gap": quantity(float(curve.mean_gap[i]), "m"),
            "stiffness": quantity(float(curve.stiffness[i]), "Pa/m"),
            "kappa": float(curve.area_fraction[i] * e_star * s.slope_rms / p),
        } for i, p in enumerate(curve.pressure)]
    return rec
