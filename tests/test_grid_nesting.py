"""The one grid (contact._grid), the one nesting stencil (contact._nesting) and the one
sample_roughness (contact._sampling), checked against closed forms."""

from __future__ import annotations

import numpy as np
import pytest

from contact._errors import ContactInputError
from contact._geometry import Domain, sphere_gap
from contact._grid import Grid, centred_grid, cylinder_grid, scan_grid, sphere_grid
from contact._nesting import can_nest, coarse_grid, coarsen, prolong
from contact._sampling import sample_roughness


def _linear(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    return 0.3 + 2.0 * x[None, :] - 1.5 * y[:, None]


def test_prolong_after_coarsen_reproduces_a_linear_field_inside() -> None:
    g = scan_grid((16, 24), 0.1, 0.2)
    f = _linear(g.x, g.y)
    c = coarsen(f)
    cg = coarse_grid(g, smallest=4)
    # the block mean of a linear field is its value at the block's centre
    np.testing.assert_allclose(c, _linear(cg.x, cg.y), rtol=0, atol=1e-13)
    back = prolong(c)
    np.testing.assert_allclose(back[1:-1, 1:-1], f[1:-1, 1:-1], rtol=0, atol=1e-13)
    # the outermost cells keep the coarse edge value outward (no extrapolation)
    np.testing.assert_allclose(back[0, 1:-1], 0.5 * (f[0, 1:-1] + f[1, 1:-1]), atol=1e-13)
    assert coarsen(f).mean() == pytest.approx(f.mean(), rel=1e-14)


def test_prolong_works_on_stacked_fields() -> None:
    rng = np.random.default_rng(1)
    q = rng.standard_normal((2, 6, 8))
    np.testing.assert_array_equal(prolong(q)[1], prolong(q[1]))
    np.testing.assert_array_equal(coarsen(q)[0], coarsen(q[0]))


def test_coarse_grid_and_can_nest() -> None:
    g = sphere_grid(0.01, 1e-4, 64)
    c = coarse_grid(g, smallest=32)
    assert c.shape == (32, 32)
    assert c.dx == pytest.approx(2 * g.dx, rel=1e-12)
    np.testing.assert_allclose(c.x, 0.5 * (g.x[0::2] + g.x[1::2]))
    np.testing.assert_array_equal(c.h, coarsen(g.h))
    assert coarse_grid(g, smallest=33) is None
    assert coarse_grid(cylinder_grid(0.01, 1e-4, 256), smallest=4) is None
    assert can_nest(128, 128) and not can_nest(126, 128) and not can_nest(130, 131)
    p = centred_grid(128, 1e-6, periodic=True)
    cp = coarse_grid(p)
    assert cp.pitch == (2e-6, 2e-6) and cp.periodic


def test_grid_geometry() -> None:
    g = centred_grid(8, 0.5, ny=6, dy=0.25)
    assert g.shape == (6, 8) and g.dx == 0.5 and g.dy == 0.25 and g.area == 0.125
    assert g.x[4] == 0.0 and g.y[3] == 0.0  # the origin on the centre of cell (ny//2, n//2)
    d = Domain(16, 2e-6)
    assert d.grid.shape == (16, 16)
    np.testing.assert_array_equal(
        sphere_gap(16, 2e-6, 0.01),
        (d.grid.x[None, :] ** 2 + d.grid.y[:, None] ** 2) / 0.02)
    s = scan_grid((3, 4), 1.0, 2.0, origin=(10.0, -1.0))
    assert s.origin == (10.0, -1.0) and s.x[-1] == 13.0 and s.y[-1] == 3.0
    line = cylinder_grid(0.01, 1e-4, 16)
    assert line.line and line.shape == (1, 16) and line.dy == 1.0
    t = sphere_grid(0.01, 1e-4, 10)
    assert t.x[0] == pytest.approx(-t.x[-1]) and t.dx == pytest.approx(2e-5)
    with pytest.raises(ContactInputError, match="shape"):
        Grid(x=np.arange(3.0), y=np.arange(2.0), h=np.zeros((3, 2)))
    with pytest.raises(ContactInputError, match="shape"):
        t.with_gap(np.zeros((3, 3)))


def test_sample_roughness_is_exact_for_a_plane_and_bilinear_between_pixels() -> None:
    zdx, zdy = 1e-6, 2e-6
    X = np.arange(41) * zdx
    Y = np.arange(31) * zdy
    plane = 1e-7 + 0.01 * X[None, :] - 0.02 * Y[:, None]
    # a grid off the pixels: a plane is reproduced everywhere
    g = centred_grid(10, 1.3e-6)
    centre = (20.3e-6, 31.1e-6)
    got = sample_roughness(plane, zdx, zdy, g, centre=centre, average=False)
    want = 1e-7 + 0.01 * (centre[0] + g.x)[None, :] - 0.02 * (centre[1] + g.y)[:, None]
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-18)
    # a parabola in x: exact on the pixels, d^2/4 high half-way between them
    para = np.broadcast_to((X - 20e-6)[None, :] ** 2, (31, 41))
    on = Grid(x=np.arange(-5, 6) * zdx, y=np.arange(-3, 4) * zdy)
    np.testing.assert_allclose(sample_roughness(para, zdx, zdy, on),
                               np.broadcast_to(on.x ** 2, (7, 11)), rtol=0, atol=1e-24)
    mid = Grid(x=(np.arange(-5, 5) + 0.5) * zdx, y=np.arange(-3, 4) * zdy)
    np.testing.assert_allclose(sample_roughness(para, zdx, zdy, mid),
                               np.broadcast_to(mid.x ** 2 + zdx**2 / 4, (7, 10)),
                               rtol=0, atol=1e-24)


