"""Every numba kernel of the contact engine against its plain-numpy twin, on small inputs."""

from __future__ import annotations

import math

import kernel_twins as twin
import numpy as np
import pytest

from contact.bem import _kernels as kernels
from contact.halfspace.influence import (
    free_kernel_quadrant,
    periodic_kernel_real,
    periodic_love_spectrum,
)


def _state(seed: int, ny: int = 7, nx: int = 9, hmax: float = math.inf):
    rng = np.random.default_rng(seed)
    n = ny * nx
    p = rng.uniform(0.0, 2.0, n)
    p[rng.random(n) < 0.3] = 0.0  # out of contact
    if math.isfinite(hmax):
        p[rng.random(n) < 0.2] = hmax  # yielded
        p = np.minimum(p, hmax)
    u = rng.normal(size=n)
    h = rng.normal(size=n)
    return rng, p, u, h


@pytest.mark.parametrize("hmax", [math.inf, 1.5])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_gap_mean_and_residual(seed, hmax):
    _, p, u, h = _state(seed, hmax=hmax)
    got = kernels.pk_gap_mean(p, u, h, hmax)
    want = twin.pk_gap_mean_reference(p, u, h, hmax)
    assert got[1] == want[1] and got[3] == want[3]
    np.testing.assert_allclose(got[0], want[0], rtol=1e-12)
    np.testing.assert_allclose(got[2], want[2], rtol=1e-12)
    gbar = got[0] / got[1]
    d = np.empty_like(p)
    G, viol, nviol = kernels.pk_residual(p, u, h, gbar, hmax, d)
    d_ref, G_ref, viol_ref, nviol_ref = twin.pk_residual_reference(p, u, h, gbar, hmax)
    np.testing.assert_allclose(d, d_ref, rtol=1e-14)
    np.testing.assert_allclose([G, viol], [G_ref, viol_ref], rtol=1e-12)
    assert nviol == nviol_ref


@pytest.mark.parametrize("hmax", [math.inf, 1.5])
def test_direction_and_masked_copy(hmax):
    rng, p, _, _ = _state(3, hmax=hmax)
    nx = 9
    d = rng.normal(size=p.size)
    t = rng.normal(size=p.size)
    t_ref, lo_ref, hi_ref = twin.pk_direction_reference(d, p, t.copy(), 0.7, hmax, nx)
    direction_fft = np.empty(p.size, dtype=np.float32)
    lo, hi = kernels.pk_direction(d, p, t, 0.7, hmax, direction_fft, nx)
    np.testing.assert_allclose(t, t_ref, rtol=1e-14)
    np.testing.assert_allclose(direction_fft, t_ref, rtol=1e-6)
    assert (lo, hi) == (lo_ref, hi_ref)
    out = np.empty(p.size)
    lo, hi = kernels.masked_copy(d, p, hmax, out, nx)
    out_ref, lo_ref, hi_ref = twin.masked_copy_reference(d, p, hmax, nx)
    np.testing.assert_array_equal(out, out_ref)
    assert (lo, hi) == (lo_ref, hi_ref)


def test_direction_empty_set_reports_no_rows():
    p = np.zeros(12)
    lo, hi = kernels.pk_direction(np.ones(12), p, np.zeros(12), 0.0, math.inf,
                             np.zeros(12, np.float32), 4)
    assert hi <= lo


@pytest.mark.parametrize("subtract", [True, False])
@pytest.mark.parametrize("hmax", [math.inf, 1.5])
def test_step_length_and_center(subtract, hmax):
    rng, p, _, _ = _state(4, hmax=hmax)
    r = rng.normal(size=p.size).astype(np.float32)
    t = rng.normal(size=p.size)
    d = rng.normal(size=p.size)
    got = kernels.pk_step_length(r, t, d, p, hmax, subtract)
    want = twin.pk_step_length_reference(r, t, d, p, hmax, subtract)
    np.testing.assert_allclose(got, want, rtol=1e-10, atol=1e-14)
    z = np.empty(p.size)
    rho = kernels.center_on_free(r, z, d, p, hmax, subtract)
    z_ref, rho_ref = twin.center_on_free_reference(r, d, p, hmax, subtract)
    np.testing.assert_allclose(z, z_ref, rtol=1e-10, atol=1e-14)
    np.testing.assert_allclose(rho, rho_ref, rtol=1e-10)


