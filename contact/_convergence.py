"""Convergence of a quantity as the pixel shrinks: its relative change over the last
halving, its observed order with a Richardson extrapolate, its local power-law exponent
against the pixel, and what theory expects of it (the trends of :mod:`contact._resolution`).

The expectations for a self-affine surface follow Bush, Gibson & Thomas 1975, Wear 35:87
and Persson 2001, J. Chem. Phys. 115:3840.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from contact._errors import ContactInputError

#: Relative change over the last halving below which a quantity counts as converged.
CONVERGED = 0.02

#: What theory expects of each quantity as the pixel shrinks.
EXPECTED = {
    "a_star": "converges (Hertz scale: set by the ball's curvature and the load)",
    "approach": "converges when the summit heights do (set by the Hertz scale and the "
                "height distribution; the highest summits rise slowly as finer pixels sample "
                "more extremes, and plastic flattening adds to it)",
    "sigma": "converges (block averaging removes only pixel-scale height variance)",
    "profile_deviation": "converges (azimuthal average: Hertz scale)",
    "area": "A ~ W/(E* h'_rms) ~ dx^(1-H): shrinks as the pixel shrinks on a self-affine "
            "surface (Bush et al. 1975, Persson 2001)",
    "corrected_area": "as the real area, A ~ dx^(1-H); the perimeter bias is removed",
    "pmax": "elastic: grows like h'_rms ~ dx^(H-1), no limit; with a hardness it saturates "
            "at the hardness",
    "pmax_elastic": "grows like h'_rms ~ dx^(H-1) on a self-affine surface, no limit",
    "yielded_fraction": "grows as more asperity peaks reach the hardness; no closed form",
    "rms_slope": "h'_rms ~ dx^(H-1): grows as the pixel shrinks on a self-affine surface",
    "lambda_eff": "no closed form; 4/3 for a smooth ball (Hertz)",
}


@dataclass(frozen=True)
class Trend:
    """How one quantity moves as the pixel shrinks.

    Attributes
    ----------
    name, unit : str
    pixels : tuple of float
        Pixel sizes (m), coarsest first.
    values : tuple of float
    last_change : float
        |v_finest - v_previous| / |v_finest| (0 when both are 0; inf when only the finest
        is 0).
    converged : bool
        ``last_change < CONVERGED`` (or, for a fraction near zero, an absolute change
        below :data:`ABSOLUTE`).
    exponent : float
        Local power-law exponent d ln|v| / d ln dx over the last halving (NaN when a value
        is 0 or the signs differ): v ~ dx^exponent.
    order : float
        Observed order p of convergence, log2 of the ratio of the last two changes (NaN
        when the changes do not shrink or fewer than three levels).
    extrapolated : float
        Richardson extrapolate v_finest + d_finest / (2^p - 1) (NaN without an order).
    expected : str
        What theory expects.
    """

    name: str
    unit: str
    pixels: tuple[float, ...]
    values: tuple[float, ...]
    last_change: float
    converged: bool
    exponent: float
    order: float
    extrapolated: float
    expected: str

    @property
    def status(self) -> str:
        """"converged" or "keeps moving"."""
        return "converged" if self.converged else "keeps moving"

    def sentence(self) -> str:
        """One line for the user."""
        if math.isnan(self.last_change):
            return (f"{self.name}: not available at the two finest pixels, convergence "
                    f"unknown. Theory: {self.expected}")
        pct = f"{100 * self.last_change:.3g} %" if math.isfinite(self.last_change) else "from 0"
        text = f"{self.name}: {self.status} ({pct} over the last halving"
        if not self.converged and math.isfinite(self.exponent):
            text += f"; ~ pixel^{self.exponent:.2f}"
        if self.converged and math.isfinite(self.extrapolated):
            text += f"; order {self.order:.2g}, extrapolated {self.extrapolated:.4g} {self.unit}"
        return text + f"). Theory: {self.expected}"


#: Absolute changes below which a fraction near zero counts as converged (a relative
#: change of a value that is itself ~0 says nothing): fractions of p0 or of pi a0^2.
ABSOLUTE = {"profile_deviation": 0.005, "yielded_fraction": 0.001}


def trend(name: str, pixels: Sequence[float], values: Sequence[float], unit: str = "",
          expected: str | None = None, atol: float | None = None) -> Trend:
    """Fit the trend of ``values`` against ``pixels`` (both ordered coarsest first).

    Parameters
    ----------
    name, unit : str
    pixels : sequence of float
        Pixel sizes, each half the previous one (a factor-2 refinement is assumed by the
        Richardson step).
    values : sequence of float
    expected : str, optional
        Theory's expectation; default from :data:`EXPECTED`.
    atol : float, optional
        Absolute change that also counts as converged; default from :data:`ABSOLUTE` (0).
    """
    h = np.asarray(pixels, dtype=float)
    v = np.asarray(values, dtype=float)
    if h.size != v.size or h.size < 2:
        raise ContactInputError("a trend needs at least two levels, one value per pixel size")
    fine, prev = float(v[-1]), float(v[-2])
    d = abs(fine - prev)
    if not (math.isfinite(fine) and math.isfinite(prev)):
        change = d = math.nan  # a level gave no value: nothing to say about convergence
    elif d == 0:
        change = 0.0
    elif fine == 0:
        change = math.inf
    else:
        change = d / abs(fine)
    if fine * prev > 0:
        exponent = math.log(fine / prev) / math.log(h[-1] / h[-2])
    else:
        exponent = math.nan
    order = extrap = math.nan
    if v.size >= 3:
        d_prev = abs(float(v[-2] - v[-3]))
        if d_prev > 0 and 0 < d < d_prev:
            ratio = h[-2] / h[-1]
            order = math.log(d_prev / d) / math.log(ratio)
            extrap = fine + (fine - prev) / (ratio**order - 1.0)
    return Trend(name=name, unit=unit, pixels=tuple(map(float, h)), values=tuple(map(float, v)),
                 last_change=float(change),
                 converged=bool(change < CONVERGED or d < (ABSOLUTE.get(name, 0.0)
                                                          if atol is None else atol)),
                 exponent=float(exponent), order=float(order), extrapolated=float(extrap),
                 expected=EXPECTED.get(name, "") if expected is None else expected)
