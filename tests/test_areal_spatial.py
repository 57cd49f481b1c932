"""Hybrid, spatial, feature and functional areal parameters against analytic truths."""

from __future__ import annotations

import math

import numpy as np
import pytest
from areal_synth import gaussian_surface

from surfmet._model import Topography
from surfmet.areal import areal_parameters
from surfmet.areal._features import feature_parameters, significant_hills
from surfmet.areal._hybrid import gradient_parameters
from surfmet.areal._material_ratio import (
    functional_parameters,
    inverse_material_ratio,
    material_ratio,
)
from surfmet.areal._spatial import spatial_parameters, texture_direction


def _grid(nx, ny, dx, dy):
    x = np.arange(nx) * dx
    y = np.arange(ny) * dy
    return np.meshgrid(x, y)


@pytest.mark.parametrize("dx, dy", [(1e-6, 1e-6), (0.5e-6, 2e-6)])
def test_sdq_sdr_of_a_sine_small_slope(dx, dy):
    # z = A sin(k x): Sdq = A k / √2 (continuous). Forward differences see
    # 2 sin(k dx / 2) / dx instead of k; with λ = 400 dx the bias is 1e-5.
    lam, amp = 400 * dx, 0.3e-6
    X, _ = _grid(4 * 400 + 1, 64, dx, dy)  # the differences span exactly 4 periods
    k = 2 * np.pi / lam
    z = amp * np.sin(k * X)
    p = gradient_parameters(Topography(z, dx, dy))
    sdq_true = amp * k / math.sqrt(2)
    assert p["Sdq"] == pytest.approx(sdq_true, rel=1e-4)
    # Small slope: Sdr ≈ Sdq²/2 (as a ratio; here in %), next term -3 Sdq⁴/16... < 1e-3 rel.
    assert p["Sdr"] == pytest.approx(100 * sdq_true**2 / 2, rel=2e-3)


def test_sdr_of_a_tilted_plane_is_exact():
    # A plane of slope (a, b): area ratio sqrt(1 + a² + b²) exactly, Sdq = sqrt(a² + b²).
    X, Y = _grid(50, 40, 1e-6, 2e-6)
    a, b = 0.3, -0.2
    p = gradient_parameters(Topography(a * X + b * Y, 1e-6, 2e-6))
    assert p["Sdq"] == pytest.approx(math.hypot(a, b), rel=1e-12)
    assert p["Sdr"] == pytest.approx(100 * (math.sqrt(1 + a * a + b * b) - 1), rel=1e-10)


def test_sdq_ignores_pairs_with_a_missing_point():
    rng = np.random.default_rng(0)
    X, _ = _grid(200, 100, 1e-6, 1e-6)
    z = 0.1 * X
    z[rng.random(z.shape) < 0.3] = np.nan
    p = gradient_parameters(Topography(z, 1e-6, 1e-6))
    assert p["Sdq"] == pytest.approx(0.1, rel=1e-9)
    assert p["Sdr"] == pytest.approx(100 * (math.sqrt(1.01) - 1), rel=1e-9)


def test_sal_str_std_of_a_sine_lay():
    # z = A sin(k x) (grooves along y): ACF = cos(k τx) → Sal = arccos(0.2)/k; the ACF never
    # decays along y, so Str is an upper bound (noted) and small; Std (wave vector) = 0°.
    dx, lam = 1e-6, 64e-6
    X, _ = _grid(1024, 256, dx, dx)
    z = 1e-6 * np.sin(2 * np.pi * X / lam)
    vals, notes = spatial_parameters(Topography(z, dx, dx))
    assert vals["Sal"] == pytest.approx(math.acos(0.2) * lam / (2 * math.pi), rel=0.02)
    assert vals["Str"] < 0.2
    assert any("upper bound" in n for n in notes)
    assert vals["Std"] == pytest.approx(0.0, abs=0.5)


@pytest.mark.parametrize("angle", [0.0, 30.0, 90.0, 135.0])
def test_std_follows_the_wave_vector(angle):
    dx = 1e-6
    X, Y = _grid(300, 300, dx, dx)
    th = math.radians(angle)
    z = np.sin(2 * np.pi * (X * math.cos(th) + Y * math.sin(th)) / 25e-6)
    assert texture_direction(Topography(z, dx, dx)) == pytest.approx(angle, abs=1.0)


@pytest.mark.parametrize("seed", [1, 2])
def test_sal_str_of_an_isotropic_gaussian_surface(seed):
    # ACF exp(-(r/τ)²): Sal = τ sqrt(ln 5), Str = 1 (isotropic).
    rng = np.random.default_rng(seed)
    corr = 6.0
    z = gaussian_surface(rng, 512, 512, 1e-6, corr)
    vals, notes = spatial_parameters(Topography(z, 1e-6, 1e-6))
    assert vals["Sal"] == pytest.approx(corr * 1e-6 * math.sqrt(math.log(5)), rel=0.08)
    assert vals["Str"] > 0.8
    assert not notes


def test_sal_str_with_holes_uses_valid_pairs():
    rng = np.random.default_rng(5)
    z = gaussian_surface(rng, 384, 384, 1e-6, 5.0)
    full, _ = spatial_parameters(Topography(z, 1e-6, 1e-6))
    z2 = z.copy()
    z2[rng.random(z.shape) < 0.3] = np.nan
    holed, _ = spatial_parameters(Topography(z2, 1e-6, 1e-6))
    # Random dropouts do not change the ACF of the remaining pairs (zero filling would
    # shrink it by 30 % at every non-zero lag and shorten Sal).
    assert holed["Sal"] == pytest.approx(full["Sal"], rel=0.02)


