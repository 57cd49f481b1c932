"""Power spectral density (PSD) of profiles and areal scans, NaN-aware.

Definitions follow Jacobs, Junge & Pastewka (2017), *Quantitative characterization of
surface topography using spectral analysis*, Surf. Topogr.: Metrol. Prop. 5, 013001,
with the wavevector ``q = 2π/λ`` (rad/m):

profile (1D)
    ``C¹ᴰ(q) = |h̃(q)|² / L`` with ``h̃(q) = ∫₀ᴸ h(x) e^{-iqx} dx`` (unit m³). It is even in
    ``q``; we return ``q ≥ 0`` and ``h_rms² = (1/π) ∫₀^∞ C¹ᴰ(q) dq``.
areal (2D)
    ``C(q) = |h̃(q)|² / A`` (unit m⁴) on the 2D wavevector grid, with
    ``h_rms² = (2π)⁻² ∬ C(q) d²q``; its radial (isotropic) average ``C^iso(|q|)`` gives
    ``h_rms² = (1/2π) ∫₀^∞ q C^iso(q) dq``.

For a self-affine surface with Hurst exponent H, ``C^iso ∝ q^(-2-2H)`` and the PSD of its
profiles ``C¹ᴰ ∝ q^(-1-2H)`` (Jacobs et al. 2017, sec. 2.3); :func:`fit_hurst` fits those
slopes.

Discretisation. With N points of step ``Δx`` the continuous transform is approximated by
``Δx`` times the DFT, so ``C¹ᴰ(q_k) = Δx |H_k|² / N`` at ``q_k = 2πk/L``; the discrete
Parseval sum ``(1/L) Σ_k C(q_k)`` over all (positive and negative) ``k`` equals the mean
square of the data exactly. :meth:`PSD.variance` evaluates that sum.

Windowing. A scan is not periodic: the jump between its two ends leaks power as a
``q⁻²`` tail into every frequency, which flattens the apparent slope of a steep
(large-H) spectrum (Jacobs et al. 2017, sec. 3.2). The default ``window="hann"``
multiplies the (mean-removed) heights by a Hann window (separable, ``w(x) w(y)``, on areal
scans) before the transform. The window takes power out; the PSD is divided by the mean of
``w²`` over the measured points, so that the PSD of a stationary signal keeps its
integral: the Parseval sum then equals the ``w²``-weighted mean square of the data, which
is the mean square itself up to the sampling error of a stationary surface.
``window="none"`` gives the plain periodogram, whose Parseval sum is exactly the mean
square of the measured heights.

Centring. The heights are centred on their window-weighted mean ``Σ w m h / Σ w m``, so
the tapered data sum to zero and no power sits at ``q = 0`` (for ``window="none"`` this
is the plain mean).

Non-measured points. NaN points are set to zero after centring (so they add no power),
and the normalisation divides by the window energy over the *measured* points only,
``Σ w² m / N`` with ``m`` the measured mask, instead of ``Σ w²/N``. The PSD level
therefore stays that of the measured surface; holes convolve the spectrum with the mask's
own spectrum, which smooths sharp peaks but keeps their position and power. Non-uniformly
sampled profiles are first put on a uniform grid by :func:`profiles.regularize`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography

WINDOWS = ("hann", "blackman", "none")


@dataclass(frozen=True, eq=False)
class PSD:
    """A one-dimensional PSD: a profile's, the mean of an areal scan's row (or column)
    PSDs, or the radial average of an areal PSD.

    Attributes
    ----------
    q : ndarray
        Wavevectors ``2π/λ`` in rad/m, increasing, ``q[0] > 0``.
    C : ndarray
        PSD values: m³ for ``kind="profile"``, m⁴ for ``kind="radial"``.
    kind : {"profile", "radial"}
    dq : float
        Spacing of the underlying DFT grid (``2π/L``), rad/m.
    weights : ndarray
        Quadrature weights for :meth:`variance` (1 for the interior of a one-sided profile
        spectrum, 1/2 at the Nyquist wavevector; for radial bins the number of DFT cells
        in the bin).
    settings : dict
        Window, detrending, NaN fraction, grid, axis...
    """

    q: np.ndarray
    C: np.ndarray
    kind: str
    dq: float
    weights: np.ndarray = field(repr=False)
    settings: dict[str, Any] = field(default_factory=dict)

    @property
    def wavelength(self) -> np.ndarray:
        """``λ = 2π/q`` in metres."""
        return 2.0 * np.pi / self.q

    @property
    def frequency(self) -> np.ndarray:
        """Spatial frequency ``1/λ = q/2π`` in 1/m."""
        return self.q / (2.0 * np.pi)

    def variance(self, q_range: tuple[float, float] | None = None) -> float:
        """Mean square height (m²) carried by the spectrum, optionally in a band.

        Profile: ``(1/π) Σ C(q) w Δq``; radial: ``(2π)⁻² Σ C_bin n_bin Δq²`` (each bin holds
        ``n_bin`` DFT cells of area ``Δq²``). Over the whole spectrum this is the discrete
        Parseval sum (see the module docstring).
        """
        sel = np.ones(self.q.size, dtype=bool)
        if q_range is not None:
            lo, hi = q_range
            sel = (self.q >= lo) & (self.q <= hi)
        c = self.C[sel] * self.weights[sel]
        if self.kind == "profile":
            return float(np.sum(c) * self.dq / math.pi)
        return float(np.sum(c) * self.dq**2 / (2.0 * math.pi) ** 2)

    def rms_height(self) -> float:
        """``sqrt(variance())``, metres."""
        return math.sqrt(self.variance())


@dataclass(frozen=True, eq=False)
class ArealPSD:
    """The 2D PSD of an areal scan on the DFT grid (``fftshift``-ed, zero at the centre).

    Attributes
    ----------
    qx, qy : ndarray
        Wavevector axes (rad/m), increasing.
    C : ndarray, shape (qy.size, qx.size)
        ``|h̃|²/A`` in m⁴.
    settings : dict
    """

    qx: np.ndarray
    qy: np.ndarray
    C: np.ndarray
    settings: dict[str, Any] = field(default_factory=dict)

    @property
    def dqx(self) -> float:
        return float(self.qx[1] - self.qx[0]) if self.qx.size > 1 else math.nan

    @property
    def dqy(self) -> float:
        return float(self.qy[1] - self.qy[0]) if self.qy.size > 1 else math.nan

    def variance(self) -> float:
        """``(2π)⁻² Σ C Δqx Δqy``: the discrete Parseval sum, m²."""
        return float(np.sum(self.C) * self.dqx * self.dqy / (2.0 * math.pi) ** 2)

    def profile_moments(self) -> tuple[float, float, float]:
        """Profile spectral moments (m0, m2, m4) of the surface taken as isotropic, summed
        exactly over the 2D wavevector grid (m², 1, 1/m²).

        ``m0 = <h²>``, ``m2 = ½ <|∇h|²>`` and ``m4 = ⅜ <(∇²h)²>`` (Nayak 1971), each the
        discrete Parseval sum ``(2π)⁻² Σ f(|q|) C Δqx Δqy`` with ``f = 1, ½|q|², ⅜|q|⁴``.
        Summing on the grid rather than over the radial bins keeps every cell at its own
        ``|q|``: a bin's mean ``|q|`` misplaces the power of a narrow-band spectrum.
        """
        qy, qx = np.meshgrid(self.qy, self.qx, indexing="ij")
        q2 = qx**2 + qy**2
        w = self.C * (self.dqx * self.dqy / (2.0 * math.pi) ** 2)
        return (float(np.sum(w)), 0.5 * float(np.sum(w * q2)),
                0.375 * float(np.sum(w * q2 * q2)))

    def radial(self, nbins: int | None = None) -> PSD:
        """Radial (isotropic) average ``C^iso(|q|)``.

        Bins are ``Δq = max(Δqx, Δqy)`` wide from 0 to the largest ``|q|`` on the grid (the
        corners included, so that no power is lost), or ``nbins`` equal bins. Empty bins
        are dropped; the zero wavevector is excluded.
        """
        qy, qx = np.meshgrid(self.qy, self.qx, indexing="ij")
        qr = np.hypot(qx, qy).ravel()
        c = self.C.ravel()
        dq = max(self.dqx, self.dqy)
        qmax = float(qr.max())
        if nbins is None:
            nbins = max(1, math.ceil(qmax / dq))
        else:
            dq = qmax / int(nbins)
        idx = np.minimum((qr / dq).astype(np.int64), nbins - 1)
        keep = qr > 0
        n = np.bincount(idx[keep], minlength=nbins)
        s = np.bincount(idx[keep], weights=c[keep], minlength=nbins)
        qs = np.bincount(idx[keep], weights=qr[keep], minlength=nbins)
        ok = n > 0
        q_mean = qs[ok] / n[ok]
        # Weights so that variance() is the exact 2D Parseval sum over the bins:
        # Σ_bin C_bin n_bin Δqx Δqy / (2π)², expressed with the radial dq.
        w = n[ok] * (self.dqx * self.dqy) / dq**2
        settings = dict(self.settings)
        settings["radial_bins"] = int(ok.sum())
        return PSD(q=q_mean, C=s[ok] / n[ok], kind="radial", dq=dq, weights=w,
                   settings=settings)


def _window(name: str, n: int) -> np.ndarray:
    if name == "none" or n < 3:
        return np.ones(n)
    if name == "hann":
        # periodic-free symmetric Hann: zero at both ends, as scipy.signal.windows.hann
        return np.hanning(n)
    if name == "blackman":
        return np.blackman(n)
    raise SurfmetInputError(f"unknown window {name!r}; use one of {', '.join(WINDOWS)}")


def _check_window(window: str) -> str:
    w = str(window).strip().lower()
    if w not in WINDOWS:
        raise SurfmetInputError(f"unknown window {window!r}; use one of {', '.join(WINDOWS)}")
    return w


def _profile_arrays(scan: Any, dx: float | None) -> tuple[np.ndarray, float, dict[str, Any]]:
    """Heights (uniform grid) and step of a Profile or a 1D array."""
    if isinstance(scan, Profile):
        if scan.is_uniform:
            return np.array(scan.z, dtype=float), scan.dx, {}
        import profiles

        reg = profiles.regularize(scan.z, scan.x)
        return np.array(reg.z, dtype=float), reg.dx, {"positions": reg.method}
    z = np.asarray(scan, dtype=float)
    if z.ndim != 1:
        raise SurfmetInputError(f"a profile PSD needs 1D heights, got shape {z.shape}")
    if dx is None or not (math.isfinite(float(dx)) and float(dx) > 0):
        raise SurfmetInputError("a profile PSD of a bare array needs its step dx (metres)")
    return z.copy(), float(dx), {}


def _one_sided(power: np.ndarray, n: int, dx: float, settings: dict[str, Any]) -> PSD:
    """PSD object from ``|H_k|²`` averaged over rows, k = 0..n//2 (rfft order)."""
    C = dx * power / n
    L = n * dx
    dq = 2.0 * math.pi / L
    q = np.arange(C.size) * dq
    w = np.full(C.size, 2.0)
    w[0] = 1.0
    if n % 2 == 0:
        w[-1] = 1.0
    # one-sided sum counts ±k: variance = (1/L) Σ_all k C = (1/L) Σ_{k>=0} w C, and with
    # dq = 2π/L that is (1/π) Σ (w/2) C dq.
    return PSD(q=q[1:], C=C[1:], kind="profile", dq=dq, weights=w[1:] / 2.0, settings=settings)


