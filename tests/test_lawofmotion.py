"""Law-of-motion models: the crossing-time evaluator against closed forms, the fits, the
selection, the paper's parabolas, leave-one-out errors, and bad input."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from contact._errors import ContactInputError
from rotor._analysis import analyse_test
from rotor._family import MODELS
from rotor._fitting import fit_all_models, fit_model, loo_exact
from rotor._forward import crossing_times
from rotor._frames import table3
from rotor._noise import Noise, quantisation_sigma
from rotor._parabola import paper_parabola
from rotor._selection import select_model

PHI = np.arange(25) * math.pi / 2


def test_constant_acceleration_closed_form():
    for phi0, t0 in ((0.0, 0.0), (-0.3, -0.2)):
        t = crossing_times(PHI, 2.1, t0=t0, phi0=phi0)
        assert np.allclose(t, t0 + np.sqrt(2 * (PHI - phi0) / 2.1), atol=1e-12, rtol=0)


def test_position_decay_is_a_harmonic_oscillator():
    # phi'' = eps0 - eta phi from rest at 0: phi = eps0/eta (1 - cos(sqrt(eta) t))
    eps0, eta = 2.2, 0.04
    t = crossing_times(PHI, eps0, eta=eta)
    exact = np.arccos(1 - eta * PHI / eps0) / math.sqrt(eta)
    assert np.max(np.abs(t - exact)) * 120 < 2e-3


def test_speed_decay_matches_the_linear_drag_solution():
    # phi'' = eps0 - gamma phi': phi = eps0/gamma (t - (1 - exp(-gamma t))/gamma)
    eps0, gamma = 2.0, 0.12

    def phi_of(t: float) -> float:
        return eps0 / gamma * (t - (1 - math.exp(-gamma * t)) / gamma)

    exact = [0.0] + [brentq(lambda tt, p=p: phi_of(tt) - p, 1e-9, 60) for p in PHI[1:]]
    t = crossing_times(PHI, eps0, gamma=gamma)
    assert np.max(np.abs(t - exact)) * 120 < 3e-3


def test_unbalance_obeys_the_energy_integral():
    # without decay, omega^2/2 = eps0 (phi - phi0) + the work of A sin(phi + psi)
    eps0, a_c, a_s, phi0 = 2.0, 0.3, -0.5, -0.2
    phi = PHI[1:]
    d = 1e-5
    t = crossing_times(np.concatenate([phi, phi + d]), eps0, a_c=a_c, a_s=a_s, phi0=phi0)
    omega = d / (t[phi.size:] - t[: phi.size])
    work = -a_c * (np.cos(phi) - math.cos(phi0)) + a_s * (np.sin(phi) - math.sin(phi0))
    assert np.allclose(omega, np.sqrt(2 * (eps0 * (phi - phi0) + work)), rtol=2e-3)
    # the unbalance makes the speed oscillate about the plain motion's
    plain = np.sqrt(2 * eps0 * (phi - phi0))
    assert np.any(omega > plain) and np.any(omega < plain)
    # a stalling model gives huge but finite times (a barrier for the fits)
    ts = crossing_times(PHI, 0.5, eta=0.1)
    assert np.all(np.isfinite(ts)) and ts[-1] > 1e3


def _synthetic(eps0=2.0, eta=0.0, gamma=0.0, a_c=0.0, a_s=0.0, phi0=-0.1, seed=0, n=25):
    # frame indices from a known motion, quantised like Table 3
    rng = np.random.default_rng(seed)
    phi = np.arange(n) * math.pi / 2
    start = rng.uniform(0.3, 1.0)
    t = start + crossing_times(phi, eps0, eta=eta, gamma=gamma, a_c=a_c, a_s=a_s, phi0=phi0)
    f = np.ceil(t * 120)
    return (f - f[0]) / 120, phi


def test_fits_recover_known_parameters():
    t, phi = _synthetic(eps0=2.1, eta=0.03, phi0=-0.15)
    fits = fit_all_models(t, phi, models=["const", "position"])
    pos = fits["position"]
    assert pos.eps0 == pytest.approx(2.1, rel=0.01)
    assert pos.params["eta"] == pytest.approx(0.03, rel=0.05)
    # at the quantisation floor: chi2 per degree of freedom about 1
    assert pos.chi2_quant < 2.0
    assert pos.rms < 2 * quantisation_sigma()
    assert fits["const"].rms > 5 * pos.rms
    assert fits["const"].runs_z < -2  # the constant-acceleration misfit is systematic
    assert select_model(fit_all_models(t, phi)) == "position"


def test_selection_prefers_the_simple_model_on_constant_acceleration():
    t, phi = _synthetic(eps0=1.9, phi0=-0.05, seed=3)
    fits = fit_all_models(t, phi)
    assert select_model(fits) in ("const", "rest")
    # richer models fit at least as well as the ones nested in them
    for name, spec in MODELS.items():
        for parent in spec.parents:
            if parent in fits and name in fits:
                assert fits[name].chi2 <= fits[parent].chi2 + 1e-6 or (
                    fits[name].rms <= fits[parent].rms + 1e-9)


def test_loo_exact_is_close_to_the_leverage_approximation():
    t, phi = _synthetic(eps0=2.0, eta=0.02, seed=5)
    fit = fit_model(t, phi, "position", noise=Noise(quantisation_sigma(), 0.0),
                    inits=[{"eps0": 2.0, "eta": 0.02, "phi0": -0.1}])
    exact = loo_exact(t, phi, fit)
    assert exact == pytest.approx(fit.loo_rms, rel=0.25)
    assert exact > fit.rms


def test_paper_parabolas_are_reproduced_and_their_labels_are_swapped():
    cols = table3()
    as_fit, _, _ = paper_parabola([cols["as1"], cols["as2"], cols["as3"]])
    s_fit, _, _ = paper_parabola([cols["s1"], cols["s2"], cols["s3"]])
    # the paper's "phi_s" = 0.821 t^2 + 1.134 t - 0.527 is the fit of the ASYMMETRIC columns
    assert np.allclose(as_fit, [0.821, 1.134, -0.527], atol=5e-4)
    # and its "phi_a" = 0.951 t^2 + 1.0254 t - 0.249 that of the symmetric ones
    assert np.allclose(s_fit, [0.951, 1.0254, -0.249], atol=7e-4)


def test_paper_column_with_two_misread_rows():
    rep = analyse_test("as2", table3()["as2"])
    assert rep.group == "as"
    assert set(rep.outliers) == {7, 24}
    assert rep.effect.startswith("decaying")
    # the chosen model is within the reading noise; constant acceleration is not
    assert rep.fit.rms * 120 < 1.5
    assert rep.fits["const"].rms * 120 > 4
    assert rep.fits["rest"].rms * 120 > 8


def test_bad_input_raises():
    t, phi = _synthetic()
    with pytest.raises(ContactInputError):
        fit_model(t, phi, "wobble")
    with pytest.raises(ContactInputError):
        fit_model(t[:4], phi[:4], "position")
    with pytest.raises(ContactInputError):
        analyse_test("x", [1, 2, 3])
    with pytest.raises(ContactInputError):
        analyse_test("x", np.arange(20)[::-1] * 10.0)
    with pytest.raises(ContactInputError):
        analyse_test("x", np.arange(20) * 10.0, fps=-1)
    with pytest.raises(ContactInputError):
        analyse_test("x", np.arange(20) * 10.0, cv="always")