def test_sample_roughness_averages_on_a_coarser_grid_fills_holes_and_checks_cover() -> None:
    zdx = 1e-6
    checker = np.where((np.arange(40)[:, None] + np.arange(40)[None, :]) % 2, 1.0, -1.0)
    coarse = Grid(x=(np.arange(8) - 4) * 2 * zdx, y=(np.arange(8) - 4) * 2 * zdx)
    # sampled on pixels two apart, a checkerboard aliases to a constant +-1 ...
    on_pixels = (20 * zdx, 20 * zdx)
    raw = sample_roughness(checker, zdx, zdx, coarse, centre=on_pixels, average=False)
    np.testing.assert_allclose(np.abs(raw), 1.0, atol=1e-9)
    # ... averaged over the coarse cell first it is its mean, 0
    np.testing.assert_allclose(sample_roughness(checker, zdx, zdx, coarse, centre=on_pixels),
                               0.0, atol=1e-15)
    z = np.zeros((20, 20))
    z[:, 10:] = 1.0
    z[5, 12] = np.nan  # its nearest measured neighbours are all 1
    g = Grid(x=np.array([2.5e-6]), y=np.array([-4.5e-6]), pitch=(zdx, zdx))
    assert sample_roughness(z, zdx, zdx, g)[0, 0] == 1.0
    # the refusal says both sizes: 19 µm of data against 23 µm of element centres
    with pytest.raises(ContactInputError,
                       match=r"data \(19 µm x 19 µm .*do not cover the contact grid \(its "
                             r"element centres span 23 µm x 23 µm\)"):
        sample_roughness(z, zdx, zdx, centred_grid(24, zdx))
    with pytest.raises(ContactInputError, match="NaN everywhere"):
        sample_roughness(np.full((4, 4), np.nan), zdx, zdx, centred_grid(2, zdx))


def test_solve_normal_takes_a_grid_and_loose_arrays_through_gap_grid() -> None:
    from contact._grid import gap_grid
    from contact.bem import solve_normal

    g = centred_grid(32, 4e-6, periodic=False)
    g = g.with_gap((g.x[None, :] ** 2 + g.y[:, None] ** 2) / 0.02)
    a = solve_normal(g, e_star=1e11, load=0.5)
    b = solve_normal(gap_grid(g.h, 4e-6, origin=g.origin), e_star=1e11, load=0.5)
    np.testing.assert_array_equal(np.asarray(a.pressure), np.asarray(b.pressure))
    np.testing.assert_array_equal(np.asarray(a.x), g.x)
    with pytest.raises(ContactInputError, match="gap_grid"):
        solve_normal(g.h, e_star=1e11, load=0.5)
    with pytest.raises(ContactInputError, match="must carry a gap"):
        solve_normal(centred_grid(32, 4e-6), e_star=1e11, load=0.5)


def test_prolong_of_a_periodic_field_wraps_round_as_periodic_linear_interpolation() -> None:
    # the truth: numpy's own linear interpolation of the periodic coarse samples (period
    # m cells), at the fine centres a quarter coarse cell either side of each coarse one
    m = 8
    rng = np.random.default_rng(3)
    coarse = rng.random((m, m))
    fine_at = (np.arange(2 * m) - 0.5) / 2.0  # fine centres in coarse-cell units
    rows = np.array([np.interp(fine_at, np.arange(m), r, period=m) for r in coarse])
    truth = np.array([np.interp(fine_at, np.arange(m), c, period=m) for c in rows.T]).T
    np.testing.assert_allclose(prolong(coarse, periodic=True), truth, rtol=0, atol=1e-14)
    # the free grid keeps its edge values outward, as before
    assert prolong(coarse)[0, 0] == coarse[0, 0]
