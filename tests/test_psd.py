"""PSD: peaks where sines put them, Parseval, NaN holes, Hurst exponents of self-affine
surfaces (Jacobs, Junge & Pastewka 2017), and the errors."""

from __future__ import annotations

import math

import numpy as np
import pytest

from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography
from surfmet.psd import areal_psd, fit_hurst, profile_psd, psd

SEEDS = [0, 1, 2, 3]


def self_affine(n: int, hurst: float, dx: float, rng: np.random.Generator) -> np.ndarray:
    """A periodic isotropic self-affine surface, C(q) ∝ q^(-2-2H) for all q > 0
    (Fourier filtering of white noise), scaled to 1 µm rms."""
    qx = 2 * np.pi * np.fft.fftfreq(n, dx)
    q = np.hypot(qx[:, None], qx[None, :])
    amp = np.zeros_like(q)
    amp[q > 0] = q[q > 0] ** (-1 - hurst)
    noise = rng.standard_normal(q.shape) + 1j * rng.standard_normal(q.shape)
    h = np.fft.ifft2(amp * noise).real
    return h / h.std() * 1e-6


@pytest.mark.parametrize("seed", SEEDS)
def test_profile_sine_peak_and_power(seed):
    rng = np.random.default_rng(seed)
    n, dx = 2048, rng.uniform(0.1e-6, 2e-6)
    amp = rng.uniform(0.05e-6, 2e-6)
    periods = rng.uniform(20, 200)  # not a whole number: the sine is not periodic in L
    lam = n * dx / periods
    z = amp * np.sin(2 * np.pi * np.arange(n) * dx / lam + rng.uniform(0, 2 * np.pi))
    p = profile_psd(Profile(z, dx))  # Hann
    q0 = 2 * np.pi / lam
    assert abs(p.q[np.argmax(p.C)] - q0) <= p.dq
    # all the power is in the peak: A²/2 within 1 %
    band = (q0 - 4 * p.dq, q0 + 4 * p.dq)
    assert p.variance(band) == pytest.approx(amp**2 / 2, rel=0.01)
    assert p.variance() - p.variance(band) < 1e-3 * amp**2
    assert p.C.min() >= 0 and p.kind == "profile"
    assert np.allclose(p.wavelength * p.frequency, 1.0)


@pytest.mark.parametrize("seed", SEEDS[:2])
def test_areal_sine_grooves_direction(seed):
    rng = np.random.default_rng(seed)
    n, dx = 256, 1e-6
    amp = rng.uniform(0.1e-6, 1e-6)
    kx, ky = rng.integers(5, 30), rng.integers(-30, 30)  # whole periods: exact bins
    y, x = np.mgrid[:n, :n] * dx
    qx0, qy0 = 2 * np.pi * kx / (n * dx), 2 * np.pi * ky / (n * dx)
    z = amp * np.cos(qx0 * x + qy0 * y + rng.uniform(0, 6))
    a = areal_psd(Topography(z, dx, dx), window="none")
    j, i = np.unravel_index(np.argmax(a.C), a.C.shape)
    found = (a.qx[i], a.qy[j])
    assert np.allclose(found, (qx0, qy0)) or np.allclose(found, (-qx0, -qy0))
    r = a.radial()
    assert abs(r.q[np.argmax(r.C)] - math.hypot(qx0, qy0)) <= r.dq
    assert a.variance() == pytest.approx(amp**2 / 2, rel=1e-9)


@pytest.mark.parametrize("seed", SEEDS)
def test_parseval_with_nan_holes(seed):
    rng = np.random.default_rng(seed)
    h = self_affine(192, rng.uniform(0.3, 0.9), 1e-6, rng)[:, :160]
    # hidden holes: random discs of non-measured points
    yy, xx = np.mgrid[:192, :160]
    for _ in range(rng.integers(1, 6)):
        cy, cx, r = rng.integers(0, 192), rng.integers(0, 160), rng.integers(3, 15)
        h[(yy - cy) ** 2 + (xx - cx) ** 2 < r * r] = np.nan
    t = Topography(h, 1e-6, 1.5e-6)
    valid = h[np.isfinite(h)]
    sq2 = np.mean((valid - valid.mean()) ** 2)
    # no window: the discrete Parseval sum is the mean square of the measured points
    a = areal_psd(t, window="none")
    assert a.variance() == pytest.approx(sq2, rel=1e-9)
    assert a.radial().variance() == pytest.approx(sq2, rel=1e-9)
    rows = [r[np.isfinite(r)] for r in h if np.isfinite(r).sum() >= 2]
    p_rows = profile_psd(t, window="none")
    assert p_rows.variance() == pytest.approx(np.mean([np.var(r) for r in rows]), rel=1e-9)
    # Hann: the taper weights the centre; for this stationary surface within 25 % of Sq²
    # (the bound is loose because a 160-point surface with H < 1 is far from ergodic)
    assert areal_psd(t).variance() == pytest.approx(sq2, rel=0.25)


@pytest.mark.parametrize("seed", SEEDS)
def test_sine_with_holes_keeps_peak(seed):
    rng = np.random.default_rng(100 + seed)
    n, dx, amp = 4096, 0.5e-6, rng.uniform(0.1e-6, 1e-6)
    lam = n * dx / rng.uniform(30, 300)
    z = amp * np.sin(2 * np.pi * np.arange(n) * dx / lam)
    for _ in range(rng.integers(2, 8)):
        start = rng.integers(0, n - 60)
        z[start: start + rng.integers(5, 60)] = np.nan
    p = profile_psd(Profile(z, dx))
    q0 = 2 * np.pi / lam
    assert abs(p.q[np.argmax(p.C)] - q0) <= p.dq
    assert p.variance((q0 - 8 * p.dq, q0 + 8 * p.dq)) == pytest.approx(amp**2 / 2, rel=0.05)