@pytest.mark.parametrize("hmax", [math.inf, 1.5])
@pytest.mark.parametrize("seed", [5, 6])
def test_update_pressure(seed, hmax):
    rng, p, _, _ = _state(seed, hmax=hmax)
    t = np.where((p > 0) & (p < hmax), rng.normal(size=p.size), 0.0)
    d = rng.normal(size=p.size)
    tau = 0.8
    new_ref, corr_ref, entered_ref = twin.pk_update_pressure_reference(p, t, d, tau, hmax)
    index = np.empty(p.size, np.int64)
    value = np.empty(p.size)
    q = p.copy()
    nc, total, entered = kernels.pk_update_pressure(q, t, d, tau, hmax, index, value)
    np.testing.assert_allclose(q, new_ref, rtol=1e-14)
    np.testing.assert_allclose(total, new_ref.sum(), rtol=1e-12)
    assert entered == entered_ref
    dense = np.zeros(p.size)
    dense[index[:nc]] = value[:nc]
    np.testing.assert_allclose(dense, corr_ref, rtol=1e-12, atol=1e-15)


@pytest.mark.parametrize("hmax", [math.inf, 1.2, 0.9])
def test_capped_scale(hmax):
    _rng, p, _, _ = _state(7, hmax=hmax)
    target = 0.9 * np.minimum(p, hmax).sum() if math.isfinite(hmax) else 1.7 * p.sum()
    index = np.empty(p.size, np.int64)
    value = np.empty(p.size)
    q = p.copy()
    s, nc = kernels.capped_scale(q, target, hmax, index, value, 0)
    _s_ref, q_ref = twin.capped_scale_reference(p, target, hmax)
    np.testing.assert_allclose(q, q_ref, rtol=1e-9)
    np.testing.assert_allclose(q.sum(), target, rtol=1e-12)
    assert q.max() <= hmax
    # the recorded corrections are exactly the departure from the plain scaling s * p
    dense = np.zeros(p.size)
    dense[index[:nc]] = value[:nc]
    np.testing.assert_allclose(s * p + dense, q, rtol=1e-12, atol=1e-14)


def test_axpy_scale():
    rng = np.random.default_rng(8)
    u = rng.normal(size=50)
    r = rng.normal(size=50).astype(np.float32)
    want = twin.axpy_scale_reference(u, r, 0.3, 1.1)
    kernels.axpy_scale(u, r, 0.3, 1.1)
    np.testing.assert_allclose(u, want, rtol=1e-14)


@pytest.mark.parametrize("periodic", [False, True])
def test_sparse_convolve_add(periodic):
    ny, nx = 6, 10
    kernel = (periodic_kernel_real(ny, nx, 1.0, 1.0) if periodic
              else free_kernel_quadrant(ny, nx, 1.0, 1.0))
    kernel = np.ascontiguousarray(kernel)
    rng = np.random.default_rng(9)
    u = rng.normal(size=ny * nx)
    index = np.array([0, 17, 59, 23], dtype=np.int64)
    value = rng.normal(size=4)
    want = twin.sparse_convolve_add_reference(u, index, value, kernel, nx, periodic)
    kernels.sparse_convolve_add(u, index, value, 4, kernel, nx, periodic)
    np.testing.assert_allclose(u, want, rtol=1e-13)


def test_scatter_sets_and_clears():
    buf = np.zeros((4, 5))
    index = np.array([3, 12, 19], dtype=np.int64)
    value = np.array([1.0, 2.0, 3.0])
    lo, hi = kernels.scatter(buf, index, value, 3, True)
    assert (lo, hi) == (0, 4)
    assert buf.ravel()[12] == 2.0 and buf.sum() == 6.0
    kernels.scatter(buf, index, value, 3, False)
    assert not buf.any()


@pytest.mark.parametrize(("ny", "nx", "dx", "dy"), [(8, 6, 1.0, 1.0), (7, 9, 1e-6, 2.5e-6)])
def test_periodic_spectrum(ny, nx, dx, dy):
    got = periodic_love_spectrum(ny, nx, dx, dy, 3)
    want = twin.periodic_love_spectrum_reference(ny, nx, dx, dy, 3)
    np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-20)


def test_scatter_adds_repeated_cells():
    # a capped cell can carry two corrections (the step's and the load rescaling's):
    # both must reach the displacement
    buf = np.zeros((3, 4))
    index = np.array([5, 5, 7], dtype=np.int64)
    value = np.array([1.0, -0.25, 2.0])
    assert kernels.scatter(buf, index, value, 3, True) == (1, 2)
    assert buf.ravel()[5] == 0.75 and buf.ravel()[7] == 2.0
    kernels.scatter(buf, index, value, 3, False)
    assert not buf.any()


