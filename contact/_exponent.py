"""The load exponent of rolling resistance: the power law M = s N^lambda fitted by least
squares on logs, with a Student-t confidence interval (:func:`fit_exponent`), and the local
exponent d ln M / d ln N at each load (:func:`local_exponent`). Used by the rolling sweeps
of :mod:`contact._rolling`, :mod:`contact.tangential` and :mod:`contact.viscoelastic`."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from contact._errors import ContactInputError


@dataclass(frozen=True)
class ExponentFit:
    """Least-squares power law M = s N^lambda.

    Attributes
    ----------
    exponent : float
        lambda (the slope of ln M against ln N).
    ci : (float, float)
        Confidence interval of lambda (Student t, ``confidence`` level).
    prefactor : float
        s (unit: [M] / [N]^lambda).
    stderr : float
        Standard error of lambda.
    n : int
        Points fitted.
    rms_log_residual : float
        Rms of the residuals of ln M.
    confidence : float
    """

    exponent: float
    ci: tuple[float, float]
    prefactor: float
    stderr: float
    n: int
    rms_log_residual: float
    confidence: float


def fit_exponent(loads: Sequence[float], moments: Sequence[float],
                 confidence: float = 0.95) -> ExponentFit:
    """Fit ln M = ln s + lambda ln N by least squares, with a confidence interval.

    Parameters
    ----------
    loads : sequence of float
        Normal loads N (N).
    moments : sequence of float
        Rolling-friction moments M (N m).
    confidence : float
        Level of the interval on lambda.

    Returns
    -------
    ExponentFit
        ``exponent`` (lambda) with its ``ci``, ``prefactor`` (s), ``stderr`` and the rms
        residual in ln M.

    Raises
    ------
    ContactInputError
        Fewer than 3 points, non-positive values, or a single load value.

    See Also
    --------
    contact.sphere_sweep : computes moments to fit.

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of Rolling
       Friction Moment on the Normal Force for Elastic Materials", Materials 15 (2022) 2518.

    Examples
    --------
    >>> from contact import fit_exponent
    >>> loads = [1.0, 2.0, 4.0, 8.0]
    >>> fit = fit_exponent(loads, [2e-5 * n ** (4 / 3) for n in loads])
    >>> print(f"lambda = {fit.exponent:.3f}, s = {fit.prefactor:.1e}")
    lambda = 1.333, s = 2.0e-05
    """
    from scipy import stats

    n_ = np.asarray(loads, dtype=float)
    m_ = np.asarray(moments, dtype=float)
    if n_.shape != m_.shape or n_.ndim != 1:
        raise ContactInputError("loads and moments must be 1D arrays of the same length")
    if n_.size < 3:
        raise ContactInputError(f"fitting an exponent with a confidence interval needs at "
                                f"least 3 loads, got {n_.size}")
    if not (np.all(n_ > 0) and np.all(m_ > 0) and np.isfinite(n_).all()
            and np.isfinite(m_).all()):
        raise ContactInputError("loads and moments must be positive and finite to take logs")
    if not 0 < confidence < 1:
        raise ContactInputError(f"confidence must lie in (0, 1), got {confidence!r}")
    lx, ly = np.log(n_), np.log(m_)
    sxx = float(((lx - lx.mean()) ** 2).sum())
    if sxx <= 0:
        raise ContactInputError("the loads must not all be equal")
    slope = float(((lx - lx.mean()) * (ly - ly.mean())).sum() / sxx)
    icpt = float(ly.mean() - slope * lx.mean())
    resid = ly - (icpt + slope * lx)
    dof = n_.size - 2
    se = math.sqrt(float((resid**2).sum()) / dof / sxx)
    t = float(stats.t.ppf(0.5 + confidence / 2, dof))
    return ExponentFit(exponent=slope, ci=(slope - t * se, slope + t * se),
                       prefactor=math.exp(icpt), stderr=se, n=int(n_.size),
                       rms_log_residual=math.sqrt(float((resid**2).mean())),
                       confidence=float(confidence))


def local_exponent(loads: Sequence[float], moments: Sequence[float]) -> np.ndarray:
    """d ln M / d ln N at each load (second-order differences; one-sided at the ends).

    Parameters
    ----------
    loads : sequence of float
        Normal loads N (N, or N/m for a line contact), positive, increasing.
    moments : sequence of float
        Rolling-resistance moments M at those loads (N m), positive.

    Returns
    -------
    ndarray
        The local exponent at each load (dimensionless); :func:`fit_exponent` gives the
        one exponent of the whole sweep.

    Raises
    ------
    ContactInputError
        Fewer than 2 loads, shapes that differ, or a load or moment that is not positive.

    Examples
    --------
    >>> from contact import local_exponent
    >>> local_exponent([1.0, 2.0, 4.0, 8.0], [1.0, 2.0**1.5, 4.0**1.5, 8.0**1.5])
    array([1.5, 1.5, 1.5, 1.5])
    """
    n_ = np.asarray(loads, dtype=float)
    m_ = np.asarray(moments, dtype=float)
    if n_.size < 2 or n_.shape != m_.shape:
        raise ContactInputError("the local exponent needs at least 2 loads and moments")
    if not (np.all(n_ > 0) and np.all(m_ > 0)):
        raise ContactInputError("loads and moments must be positive to take logs")
    if n_.size == 2:
        s = (math.log(m_[1]) - math.log(m_[0])) / (math.log(n_[1]) - math.log(n_[0]))
        return np.array([s, s])
    return np.gradient(np.log(m_), np.log(n_))


def dissipating_exponents(loads: Sequence[float], moments: Sequence[float],
                          confidence: float = 0.95) -> tuple[ExponentFit | None, np.ndarray]:
    """The exponent fitted over the loads whose moment is positive (None with fewer than 3
    of them) and the local exponent at those loads (NaN elsewhere; all NaN with fewer
    than 2)."""
    n_ = np.asarray(loads, dtype=float)
    m_ = np.asarray(moments, dtype=float)
    pos = m_ > 0
    fit = fit_exponent(n_[pos], m_[pos], confidence) if pos.sum() >= 3 else None
    local = np.full(n_.size, math.nan)
    if pos.sum() >= 2:
        local[pos] = local_exponent(n_[pos], m_[pos])
    return fit, local
