"""Preparing a plate scan and a ball scan for contact: levelling, sphere removal, one grid."""

from __future__ import annotations

import numpy as np
import pytest
from contact_synth import rough_surface

from surfmet import Profile, SurfmetInputError, Topography
from surfmet.mechanics.pairing import prepare_pair


def _plate(seed, n=160, dx=5e-6, rms=1e-6, tilt=True):
    rng = np.random.default_rng(seed)
    z = rough_surface(n, dx, rms, seed)
    yy, xx = np.indices(z.shape)
    form = 0.0
    if tilt:  # hidden: random tilt and offset of the specimen
        sx, sy = rng.uniform(-3e-3, 3e-3, 2)
        form = rng.uniform(-50e-6, 50e-6) + sx * xx * dx + sy * yy * dx
    return Topography(z + form, dx, dx), z


def _ball(seed, radius=0.02, n=48, dx=20e-6, rms=0.2e-6):
    rng = np.random.default_rng(seed)
    z = rough_surface(n, dx, rms, seed + 100, corr=60e-6)
    yy, xx = np.indices(z.shape)
    # apex somewhere near the middle (hidden offset), cap seen from above
    xc = (0.5 * (n - 1) + rng.uniform(-3, 3)) * dx
    yc = (0.5 * (n - 1) + rng.uniform(-3, 3)) * dx
    cap = np.sqrt(radius**2 - (xx * dx - xc) ** 2 - (yy * dx - yc) ** 2) - radius
    return Topography(cap + z + rng.uniform(-1e-3, 1e-3), dx, dx), z


def _detrend(z):
    yy, xx = np.indices(z.shape)
    a = np.column_stack([np.ones(z.size), xx.ravel(), yy.ravel()])
    coef, *_ = np.linalg.lstsq(a, z.ravel(), rcond=None)
    return z - (a @ coef).reshape(z.shape)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_plate_is_levelled_whatever_its_tilt(seed):
    plate, z = _plate(seed)
    pair = prepare_pair(plate)
    assert pair.dx == plate.dx
    np.testing.assert_allclose(pair.roughness, _detrend(z), atol=1e-12)
    assert pair.plate_rms == pytest.approx(np.std(_detrend(z)), rel=1e-6)
    assert pair.ball_rms is None and pair.filled_fraction == 0


@pytest.mark.parametrize("seed", [3, 4])
def test_ball_sphere_is_removed_and_radius_found(seed):
    ball, z = _ball(seed)
    pair = prepare_pair(None, ball, mirror_ball=False)
    # the cap sags 5.5 um; 0.2 um of long-wavelength roughness bends the fit by <1 %
    assert pair.ball_radius == pytest.approx(0.02, rel=1e-2)
    # what remains is the roughness (the sphere fit also takes its lowest-order part)
    resid = pair.roughness - _detrend(z)
    assert np.std(resid) < 0.1 * np.std(z)
    mirrored = prepare_pair(None, ball).roughness
    np.testing.assert_allclose(mirrored, pair.roughness[:, ::-1], atol=1e-15)


def test_pair_on_common_grid_at_the_finer_pitch():
    plate, _zp = _plate(5, n=200, dx=5e-6)
    ball, _zb = _ball(6, n=40, dx=20e-6)  # 780 um wide, coarser
    pair = prepare_pair(plate, ball)
    assert pair.dx == 5e-6
    ny, nx = pair.roughness.shape
    assert (nx - 1) * pair.dx <= 39 * 20e-6 + 1e-12  # the shared area only
    assert nx == ny == 157
    assert pair.rms == pytest.approx(np.hypot(pair.plate_rms, pair.ball_rms), rel=0.2)
    assert np.isfinite(pair.roughness).all()
    assert any("common" in note for note in pair.notes)


def test_holes_are_filled_and_counted():
    plate, _ = _plate(7, tilt=False)
    h = np.array(plate.heights)
    h[40:50, 60:80] = np.nan
    pair = prepare_pair(Topography(h, plate.dx, plate.dy))
    assert np.isfinite(pair.roughness).all()
    assert pair.filled_fraction == pytest.approx(200 / 160**2, rel=1e-9)
    with pytest.raises(SurfmetInputError, match="not measured"):
        prepare_pair(Topography(h, plate.dx, plate.dy), max_filled=0.001)


def test_bad_input():
    with pytest.raises(SurfmetInputError, match="plate scan, a ball scan"):
        prepare_pair()
    with pytest.raises(SurfmetInputError, match="areal"):
        prepare_pair(Profile(np.zeros(10), 1e-6))
    with pytest.raises(SurfmetInputError):
        prepare_pair(Topography(np.full((10, 10), np.nan), 1e-6, 1e-6))
    plate, _ = _plate(8, n=16)
    with pytest.raises(SurfmetInputError, match="common area"):
        prepare_pair(plate, pitch=40e-6)
