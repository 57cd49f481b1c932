"""The threaded passes of :mod:`contact.bem._kernels` on grids of several chunks.

A pass over more than one chunk (:mod:`contact.bem._chunks`) must give its numpy twin's
answer, its corrections in cell order, and the same bits on one thread as on two.
"""

from __future__ import annotations

import math

import kernel_twins as twin
import numba as nb
import numpy as np
import pytest

from contact.bem import _kernels as kernels
from contact.bem._chunks import kernel_threads, n_chunks

NY, NX = 96, 1100  # 105600 cells: three chunks


def _state(hmax: float):
    rng = np.random.default_rng(11)
    n = NY * NX
    p = rng.uniform(0.0, 2.0, n)
    p[rng.random(n) < 0.6] = 0.0
    if math.isfinite(hmax):
        p[rng.random(n) < 0.1] = hmax
        p = np.minimum(p, hmax)
    return rng, p


def _passes(hmax: float, workers: int) -> list[np.ndarray]:
    rng, p = _state(hmax)
    u, h, d = (rng.normal(size=p.size) for _ in range(3))
    t = np.where((p > 0) & (p < hmax), rng.normal(size=p.size), 0.0)
    index = np.empty(2 * p.size, np.int64)
    value = np.empty(2 * p.size)
    z = np.empty_like(p)
    with kernel_threads(workers):
        out = [np.array(kernels.pk_gap_mean(p, u, h, hmax)),
               np.array(kernels.pk_residual(p, u, h, 0.1, hmax, z)), z.copy(),
               np.array(kernels.pk_step_length(u, t, d, p, hmax, True)),
               np.array([kernels.center_on_free(u, z, d, p, hmax, True)]), z.copy()]
        q = p.copy()
        nc, total, entered = kernels.pk_update_pressure(q, t, d, 0.8, hmax, index, value)
        out += [q.copy(), np.array([total, entered]), index[:nc].copy(), value[:nc].copy()]
        target = 0.9 * q.sum()
        s, nc2 = kernels.capped_scale(q, target, hmax, index, value, nc)
        out += [q, np.array([s]), index[:nc2].copy(), value[:nc2].copy()]
    return out


@pytest.mark.parametrize("hmax", [math.inf, 1.5])
def test_several_chunks_match_the_twins(hmax):
    assert n_chunks(NY * NX) == 3
    rng, p = _state(hmax)
    u, h, d = (rng.normal(size=p.size) for _ in range(3))
    t = np.where((p > 0) & (p < hmax), rng.normal(size=p.size), 0.0)
    got = _passes(hmax, 2)
    want = twin.pk_gap_mean_reference(p, u, h, hmax)
    np.testing.assert_allclose(got[0], want, rtol=1e-12)
    d_ref, g_ref, viol_ref, nviol_ref = twin.pk_residual_reference(p, u, h, 0.1, hmax)
    np.testing.assert_allclose(got[1], [g_ref, viol_ref, nviol_ref], rtol=1e-12)
    np.testing.assert_array_equal(got[2], d_ref)
    new_ref, corr_ref, entered_ref = twin.pk_update_pressure_reference(p, t, d, 0.8, hmax)
    np.testing.assert_allclose(got[6], new_ref, rtol=1e-14)
    assert got[7][1] == entered_ref
    # the corrections in cell order, as one serial pass lists them
    assert np.all(np.diff(got[8]) > 0)
    dense = np.zeros(p.size)
    dense[got[8]] = got[9]
    np.testing.assert_allclose(dense, corr_ref, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(got[10].sum(), 0.9 * new_ref.sum(), rtol=1e-12)


@pytest.mark.parametrize("hmax", [math.inf, 1.5])
def test_one_thread_and_two_give_the_same_bits(hmax):
    one, two = _passes(hmax, 1), _passes(hmax, 2)
    for a, b in zip(one, two, strict=True):
        np.testing.assert_array_equal(a, b)


def test_thread_count_restored():
    before = nb.get_num_threads()
    with kernel_threads(1):
        assert nb.get_num_threads() == 1
    assert nb.get_num_threads() == before
