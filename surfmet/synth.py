"""Random-phase self-affine surfaces: a generator with ISO-style parameters.

The isotropic PSD (Jacobs, Junge & Pastewka 2017, Surf. Topogr.: Metrol. Prop. 5, 013001,
Eq. 1 and sec. 2.3) is

    C(q) = C0                         for q_L ≤ q < q_r   (roll-off plateau),
    C(q) = C0 (q/q_r)^(-2-2H)         for q_r ≤ q ≤ q_s,
    C(q) = 0                          for q > q_s          (short-wavelength cut-off),

with ``q = 2π/λ``. Every Fourier coefficient gets the amplitude ``sqrt(C(|q|))`` and a
uniformly random phase (the "random-phase" construction of e.g. Persson et al. 2005,
J. Phys.: Condens. Matter 17, R1, appendix), so that the periodogram of the result follows
C(q) without the exponential scatter of Gaussian amplitudes. The surface is periodic on its
grid. It is then scaled to the requested rms height ``Sq`` or rms gradient ``Sdq``
(ISO 25178-2 names; the gradient is the spectral one, ``<|∇h|²> = (2π)⁻² Σ q² C Δq²``,
which is exact for a periodic surface).
"""

from __future__ import annotations

import math

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography


def _grid(n: int | tuple[int, int]) -> tuple[int, int]:
    if isinstance(n, (int, np.integer)):
        ny = nx = int(n)
    else:
        try:
            ny, nx = (int(v) for v in n)
        except (TypeError, ValueError):
            raise SurfmetInputError(f"n must be an int or (ny, nx), got {n!r}") from None
    if ny < 8 or nx < 8:
        raise SurfmetInputError(f"the grid must be at least 8 x 8, got {ny} x {nx}")
    return ny, nx


def self_affine(
    n: int | tuple[int, int],
    pixel: float,
    *,
    hurst: float,
    h_rms: float | None = None,
    slope_rms: float | None = None,
    roll_off: float | None = None,
    short_cutoff: float | None = None,
    seed: int | np.random.Generator | None = None,
) -> Topography:
    """A periodic, isotropic, random-phase self-affine surface.

    Parameters
    ----------
    n : int or (ny, nx)
        Grid size (points).
    pixel : float
        Pixel size, m (square pixels).
    hurst : float
        Hurst exponent H, 0 < H < 1 (fractal dimension 3 - H).
    h_rms, slope_rms : float
        Exactly one: the rms height Sq (m) or the rms gradient Sdq (dimensionless).
    roll_off : float, optional
        Roll-off wavelength λ_r (m): the PSD is flat above it. Default: the scan length.
    short_cutoff : float, optional
        Short-wavelength cut-off λ_s (m): no power below it. Default: none (the power law
        runs to the grid's largest wavevector).
    seed : int or numpy Generator, optional
        Random phases.

    Returns
    -------
    Topography
        Heights in metres (zero mean); ``metadata["synth"]`` holds the parameters.

    Raises
    ------
    SurfmetInputError
        H outside (0, 1), not exactly one of h_rms / slope_rms, non-positive lengths,
        or cut-offs that leave no power on the grid.
    """
    ny, nx = _grid(n)
    if not (math.isfinite(pixel) and pixel > 0):
        raise SurfmetInputError(f"pixel must be a positive length, got {pixel!r}")
    if not (0.0 < hurst < 1.0):
        raise SurfmetInputError(f"the Hurst exponent must lie in (0, 1), got {hurst!r}")
    if (h_rms is None) == (slope_rms is None):
        raise SurfmetInputError("give exactly one of h_rms (Sq) and slope_rms (Sdq)")
    target = h_rms if h_rms is not None else slope_rms
    if not (math.isfinite(target) and target > 0):
        raise SurfmetInputError(f"the rms value must be positive, got {target!r}")
    side = max(nx, ny) * pixel
    lam_r = side if roll_off is None else float(roll_off)
    # without a cut-off the power law runs into the corners of the DFT grid
    lam_s = pixel / math.sqrt(2.0) if short_cutoff is None else float(short_cutoff)
    if not (lam_r > 0 and lam_s > 0 and lam_s < lam_r):
        raise SurfmetInputError(
            f"need 0 < short_cutoff ({lam_s:.4g} m) < roll_off ({lam_r:.4g} m)"
        )
    q_r, q_s = 2.0 * math.pi / lam_r, 2.0 * math.pi / lam_s
    qy = 2.0 * math.pi * np.fft.fftfreq(ny, d=pixel)[:, None]
    qx = 2.0 * math.pi * np.fft.fftfreq(nx, d=pixel)[None, :]
    q = np.hypot(qx, qy)
    C = np.where(q < q_r, 1.0, (np.maximum(q, q_r) / q_r) ** (-2.0 - 2.0 * hurst))
    if short_cutoff is not None:
        C[q > q_s * (1.0 + 1e-12)] = 0.0
    C[0, 0] = 0.0
    if not np.any(C > 0):
        raise SurfmetInputError("the cut-offs leave no wavevector on the grid; "
                                "use a larger grid or a longer short_cutoff")
    rng = seed if isinstance(seed, np.random.Generator) else np.random.default_rng(seed)
    # Phases of the FFT of real white noise are uniform and already Hermitian-symmetric,
    # so the inverse transform is real without bookkeeping of conjugate pairs.
    spec = np.fft.fft2(rng.standard_normal((ny, nx)))
    mag = np.abs(spec)
    phase = np.divide(spec, mag, out=np.zeros_like(spec), where=mag > 0)
    z = np.fft.ifft2(phase * np.sqrt(C)).real
    z -= z.mean()
    if h_rms is not None:
        z *= h_rms / float(np.sqrt(np.mean(z**2)))
    else:
        zk = np.fft.fft2(z)
        grad2 = float(np.sum(q**2 * np.abs(zk) ** 2)) / (nx * ny) ** 2
        z *= slope_rms / math.sqrt(grad2)
    meta = {"synth": {"kind": "self-affine random-phase", "hurst": float(hurst),
                      "roll_off_m": lam_r, "short_cutoff_m": short_cutoff,
                      "h_rms_m": h_rms, "slope_rms": slope_rms,
                      "seed": seed if isinstance(seed, (int, type(None))) else "generator"},
            "periodic": True}
    return Topography(z, pixel, pixel, metadata=meta)
