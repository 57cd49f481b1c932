"""Where a scan's spectrum bends: its roll-off, its short-wavelength cut-off and an
instrument's noise floor, found on the binned log-log PSD.

The binned log-PSD is fitted by a continuous piecewise-linear curve, its knots placed on a
fine grid, and the candidate models (no knot, a roll-off, a short cut-off, both; a floor's
upward hinge) compete by the Bayesian information criterion (Schwarz 1978, Ann. Stat. 6,
461-464), so that a periodogram's scatter does not pass for a bend. What the bends mean for
the Hurst fit is :func:`surfmet.mechanics.spectrum.spectrum`'s business.
"""

from __future__ import annotations

import math

import numpy as np

from surfmet.psd import PSD

__all__ = ["KNOT_MIN", "binned", "cutoffs", "noise_floor"]

#: Minimum change of log-log slope for a knot to count as a cut-off.
KNOT_MIN = 1.0


def binned(spec: PSD, bins_per_decade: int = 10) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cell-weighted mean PSD in logarithmic bins: (log q, log C, bin upper edges in log q)."""
    lq = np.log10(spec.q)
    edges = np.arange(math.floor(lq.min() * bins_per_decade),
                      math.ceil(lq.max() * bins_per_decade) + 1) / bins_per_decade
    idx = np.clip(np.searchsorted(edges, lq, side="right") - 1, 0, edges.size - 2)
    w = spec.weights
    n = np.bincount(idx, weights=w, minlength=edges.size - 1)
    ok = n > 0
    bq = np.bincount(idx, weights=lq * w, minlength=edges.size - 1)[ok] / n[ok]
    bc = np.bincount(idx, weights=spec.C * w, minlength=edges.size - 1)[ok] / n[ok]
    return bq, bc, edges[1:][ok]


def cutoffs(spec: PSD, q_min: float = 0.0
            ) -> tuple[float | None, float | None, tuple[float, float]]:
    """Roll-off and short cut-off wavevectors and the self-affine band between them.

    ``q_min``: wavevectors below it are left out (a window's main lobe flattens them).
    """
    has_power = spec.C > 1e-12 * float(spec.C.max())
    short = None
    keep = spec.q >= q_min
    if not has_power[-1]:
        # the spectrum carries no power beyond this wavevector: a hard short cut-off
        short = float(spec.q[np.nonzero(has_power)[0].max()])
        keep &= spec.q <= short * (1.0 - 1e-9) * 10**-0.1  # drop the bin cut through
    bq, bc, _ = binned(PSD(q=spec.q[keep], C=spec.C[keep], kind=spec.kind, dq=spec.dq,
                            weights=spec.weights[keep]))
    y = np.log10(bc)
    x = bq
    m = x.size
    lo_q, hi_q = float(10 ** x[0]), float(10 ** x[-1])
    roll = None
    if m < 5:
        return roll, short, (lo_q, hi_q)
    # knots on a fine grid strictly inside the data (a knot at an end duplicates the
    # linear term); a continuous knot position follows a bend that a bin average smears.
    # Models with no knot, a roll-off, a short cut-off or both compete by the Bayesian
    # information criterion (a knot costs two parameters, its place and its bend), so
    # that the periodogram's scatter on a single scan does not pass for a cut-off.
    grid = np.arange(x[2], x[-2] + 1e-9, 0.02)
    cands: list[tuple[float | None, float | None]] = [(None, None)]
    cands += [(g, None) for g in grid]
    if short is None:
        cands += [(None, g) for g in grid if g >= x[-4]]
        cands += [(g, h) for k, g in enumerate(grid) for h in grid[k + 10:] if h >= x[-4]]
    # (BIC, roll-off knot, short knot, coefficients); the knot-free candidate, first, always
    # replaces the start, whose empty coefficients are never read
    best: tuple[float, float | None, float | None, np.ndarray] = (math.inf, None, None,
                                                                  np.empty(0))
    for xr, xs in cands:
        cols = [np.ones(m), x]
        if xr is not None:
            cols.append(np.maximum(x - xr, 0.0))
        if xs is not None:
            cols.append(np.maximum(x - xs, 0.0))
        A = np.column_stack(cols)
        coef, *_ = np.linalg.lstsq(A, y, rcond=None)
        rss = max(float(np.sum((A @ coef - y) ** 2)), 1e-12 * m)
        bic = m * math.log(rss / m) + (2 + 2 * (len(cols) - 2)) * math.log(m)
        if bic < best[0]:
            best = (bic, xr, xs, coef)
    _, xr, xs, coef = best
    k = 2
    if xr is not None:
        if coef[k] < -KNOT_MIN:
            roll = float(10**xr)
            lo_q = roll
        k += 1
    if xs is not None and coef[k] < -KNOT_MIN:
        short = float(10**xs)
        hi_q = short
    if short is not None:
        hi_q = min(hi_q, short)
    return roll, short, (lo_q, hi_q)


def noise_floor(spec: PSD, band: tuple[float, float]) -> float | None:
    """Wavevector where the spectrum stops falling inside ``band``, or None.

    An instrument's noise (or its lateral resolution) adds a white floor: above some q the
    log-log spectrum turns flat. A line and a line with one upward bend (a hinge) are
    fitted to the binned spectrum of the band and compared by the Bayesian information
    criterion, as the cut-offs are. A winning bend of more than :data:`KNOT_MIN` in slope,
    after which the spectrum falls slower than ``q^-2`` (no self-affine surface does:
    ``C ∝ q^(-2(1+H))`` with ``0 < H < 1``), is the floor's onset. The power law is fitted
    below it, never into it.
    """
    sel = (spec.q >= band[0]) & (spec.q <= band[1])
    bq, bc, _ = binned(PSD(q=spec.q[sel], C=spec.C[sel], kind=spec.kind, dq=spec.dq,
                            weights=spec.weights[sel]))
    x, y = bq, np.log10(bc)
    m = x.size
    if m < 6:
        return None

    def bic(cols: list[np.ndarray]) -> tuple[float, np.ndarray]:
        A = np.column_stack(cols)
        coef, *_ = np.linalg.lstsq(A, y, rcond=None)
        rss = max(float(np.sum((A @ coef - y) ** 2)), 1e-12 * m)
        return m * math.log(rss / m) + 2 * (len(cols) - 1) * math.log(m), coef

    best, floor = bic([np.ones(m), x])[0], None
    for g in np.arange(x[1], x[-2] + 1e-9, 0.02):
        b, coef = bic([np.ones(m), x, np.maximum(x - g, 0.0)])
        if b < best and coef[2] > KNOT_MIN and coef[1] + coef[2] > -2.0:
            best, floor = b, float(10**g)
    return floor
