"""JSON record of the rotor's law-of-motion analysis (``surfmet rotor --json``): each
launch's selected model, its fits, adequacy and misreads; each group's parabola and means;
the comparisons between the groups (:class:`rotor.LawOfMotionAnalysis`).
"""

from __future__ import annotations

from typing import Any

from surfmet.mechanics._rotor_adequacy import adequacy_sentences, named_wave_of
from surfmet.units import quantity

__all__ = ["analysis_record"]

#: The JSON unit of an angular acceleration (surfmet.units.JSON_UNITS).
ACC = "rad/s^2"


def _fit_record(fit: Any, fps: float) -> dict[str, Any]:
    from rotor import MODELS, PARAM_UNITS

    spec = MODELS[fit.model]
    keys = list(spec.free)
    if fit.model != "parabola" and ("a_c" in keys):
        keys += ["amplitude", "phase"]
    params = {k: quantity(fit.params[k], PARAM_UNITS[k]) for k in keys}
    stderr = {k: quantity(v, PARAM_UNITS[k]) for k, v in fit.stderr.items()}
    rec: dict[str, Any] = {
        "description": spec.description,
        "effect": spec.effect,
        "n_params": fit.p,
        "n_rows": fit.n,
        "rms": quantity(fit.rms, "s"),
        "rms_frames": quantity(fit.rms * fps, "frame"),
        "bic": fit.bic,
        "loo_rms": quantity(fit.loo_rms, "s"),
        "loo_kind": fit.loo_kind,
        "chi2_quantisation": fit.chi2_quant,
        "runs_z": fit.runs_z,
        "lag1": fit.lag1,
        "noise": {"sigma_t": quantity(fit.noise.sigma_t, "s"),
                  "sigma_a": quantity(fit.noise.sigma_a, "rad")},
        "params": params,
        "stderr": stderr,
        "residuals": quantity([float(v) for v in fit.residuals], "s"),
    }
    if fit.angle_rms is not None:
        rec["angle_rms"] = quantity(fit.angle_rms, "rad")
    return rec


def analysis_record(an: Any, source: str) -> dict[str, Any]:
    """The JSON record of a :class:`rotor.LawOfMotionAnalysis` read from ``source``."""
    from rotor import G_STANDARD, mass_properties

    sym = mass_properties(collar_offset="symmetric")
    fps = an.fps
    tests = []
    for t in an.tests:
        sel = t.fit
        rec = {
            "name": t.name,
            "group": t.group,
            "selected_model": t.selected,
            "effect": t.effect,
            "decay_form": t.decay_form,
            "outliers": list(t.outliers),
            "evidence": {"delta_bic_to_next_simpler": t.delta_bic,
                         "effect_evidence_delta_bic": t.effect_evidence,
                         "false_alarm_probability": t.false_alarm,
                         "weak": t.weak_evidence},
            "eps0": quantity(t.eps0, "rad/s^2"),
            "eps0_stderr": quantity(t.eps0_stderr, "rad/s^2"),
            "start": {
                "t0": quantity(sel.params.get("t0", 0.0), "s"),
                "phi0": quantity(sel.params.get("phi0", 0.0), "rad"),
                "omega_at_first_mark": quantity(t.omega_first, "rad/s"),
            },
            "noise": {"sigma_t": quantity(sel.noise.sigma_t, "s"),
                      "sigma_a": quantity(sel.noise.sigma_a, "rad")},
            "k": [int(v) for v in t.k],
            "frames": [float(v) for v in t.frames],
            "misread_z": [float(v) for v in t.z],
            "adequacy": _adequacy_record(t),
            "models": {m: _fit_record(f, fps) for m, f in t.fits.items()},
        }
        amp = sel.params.get("amplitude", 0.0)
        if amp:
            # for the paper's rotor: A = M g e / (J + M R^2)
            rec["com_offset_paper_rotor"] = quantity(
                amp * sym.rolling_inertia / (sym.mass * G_STANDARD), "m")
        tests.append(rec)
    groups = []
    units = ("rad/s^2", "rad/s", "rad")
    for g in an.groups:
        groups.append({
            "name": g.name,
            "tests": list(g.tests),
            "paper_parabola": [quantity(float(c), u) for c, u in zip(g.paper_parabola, units)],
            "paper_parabola_stderr": [quantity(float(c), u)
                                      for c, u in zip(g.paper_parabola_stderr, units)],
            "paper_parabola_rms": quantity(g.paper_rms, "rad"),
            "eps0": {m: {"mean": quantity(v[0], ACC), "uncertainty": quantity(v[1], ACC),
                         "values": quantity(list(v[2]), ACC)} for m, v in g.eps.items()},
            "study_params": {k: {"mean": quantity(v[0], _unit(k)),
                                 "uncertainty": quantity(v[1], _unit(k)),
                                 "values": quantity(list(v[2]), _unit(k))}
                             for k, v in g.params.items()},
            "leave_one_test_out_rms": {m: quantity(v, "s") for m, v in g.loto_rms.items()},
            "residual_alignment": _alignment_record(g.residual_alignment),
        })
    comps = []
    for c in an.comparisons:
        unit = "rad/s^2" if c.quantity == "eps0" else _unit(c.quantity)
        comps.append({
            "groups": [c.a, c.b],
            "model": c.model,
            "quantity": c.quantity,
            "difference": quantity(c.difference, unit),
            "uncertainty": quantity(c.uncertainty, unit),
            "z": c.z,
            "p_value": c.p_value,
            "ratio": c.ratio,
        })
    return {
        "file": source,
        "fps": quantity(an.fps, "1/s"),
        "step": quantity(an.step, "rad"),
        "noise_floor": quantity(an.noise_floor, "s"),
        "study_model": an.study_model,
        "total_bic": an.total_bic,
        "tests": tests,
        "groups": groups,
        "comparisons": comps,
    }