def _egg_crate(n_periods=8, spp=64, amp=1e-6, dx=1e-6):
    lam = spp * dx
    X, Y = _grid(n_periods * spp, n_periods * spp, dx, dx)
    k = 2 * np.pi / lam
    return Topography(amp * np.sin(k * X) * np.sin(k * Y), dx, dx), lam, amp, k


def test_spd_spc_of_an_egg_crate():
    # z = A sin(kx) sin(ky): 2 peaks per λ², each with curvature -(zxx + zyy)/2 = A k².
    topo, lam, amp, k = _egg_crate()
    p = feature_parameters(topo, exclude_edge=False)
    assert p["Spd"] == pytest.approx(2 / lam**2, rel=1e-12)
    # central second differences: k² → (2 - 2 cos(k dx))/dx², 0.08 % low at 64 samples/λ
    k2 = (2 - 2 * math.cos(k * topo.dx)) / topo.dx**2
    assert p["Spc"] == pytest.approx(amp * k2, rel=1e-9)
    # Hills touching the border are incomplete and not counted by default.
    p_edge = feature_parameters(topo)
    n_edge = len(significant_hills(topo).edge_peaks)
    assert n_edge > 0
    assert p_edge["Spd"] * topo.size_x * topo.size_y == pytest.approx(
        2 * 8 * 8 - n_edge, abs=0.5)


def test_wolf_pruning_drops_hills_below_5_percent_of_sz():
    # Big Gaussian bumps (height 1) and small ones on their flanks: the small ones count
    # only when their prominence exceeds 5 % of Sz.
    dx = 1e-6
    X, Y = _grid(400, 400, dx, dx)
    z = np.zeros_like(X)
    big = [(100, 100), (300, 120), (200, 300)]
    for cx, cy in big:
        z += np.exp(-((X / dx - cx) ** 2 + (Y / dx - cy) ** 2) / (2 * 20**2))
    small_ok = (100, 300)      # isolated, prominence 0.08 > 0.05 Sz
    small_pruned = (300, 300)  # isolated, prominence 0.03 < 0.05 Sz
    z += 0.08 * np.exp(-((X / dx - small_ok[0]) ** 2 + (Y / dx - small_ok[1]) ** 2) / 50)
    z += 0.03 * np.exp(-((X / dx - small_pruned[0]) ** 2 + (Y / dx - small_pruned[1]) ** 2)
                       / 50)
    topo = Topography(z * 1e-6, dx, dx)
    hills = significant_hills(topo, exclude_edge=False)
    got = {(int(c), int(r)) for r, c in hills.peaks}
    assert got == set(big) | {small_ok}


def test_sk_family_of_a_uniform_height_distribution():
    # Heights uniform in [-A, A] (a triangle wave): the material ratio curve is a straight
    # line, so Sk = 2A, Spk = Svk = 0, Smr1 = 0 %, Smr2 = 100 %.
    amp, n = 1e-6, 200
    tri = amp * (2 * np.abs(((np.arange(8 * n) + 0.5) / n) % 2 - 1) - 1)
    z = np.tile(tri, (40, 1))
    p = functional_parameters(Topography(z, 1e-6, 1e-6))
    assert p["Sk"] == pytest.approx(2 * amp, rel=1e-3)
    assert p["Spk"] == pytest.approx(0, abs=2e-3 * amp)
    assert p["Svk"] == pytest.approx(0, abs=2e-3 * amp)
    assert p["Smr1"] < 0.5 and p["Smr2"] > 99.5


def test_sk_family_of_a_gaussian_distribution():
    # For N(0, σ²) the 40 % window of least drop is centred (30..70 %); the least-squares
    # line through the quantile function there gives Sk, computed here from scipy's ppf.
    from scipy.stats import norm

    rng = np.random.default_rng(11)
    sigma = 1e-6
    z = rng.normal(0, sigma, size=(700, 700))
    p = functional_parameters(Topography(z, 1e-6, 1e-6))
    mr = np.linspace(30, 70, 4001)
    slope, icpt = np.polyfit(mr, sigma * norm.ppf(1 - mr / 100), 1)
    sk_true = -slope * 100
    assert p["Sk"] == pytest.approx(sk_true, rel=0.01)
    assert p["Spk"] == pytest.approx(p["Svk"], rel=0.1)  # symmetric distribution
    assert p["Smr1"] == pytest.approx(100 - p["Smr2"], abs=0.5)
    upper = icpt
    assert p["Smr1"] == pytest.approx(100 * norm.sf(upper / sigma), abs=0.3)


def test_material_ratio_and_its_inverse():
    rng = np.random.default_rng(2)
    z = rng.normal(0, 1e-6, size=(300, 300))
    topo = Topography(z, 1e-6, 1e-6)
    assert material_ratio(topo, 0.0) == pytest.approx(50, abs=0.5)
    assert material_ratio(topo, 1e-6) == pytest.approx(15.87, abs=0.3)
    assert inverse_material_ratio(topo, 15.87) == pytest.approx(1e-6, rel=0.02)


def test_areal_parameters_selection_and_groups():
    topo, *_ = _egg_crate(4, 32)
    p = areal_parameters(topo, which="height,Sdq")
    assert set(p.as_dict()) == {"Sa", "Sq", "Sp", "Sv", "Sz", "Ssk", "Sku", "Sdq"}
    assert p.Sal is None
