"""ISO profile parameters against analytic truths (sine profiles, Gaussian heights)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import stats

from profiles import (
    ProfileError,
    ProfileParameters,
    height_at_ratio,
    material_ratio,
    material_ratio_curve,
    profile_parameters,
    rk_parameters,
)

SEEDS = range(6)


def _sine(seed: int, periods: int = 12, per_period: int = 400):
    rng = np.random.default_rng(seed)
    amp = rng.uniform(0.05, 3.0) * 1e-6
    lam = rng.uniform(20, 400) * 1e-6
    phase = rng.uniform(0, 2 * np.pi)
    dx = lam / per_period
    x = np.arange(periods * per_period) * dx
    return amp, lam, dx, amp * np.sin(2 * np.pi * x / lam + phase)


@pytest.mark.parametrize("seed", SEEDS)
def test_sine_parameters_match_analytic_values(seed):
    amp, lam, dx, z = _sine(seed)
    p = profile_parameters(z, dx)
    assert p.Ra == pytest.approx(2 * amp / np.pi, rel=1e-4)
    assert p.Rq == pytest.approx(amp / np.sqrt(2), rel=1e-4)
    assert abs(p.Rsk) < 1e-3
    assert p.Rku == pytest.approx(1.5, rel=1e-3)
    assert p.Rsm == pytest.approx(lam, rel=1e-4)
    assert p.Rdq == pytest.approx(2 * np.pi * amp / lam / np.sqrt(2), rel=1e-3)
    # each of the 5 sampling lengths holds >= 2 periods: its peak-to-valley is 2A
    assert p.Rz == pytest.approx(2 * amp, rel=1e-4)
    assert p.Rp == pytest.approx(amp, rel=1e-4)
    assert p.Rv == pytest.approx(amp, rel=1e-4)
    assert p.Rt == pytest.approx(2 * amp, rel=1e-4)


def test_rz_is_mean_of_sampling_lengths_not_total_range():
    # a single high spike in one of five sampling lengths: Rt sees it fully, Rz a fifth
    amp, _lam, dx, z = _sine(11)
    z = z.copy()
    spike = 10 * amp
    z[z.size // 10] = spike
    p = profile_parameters(z, dx)
    assert p.Rt == pytest.approx(spike + amp, rel=1e-3)
    assert p.Rz == pytest.approx((4 * 2 * amp + spike + amp) / 5, rel=1e-3)


def test_parameters_are_nan_aware():
    amp, lam, dx, z = _sine(3)
    rng = np.random.default_rng(3)
    holes = z.copy()
    for start in rng.integers(0, z.size - 50, 8):
        holes[start : start + rng.integers(5, 40)] = np.nan
    p = profile_parameters(holes, dx)
    assert all(math.isfinite(v) for v in p.as_dict().values())
    assert p.Ra == pytest.approx(2 * amp / np.pi, rel=0.02)
    assert p.Rq == pytest.approx(amp / np.sqrt(2), rel=0.02)
    assert p.Rz == pytest.approx(2 * amp, rel=1e-3)
    assert p.Rsm == pytest.approx(lam, rel=1e-3)


@pytest.mark.parametrize("seed", range(3))
def test_rsm_ignores_ripple_below_height_discrimination(seed):
    # hidden ripple (< 10 % Rz) makes extra mean-line crossings near every zero crossing
    rng = np.random.default_rng(seed)
    amp, lam = rng.uniform(0.1, 2) * 1e-6, rng.uniform(50, 200) * 1e-6
    dx = lam / 800
    x = np.arange(10 * 800) * dx
    ripple = rng.uniform(0.05, 0.08) * amp
    z = amp * np.sin(2 * np.pi * x / lam) + ripple * np.sin(
        2 * np.pi * x / (lam / rng.uniform(60, 90)) + rng.uniform(0, 6)
    )
    assert profile_parameters(z, dx).Rsm == pytest.approx(lam, rel=3e-3)
    # without discrimination the ripple's crossings would be counted as elements
    raw = profile_parameters(z, dx, height_discrimination=0, width_discrimination=0)
    assert raw.Rsm < 0.6 * lam


def test_nonuniform_positions_are_weighted_by_length():
    # positive half-waves sampled three times more densely than negative ones: a plain
    # average over points would report a strongly positive skewness
    lam, amp = 100e-6, 1e-6
    dense = np.arange(600) * (lam / 1200)  # first half-period, fine steps
    sparse = lam / 2 + np.arange(200) * (lam / 400)  # second half-period, coarse
    x = np.concatenate([k * lam + np.concatenate([dense, sparse]) for k in range(10)])
    z = amp * np.sin(2 * np.pi * x / lam)
    p = profile_parameters(z, lam / 800, x=x)
    assert abs(p.Rsk) < 0.02
    assert p.Ra == pytest.approx(2 * amp / np.pi, rel=2e-3)
    plain = np.mean(z**3) / np.mean(z**2) ** 1.5
    assert plain > 0.3  # the effect the weighting removes is real


def test_sampling_length_selects_central_evaluation_length():
    amp, lam, dx, z = _sine(4)  # 12 periods
    lr = 2 * lam  # room for 6 sampling lengths
    p = profile_parameters(z, dx, sampling_length=lr, n_sampling=5)
    assert p.Rq == pytest.approx(amp / np.sqrt(2), rel=1e-4)
    # a trend only in the outer sampling lengths is outside the central evaluation length
    bent = z.copy()
    k = round(lam / dx)
    bent[:k] += 5 * amp
    bent[-k:] -= 5 * amp
    assert profile_parameters(bent, dx, sampling_length=lr, n_sampling=5).Rt == pytest.approx(
        2 * amp, rel=1e-4
    )
    assert profile_parameters(bent, dx, sampling_length=lr, n_sampling=None).Rt > 10 * amp
    with pytest.raises(ProfileError, match="sampling length"):
        profile_parameters(z, dx, sampling_length=lr, n_sampling=7)


def test_units_and_as_dict():
    _amp, _lam, dx, z = _sine(0)
    d = profile_parameters(z, dx).as_dict()
    assert list(d) == list(ProfileParameters.UNITS)
    assert ProfileParameters.UNITS["Ra"] == "m"
    assert ProfileParameters.UNITS["Rsk"] == ""
    assert ProfileParameters.UNITS["Rdq"] == ""


@pytest.mark.parametrize("seed", SEEDS)
def test_material_ratio_of_a_sine(seed):
    amp, _lam, _dx, z = _sine(seed, per_period=2000)
    rng = np.random.default_rng(seed)
    for c in rng.uniform(-0.95, 0.95, 5):
        expected = np.arccos(c) / np.pi  # fraction of a period where sin >= c
        assert material_ratio(z, c * amp) == pytest.approx(expected, abs=2e-3)
    # from the highest peak: depth d below the top
    d = rng.uniform(0.1, 1.9) * amp
    assert material_ratio(z, d, reference="peak") == pytest.approx(
        np.arccos(1 - d / amp) / np.pi, abs=2e-3
    )
    mr = rng.uniform(0.05, 0.95)
    assert height_at_ratio(z, mr) == pytest.approx(amp * np.cos(np.pi * mr), abs=5e-3 * amp)
    ratio, heights = material_ratio_curve(z)
    assert np.all(np.diff(heights) <= 0) and ratio[-1] == 1.0


def test_rk_family_of_gaussian_heights():
    # for normal heights the flattest 40 % secant is centred on 50 %, so analytically
    # Rk = 2 sigma q / 0.4 with q = Phi^-1(0.7); Mr1 = 1 - Phi(Rk / 2 sigma)
    rng = np.random.default_rng(5)
    sigma = rng.uniform(0.1, 2.0) * 1e-6
    z = rng.normal(0, sigma, 400_000)
    q = stats.norm.ppf(0.7)
    t = q / 0.4  # line top at mr = 0, in sigma units
    rk = rk_parameters(z)
    assert rk.Rk == pytest.approx(2 * t * sigma, rel=0.02)
    mr1 = stats.norm.sf(t)
    assert rk.Mr1 == pytest.approx(mr1, abs=0.005)
    assert rk.Mr2 == pytest.approx(1 - mr1, abs=0.005)
    a1 = sigma * (stats.norm.pdf(t) - t * stats.norm.sf(t))
    assert rk.Rpk == pytest.approx(2 * a1 / mr1, rel=0.05)
    assert rk.Rvk == pytest.approx(2 * a1 / mr1, rel=0.05)


def test_bad_input_raises_profile_error():
    with pytest.raises(ProfileError, match="all heights are NaN"):
        profile_parameters(np.full(100, np.nan), 1e-6)
    with pytest.raises(ProfileError, match="positive"):
        profile_parameters(np.zeros(10), -1.0)
    with pytest.raises(ProfileError, match="1D"):
        profile_parameters(np.zeros((3, 3)), 1e-6)
    with pytest.raises(ProfileError, match="all heights are NaN"):
        material_ratio(np.full(5, np.nan), 0.0)
