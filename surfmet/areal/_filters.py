"""Areal Gaussian filters (ISO 16610-61): the S-filter (λs) and the L-filter (λc).

The areal Gaussian weighting function of ISO 16610-61 (2015), Eq. (1), is

    s(x, y) = 1 / (α² λc²) · exp(-π (x² + y²) / (α λc)²),   α = sqrt(ln 2 / π),

so the mean surface transmits ``exp(-π (α λc / λ)²)`` of a wavelength λ: exactly 50 % at
λ = λc. The function is separable, so the filter is two 1D convolutions (one along x with
λc/dx, one along y with λc/dy). The kernel is sampled at the grid points, truncated at
±λc (where it has fallen to exp(-π/α²) ≈ 7·10⁻⁷ of its peak) and normalised to unit sum.

Non-measured points and edges. Nothing is invented: no mirror padding, no zero filling.
Missing points (and the area outside the scan) get zero weight, and the weights that
remain are corrected at each point. Three treatments, the same as the profile engine's
(:mod:`profiles._filters`, ISO 16610-28), recorded in :class:`FilterInfo`:

``"discard"`` (default)
    Zeroth order, then a band of λc/2 (the run-up/run-out of ISO 3274 / ISO 4288 for
    profiles) along each edge becomes NaN: what is kept is the ISO 16610-61 filter with
    its complete weights (the end effects are left out, not corrected).
``"moment"``
    First-order moment criterion: at every point the local plane under the (truncated,
    hole-masked) Gaussian weights is fitted and its value taken, i.e. a Gaussian
    regression filter of order 1 (cf. ISO 16610-71). In the interior of a complete scan it
    is exactly the ISO 16610-61 filter; at edges and around holes it reproduces any plane
    exactly, so a residual tilt creates no false roughness near the border.
``"renormalise"``
    Zeroth order: normalised convolution (Knutsson & Westin 1993), the surviving weights
    divided by their sum.

Outputs are NaN where the input is NaN. Short kernels are applied directly
(:func:`scipy.ndimage.correlate1d`); long ones by FFT along each axis with zero padding (a
linear, not circular, correlation). On a complete grid the weight moments are separable
(outer products of 1D sums), so the moment filter adds only passes over the edge bands.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography

ALPHA = math.sqrt(math.log(2.0) / math.pi)
"""ISO 16610-61 constant α = sqrt(ln 2 / π) ≈ 0.4697."""

EDGE_MODES = ("moment", "renormalise", "discard")
#: The default edge treatment of every areal filter (and of ``surfmet roughness``): the
#: band where the Gaussian weights run past the scan is left out, so every value kept is
#: the ISO 16610-61 filter itself (docs/parameters.md, "Filter edges": what the ISO 16610
#: series says of end effects, and what surfalize does).
DEFAULT_EDGE = "discard"
EDGE_MEANING = {
    "discard": "the band of half a nesting index along each border, where the Gaussian "
    "weights run past the scan's end (end effects), is left out; parameters come from the "
    "inner area only",
    "moment": "kept, with a first-order (moment) end-effect correction: exact for a plane, "
    "but a wavelength near the nesting index is attenuated there (Sq about 2 % low near λc)",
    "renormalise": "kept, the truncated weights renormalised (zeroth order)",
}
"""What each edge treatment means, stated in every result that used a filter."""
_EDGE_ALIASES = {"renormalize": "renormalise", "crop": "discard", "moment-criterion": "moment"}

# Above this kernel length a 1D FFT convolution beats scipy's direct correlate1d.
_DIRECT_MAX_TAPS = 25
# Points whose surviving weight is below this fraction get no filtered value.
_MIN_WEIGHT = 1e-6


@dataclass(frozen=True)
class FilterInfo:
    """How a filter was applied (for the record in a result's settings)."""

    kind: str  # "S" or "L"
    nesting_index: float  # metres
    standard: str = "ISO 16610-61 areal Gaussian"
    edge: str = DEFAULT_EDGE
    truncation: float = 1.0  # kernel half-width in nesting indices
    discarded: tuple[int, int] = (0, 0)  # rows, columns set to NaN along each edge



def parse_edge(edge: str) -> str:
    """Canonical edge treatment name (see the module docstring)."""
    e = str(edge).strip().lower()
    e = _EDGE_ALIASES.get(e, e)
    if e not in EDGE_MODES:
        raise SurfmetInputError(f"edge must be one of {', '.join(EDGE_MODES)}, got {edge!r}")
    return e


def transmission(wavelength: float | np.ndarray, cutoff: float) -> float | np.ndarray:
    """Amplitude transmission of the Gaussian *mean surface* (low-pass) at a wavelength.

    ``exp(-π (α λc / λ)²)``; the L-filtered (roughness) surface transmits ``1 -`` this.
    """
    lam = np.asarray(wavelength, dtype=float)
    return np.exp(-np.pi * (ALPHA * cutoff / lam) ** 2)


def gaussian_weights(cutoff: float, step: float) -> tuple[np.ndarray, np.ndarray]:
    """Sampled ISO 16610-61 Gaussian weights truncated at ±cutoff, and their offsets.

    Returns ``(weights, offsets)``; offsets in samples (-h..h), weights not normalised
    (every use divides by the weight sum it actually sees).
    """
    half = max(math.ceil(cutoff / step - 1e-9), 1)
    k = np.arange(-half, half + 1, dtype=np.float64)
    return np.exp(-np.pi * (k * step / (ALPHA * cutoff)) ** 2), k


def _correlate_axis(a: np.ndarray, w: np.ndarray, axis: int) -> np.ndarray:
    """``out[i] = Σ_k w[h + k] a[i + k]`` along ``axis`` with zeros outside (same size)."""
    return _correlate_many(a, (w,), axis)[0]


def _correlate_many(a: np.ndarray, kernels: tuple[np.ndarray, ...], axis: int
                    ) -> list[np.ndarray]:
    """:func:`_correlate_axis` for several kernels of one length, sharing one forward FFT."""
    n = a.shape[axis]
    size = kernels[0].size
    half = (size - 1) // 2
    if size <= _DIRECT_MAX_TAPS or n <= 8:
        from scipy.ndimage import correlate1d

        return [correlate1d(a, w, axis=axis, mode="constant", cval=0.0) for w in kernels]
    from scipy import fft

    # Zero-pad to a fast length ≥ n + half so that nothing wraps around; a correlation
    # is a convolution with the reversed kernel.
    m = fft.next_fast_len(n + half, real=True)
    fa = fft.rfft(a, n=m, axis=axis, workers=-1)
    shape = [1] * a.ndim
    shape[axis] = m // 2 + 1
    out = []
    for w in kernels:
        ker = np.zeros(m)
        ker[: half + 1] = w[half::-1]
        if half:
            ker[m - half:] = w[:half:-1]
        prod = fa * fft.rfft(ker).reshape(shape)
        res = fft.irfft(prod, n=m, axis=axis, workers=-1)
        out.append(res[(slice(None),) * axis + (slice(0, n),)])
    return out


def _corr2(a: np.ndarray, kx: np.ndarray, ky: np.ndarray) -> np.ndarray:
    return _correlate_axis(_correlate_axis(a, kx, 1), ky, 0)


def _check_cutoff(topo: Topography, cutoff: float, what: str) -> float:
    try:
        c = float(cutoff)
    except (TypeError, ValueError):
        raise SurfmetInputError(f"{what} must be a length in metres, got {cutoff!r}") from None
    if not (math.isfinite(c) and c > 0):
        raise SurfmetInputError(f"{what} must be a positive length, got {cutoff!r}")
    from profiles._resolution import nesting_index_problem

    # the one rule of profiles._resolution: a nesting index spans 3 pixels on each axis
    problem = nesting_index_problem(c, max(topo.dx, topo.dy), what)
    if problem:
        raise SurfmetInputError(problem)
    if topo.size_x < c or topo.size_y < c:
        raise SurfmetInputError(
            f"scan of {topo.size_x * 1e6:.4g} µm × {topo.size_y * 1e6:.4g} µm is too small "
            f"for {what} = {c * 1e6:.4g} µm: each side must be at least one nesting index "
            "long; use a shorter cut-off or a larger scan"
        )
    return c


def _edge_slices(mask: np.ndarray) -> list[slice]:
    """The runs of True in a 1D mask, as slices (the lopsided bands at both ends)."""
    idx = np.flatnonzero(mask)
    if idx.size == 0:
        return []
    breaks = np.flatnonzero(np.diff(idx) > 1)
    starts = np.concatenate(([idx[0]], idx[breaks + 1]))
    stops = np.concatenate((idx[breaks] + 1, [idx[-1] + 1]))
    return [slice(int(a), int(b)) for a, b in zip(starts, stops)]


def _moment_full(z: np.ndarray, gx, kx, gy, ky) -> np.ndarray:
    """Order-1 regression filter on a complete grid, using separable weight moments.

    With product weights g(u) g(v) the local plane fit decouples in centred coordinates,
    so the fitted value at the point is

        Z00 - mux (Z10 - mux Z00) / vx - muy (Z01 - muy Z00) / vy

    (moments normalised by the weight sum; mux, vx the mean and variance of the x offsets
    under the truncated weights, likewise for y). mux and muy vanish except in bands of
    one nesting index along the edges, so the slope terms are computed on those bands
    only; the normalisations are folded into per-row and per-column coefficients to keep
    the passes over scan-sized arrays few.
    """
    ny, nx = z.shape

    def sums(g: np.ndarray, k: np.ndarray, n: int) -> tuple[np.ndarray, ...]:
        one = np.ones((1, n))
        return tuple(_correlate_axis(one, g * k**p, 1)[0] for p in range(3))

    sx0, sx1, sx2 = sums(gx, kx, nx)
    sy0, sy1, sy2 = sums(gy, ky, ny)
    mux, muy = sx1 / sx0, sy1 / sy0
    vx, vy = sx2 / sx0 - mux**2, sy2 / sy0 - muy**2
    bands_x = _edge_slices(np.abs(mux) > 1e-12 * (1 + np.sqrt(vx)))
    bands_y = _edge_slices(np.abs(muy) > 1e-12 * (1 + np.sqrt(vy)))

    # x pass: P = (z ⋆ g) / sx0 everywhere; on the x bands also the slope correction
    # D = mux (Q - mux P) / vx with Q = (z ⋆ g·k) / sx0, which the y pass must subtract.
    xs = _correlate_many(z, (gx, gx * kx) if bands_x else (gx,), 1)
    p = xs[0]
    p *= 1.0 / sx0
    d_blocks = []
    for b in bands_x:
        q = xs[1][:, b]
        d_blocks.append(q * (mux[b] / (vx[b] * sx0[b])) - p[:, b] * (mux[b] ** 2 / vx[b]))

    # y pass on P: A = P ⋆ g, and on the y bands B = P ⋆ g·k for the y slope term.
    ys = _correlate_many(p, (gy, gy * ky) if bands_y else (gy,), 0)
    out = ys[0]
    ca = 1.0 / sy0
    for b in bands_y:
        ca[b] *= 1.0 + muy[b] ** 2 / vy[b]
    out *= ca[:, None]
    for b in bands_y:
        out[b] -= ys[1][b] * (muy[b] / (vy[b] * sy0[b]))[:, None]
    if d_blocks:
        # the x slope term is weighted along y like Z00 itself, by g / sy0
        corr = _correlate_axis(np.concatenate(d_blocks, axis=1), gy, 0)
        corr *= (1.0 / sy0)[:, None]
        start = 0
        for b, blk in zip(bands_x, d_blocks):
            width = blk.shape[1]
            out[:, b] -= corr[:, start:start + width]
            start += width
    return out


def _moment_masked(z: np.ndarray, valid: np.ndarray, gx, kx, gy, ky) -> np.ndarray:
    """Order-1 regression filter with holes: 3 × 3 weighted least squares per point."""
    w = valid.astype(np.float64)
    zw = np.where(valid, z, 0.0)
    gxk, gxk2 = gx * kx, gx * kx * kx
    gyk, gyk2 = gy * ky, gy * ky * ky
    # Weight moments W_pq = Σ w u^p v^q g and data moments Z_pq = Σ z w u^p v^q g.
    wx0, wx1, wx2 = (_correlate_axis(w, k, 1) for k in (gx, gxk, gxk2))
    w00 = _correlate_axis(wx0, gy, 0)
    w10 = _correlate_axis(wx1, gy, 0)
    w20 = _correlate_axis(wx2, gy, 0)
    w01 = _correlate_axis(wx0, gyk, 0)
    w02 = _correlate_axis(wx0, gyk2, 0)
    w11 = _correlate_axis(wx1, gyk, 0)
    zx0, zx1 = (_correlate_axis(zw, k, 1) for k in (gx, gxk))
    z00 = _correlate_axis(zx0, gy, 0)
    z10 = _correlate_axis(zx1, gy, 0)
    z01 = _correlate_axis(zx0, gyk, 0)
    # a = first unknown of [[w00 w10 w01] [w10 w20 w11] [w01 w11 w02]] [a b c] = [z00 z10 z01]
    c00 = w20 * w02 - w11 * w11
    c01 = w10 * w02 - w11 * w01
    c02 = w10 * w11 - w20 * w01
    det = w00 * c00 - w10 * c01 + w01 * c02
    with np.errstate(invalid="ignore", divide="ignore"):
        order1 = (z00 * c00 - z10 * c01 + z01 * c02) / det
        order0 = z00 / w00
    # Too few points under the window to fix a plane (a line of points): order 0.
    weak = ~(det > 1e-9 * w00 * c00) | ~np.isfinite(order1)
    return np.where(weak, order0, order1)


def mean_surface(topo: Topography, cutoff: float, *, edge: str = DEFAULT_EDGE,
                 what: str = "cut-off") -> np.ndarray:
    """The Gaussian-filtered (low-pass) mean surface at nesting index ``cutoff``.

    NaN where the input is NaN, where no weight survives, and (``edge="discard"``) within
    ``cutoff/2`` of the scan border.
    """
    edge = parse_edge(edge)
    c = _check_cutoff(topo, cutoff, what)
    z = topo.heights
    valid = np.isfinite(z)
    full = bool(valid.all())
    gx, kx = gaussian_weights(c, topo.dx)
    gy, ky = gaussian_weights(c, topo.dy)
    if edge == "moment":
        out = _moment_full(z, gx, kx, gy, ky) if full else _moment_masked(
            z, valid, gx, kx, gy, ky)
        den = None
    else:
        zz = z if full else np.where(valid, z, 0.0)
        num = _corr2(zz, gx, gy)
        if full:
            one_x = _correlate_axis(np.ones((1, topo.nx)), gx, 1)[0]
            one_y = _correlate_axis(np.ones((1, topo.ny)), gy, 1)[0]
            den = np.outer(one_y, one_x)
        else:
            den = _corr2(valid.astype(np.float64), gx, gy)
        with np.errstate(invalid="ignore", divide="ignore"):
            out = num / den
    if not full:
        w00 = den if den is not None else _corr2(valid.astype(np.float64), gx, gy)
        out[w00 < _MIN_WEIGHT * gx.sum() * gy.sum()] = np.nan
    out[~valid] = np.nan
    if edge == "discard":
        bx, by = _discard_band(topo, c)
        out[:by] = np.nan
        out[topo.ny - by:] = np.nan
        out[:, :bx] = np.nan
        out[:, topo.nx - bx:] = np.nan
    return out


def _discard_band(topo: Topography, cutoff: float) -> tuple[int, int]:
    bx = math.ceil(0.5 * cutoff / topo.dx - 1e-9)
    by = math.ceil(0.5 * cutoff / topo.dy - 1e-9)
    if 2 * bx >= topo.nx or 2 * by >= topo.ny:
        raise SurfmetInputError(
            f"edge='discard' drops λc/2 along each edge, which leaves nothing of a "
            f"{topo.size_x * 1e6:.4g} µm × {topo.size_y * 1e6:.4g} µm scan; use "
            "edge='moment' or a shorter cut-off"
        )
    return bx, by


def _apply(topo: Topography, cutoff: float, kind: str, edge: str) -> tuple[Topography, FilterInfo]:
    edge = parse_edge(edge)
    what = "λs (S-filter nesting index)" if kind == "S" else "λc (L-filter nesting index)"
    mean = mean_surface(topo, cutoff, edge=edge, what=what)
    heights = mean if kind == "S" else topo.heights - mean
    if not np.isfinite(heights).any():
        raise SurfmetInputError(f"no measured point is left after the {kind}-filter")
    discarded = (0, 0)
    if edge == "discard":
        bx, by = _discard_band(topo, float(cutoff))
        discarded = (by, bx)
    info = FilterInfo(kind=kind, nesting_index=float(cutoff), edge=edge, discarded=discarded)
    key = "ls" if kind == "S" else "lc"
    return topo.replace(heights=heights).with_metadata(**{key: float(cutoff)}), info


def s_filter(
    topo: Topography, ls: float, *, edge: str = DEFAULT_EDGE
) -> tuple[Topography, FilterInfo]:
    """S-filter: remove wavelengths shorter than ``ls`` (keeps the Gaussian mean surface).

    Raises
    ------
    SurfmetInputError
        Non-positive ``ls``, a scan smaller than ``ls``, ``ls`` under three pixels
        (:mod:`profiles._resolution`), an unknown edge treatment.
    """
    return _apply(topo, ls, "S", edge)


def l_filter(
    topo: Topography, lc: float, *, edge: str = DEFAULT_EDGE
) -> tuple[Topography, FilterInfo]:
    """L-filter: remove wavelengths longer than ``lc`` (returns ``z -`` mean surface).

    Raises
    ------
    SurfmetInputError
        Non-positive ``lc``, a scan smaller than ``lc`` in either direction, ``lc`` under
        three pixels (:mod:`profiles._resolution`), an unknown edge treatment.
    """
    return _apply(topo, lc, "L", edge)
