"""The Newton steps' GMRES (contact.tangential._newton.gmres) against a direct solve.

GMRES returns on its least-squares residual estimate, with no product to confirm it, so
the estimate must be the true residual: checked here on a non-symmetric system with a
known solution, in one cycle and over restarts, with and without a preconditioner.
"""

from __future__ import annotations

import numpy as np
import pytest

from contact.tangential._newton import gmres


def _system(n: int = 120, seed: int = 3):
    rng = np.random.default_rng(seed)
    a = np.eye(n) + 0.4 * rng.standard_normal((n, n)) / np.sqrt(n)
    a[np.arange(n), np.arange(n)] *= np.linspace(1.0, 20.0, n)  # unequal row scales
    b = rng.standard_normal(n)
    return a, b


@pytest.mark.parametrize("restart", [100, 7])
@pytest.mark.parametrize("jacobi", [False, True])
def test_gmres_true_residual_meets_tolerance(restart: int, jacobi: bool) -> None:
    a, b = _system()
    d = np.diag(a).copy()
    precondition = (lambda v: v / d) if jacobi else (lambda v: v)
    for rtol in (1e-2, 1e-6, 1e-10):
        x = gmres(lambda v: a @ v, b, precondition, rtol, restart=restart, max_cycles=200)
        true = np.linalg.norm(b - a @ x) / np.linalg.norm(b)
        # in exact arithmetic the estimate is the residual; rounding adds ~1e-15
        assert true <= rtol * (1 + 1e-6) + 1e-13, (rtol, true)
    exact = np.linalg.solve(a, b)
    assert np.abs(x - exact).max() <= 1e-8 * np.abs(exact).max()


def test_gmres_zero_right_hand_side() -> None:
    a, _ = _system(20)
    x = gmres(lambda v: a @ v, np.zeros(20), lambda v: v, 1e-6)
    assert not np.any(x)
