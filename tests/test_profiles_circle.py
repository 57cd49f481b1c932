"""Circle fit: a ball's radius from a profile (paper Fig. 16: R = 20 mm, 7.3 mm scan, 50 µm step).

Synthetic arcs hide a random form error (waviness along the arc) and, where stated, a few
outlier spikes of random height and position.
"""

from __future__ import annotations

import numpy as np
import pytest

from profiles import ProfileError, fit_circle

NOISE = 0.3e-6


def _arc(seed, *, form=True, spikes=False):
    rng = np.random.default_rng(seed)
    radius = rng.uniform(5, 25) * 1e-3
    xc, zc = rng.uniform(-5, 5, 2) * 1e-3
    half = 3.5e-3 / radius  # 7 mm of arc
    tilt = rng.uniform(-0.1, 0.1)  # apex not centred in the scan
    x = np.arange(xc + radius * np.sin(tilt - half), xc + radius * np.sin(tilt + half), 50e-6)
    s = radius * np.arcsin((x - xc) / radius)  # arc length coordinate
    form_error = np.zeros_like(x)
    if form:
        for _ in range(2):
            form_error += rng.uniform(0.1, 0.5) * 1e-6 * np.sin(
                2 * np.pi * s / rng.uniform(0.7e-3, 2e-3) + rng.uniform(0, 2 * np.pi)
            )
    z = zc + np.sqrt(radius**2 - (x - xc) ** 2) + form_error + rng.normal(0, NOISE, x.size)
    spike_idx = np.empty(0, dtype=int)
    if spikes:
        spike_idx = rng.choice(x.size, rng.integers(3, 7), replace=False)
        z[spike_idx] += rng.uniform(20, 60, spike_idx.size) * 1e-6
    return x, z, radius, (xc, zc), form_error, spike_idx


def test_radius_within_stated_uncertainty_over_seeds():
    k = []
    for seed in range(20):
        x, z, radius, centre, _, _ = _arc(seed)
        fit = fit_circle(x, z)
        assert fit.radius_uncertainty > 0
        k.append((fit.radius - radius) / fit.radius_uncertainty)
        assert abs(fit.center[0] - centre[0]) < 4 * fit.center_uncertainty[0]
        assert abs(fit.center[1] - centre[1]) < 4 * fit.center_uncertainty[1]
    k = np.array(k)
    # coverage: at most one of 20 outside 3 u, and u is not grossly inflated either
    assert np.count_nonzero(np.abs(k) > 3) <= 1
    assert 0.5 < np.std(k) < 1.6


@pytest.mark.parametrize("method", ["taubin", "pratt", "kasa"])
def test_all_algebraic_starts_converge_to_the_geometric_fit(method):
    x, z, radius, _, _, _ = _arc(3)
    fit = fit_circle(x, z, method=method)
    ref = fit_circle(x, z)
    assert fit.method == method
    assert fit.radius == pytest.approx(ref.radius, rel=1e-9)
    assert abs(fit.radius - radius) < 3 * fit.radius_uncertainty


@pytest.mark.parametrize("seed", range(4))
def test_clean_arc_reports_small_residual_and_form_error_is_found(seed):
    x, z, radius, _, _, _ = _arc(seed, form=False)
    clean = fit_circle(x, z)
    assert abs(clean.radius - radius) < 3 * clean.radius_uncertainty
    assert clean.rms_residual == pytest.approx(NOISE, rel=0.2)
    assert clean.pv_form_deviation < 8 * NOISE
    x, z, _radius, _, form_error, _ = _arc(seed, form=True)
    wavy = fit_circle(x, z)
    # the hidden waviness shows in the residuals (the circle absorbs very little of it)
    expected = np.sqrt(NOISE**2 + np.var(form_error))
    assert wavy.rms_residual == pytest.approx(expected, rel=0.2)
    assert wavy.pv_form_deviation > 0.8 * np.ptp(form_error)
    assert wavy.n_points == x.size
    assert wavy.residuals.shape == x.shape


def test_robust_loss_recovers_radius_with_spikes():
    robust_k, linear_k, found = [], [], 0
    for seed in range(12):
        x, z, radius, _, _, spike_idx = _arc(seed, spikes=True)
        lin = fit_circle(x, z)
        rob = fit_circle(x, z, loss="soft_l1")
        assert rob.loss == "soft_l1" and rob.f_scale > 0
        robust_k.append(abs(rob.radius - radius) / rob.radius_uncertainty)
        linear_k.append(abs(lin.radius - radius) / rob.radius_uncertainty)
        # the spikes are exactly the points far off the robust circle
        flagged = np.flatnonzero(np.abs(rob.residuals) > 10e-6)
        found += set(flagged.tolist()) == set(spike_idx.tolist())
        assert rob.radius_uncertainty < lin.radius_uncertainty
    assert max(robust_k) < 3
    assert np.count_nonzero(np.array(linear_k) > 3) >= 8
    assert found == 12
    for loss in ("huber", "cauchy"):
        x, z, radius, _, _, _ = _arc(0, spikes=True)
        fit = fit_circle(x, z, loss=loss)
        assert abs(fit.radius - radius) < 3 * fit.radius_uncertainty


def test_paper_ball_scan_geometry():
    # Fig. 16 geometry: R = 20 mm ball, 7.3 mm scan at 50 µm step, Ra ~ 0.25 µm roughness
    rng = np.random.default_rng(16)
    radius = 20e-3
    x = np.arange(-3.65e-3, 3.65e-3, 50e-6)
    rough = rng.normal(0, 0.25e-6 * np.sqrt(np.pi / 2), x.size)  # Ra = 0.25 µm
    z = np.sqrt(radius**2 - x**2) - radius + rough
    fit = fit_circle(x, z)
    assert abs(fit.radius - radius) < 3 * fit.radius_uncertainty
    assert fit.radius_uncertainty < 0.1e-3  # a 20 mm ball is told apart from 19.9 mm
    assert fit.center[1] == pytest.approx(-radius, abs=3 * fit.center_uncertainty[1])


def test_circle_errors():
    with pytest.raises(ProfileError, match="at least 3"):
        fit_circle([0.0, 1.0], [0.0, 1.0])
    with pytest.raises(ProfileError, match="at least 3"):
        fit_circle([0.0, 1.0, np.nan], [0.0, 1.0, 2.0])
    with pytest.raises(ProfileError, match="straight line"):
        fit_circle(np.arange(10.0), 2 * np.arange(10.0) + 1)
    with pytest.raises(ProfileError, match="method"):
        fit_circle([0, 1, 2], [0, 1, 0], method="hyper")
    with pytest.raises(ProfileError, match="loss"):
        fit_circle([0, 1, 2], [0, 1, 0], loss="tukey")
    with pytest.raises(ProfileError, match="points"):
        fit_circle([0, 1, 2], [0, 1])