@pytest.mark.parametrize("case", ["capped_too_much", "all_capped_too_little"])
def test_capped_scale_leaves_an_unreachable_target(case):
    # no scaling of the uncapped cells reaches the target: p must stay feasible (<= hmax)
    # and unchanged, s = 1, so that the caller sees the total and steps otherwise
    hmax = 1.0
    if case == "capped_too_much":
        p = np.array([1.0, 1.0, 1.0, 0.3, 0.0])
        target = 2.5
    else:
        p = np.array([1.0, 1.0, 0.0, 0.0])
        target = 3.0
    q = p.copy()
    index = np.empty(2 * p.size, np.int64)
    value = np.empty(2 * p.size)
    s, nc = kernels.capped_scale(q, target, hmax, index, value, 0)
    assert s == 1.0 and nc == 0
    np.testing.assert_array_equal(q, p)
    s_ref, q_ref = twin.capped_scale_reference(p, target, hmax)
    assert s_ref == 1.0
    np.testing.assert_array_equal(q_ref, p)


@pytest.mark.parametrize("load_control", [True, False])
@pytest.mark.parametrize("seed", [10, 11, 12])
def test_projected_gradient(seed, load_control):
    _, p, _, _ = _state(seed, hmax=1.5)
    rng = np.random.default_rng(seed + 100)
    d = rng.normal(size=p.size)
    target = float(p.sum())
    s = np.empty(p.size)
    candidates = np.empty(p.size, np.int64)
    gs, ss, mu, lo, hi = kernels.projected_gradient(p, d, 0.7, target, 1.5, load_control, s,
                                               candidates, 9)
    s_ref, gs_ref, ss_ref, mu_ref = twin.projected_gradient_reference(p, d, 0.7, target, 1.5,
                                                                    load_control)
    np.testing.assert_allclose(s, s_ref, atol=1e-12)
    np.testing.assert_allclose([gs, ss, mu], [gs_ref, ss_ref, mu_ref], rtol=1e-9,
                               atol=1e-12)
    new = p + s
    assert new.min() >= 0 and new.max() <= 1.5
    if load_control:
        assert new.sum() == pytest.approx(target, rel=1e-14)
    # a projected gradient step is a descent direction (d.s <= -|s|^2 / alpha)
    assert gs <= -ss / 0.7 * (1 - 1e-12)
    rows = np.nonzero(s.reshape(-1, 9).any(axis=1))[0]
    assert (lo, hi) == (int(rows[0]), int(rows[-1]) + 1)


def test_projected_gradient_from_an_overloaded_start():
    # loaded cells far above the cap (a warm start for a larger load): the projection
    # must spread the excess onto other cells, here ranked by d
    p = np.array([0.0, 5.0, 0.0, 0.0, 7.0, 0.0])
    d = np.array([3.0, 0.0, 1.0, 2.0, 0.0, 4.0])
    s = np.empty(6)
    candidates = np.empty(6, np.int64)
    kernels.projected_gradient(p, d, 1.0, 12.0, 2.5, True, s, candidates, 3)
    s_ref, *_ = twin.projected_gradient_reference(p, d, 1.0, 12.0, 2.5, True)
    np.testing.assert_allclose(s, s_ref, atol=1e-12)
    new = p + s
    assert new.sum() == pytest.approx(12.0, rel=1e-14) and new.max() <= 2.5
    assert new[2] >= new[3] >= new[0] >= new[5]  # the smaller d, the more pressure


def test_add_step_step_terms_and_blend():
    rng, p, u, _ = _state(13, hmax=1.5)
    s = np.where(rng.random(p.size) < 0.5, rng.normal(size=p.size), 0.0)
    s = np.clip(p + s, 0.0, 1.5) - p
    s[3] = 1.5 - p[3]  # meant to land on the cap
    w = rng.normal(size=p.size).astype(np.float32)
    p_ref, u_ref = twin.add_step_reference(p, s, u, w, 1.0, 1.5)
    q, v = p.copy(), u.copy()
    kernels.add_step(q, s, v, w, 1.0, 1.5)
    np.testing.assert_allclose(q, p_ref, rtol=1e-15)
    np.testing.assert_allclose(v, u_ref, rtol=1e-14)
    assert q[3] == 1.5
    d = rng.normal(size=p.size)
    got = kernels.step_terms(q, p, v, u, d)
    np.testing.assert_allclose(got, twin.step_terms_reference(q, p, v, u, d), rtol=1e-12)
    p_ref, u_ref = twin.blend_reference(q, p, v, u, 0.3)
    kernels.blend(q, p, v, u, 0.3)
    np.testing.assert_allclose(q, p_ref, rtol=1e-14)
    np.testing.assert_allclose(v, u_ref, rtol=1e-14)
