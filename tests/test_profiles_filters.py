"""ISO 16610-21 Gaussian profile filter: transmission, polynomials, end effects, NaN holes."""

from __future__ import annotations

import math

import numpy as np
import pytest

from profiles import ALPHA, ProfileError, gaussian_mean_line, gaussian_transmission, split_profile
from profiles._filters import END_TREATMENTS


def _amplitude(signal, x, lam):
    # least-squares amplitude of the component of wavelength lam
    m = np.column_stack([np.sin(2 * np.pi * x / lam), np.cos(2 * np.pi * x / lam)])
    coef, *_ = np.linalg.lstsq(m, signal, rcond=None)
    return float(np.hypot(*coef))


def test_alpha_gives_half_transmission_at_cutoff():
    assert math.exp(-math.pi * ALPHA**2) == pytest.approx(0.5, abs=1e-15)


@pytest.mark.parametrize("seed", range(3))
def test_transmission_follows_iso_16610_21(seed):
    rng = np.random.default_rng(seed)
    lc = rng.choice([0.25e-3, 0.8e-3, 2.5e-3])
    dx = lc / rng.uniform(150, 400)
    n = int(16 * lc / dx)
    x = np.arange(n) * dx
    interior = slice(int(2 * lc / dx), n - int(2 * lc / dx))
    for ratio in (1.0, 0.4, 0.7, 1.5, 3.0):
        lam = ratio * lc
        amp = rng.uniform(0.1, 2.0) * 1e-6
        z = amp * np.sin(2 * np.pi * x / lam + rng.uniform(0, 2 * np.pi))
        mean_line = gaussian_mean_line(z, dx, lc)
        t = _amplitude(mean_line[interior], x[interior], lam) / amp
        expected = float(gaussian_transmission(lam, lc))
        if ratio == 1.0:
            assert t == pytest.approx(0.5, abs=0.005)
        assert t == pytest.approx(expected, abs=0.005)
        # the roughness gets the complement
        r = z - mean_line
        assert _amplitude(r[interior], x[interior], lam) / amp == pytest.approx(
            1 - expected, abs=0.005
        )


@pytest.mark.parametrize("end_treatment", END_TREATMENTS)
def test_mean_line_of_a_line_is_the_line_in_the_interior(end_treatment):
    rng = np.random.default_rng(1)
    lc, dx = 0.8e-3, 1e-6
    x = np.arange(6000) * dx
    z = rng.uniform(-5, 5) * 1e-3 * x + rng.uniform(-1, 1) * 1e-6
    m = gaussian_mean_line(z, dx, lc, end_treatment=end_treatment)
    inner = slice(int(lc / dx), x.size - int(lc / dx))
    assert np.allclose(m[inner], z[inner], rtol=0, atol=1e-9 * np.ptp(z))


def _mirror_mean_line(z, dx, lc):
    """Naive end handling (the way several tools do it): mirror the profile at its ends."""
    h = math.ceil(lc / dx)
    d = np.arange(-h, h + 1) * dx
    g = np.exp(-np.pi * (d / (ALPHA * lc)) ** 2)
    g /= g.sum()
    padded = np.pad(z, h, mode="symmetric")
    return np.convolve(padded, g, mode="same")[h:-h]


def _end_bend(mean_line, z):
    return float(np.nanmax(np.abs(mean_line - z)))


@pytest.mark.parametrize("seed", range(3))
def test_tilted_line_gets_no_end_effect(seed):
    rng = np.random.default_rng(seed)
    lc = 0.8e-3
    dx = rng.uniform(0.5, 2.0) * 1e-6
    x = np.arange(int(4 * lc / dx)) * dx
    slope = rng.choice([-1, 1]) * rng.uniform(1e-3, 2e-2)
    z = slope * x + rng.uniform(-1, 1) * 1e-6
    rise = abs(slope) * lc
    tol = 1e-6 * rise
    assert _end_bend(gaussian_mean_line(z, dx, lc), z) < tol  # moment criterion, default
    assert _end_bend(gaussian_mean_line(z, dx, lc, end_treatment="discard"), z) < 0.01 * rise
    # the check has teeth: mirroring the ends bends the mean line by a large fraction
    assert _end_bend(_mirror_mean_line(z, dx, lc), z) > 0.05 * rise
    # so does plain renormalisation of truncated weights (zeroth-order moment only)
    assert _end_bend(gaussian_mean_line(z, dx, lc, end_treatment="renormalise"), z) > 0.05 * rise


def test_discard_returns_nan_half_cutoff_at_each_end():
    lc, dx = 0.25e-3, 1e-6
    z = np.sin(np.arange(3000) * dx / 40e-6)
    m = gaussian_mean_line(z, dx, lc, end_treatment="discard")
    cut = round(0.5 * lc / dx)  # 125 samples
    assert np.all(np.isnan(m[:cut])) and np.all(np.isnan(m[-cut:]))
    assert np.all(np.isfinite(m[cut:-cut]))


