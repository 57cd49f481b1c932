"""``surfmet spectrum``'s figure and its noise floor (issue 16, item 14).

A self-affine surface with white noise added: the power law must be fitted, and drawn,
below the wavevector where the noise overtakes the surface. That crossover is computed here
independently, from the discrete Fourier transforms of the clean surface and of the noise
(white noise of variance σ² has the mean DFT power N σ² in every mode), not from surfmet.psd.
"""

from __future__ import annotations

import numpy as np
import pytest

from surfmet._model import Topography
from surfmet.mechanics.spectrum import spectrum
from surfmet.synth import self_affine

N, PX = 256, 1e-6


def _noisy(hurst: float, sigma: float, seed: int) -> tuple[Topography, float]:
    """A periodic self-affine scan plus white noise, and the crossover wavevector (rad/m)."""
    clean = self_affine(N, PX, hurst=hurst, h_rms=1e-6, roll_off=N * PX / 4, seed=seed)
    z = np.asarray(clean.heights, float)
    power = np.abs(np.fft.fft2(z - z.mean())) ** 2
    q1 = 2 * np.pi * np.fft.fftfreq(N, PX)
    q = np.hypot(*np.meshgrid(q1, q1))
    edges = np.geomspace(2 * np.pi / (N * PX), q.max(), 60)
    ring = np.digitize(q, edges)
    noise_power = z.size * sigma**2
    crossing = None
    for k in range(1, edges.size):
        cell = ring == k
        if cell.any() and power[cell].mean() < noise_power:
            crossing = float(edges[k - 1])
            break
    assert crossing is not None
    rng = np.random.default_rng(seed + 100)
    noisy = Topography(heights=z + sigma * rng.standard_normal(z.shape), dx=PX, dy=PX)
    return noisy, crossing


@pytest.mark.parametrize(("hurst", "seed"), [(0.8, 0), (0.5, 1)])
def test_hurst_is_fitted_below_the_noise_floor(hurst: float, seed: int) -> None:
    topo, crossing = _noisy(hurst, 1e-7, seed)
    s = spectrum(topo, periodic=True)
    assert s.noise_floor is not None
    assert crossing / 2 < s.noise_floor < crossing * 2
    assert s.hurst.q_range[1] <= crossing
    assert abs(s.hurst.hurst - hurst) < 0.05


def test_clean_surface_has_no_noise_floor() -> None:
    topo = self_affine(N, PX, hurst=0.7, h_rms=1e-6, roll_off=N * PX / 4, seed=3)
    assert spectrum(topo, periodic=True).noise_floor is None


def test_figure_units_labels_and_fitted_line() -> None:
    from surfmet.plots._style import close
    from surfmet.plots.spectrum import spectrum_figure

    topo, _ = _noisy(0.8, 1e-7, 0)
    s = spectrum(topo, periodic=True)
    fig = spectrum_figure(s)
    try:
        ax = fig.axes[0]
        assert "rad/µm" in ax.get_xlabel()
        ylabel = ax.get_ylabel()
        # C^iso as mathtext (between $...$), never as the literal text "C^iso"
        assert r"$C^{\mathrm{iso}}(q)$" in ylabel and "µm$^4$" in ylabel
        assert "C^iso" not in ylabel.replace(r"$C^{\mathrm{iso}}(q)$", "")
        assert any("wavelength" in c.get_xlabel() for c in ax.child_axes)  # the top axis
        fit = [ln for ln in ax.get_lines() if "power law" in str(ln.get_label())]
        assert len(fit) == 1
        x = np.asarray(fit[0].get_xdata(), float)
        lo, hi = s.hurst.q_range
        assert x.min() == pytest.approx(lo * 1e-6, rel=1e-9)
        assert x.max() == pytest.approx(hi * 1e-6, rel=1e-9)
        assert x.max() < s.noise_floor * 1e-6
        # the PSD in µm⁴: its largest value is the m⁴ one times 1e24
        dots = next(ln for ln in ax.get_lines() if ln.get_label() == "isotropic PSD")
        assert np.max(dots.get_ydata()) == pytest.approx(float(s.psd.C.max()) * 1e24, rel=1e-9)
        fig.canvas.draw()  # the mathtext renders
    finally:
        close(fig)