@pytest.mark.parametrize("seed", SEEDS)
def test_hurst_exponent_recovered(seed):
    rng = np.random.default_rng(seed)
    hurst = rng.uniform(0.2, 0.95)
    # a non-periodic crop of a larger surface, as an instrument sees it
    big = self_affine(1024, hurst, 0.5e-6, rng)
    i0, j0 = rng.integers(0, 1024 - 320, size=2)
    t = Topography(big[j0: j0 + 320, i0: i0 + 320], 0.5e-6, 0.5e-6)
    fit2d = fit_hurst(psd(t))
    assert fit2d.hurst == pytest.approx(hurst, abs=0.08)
    assert fit2d.slope == pytest.approx(-2 - 2 * hurst, abs=0.16)
    fit1d = fit_hurst(profile_psd(t))
    assert fit1d.hurst == pytest.approx(hurst, abs=0.12)


def test_without_window_edge_leakage_flattens_steep_spectra():
    # Why Hann is the default: the end-to-end jump of a non-periodic crop leaks a q^-2
    # tail that hides a steep spectrum (Jacobs et al. 2017, sec. 3.2).
    rng = np.random.default_rng(7)
    big = self_affine(1024, 0.9, 1e-6, rng)
    t = Topography(big[:256, :256], 1e-6, 1e-6)
    assert fit_hurst(areal_psd(t, window="none").radial()).hurst < 0.7
    assert fit_hurst(areal_psd(t, window="hann").radial()).hurst == pytest.approx(0.9, abs=0.08)


@pytest.mark.parametrize("seed", SEEDS[:2])
def test_white_noise_is_flat(seed):
    # clean data, no hidden power law: white noise has a flat PSD, "H" = -1
    rng = np.random.default_rng(seed)
    t = Topography(rng.standard_normal((512, 512)) * 1e-7, 1e-6, 1e-6)
    fit = fit_hurst(psd(t))
    # the Hann taper leaves fewer independent samples: the slope scatters by ~0.07 here,
    # against -2.4 or steeper for any self-affine surface with H >= 0.2
    assert fit.slope == pytest.approx(0.0, abs=0.25)
    assert fit.hurst == pytest.approx(-1.0, abs=0.125)


def test_nonuniform_profile_and_bare_array():
    rng = np.random.default_rng(3)
    x = np.cumsum(rng.uniform(0.5e-6, 1.5e-6, 600))
    lam = 40e-6
    z = 1e-7 * np.sin(2 * np.pi * x / lam)
    p = profile_psd(Profile(z, float(np.mean(np.diff(x))), x=x))
    assert p.settings["positions"] == "resampled"
    assert abs(p.q[np.argmax(p.C)] - 2 * np.pi / lam) <= p.dq
    q = profile_psd(z, 1e-6, window="none")
    assert q.variance() == pytest.approx(np.var(z), rel=1e-9)


@pytest.mark.parametrize("call, needle", [
    (lambda: profile_psd(np.full(10, np.nan), 1e-6), "no measured point"),
    (lambda: profile_psd(np.ones(3), 1e-6), "at least 4"),
    (lambda: profile_psd(np.ones(10)), "step dx"),
    (lambda: profile_psd(np.ones(10), 1e-6, window="tukey"), "window"),
    (lambda: areal_psd(Topography(np.ones((2, 9)), 1e-6, 1e-6)), "4 x 4"),
    (lambda: areal_psd(np.ones((8, 8))), "Topography"),
    (lambda: fit_hurst(profile_psd(np.sin(np.arange(16.0)), 1e-6), (1e9, 2e9)), "fewer than 3"),
])
def test_errors(call, needle):
    with pytest.raises(SurfmetInputError, match=needle):
        call()


def test_profile_moments_of_a_single_wave_are_exact():
    """h = A cos(q0 x + φ) on a periodic grid: <|∇h|²> = A²q0²/2, <(∇²h)²> = A²q0⁴/2, so
    m0 = A²/2, m2 = A²q0²/4, m4 = 3A²q0⁴/16, whatever the random A, φ and wavelength."""
    from surfmet._model import Topography
    from surfmet.psd import areal_psd

    rng = np.random.default_rng(175)
    n, dx = 128, 1e-6
    k = int(rng.integers(3, 40))
    amp, phase = rng.uniform(0.1e-6, 2e-6), rng.uniform(0, 2 * np.pi)
    q0 = 2 * np.pi * k / (n * dx)
    x = np.arange(n) * dx
    h = np.tile(amp * np.cos(q0 * x + phase), (n, 1))
    if rng.random() < 0.5:
        h = h.T.copy()  # the wave along y
    m0, m2, m4 = areal_psd(Topography(h, dx, dx), window="none").profile_moments()
    assert m0 == pytest.approx(amp**2 / 2, rel=1e-9)
    assert m2 == pytest.approx(amp**2 * q0**2 / 4, rel=1e-9)
    assert m4 == pytest.approx(3 * amp**2 * q0**4 / 16, rel=1e-9)