@pytest.mark.parametrize("seed", range(3))
def test_nan_holes_do_not_spread(seed):
    rng = np.random.default_rng(seed)
    lc, dx = 0.8e-3, 1e-6
    n = 6000
    x = np.arange(n) * dx
    lam = lc / rng.uniform(5, 10)
    amp = rng.uniform(0.2, 1.0) * 1e-6
    tilt = rng.uniform(-3e-3, 3e-3) * x
    rough = amp * np.sin(2 * np.pi * x / lam + rng.uniform(0, 6))
    z = tilt + rough
    holes = z.copy()
    for start in rng.integers(100, n - 200, 6):
        holes[start : start + rng.integers(3, 60)] = np.nan
    missing = np.isnan(holes)
    split = split_profile(holes, dx, lc=lc)
    assert np.array_equal(np.isnan(split.roughness), missing)
    assert np.array_equal(np.isnan(split.waviness), missing)
    # the tilt goes entirely into the mean line, also across holes
    lines = gaussian_mean_line(np.where(missing, np.nan, tilt), dx, lc)
    assert np.nanmax(np.abs(lines - tilt)) < 1e-9 * np.ptp(tilt)
    # the roughness is the sine, with the filter's own transmission
    t = 1 - float(gaussian_transmission(lam, lc))
    ok = ~missing
    assert np.sqrt(np.mean(split.roughness[ok] ** 2)) == pytest.approx(
        t * amp / np.sqrt(2), rel=0.02
    )


def test_split_profile_with_ls_removes_short_waves():
    rng = np.random.default_rng(2)
    lc, ls, dx = 0.8e-3, 2.5e-6, 0.25e-6
    x = np.arange(int(5 * lc / dx)) * dx
    signal = 0.5e-6 * np.sin(2 * np.pi * x / 80e-6)
    noise = 0.05e-6 * np.sin(2 * np.pi * x / 1.0e-6 + rng.uniform(0, 6))  # λ = ls / 2.5
    split = split_profile(signal + noise, dx, lc=lc, ls=ls)
    inner = slice(1000, x.size - 1000)
    left = split.primary[inner] - signal[inner]
    # λs transmits exp(-pi (alpha * 2.5)^2) = 1.3e-2 % of a wave 2.5 times shorter
    assert np.max(np.abs(left)) < 0.02 * 0.05e-6 + 1e-3 * 0.5e-6
    assert split.settings["ls"] == ls and split.settings["lc"] == lc


def test_filter_errors():
    z = np.zeros(1000)
    with pytest.raises(ProfileError, match="too short for the cut-off"):
        split_profile(z, 1e-6, lc=2.5e-3)
    with pytest.raises(ProfileError, match=r"leaves nothing|too short"):
        split_profile(z, 1e-6, lc=0.8e-3, end_treatment="discard")
    with pytest.raises(ProfileError, match="all heights are NaN"):
        gaussian_mean_line(np.full(100, np.nan), 1e-6, 8e-6)
    with pytest.raises(ProfileError, match="end treatment"):
        gaussian_mean_line(z, 1e-6, 80e-6, end_treatment="reflect")
    with pytest.raises(ProfileError, match="shorter than λc"):
        split_profile(z, 1e-6, lc=0.25e-3, ls=0.3e-3)


def test_cutoff_shorter_than_three_steps_is_refused():
    # the one rule of profiles._resolution (ISO 25178-3 Table 1): 3 sampling distances
    with pytest.raises(ProfileError, match=r"spans 1\.25 sampling distances"):
        gaussian_mean_line(np.zeros(100), 2e-6, 2.5e-6)


def test_iso13565_1_valley_suppression_keeps_the_plateau():
    # plateau at 0 with rectangular grooves (depth d, width w, period P << λc): the plain
    # Gaussian mean line is the average -d w/P; ISO 13565-1 replaces the grooves by that
    # line and filters again, whose mean is -d (w/P)² (closed forms, away from the ends)
    from profiles import split_profile

    dx, lc, period, width, depth = 1e-6, 0.8e-3, 80e-6, 16e-6, 5e-6
    x = np.arange(8000) * dx
    z = np.where(np.mod(x, period) < width, -depth, 0.0)
    frac = width / period
    inner = slice(1000, 7000)
    plain = split_profile(z, dx, lc=lc)
    assert np.allclose(plain.waviness[inner], -depth * frac, atol=1e-3 * depth)
    iso = split_profile(z, dx, lc=lc, valley_suppression=True)
    assert np.allclose(iso.waviness[inner], -depth * frac**2, atol=1e-3 * depth)
    assert "13565-1" in iso.settings["filter"]
