"""Love's influence coefficients and the two FFT convolutions, against direct sums."""

from __future__ import annotations

import math

import numpy as np
import pytest

from contact.halfspace.convolution import Convolution
from contact.halfspace.influence import love_coefficients, periodic_kernel_real, self_influence


def test_self_influence_closed_form():
    # square cell: (4/pi) asinh(1) dx (Johnson 1985, eq. 3.25 at the centre)
    assert self_influence(2e-6, 2e-6) == pytest.approx(4 / math.pi * math.asinh(1) * 2e-6,
                                                       rel=1e-14)
    dx, dy = 1e-6, 3e-6
    want = 2 / math.pi * (dx * math.asinh(dy / dx) + dy * math.asinh(dx / dy))
    assert self_influence(dx, dy) == pytest.approx(want, rel=1e-14)


def test_far_field_is_a_point_load_and_kernel_is_even():
    dx, dy = 1e-6, 2e-6
    for x, y in ((50e-6, 0.0), (-30e-6, 80e-6), (0.0, -200e-6)):
        r = math.hypot(x, y)
        k = float(love_coefficients(np.array(x), np.array(y), dx, dy))
        assert k == pytest.approx(dx * dy / (math.pi * r), rel=2e-3 * (10e-6 / r) ** 2 * 100)
    xs = np.array([3e-6, -3e-6])
    ys = np.array([[5e-6], [-5e-6]])
    k = love_coefficients(xs, ys, dx, dy)
    assert np.ptp(k) < 1e-18


def test_corner_formula_matches_quadrature():
    # the displacement of a uniformly loaded cell, by 2D quadrature of 1/(pi r)
    from scipy import integrate

    dx, dy = 1.0, 1.5
    for x, y in ((0.2, 0.1), (1.7, -0.4), (3.0, 2.0)):
        val = integrate.dblquad(lambda t, s, x=x, y=y: 1 / (math.pi * math.hypot(x - s, y - t)),
                                -dx / 2, dx / 2, -dy / 2, dy / 2, epsabs=1e-11)[0]
        assert float(love_coefficients(np.array(x), np.array(y), dx, dy)) == pytest.approx(
            val, rel=1e-7)


def _direct_free(p, dx, dy):
    ny, nx = p.shape
    u = np.zeros_like(p)
    for i in range(ny):
        for j in range(nx):
            if p[i, j]:
                xx = (np.arange(nx)[None, :] - j) * dx
                yy = (np.arange(ny)[:, None] - i) * dy
                u += p[i, j] * love_coefficients(xx, yy, dx, dy)
    return u


@pytest.mark.parametrize("single", [False, True])
def test_dc_fft_equals_direct_summation(single):
    rng = np.random.default_rng(0)
    ny, nx, dx, dy = 12, 10, 1e-6, 1.3e-6
    p = rng.random((ny, nx)) * (rng.random((ny, nx)) < 0.5)
    p[:3] = 0.0
    conv = Convolution(ny, nx, dx, dy, periodic=False)
    want = _direct_free(p, dx, dy)
    got_full = conv(p, single=single)
    got_rows = conv(p, rows=(3, ny), single=single)
    rtol = 1e-5 if single else 1e-12
    np.testing.assert_allclose(got_full, want, rtol=rtol, atol=rtol * np.abs(want).max())
    np.testing.assert_allclose(got_rows, want, rtol=rtol, atol=rtol * np.abs(want).max())


def test_periodic_kernel_equals_the_image_sum():
    # Sum Love's kernel over (2M+1)^2 periodic images; the sum converges like 1/M, so
    # compare differences of values, extrapolated from M and 2M (Richardson).
    ny, nx, dx, dy = 16, 12, 1.0, 1.5
    i = np.arange(ny)[:, None]
    j = np.arange(nx)[None, :]

    def images(M):
        k = np.zeros((ny, nx))
        for m in range(-M, M + 1):
            for n in range(-M, M + 1):
                k += love_coefficients((j + n * nx) * dx, (i + m * ny) * dy, dx, dy)
        return k - k[ny // 2, nx // 2]

    k_img = 2 * images(24) - images(12)
    kp = periodic_kernel_real(ny, nx, dx, dy, 16)
    kp = kp - kp[ny // 2, nx // 2]
    np.testing.assert_allclose(kp, k_img, atol=2e-4 * kp[0, 0])


def test_periodic_convolution_of_a_sine_is_the_westergaard_response():
    # p = cos(2 pi x / L), uniform in y, held constant over each cell: the displacement at
    # the cell centres is cos(2 pi x / L) times the alias sum of the half-space response
    # 2/|q'| (E* = 1) times the cell's transform sinc(q' dx / 2), q' = q + 2 pi m / dx
    # (Johnson 1985 sec. 13.2 for the m = 0 term; here summed to |m| = 20000 in 1D).
    n, dx = 64, 1e-6
    L = n * dx
    x = np.arange(n) * dx
    p = np.tile(np.cos(2 * np.pi * x / L), (4, 1))
    conv = Convolution(4, n, dx, dx, periodic=True)
    u = conv(p)
    m = np.arange(-20000, 20001)
    qm = 2 * np.pi / L + 2 * np.pi * m / dx
    amp = float(np.sum(2 / np.abs(qm) * np.sinc(qm * dx / (2 * np.pi))))
    np.testing.assert_allclose(u, amp * p, rtol=1e-7, atol=1e-9 * amp)
    # the continuous Westergaard response L/pi, less the cell averaging ~ (q dx)^2 / 24
    assert amp == pytest.approx(L / np.pi, rel=1e-3)
