"""surfmet.synth and surfmet.mechanics.spectrum: the spectrum recovers what the generator hid."""

from __future__ import annotations

import math

import numpy as np
import pytest

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.mechanics.spectrum import is_periodic, spectrum
from surfmet.synth import self_affine

PX = 1e-6
N = 256


def _case(seed: int) -> dict:
    rng = np.random.default_rng(1000 + seed)
    return {"hurst": rng.uniform(0.3, 0.9), "roll_off": N * PX / rng.uniform(3, 8),
            "short_cutoff": PX * rng.uniform(3, 6), "h_rms": rng.uniform(0.05e-6, 3e-6)}


@pytest.mark.parametrize("seed", range(6))
def test_recovers_hidden_hurst_cutoffs_and_rms(seed: int) -> None:
    c = _case(seed)
    topo = self_affine(N, PX, seed=seed, **c)
    s = spectrum(topo)
    assert s.periodic and s.settings["window"] == "none"
    assert abs(s.hurst.hurst - c["hurst"]) < 0.04
    assert s.roll_off == pytest.approx(2 * math.pi / c["roll_off"], rel=0.12)
    assert s.short_cutoff == pytest.approx(2 * math.pi / c["short_cutoff"], rel=0.05)
    # the fitted band lies between the cut-offs
    assert s.roll_off <= s.hurst.q_range[0] < s.hurst.q_range[1] <= s.short_cutoff
    # Parseval on a periodic scan: spectrum and real space agree on h_rms
    assert s.h_rms == pytest.approx(c["h_rms"], rel=1e-9)
    assert s.h_rms_real == pytest.approx(c["h_rms"], rel=1e-9)
    # Finite differences see less slope than the spectrum (they filter the short waves),
    # but with >= 3 pixels per shortest wavelength not much less
    assert 0.8 * s.slope_rms < s.slope_rms_real < s.slope_rms
    assert 0.4 * s.curvature_rms < s.curvature_rms_real < s.curvature_rms


@pytest.mark.parametrize("seed", range(4))
def test_slope_scaling_and_clean_spectrum_reports_no_cutoff(seed: int) -> None:
    rng = np.random.default_rng(seed)
    hurst, slope = rng.uniform(0.3, 0.9), rng.uniform(0.02, 0.5)
    topo = self_affine(N, PX, hurst=hurst, slope_rms=slope, seed=seed)
    s = spectrum(topo)
    # radial bins put every cell at its bin's mean |q|: a quadrature error below 1 %
    assert s.slope_rms == pytest.approx(slope, rel=1e-2)
    assert abs(s.hurst.hurst - hurst) < 0.03
    assert s.roll_off is None and s.short_cutoff is None
    # an independent check of the slope: the spectral derivative in real space
    z = topo.heights
    q = 2 * np.pi * np.fft.fftfreq(N, d=PX)
    gx = np.fft.ifft(1j * q[None, :] * np.fft.fft(z, axis=1), axis=1).real
    gy = np.fft.ifft(1j * q[:, None] * np.fft.fft(z, axis=0), axis=0).real
    assert math.sqrt(np.mean(gx**2 + gy**2)) == pytest.approx(slope, rel=1e-2)


@pytest.mark.parametrize("seed", range(3))
def test_cropped_scan_is_windowed_and_still_finds_hurst(seed: int) -> None:
    rng = np.random.default_rng(50 + seed)
    hurst = rng.uniform(0.3, 0.9)
    topo = self_affine(N, PX, hurst=hurst, h_rms=1e-6, seed=seed)
    crop = Topography(topo.heights[:200, :190], PX, PX)
    assert is_periodic(topo) and not is_periodic(crop)
    s = spectrum(crop)
    assert not s.periodic and s.settings["window"] == "hann"
    assert abs(s.hurst.hurst - hurst) < 0.12
    forced = spectrum(crop, periodic=True)
    assert forced.settings["window"] == "none"


def test_summits_and_plasticity_follow_nayak() -> None:
    topo = self_affine(N, PX, hurst=0.7, h_rms=1e-6, short_cutoff=8 * PX, seed=3)
    s = spectrum(topo, e_star=100e9, hardness=2e9)
    m = s.summits
    assert m.alpha >= 1.5
    # Nayak (1971): density m4/(6π√3 m2); McCool (1986): R_s = 3/8 √(π/m4)
    assert m.density == pytest.approx(m.m4 / (6 * math.pi * math.sqrt(3) * m.m2))
    assert s.plasticity == pytest.approx(50 * math.sqrt(m.sigma_s / m.radius))
    # a finer short cut-off raises the curvature and the summit density (resolution)
    fine = spectrum(self_affine(N, PX, hurst=0.7, h_rms=1e-6, short_cutoff=4 * PX, seed=3))
    assert fine.summits.density > 2 * m.density
    assert fine.h_rms == pytest.approx(s.h_rms, rel=1e-9)


def test_bad_input() -> None:
    with pytest.raises(SurfmetInputError):
        self_affine(64, PX, hurst=1.2, h_rms=1e-6)
    with pytest.raises(SurfmetInputError):
        self_affine(64, PX, hurst=0.5, h_rms=1e-6, slope_rms=0.1)
    with pytest.raises(SurfmetInputError):
        self_affine(64, PX, hurst=0.5, h_rms=1e-6, roll_off=2 * PX, short_cutoff=4 * PX)
    with pytest.raises(SurfmetInputError):
        spectrum(Topography(np.zeros((8, 8)), PX, PX))