def _weighted_mean(z: np.ndarray, wm: np.ndarray) -> float:
    # Centring on the window-weighted mean makes the tapered data sum to zero, so no power
    # sits at q = 0 and the Parseval sum over q > 0 is the whole (weighted) mean square.
    s = float(np.sum(wm))
    if s <= 0:
        raise SurfmetInputError("the window leaves no weight on the measured points")
    return float(np.sum(np.where(wm > 0, z, 0.0) * wm) / s)


def _prepare_rows(z2: np.ndarray, win: np.ndarray) -> tuple[np.ndarray, float]:
    """Centred, masked, windowed rows and the energy normalisation mean(w² m)."""
    m = np.isfinite(z2)
    if not m.any():
        raise SurfmetInputError("the scan has no measured point")
    wm = win[None, :] * m
    d = np.where(m, z2 - _weighted_mean(z2, wm), 0.0)
    norm = float(np.mean(wm**2))
    if norm <= 0:
        raise SurfmetInputError("the window leaves no weight on the measured points")
    return d * win[None, :], norm


def profile_psd(
    scan: Profile | Topography | np.ndarray,
    dx: float | None = None,
    *,
    window: str = "hann",
    detrend: str = "mean",
    axis: str = "x",
) -> PSD:
    """The 1D PSD ``C¹ᴰ(q)`` of a profile, or the mean profile PSD of an areal scan.

    Parameters
    ----------
    scan : Profile, Topography or 1D array
        Heights in metres (NaN = not measured). For a Topography the PSD of every row
        (``axis="x"``) or column (``axis="y"``) is computed and averaged, as
        profilometry software does for "PSD along x".
    dx : float, optional
        Step in metres, needed only for a bare array.
    window : {"hann", "blackman", "none"}
        Taper against edge leakage (see the module docstring).
    detrend : {"mean", "line"}
        Remove the mean of the measured points, or a least-squares line (for a profile;
        each row of a Topography gets its own line), before the transform.
    axis : {"x", "y"}
        For a Topography: along rows (x) or columns (y).

    Returns
    -------
    PSD
        ``kind="profile"``, ``C`` in m³, ``q > 0`` in rad/m.

    Raises
    ------
    SurfmetInputError
        No measured point, fewer than 4 points, unknown window or detrend.
    """
    window = _check_window(window)
    detrend = str(detrend).strip().lower()
    if detrend not in ("mean", "line"):
        raise SurfmetInputError(f"detrend must be 'mean' or 'line', got {detrend!r}")
    settings: dict[str, Any] = {"window": window, "detrend": detrend}
    if isinstance(scan, Topography):
        if axis not in ("x", "y"):
            raise SurfmetInputError(f"axis must be 'x' or 'y', got {axis!r}")
        z2 = np.array(scan.heights, dtype=float)
        step = scan.dx
        if axis == "y":
            z2, step = z2.T.copy(), scan.dy
        settings.update(axis=axis, rows=int(z2.shape[0]))
    else:
        z, step, extra = _profile_arrays(scan, dx)
        settings.update(extra)
        z2 = z[None, :]
    n = z2.shape[1]
    if n < 4:
        raise SurfmetInputError(f"a PSD needs at least 4 points along {axis}, got {n}")
    valid_rows = np.isfinite(z2).sum(axis=1) >= 2
    if not valid_rows.any():
        raise SurfmetInputError("the scan has no measured point")
    z2 = z2[valid_rows]
    if detrend == "line":
        x = np.arange(n, dtype=float)
        for r in z2:
            m = np.isfinite(r)
            slope, icpt = np.polyfit(x[m], r[m], 1)
            r -= slope * x + icpt
    settings["nan_fraction"] = float(np.mean(~np.isfinite(z2)))
    win = _window(window, n)
    # each row is centred and normalised on its own measured points
    power = np.zeros(n // 2 + 1)
    used = 0
    for r in z2:
        d, norm = _prepare_rows(r[None, :], win)
        power += np.abs(np.fft.rfft(d[0])) ** 2 / norm
        used += 1
    settings["n"] = n
    settings["dx"] = step
    return _one_sided(power / used, n, step, settings)


def areal_psd(topo: Topography, *, window: str = "hann", detrend: str = "mean") -> ArealPSD:
    """The 2D PSD ``C(qx, qy) = |h̃|²/A`` of an areal scan.

    Parameters
    ----------
    topo : Topography
        Heights in metres (NaN = not measured).
    window : {"hann", "blackman", "none"}
        Separable taper ``w(x) w(y)`` (see the module docstring).
    detrend : {"mean", "plane"}
        Remove the mean, or a least-squares plane (:func:`surfmet.areal._form.remove_form`),
        of the measured points before the transform.

    Returns
    -------
    ArealPSD
        Use :meth:`ArealPSD.radial` for the isotropic ``C^iso(q)``.
    """
    if not isinstance(topo, Topography):
        raise SurfmetInputError(f"areal_psd needs a Topography, got {type(topo).__name__}")
    window = _check_window(window)
    detrend = str(detrend).strip().lower()
    if detrend not in ("mean", "plane"):
        raise SurfmetInputError(f"detrend must be 'mean' or 'plane', got {detrend!r}")
    if topo.nx < 4 or topo.ny < 4:
        raise SurfmetInputError(f"an areal PSD needs at least 4 x 4 points, got "
                                f"{topo.nx} x {topo.ny}")
    if detrend == "plane":
        from surfmet.areal._form import remove_form

        topo, _ = remove_form(topo, "plane")
    z = np.array(topo.heights, dtype=float)
    m = np.isfinite(z)
    if not m.any():
        raise SurfmetInputError("the scan has no measured point")
    w2 = np.outer(_window(window, topo.ny), _window(window, topo.nx))
    d = np.where(m, z - _weighted_mean(z, w2 * m), 0.0)
    norm = float(np.mean((w2 * m) ** 2))
    H = np.fft.fftshift(np.fft.fft2(d * w2))
    ny, nx = z.shape
    C = topo.dx * topo.dy * np.abs(H) ** 2 / (nx * ny) / norm
    qx = 2 * np.pi * np.fft.fftshift(np.fft.fftfreq(nx, d=topo.dx))
    qy = 2 * np.pi * np.fft.fftshift(np.fft.fftfreq(ny, d=topo.dy))
    settings = {"window": window, "detrend": detrend, "nan_fraction": topo.nan_fraction,
                "nx": nx, "ny": ny, "dx": topo.dx, "dy": topo.dy}
    return ArealPSD(qx=qx, qy=qy, C=C, settings=settings)


def psd(scan: Profile | Topography, *, window: str = "hann") -> PSD:
    """The PSD a user usually wants: ``C¹ᴰ`` of a profile, ``C^iso`` of an areal scan."""
    if isinstance(scan, Topography):
        return areal_psd(scan, window=window).radial()
    return profile_psd(scan, window=window)


@dataclass(frozen=True)
class HurstFit:
    """A power law ``C = prefactor · q^slope`` fitted to a PSD.

    ``hurst`` is ``-(slope + 1)/2`` for a profile PSD and ``-(slope + 2)/2`` for a radial
    (areal) PSD (Jacobs et al. 2017). ``q_range`` is the band fitted (rad/m).
    """

    hurst: float
    slope: float
    prefactor: float
    q_range: tuple[float, float]
    n_points: int
    residual_rms: float


def fit_hurst(spectrum: PSD, q_range: tuple[float, float] | None = None,
              bins_per_decade: int = 10) -> HurstFit:
    """Fit the self-affine power law of a PSD and return its Hurst exponent.

    The spectrum is averaged in logarithmic bins (``bins_per_decade``; the mean PSD of
    each bin, weighted by the DFT cells behind each point) before a least-squares line is
    fitted to ``log C`` against ``log q``, so that each decade of wavevectors weighs the
    same (a plain fit would be dominated by the many large-q points).

    Parameters
    ----------
    spectrum : PSD
    q_range : (q_min, q_max), optional
        Band to fit in rad/m. Default: from ``8 Δq`` (the first wavevectors carry the
        window's main lobe and the finite size's imprint: on synthetic self-affine
        crops a start at ``4 Δq`` doubled the scatter of H) to half the largest wavevector
        (the last octave carries the instrument's transfer function and aliasing).
    bins_per_decade : int

    Raises
    ------
    SurfmetInputError
        Fewer than 3 non-empty bins in the band, or a non-positive PSD there.
    """
    q, C = spectrum.q, spectrum.C
    if q_range is None:
        q_range = (8.0 * spectrum.dq, 0.5 * float(q.max()))
    lo, hi = float(q_range[0]), float(q_range[1])
    sel = (q >= lo) & (q <= hi) & (C > 0)
    if np.count_nonzero(sel) < 3:
        raise SurfmetInputError(
            f"the band {lo:.4g}..{hi:.4g} rad/m holds fewer than 3 PSD points; widen it"
        )
    lq = np.log10(q[sel])
    wts = spectrum.weights[sel]
    edges = np.arange(math.floor(lq.min() * bins_per_decade),
                      math.ceil(lq.max() * bins_per_decade) + 1) / bins_per_decade
    idx = np.clip(np.searchsorted(edges, lq, side="right") - 1, 0, edges.size - 2)
    n = np.bincount(idx, weights=wts, minlength=edges.size - 1)
    ok = n > 0
    # log of the (cell-weighted) mean PSD in each bin, not the mean of the logs: periodogram
    # values scatter like exponential variables, and the mean of their logs is biased low
    # by an amount that depends on how many values a bin averages, which would tilt the fit.
    bq = np.bincount(idx, weights=lq * wts, minlength=edges.size - 1)[ok] / n[ok]
    bc = np.log10(np.bincount(idx, weights=C[sel] * wts, minlength=edges.size - 1)[ok]
                  / n[ok])
    if bq.size < 3:
        raise SurfmetInputError(
            f"the band {lo:.4g}..{hi:.4g} rad/m spans too little for a power-law fit"
        )
    slope, icpt = np.polyfit(bq, bc, 1)
    resid = bc - (slope * bq + icpt)
    offset = 1.0 if spectrum.kind == "profile" else 2.0
    return HurstFit(hurst=float(-(slope + offset) / 2.0), slope=float(slope),
                    prefactor=float(10.0**icpt), q_range=(lo, hi), n_points=int(bq.size),
                    residual_rms=float(np.sqrt(np.mean(resid**2))))
