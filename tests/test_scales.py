"""Scale-dependent statistics (profiles._scales, surfmet.scale_dependent) against independent
truths: the values SurfaceTopography's tests assert on real files, closed forms for a
sinusoid and for a self-affine profile built from a known spectrum, and Parseval between
surfmet's PSD and the rms height and slope."""

from __future__ import annotations

import math

import numpy as np
import pytest

import surfmet
from profiles._scales import (
    derivative,
    height_difference_acf,
    make_scan,
    scale_variance,
    tip_cutoff,
)
from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography
from surfmet.io import read_container
from surfmet.scale_dependent import analyze_scales, distance_grid

# --- SurfaceTopography's asserted values on real files ------------------------------------


@pytest.mark.realdata
def test_container_variance_of_slope_matches_surfacetopography(realdata):
    # ST test_scale_dependent_statistics.py::test_container_mixed (MANIFEST.tsv), in µm:
    # one point per decade, var of the first derivative averaged over the measurements.
    a = analyze_scales(read_container(realdata("container-2.zip")), per_decade=1)
    sel = np.isfinite(a.rms_slope)
    assert np.allclose(a.distance[sel], [1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4], rtol=1e-12)
    expected = [1.057908e-03, 4.016837e-02, 2.302750e-03, 2.058876e-04, 2.822253e-06,
                2.650320e-08]
    np.testing.assert_allclose(a.rms_slope[sel] ** 2, expected, atol=1e-8, rtol=1e-6)
    # who votes where: TEM (0) at 10, 100 nm; AFM (1) at 1, 10 nm; stylus (2) from 100 nm
    votes = a.contributors("slope")[:, sel]
    assert votes.tolist() == [[False, True, True, False, False, False],
                              [True, True, False, False, False, False],
                              [False, False, True, True, True, True]]


@pytest.mark.realdata
def test_tip_radius_cutoff_of_di_1_matches_surfacetopography(realdata):
    # ST test_reliability_cutoff.py: a 40 nm tip on di-1.di gives 90.700854 nm
    t = surfmet.read(realdata("di-1.di"))
    cut = tip_cutoff(make_scan(t.heights, t.dx, t.dy), 40e-9)
    assert cut == pytest.approx(90.700854e-9, rel=1e-7)


@pytest.mark.realdata
def test_stylus_radius_in_the_dektak_file_gives_1_57_um(realdata):
    # ST test_csv.py: the file's stylus radius (2.5 µm) -> short_reliability_cutoff 1.57 µm
    p = surfmet.read(realdata("dektak-1.csv"))
    assert p.metadata["tip_radius"]["value"] == pytest.approx(2.5e-6)
    a = analyze_scales([p], per_decade=10)
    (m,) = a.measurements
    assert m.cutoff_source == "tip radius from file"
    assert m.cutoff == pytest.approx(1.57e-6, rel=0.01)
    # nothing at or below the cut-off votes
    votes = a.contributors("slope")[0]
    assert not votes[a.distance <= m.cutoff].any() and votes[a.distance > 2 * m.cutoff].any()


# --- closed forms ----------------------------------------------------------------------------


def _sine(periods: int, per_period: int, extra: int, amplitude: float = 1e-6):
    dx = 1e-7
    lam = per_period * dx
    x = np.arange(periods * per_period + extra) * dx
    return amplitude * np.sin(2 * np.pi * x / lam), dx, 2 * np.pi / lam


@pytest.mark.parametrize("s", [1, 3, 7])
def test_sinusoid_slope_curvature_and_acf_at_whole_pixels(s):
    a = 1e-6
    # the retained points cover exactly 40 periods, so averages are exact
    z, dx, k = _sine(40, 32, s, a)
    d = s * dx
    scan = make_scan(z, dx)
    assert scale_variance(scan, [d], 1)[0] == pytest.approx(a**2 * (1 - math.cos(k * d)) / d**2,
                                                            rel=1e-10)
    assert height_difference_acf(scan, [d])[0] == pytest.approx(
        0.5 * a**2 * (1 - math.cos(k * d)), rel=1e-10)
    z2, dx, k = _sine(40, 32, 2 * s, a)  # curvature at distance 2 s dx trims s at each end
    d2 = 2 * s * dx
    curv = a * (2 - 2 * math.cos(k * d2 / 2)) / (d2 / 2) ** 2
    assert scale_variance(make_scan(z2, dx), [d2], 2)[0] == pytest.approx(curv**2 / 2, rel=1e-10)


