"""Persson, Greenwood-Williamson and Bush-Gibson-Thomas against their limits and closed forms."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from scipy.integrate import quad

from contact._errors import ContactInputError
from contact.roughcontact import (
    KAPPA_BGT,
    bush_gibson_thomas,
    greenwood_williamson,
    gw_integral,
    kappa,
    persson,
    summit_parameters,
)
from surfmet.mechanics.spectrum import spectrum
from surfmet.synth import self_affine

E = 100e9


@pytest.fixture(scope="module")
def spec():
    topo = self_affine(128, 1e-6, hurst=0.7, slope_rms=0.1, roll_off=32e-6,
                       short_cutoff=4e-6, seed=1)
    return spectrum(topo)


def test_persson_kappa_tends_to_sqrt_8_over_pi(spec):
    p = np.geomspace(1e-6, 1e-1, 6) * E * spec.slope_rms
    c = persson(p, E, spec.psd.q, spec.psd.C, spec.psd.weights, spec.psd.dq)
    k = kappa(c.area_fraction, p, E, spec.slope_rms)
    assert k[0] == pytest.approx(math.sqrt(8 / math.pi), rel=1e-6)
    assert np.all(np.diff(k) < 0)  # erf bends down
    assert np.all(np.diff(c.mean_gap) < 0) and np.all(np.diff(c.stiffness) > 0)


def test_persson_stiffness_is_minus_dp_dgap(spec):
    for p0 in (1e4, 1e6, 1e8):
        p = p0 * np.array([1 - 1e-4, 1, 1 + 1e-4])
        c = persson(p, E, spec.psd.q, spec.psd.C, spec.psd.weights, spec.psd.dq)
        fd = -(p[2] - p[0]) / (c.mean_gap[2] - c.mean_gap[0])
        assert c.stiffness[1] == pytest.approx(fd, rel=2e-3)


def test_persson_gap_follows_yang_persson_exponential_law(spec):
    # at low pressure F(x0) ≈ γ ln(1/x0) + const, so dū/d ln p -> -γ √π ∫ q² C_P w dq
    # (Yang & Persson 2008: p ∝ exp(-ū/u0)); u0 from the spectrum by independent sums
    q, C, w, dq = spec.psd.q, spec.psd.C, spec.psd.weights, spec.psd.dq
    base = C * w * dq**2 / (2 * math.pi) ** 2
    wq = np.sqrt(2 / np.cumsum(q**2 * base))
    u0 = 0.4 * math.sqrt(math.pi) / (2 * math.pi) * np.sum(q * base * wq)
    p = np.array([1e-3, 1e-2])
    c = persson(p, E, q, C, w, dq)
    assert (c.mean_gap[0] - c.mean_gap[1]) / math.log(10) == pytest.approx(u0, rel=1e-3)


@pytest.mark.parametrize("n", [0.0, 0.5, 1.0, 1.5])
@pytest.mark.parametrize("t", [-2.0, 0.0, 1.3, 4.0])
def test_gw_integral_closed_form_matches_quad(n, t):
    ref = quad(lambda s: (s - t) ** n * math.exp(-s * s / 2), t, np.inf)[0] / math.sqrt(
        2 * math.pi)
    assert float(gw_integral(n, t)) == pytest.approx(ref, rel=1e-6)


def _deep_moment(n: float, t: float) -> float:
    """E[(s - t)^n] for a standard normal s and t << 0: a^n (1 + C(n,2)/a² + 3 C(n,4)/a⁴)
    with a = -t (binomial series; the Gaussian moments E s² = 1, E s⁴ = 3)."""
    a = -t
    c2 = n * (n - 1) / 2
    c4 = n * (n - 1) * (n - 2) * (n - 3) / 24
    return a**n * (1 + c2 / a**2 + 3 * c4 / a**4)


@pytest.mark.parametrize("t", [-9.0, -60.0, -100.0, -1e4])
def test_gw_integral_deep_in_contact_is_the_gaussian_moment(t):
    # past t ≈ -54 the closed form was 0 × inf = NaN; F_0, F_1, F_2 are exact moments
    assert float(gw_integral(0.0, t)) == pytest.approx(1.0, rel=1e-13)
    assert float(gw_integral(1.0, t)) == pytest.approx(-t, rel=1e-13)
    assert float(gw_integral(2.0, t)) == pytest.approx(1 + t * t, rel=1e-13)
    for n in (0.5, 1.5):
        if t < -50:  # the series' next term, 15 C(n,6)/t⁶, is below 1e-11 there
            ref = _deep_moment(n, t)
        else:
            ref = quad(lambda s, n=n: (s - t) ** n * math.exp(-s * s / 2), t, np.inf)[0] / (
                math.sqrt(2 * math.pi))
        assert float(gw_integral(n, t)) == pytest.approx(ref, rel=1e-9)


def test_gw_deep_in_contact_and_beyond_its_range():
    s = summit_parameters(1e-12, 1e-4, 1e5)  # σ = 1 µm, slope 0.01, α = 10
    t0 = -100.0  # the summits' mean plane 100 σ_s into the surface
    p = 4 / 3 * s.density * E * math.sqrt(s.radius) * s.sigma_s**1.5 * _deep_moment(1.5, t0)
    c = greenwood_williamson([p], E, s)
    assert c.mean_gap[0] == pytest.approx(t0 * s.sigma_s + s.mean_height, rel=1e-9)
    assert c.area_fraction[0] == 1.0  # clipped: every summit flattened
    tiny = summit_parameters(1e-46, 1e-34, 1e-21)  # rounding noise of a levelled plane
    with pytest.raises(ContactInputError, match="too smooth"):
        greenwood_williamson([1e6], E, tiny)


def test_gw_on_a_single_scale_surface_matches_independent_quadrature():
    # a narrow band (roll-off at 24 µm, cut-off at 12 µm): nearly a single scale
    topo = self_affine(128, 1e-6, hurst=0.8, h_rms=0.5e-6, roll_off=24e-6,
                       short_cutoff=12e-6, seed=2)
    s = spectrum(topo, periodic=True).summits
    eta, R, sig = s.density, s.radius, s.sigma_s
    p = np.array([1e4, 1e6, 3e7])
    g = greenwood_williamson(p, E, s)
    for k, pk in enumerate(p):
        d = g.mean_gap[k] - s.mean_height  # separation from the mean summit plane

        def phi(z):
            return math.exp(-z * z / (2 * sig**2)) / (sig * math.sqrt(2 * math.pi))

        def integral(n, d=d):
            # the integrand decays over ~σ²/d beyond d when d is many σ out: integrate
            # piecewise on that scale, out to where the Gaussian is negligible
            scale = sig**2 / max(d, sig)
            edges = d + scale * np.arange(0, 200)
            return sum(quad(lambda z: (z - d) ** n * phi(z), a, b)[0]
                       for a, b in itertools.pairwise(edges))

        load = 4 / 3 * eta * E * math.sqrt(R) * integral(1.5)
        area = math.pi * eta * R * integral(1.0)
        assert load == pytest.approx(pk, rel=1e-6)
        assert g.area_fraction[k] == pytest.approx(area, rel=1e-6)


def test_gw_and_bgt_low_pressure_slopes():
    s = summit_parameters(1e-12, 2e-3, 1e7)  # α = 2.5
    slope = s.slope_rms
    b = bush_gibson_thomas(1e3, E, slope)
    assert kappa(b.area_fraction, 1e3, E, slope)[0] == pytest.approx(math.sqrt(2 * math.pi))
    assert KAPPA_BGT == pytest.approx(2.5066, rel=1e-4)
    # GW: κ falls slowly (logarithmically) as the pressure falls, unlike BGT's constant
    g = greenwood_williamson(np.array([1e-2, 1e2]), E, s)
    k = kappa(g.area_fraction, np.array([1e-2, 1e2]), E, slope)
    assert k[0] > k[1] > 0


def test_bad_input():
    with pytest.raises(ContactInputError):
        bush_gibson_thomas(-1.0, E, 0.1)
    with pytest.raises(ContactInputError):
        persson([1e6], E, np.array([1.0, 2.0]), np.array([1.0]), np.array([1.0]), 1.0)
