"""Diagnostics of a fit's residuals: the Gaussian likelihood, the runs test, the lag-1
autocorrelation.

References
----------
Wald A., Wolfowitz J. (1940) On a test whether two samples are from the same population.
Ann. Math. Stat. 11:147-162.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["lag1_autocorrelation", "minus_two_log_likelihood", "runs_test_z"]


def minus_two_log_likelihood(r: np.ndarray, sigma: np.ndarray) -> float:
    return float(np.sum(np.log(2 * math.pi * sigma**2) + (r / sigma) ** 2))


def runs_test_z(r: np.ndarray) -> float:
    signs = r[r != 0] > 0
    n1 = int(signs.sum())
    n2 = int(signs.size - n1)
    n = n1 + n2
    if n1 == 0 or n2 == 0 or n < 3:
        return math.nan
    runs = 1 + int(np.count_nonzero(signs[1:] != signs[:-1]))
    mu = 2.0 * n1 * n2 / n + 1.0
    var = 2.0 * n1 * n2 * (2.0 * n1 * n2 - n) / (n * n * (n - 1.0))
    return (runs - mu) / math.sqrt(var) if var > 0 else math.nan


def lag1_autocorrelation(r: np.ndarray) -> float:
    den = float(np.sum(r * r))
    return float(np.sum(r[1:] * r[:-1]) / den) if den > 0 else math.nan