def _unit(key: str) -> str:
    from rotor import PARAM_UNITS

    return PARAM_UNITS.get(key, "")


def _wave_record(w: Any) -> dict[str, Any]:
    return {
        "period": quantity(w.period, "rad"),
        "revolutions": w.revolutions,
        "track_length": quantity(w.track_length, "m"),
        "amplitude": quantity(w.amplitude, "rad/s^2"),
        "phase_rotor": quantity(w.phase_rotor, "rad"),
        "phase_track": quantity(w.phase_track, "rad"),
        "unbalance_like": w.unbalance_like,
        "share_of_residual": w.share,
    }


def _adequacy_record(t: Any) -> dict[str, Any]:
    from rotor import ALPHA

    a = t.adequacy
    rec: dict[str, Any] = {
        "adequate": a.adequate,
        "statistic": a.statistic,
        "p_value": a.p_value,
        "p_value_floor": a.p_floor,
        "alpha": ALPHA,
        "runs_z": a.runs_z,
        "lag1": a.lag1,
        "periodogram_share": a.wave_share,
        "nominal_p": dict(a.nominal),
        "family_choice": t.family_choice,
        "family_adequate": t.family_adequacy.adequate if t.family_adequacy else None,
        "family_p_value": t.family_adequacy.p_value if t.family_adequacy else None,
        "extension_tried": list(t.extension_tried),
        "judged": a.judged,
        "summary": adequacy_sentences(t),
    }
    if a.residual is not None and not a.adequate:
        rec["residual_wave"] = _wave_record(a.residual)
    named = named_wave_of(t)
    if named is not None:
        rec["named_wave"] = _wave_record(named)
    sm = t.smooth
    if sm is not None:
        rec["smooth_deviation"] = {
            "added_to": sm.model, "modes": sm.modes, "basis": "Legendre P2..P(modes+1)",
            "coefficients": quantity(list(sm.coefficients), "rad/s^2"),
            "amplitude": quantity(sm.amplitude, "rad/s^2"),
            "at_angle": quantity(sm.at_angle, "rad"), "rms": quantity(sm.rms, "rad/s^2"),
            "delta_bic": sm.delta_bic, "runs_z_after": sm.runs_z, "lag1_after": sm.lag1}
    return rec


def _alignment_record(al: Any) -> dict[str, Any] | None:
    if al is None:
        return None
    return {"period": quantity(al.period, "rad"), "revolutions": al.revolutions,
            "track_length": quantity(al.track_length, "m"), "tests": list(al.tests),
            "amplitude": quantity(list(al.amplitude), "rad/s^2"),
            "phase_rotor": quantity(list(al.phase_rotor), "rad"),
            "phase_track": quantity(list(al.phase_track), "rad"),
            "coherence_rotor": al.coherence_rotor, "coherence_track": al.coherence_track,
            "rayleigh_p_rotor": al.p_rotor, "rayleigh_p_track": al.p_track,
            "lines_up_by": al.verdict}
