"""Elastic-perfectly-plastic contact: the pressure cap, load balance, the regime report."""

from __future__ import annotations

import numpy as np
import pytest
from contact_synth import rough_surface

from contact import composite_modulus, hertz_sphere, material, solve_sphere
from contact.bem import solve_normal
from contact.geometry import sphere_gap

E_STAR = composite_modulus(material("steel"), material("aluminium"))
H_AL = material("aluminium").hardness
R, W = 0.02, 10.0


@pytest.mark.parametrize("ratio", [0.9, 0.6])
def test_pressure_is_capped_and_load_balanced(ratio):
    hz = hertz_sphere(R, W, E_STAR)
    H = ratio * hz.p0
    n = 128
    dx = 4 * hz.a / n
    res = solve_normal(sphere_gap(n, dx, R), dx, e_star=E_STAR, load=W, hardness=H)
    assert res.converged
    assert res.pmax <= H
    assert res.pressure.sum() * dx * dx == pytest.approx(W, rel=1e-10)
    assert res.plastic_area > 0
    # the capped cells carry H: W lies between H * plastic area and H * contact area
    assert H * res.plastic_area <= W <= H * res.contact_area
    # the plastic displacement lives exactly on the capped cells and is an indentation
    capped = res.pressure >= H
    assert np.all(res.plastic_displacement[~capped] == 0)
    assert res.plastic_displacement[capped].max() > 0
    assert res.plastic_displacement.min() >= 0
    # the cap flattens the peak and spreads the contact beyond the Hertz radius
    assert res.contact_radius > hz.a
    assert res.regime == "plastic at the Hertz scale"


def test_plastic_displacement_closes_the_gap():
    # on capped cells the surfaces interpenetrate elastically by exactly the plastic
    # displacement: h + u - delta + u_plastic = 0
    hz = hertz_sphere(R, W, E_STAR)
    n = 96
    dx = 4 * hz.a / n
    h = sphere_gap(n, dx, R)
    res = solve_normal(h, dx, e_star=E_STAR, load=W, hardness=0.7 * hz.p0, tol=1e-8)
    capped = res.pressure >= res.hardness
    closure = h + res.displacement - res.approach + res.plastic_displacement
    assert np.abs(closure[capped]).max() < 1e-6 * hz.delta


def test_plastic_at_asperity_scale_but_elastic_at_hertz_scale():
    hz = hertz_sphere(R, W, E_STAR)
    assert hz.p0 < H_AL  # the smooth ball would stay elastic
    zdx = 5e-6
    z = rough_surface(256, zdx, 0.5e-6, seed=3)
    res = solve_sphere(R, W, E_STAR, roughness=z, roughness_dx=zdx, hardness=H_AL, grid=128)
    assert res.converged and not res.touches_edge
    assert res.pmax <= H_AL
    assert res.load == pytest.approx(W, rel=1e-10)
    assert res.plastic_area > 0
    assert res.regime == "plastic at the asperity scale"
    assert any("asperity scale" in note and "elastic at the Hertz scale" in note
               for note in res.notes)
    # the clean (smooth) ball with the same hardness: elastic, nothing reported
    smooth = solve_sphere(R, W, E_STAR, hardness=H_AL, grid=128)
    assert smooth.plastic_area == 0
    assert smooth.regime == "elastic"
    assert not any("plastic" in note for note in smooth.notes)
    assert smooth.pmax == pytest.approx(hz.p0, rel=2e-3)
