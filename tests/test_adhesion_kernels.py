"""The adhesive solve's numba kernels (contact.adhesion.kernels) against numpy twins.

Each twin states in whole-array numpy what its kernel computes, written from the laws'
own methods (contact.adhesion.laws), so kernel and twin share no code.
"""

from __future__ import annotations

import numpy as np
import pytest

from contact.adhesion import kernels
from contact.adhesion.laws import DugdaleLaw, ExponentialLaw
from contact.adhesion.solver import law_code


def gradient_step_reference(y, g, p, law, step):
    """Twin of kernels.gradient_step: (g_new, violation, largest p, <grad, g_new - g>)."""
    grad = p + law.traction(y)
    viol = np.where(y <= 0.0, np.maximum(-grad, 0.0), np.abs(grad))
    g_new = np.maximum(y - step * grad, 0.0)
    return g_new, viol.max(), p.max(), float(np.sum(grad * (g_new - g)))


def momentum_reference(g_new, g, c):
    """Twin of the momentum kernels: the new y."""
    return np.maximum(g_new + c * (g_new - g), 0.0)


@pytest.mark.parametrize("law", [DugdaleLaw(0.05, 2e7), DugdaleLaw(0.05, 2e7, 1e-9),
                                 ExponentialLaw(0.05, 3e-9)])
def test_gradient_step_is_its_twin(law):
    rng = np.random.default_rng(7)
    n = 500
    y = np.where(rng.random(n) < 0.3, 0.0, rng.random(n) * 3 * law.range)
    g = np.maximum(y + rng.normal(0.0, 0.2 * law.range, n), 0.0)
    p = rng.normal(0.0, law.peak, n)
    step = 0.7 * law.range / law.peak
    kind, reach, width = law_code(law)
    out = np.empty(n)
    viol, pmax, dot = kernels.gradient_step(y, g, p, kind, law.peak, reach, width, step, out)
    g_ref, viol_ref, pmax_ref, dot_ref = gradient_step_reference(y, g, p, law, step)
    assert np.allclose(out, g_ref, rtol=1e-14, atol=0.0)
    assert viol == pytest.approx(viol_ref, rel=1e-14) and pmax == pmax_ref
    assert dot == pytest.approx(dot_ref, rel=1e-10)
    assert (out == 0.0).any() and (out > 0.0).any()  # both branches of the projection


def test_single_exponential_is_its_twin_to_float32():
    """The single-precision exponential of the loose solves: the law's traction to 1e-7."""
    law = ExponentialLaw(0.05, 3e-9)
    rng = np.random.default_rng(9)
    n = 500
    y = np.where(rng.random(n) < 0.3, 0.0, rng.random(n) * 3 * law.range)
    g = np.maximum(y + rng.normal(0.0, 0.2 * law.range, n), 0.0)
    p = rng.normal(0.0, law.peak, n)
    step = 0.7 * law.range / law.peak
    out = np.empty(n)
    viol, pmax, _ = kernels.gradient_step(y, g, p, kernels.EXPONENTIAL_SINGLE, law.peak,
                                          law.range, 0.0, step, out)
    g_ref, viol_ref, pmax_ref, _ = gradient_step_reference(y, g, p, law, step)
    # the step moves y by step * t: an error of 1e-7 in t is 1e-7 of step * peak
    assert np.allclose(out, g_ref, rtol=0.0, atol=2e-7 * step * law.peak)
    assert not np.array_equal(out, g_ref)  # it is not the float64 exponential
    touching = y <= 0.0  # t = peak exactly there
    assert np.array_equal(out[touching], g_ref[touching])
    assert viol == pytest.approx(viol_ref, rel=1e-6) and pmax == pmax_ref


def test_momentum_into_also_writes_float32_and_leaves_g():
    rng = np.random.default_rng(10)
    g_new, g = rng.random(300), rng.random(300)
    y, y32, g_copy = np.empty(300), np.empty(300, np.float32), g.copy()
    kernels.momentum_into(g_new, g_copy, 0.8, y, y32)
    ref = momentum_reference(g_new, g, 0.8)
    assert np.array_equal(y, ref) and np.array_equal(y32, ref.astype(np.float32))
    assert np.array_equal(g_copy, g)  # the caller swaps g and g_new


def test_free_mean_step_and_shift_are_their_twins():
    """The free cells' mean step, and the momentum after moving the free cells by a
    shift (some pushed to contact by it), against numpy written from their definitions."""
    rng = np.random.default_rng(12)
    y = np.where(rng.random(400) < 0.3, 0.0, rng.random(400))
    g_new = np.maximum(y + rng.normal(0.0, 0.3, 400), 0.0)
    g = rng.random(400)
    free = g_new > 0.0
    assert kernels.free_mean_step(y, g_new) == pytest.approx(
        np.sum(g_new[free] - y[free]) / y.size, rel=1e-12)
    assert kernels.free_mean_step(y, np.zeros(400)) == 0.0
    shift = -0.2
    moved = np.where(free, np.maximum(g_new + shift, 0.0), g_new)
    out, y_new, y32 = g_new.copy(), np.empty(400), np.empty(400, np.float32)
    kernels.momentum_shift_into(out, g, 0.8, shift, y_new, y32)
    assert np.array_equal(out, moved) and ((moved == 0.0) & free).any()
    ref = momentum_reference(moved, g, 0.8)
    assert np.array_equal(y_new, ref) and np.array_equal(y32, ref.astype(np.float32))