def test_sinusoid_slope_between_pixels_is_the_linear_interpolation():
    a, s = 1e-6, 2.4
    z, dx, k = _sine(40, 32, math.ceil(s), a)
    d = s * dx
    # h(x + d) interpolated between pixels K and K+1 is a sinusoid of complex amplitude c
    c = (1 - 0.4) * np.exp(1j * k * 2 * dx) + 0.4 * np.exp(1j * k * 3 * dx)
    expected = a**2 * abs(c - 1) ** 2 / 2 / d**2
    assert scale_variance(make_scan(z, dx), [d], 1)[0] == pytest.approx(expected, rel=1e-10)


def test_maps_take_x_rows_and_trim_y_too():
    z, dx, _k = _sine(20, 16, 3)
    m = np.tile(z, (50, 1))
    d = 3 * dx
    vals = derivative(make_scan(m, dx, dx), d, 1)
    assert vals.size == (50 - 3) * (z.size - 3)  # ceil(s) rows and columns trimmed
    assert np.var(vals) == pytest.approx(np.var(derivative(make_scan(z, dx), d, 1)), rel=1e-12)


def _self_affine(n: int, hurst: float, dx: float, seed: int = 3):
    """Periodic profile with exact amplitudes sqrt(C(q) Δq / π) x 2 (cosines), random
    phases, C(q) = C0 q^(-1-2H) for all q > 0 below Nyquist."""
    rng = np.random.default_rng(seed)
    L = n * dx
    ks = np.arange(1, n // 2)
    q = 2 * np.pi * ks / L
    c0 = 1e-30
    C = c0 * q ** (-1 - 2 * hurst)
    amp = np.sqrt(2 * C * (2 * np.pi / L) / np.pi)
    phase = rng.uniform(0, 2 * np.pi, ks.size)
    x = np.arange(n + 64) * dx  # 64 extra points: the retained ones span whole periods
    z = (amp[:, None] * np.cos(np.outer(q, x) + phase[:, None])).sum(axis=0)
    return z, q, C, amp


def test_self_affine_slope_at_distance_and_psd_level_and_slope():
    n, dx, hurst = 2048, 1e-8, 0.8
    z, q, _C, amp = _self_affine(n, hurst, dx)
    for s in (1, 4, 16, 64):
        d = s * dx
        zs = z[: n + s]
        expected = np.sum(amp**2 * (1 - np.cos(q * d))) / d**2
        assert scale_variance(make_scan(zs, dx), [d], 1)[0] == pytest.approx(expected, rel=1e-9)
    # the PSD averaged over 8 measurements of the surface (random phases, exact amplitudes):
    # level and exponent of the generating spectrum, to the phases' statistical scatter
    z8 = [Profile(_self_affine(4096, hurst, dx, seed)[0][:4096], dx) for seed in range(8)]
    a = analyze_scales(z8, per_decade=5)
    q0 = 2 * np.pi / (4096 * dx)
    band = (a.q > 20 * q0) & (a.q < 400 * q0) & np.isfinite(a.psd)
    assert band.sum() >= 6
    expected = 1e-30 * a.q[band] ** (-1 - 2 * hurst)
    np.testing.assert_allclose(a.psd[band], expected, rtol=0.25)
    slope = np.polyfit(np.log(a.q[band]), np.log(a.psd[band]), 1)[0]
    assert slope == pytest.approx(-1 - 2 * hurst, abs=0.06)


@pytest.mark.parametrize("hurst", [0.3, 0.8])
def test_variable_bandwidth_grows_as_the_hurst_power(hurst):
    # Self-affine: the rms height over a window of width ℓ scales as ℓ^H (Jacobs, Junge &
    # Pastewka 2017, sec. 3.3); a tilted line leaves nothing once each segment loses its line.
    from profiles._scales import variable_bandwidth

    z = _self_affine(4096, hurst, 1e-8, 1)[0][:4096]
    w, r = variable_bandwidth(make_scan(z, 1e-8))
    assert w[0] == pytest.approx(4096e-8) and np.allclose(w[1:] / w[:-1], 0.5)
    sel = (w >= 32e-8) & (w <= 1024e-8)
    assert np.polyfit(np.log(w[sel]), np.log(r[sel]), 1)[0] == pytest.approx(hurst, abs=0.05)
    x = np.arange(100) * 1e-8
    assert np.all(variable_bandwidth(make_scan(3e-3 * x + 1e-9, 1e-8))[1] < 1e-20)


def test_parseval_psd_against_rms_height_and_slope():
    from surfmet.psd import profile_psd

    n, dx = 1024, 1e-8
    rng = np.random.default_rng(7)
    z = np.cumsum(rng.normal(size=n)) * 1e-9
    z -= np.linspace(z[0], z[-1], n)  # make it periodic (equal ends) ...
    z = z[:-1]  # ... and drop the repeated end point
    spec = profile_psd(z, dx, window="none")
    assert spec.variance() == pytest.approx(np.var(z), rel=1e-10)
    # slope over one pixel on the periodic continuation: (1/π) Σ C w 2(1 - cos qΔ)/Δ² Δq
    ms_slope = np.sum(spec.C * spec.weights * 2 * (1 - np.cos(spec.q * dx)) / dx**2) \
        * spec.dq / math.pi
    ext = np.r_[z, z[0]]
    assert scale_variance(make_scan(ext, dx), [dx], 1)[0] == pytest.approx(ms_slope, rel=1e-9)


# --- bad input and grid ------------------------------------------------------------------------


def _rough(n: int, dx: float, seed: int) -> Profile:
    rng = np.random.default_rng(seed)
    return Profile(np.cumsum(rng.normal(size=n)) * dx * 0.1, dx)


def test_measurements_without_common_scale_are_refused():
    near, far = _rough(500, 1e-8, 1), _rough(500, 1e-3, 2)
    with pytest.raises(SurfmetInputError, match="no overlapping bandwidth"):
        analyze_scales([near, far])


def test_tip_radius_that_masks_everything_is_refused():
    with pytest.raises(SurfmetInputError, match="no reliable scale"):
        analyze_scales([_rough(500, 1e-8, 1)], tip_radius=1.0)
    with pytest.raises(SurfmetInputError, match="positive"):
        analyze_scales([_rough(500, 1e-8, 1)], tip_radius=-1.0)


def test_distance_grid_holds_whole_decades():
    d = distance_grid(3e-9, 2e-6, 4)
    assert d[0] == pytest.approx(1e-9) and d[-1] == pytest.approx(1e-5)
    assert np.allclose(np.diff(np.log10(d)), 0.25)
    assert any(abs(v - 1e-7) < 1e-20 for v in d)


def test_equal_votes_per_measurement():
    t = Topography(np.random.default_rng(0).normal(size=(64, 64)) * 1e-9, 1e-8, 1e-8)
    p = _rough(256, 1e-8, 5)
    a = analyze_scales([t, p], per_decade=5)
    both = a.contributors("slope").all(axis=0)
    mean = 0.5 * (a.measurements[0].variance_slope + a.measurements[1].variance_slope)
    np.testing.assert_allclose(a.rms_slope[both] ** 2, mean[both], rtol=1e-12)


@pytest.mark.realdata
def test_container_slope_and_curvature_at_five_per_decade_match_the_peer(realdata):
    # Reference numbers from SurfaceTopography 1.27.1, provenance in the JSON file.
    import json
    from pathlib import Path

    ref = json.loads((Path(__file__).parent / "data" / "scales_container2_st.json")
                     .read_text(encoding="utf-8"))
    a = analyze_scales(read_container(realdata("container-2.zip")), per_decade=5)
    for key, mine in (("variance_slope", a.rms_slope**2),
                      ("variance_curvature", a.rms_curvature**2)):
        sel = np.isfinite(mine)
        np.testing.assert_allclose(a.distance[sel], ref[key]["distance_m"], rtol=1e-12)
        np.testing.assert_allclose(mine[sel], ref[key]["value"], rtol=1e-9)


def test_a_map_scan_without_dy_has_square_pixels():
    # found by the type check (issue 36): Scan(z_map, dx) without dy raised TypeError in
    # bandwidth(); make_scan's rule is dy = dx, so the longest distance is the mean side
    from profiles._scales import Scan

    s = Scan(np.zeros((4, 8)), 1e-6)
    assert s.bandwidth() == pytest.approx((1e-6, 0.5 * (8e-6 + 4e-6)))
