"""Adhesive line contact: a cylinder on a flat in plane strain (contact.adhesion.line).

Truths used (none computed by the package):
- Johnson (1985) sec. 5.6: a Hertz cylinder's pressure (E* / (2 R)) sqrt(a^2 - x^2) leaves
  the surface inside the contact shaped like the cylinder (the plane-strain operator);
- the rigid-cylinder limit: the law's traction integrated over the undeformed gap
  x^2 / (2 R) (2 sqrt(2 R w sigma0) for Dugdale, w sqrt(2 pi R / rho) exponential);
- Maugis-Dugdale for the cylinder (Baney & Hui 1997; Johnson & Greenwood 2008), solved by
  quadrature in tests/maugis_line_reference.py, and its JKR limit
  3 (pi w^2 E* R / 16)^(1/3) (Barquins 1988; Chaudhury et al. 1996).

Measured pull-off errors against Maugis-Dugdale (E* 1 GPa, w 50 mJ/m^2, R 10 um, period
8 max(a_0, reach), 16 steps, tol 1e-6): lambda 0.30: +2.7 % (128 cells, 66 zone px),
+0.6 % (256), +0.7 % (1024); lambda 0.99: +3.9 %, +2.1 %, +1.6 % at 512, 1024, 2048 cells
(30, 60, 121 zone px), +1.7 % at 2048 cells and period 16 (the images' share about 0.4 %);
lambda 3.0: +12.6 % at 1024 cells (6.7 zone px, warned about).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from maugis_line_reference import md_line_pull_off, md_line_state

from contact._errors import ContactInputError
from contact.adhesion.laws import DugdaleLaw, ExponentialLaw
from contact.adhesion.line import (
    adhesive_line,
    jkr_line_load,
    jkr_line_pull_off,
    line_problem,
    line_scales,
    periodic_line_grid,
)
from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.cli import main

E_STAR, W, R = 1e9, 0.05, 10e-6


def _line(law, cells, steps=8, widths=8.0, e_star=E_STAR, **kw):
    a0, reach = line_scales(R, e_star, law)
    return adhesive_line(R, e_star, law, cells=cells, steps=steps,
                         size=widths * max(a0, reach), **kw)


def test_plane_strain_operator_keeps_a_hertz_cylinder_flat():
    """Hertz's cylinder pressure displaces the contact by x^2 / (2 R) + const, and the
    stiffness is E* |q| / 2 at long wavelengths (Johnson 1985, eqs. 2.25, 5.6)."""
    n, size, a = 8192, 200e-6, 2e-6  # a / L = 0.01: the images bend it by ~2e-4
    dx = size / n
    x = (np.arange(n) - n // 2) * dx
    prob = line_problem(periodic_line_grid(n, dx, x * x / (2 * R)), E_STAR, DugdaleLaw(W, 1e7))
    q = 2 * math.pi * np.arange(1, 4) / size
    assert prob.stiffness[0, 1:4] == pytest.approx(E_STAR * q / 2, rel=1e-6)
    p = E_STAR / (2 * R) * np.sqrt(np.maximum(a * a - x * x, 0.0))
    u = np.fft.irfft2(np.fft.rfft2(p.reshape(1, -1)) / prob.stiffness, s=(1, n))[0]
    inside = np.abs(x) < 0.8 * a
    gap = x * x / (2 * R) + u  # the deformed surface against the cylinder, up to a constant
    assert np.ptp(gap[inside]) < 2e-3 * a * a / (2 * R)


@pytest.mark.parametrize("law", [DugdaleLaw(W, 1e6), ExponentialLaw(W, 5e-8)],
                         ids=["dugdale", "exponential"])
def test_rigid_cylinder_limit(law):
    """E* = 1 TPa against sigma0 = 1 MPa (lambda 7e-4): the undeformed gap's pull."""
    res = _line(law, 128, e_star=1e12)
    exact = (2 * math.sqrt(2 * R * W * law.peak) if isinstance(law, DugdaleLaw)
             else W * math.sqrt(2 * math.pi * R / law.rho))
    assert res.rigid_pull_off == pytest.approx(exact, rel=1e-12)
    # Dugdale: each end of the zone snaps to a cell, sigma0 dx each; exponential: 0.1 %
    slack = 2 * law.peak * res.dx if isinstance(law, DugdaleLaw) else 1e-3 * exact
    assert abs(res.cycle.pull_off_force - exact) <= slack
    assert res.cycle.jump_in is not None and res.warnings == ()


def test_reference_reaches_its_limits():
    """The quadrature reference itself: JKR's curve and pull-off at large sigma0 and the
    rigid pull-off at large E*."""
    a_c = (2 * W * R * R / (math.pi * E_STAR)) ** (1 / 3)
    _, load = md_line_state(1.3 * a_c, W, 1e8, R, E_STAR)
    assert load == pytest.approx(float(jkr_line_load(1.3 * a_c, W, R, E_STAR)), rel=6e-3)
    assert md_line_pull_off(W, 1e8, R, E_STAR) == pytest.approx(
        jkr_line_pull_off(W, R, E_STAR), rel=1e-4)
    _, load0 = md_line_state(1e-12, W, 1e6, R, 1e12)
    assert -load0 == pytest.approx(2 * math.sqrt(2 * R * W * 1e6), rel=1e-3)


@pytest.fixture(scope="module")
def coarse():
    """lambda 0.30 (sigma0 4.5 MPa), 128 cells, zone 66 cells."""
    return _line(DugdaleLaw(W, 4.5e6), 128)


def test_maugis_dugdale_pull_off_coarse(coarse):
    """lambda 0.30 (sigma0 4.5 MPa), 128 cells, zone 66 cells: measured +2.7 %."""
    res = coarse
    ref = md_line_pull_off(W, 4.5e6, R, E_STAR)
    assert res.cycle.pull_off_force == pytest.approx(ref, rel=0.04)
    assert res.maugis_parameter == pytest.approx(0.297, abs=1e-3)
    # a closed cycle loses energy, and the touching width appears and vanishes
    assert res.cycle.hysteresis_energy > 0
    assert res.cycle.jump_in is not None and res.cycle.jump_out is not None
    half_in, half_out = res.half_width
    assert half_in.max() > 0 and half_out[-1] == 0.0


def test_energy_balance_per_length(coarse):
    """dPi/d(delta) = P' along the smooth parts of both legs (per unit length)."""
    res = coarse
    for leg in (res.cycle.approach_leg, res.cycle.retraction_leg):
        d, pi_, p = leg.approach, leg.energy, leg.load
        mid = 0.5 * (p[1:] + p[:-1])
        slope = np.diff(pi_) / np.diff(d)
        smooth = np.abs(np.diff(p)) < 0.05 * np.abs(p).max()
        assert smooth.sum() > 10
        np.testing.assert_allclose(slope[smooth], mid[smooth], atol=0.01 * np.abs(p).max())


def test_flat_roughness_is_the_smooth_cylinder(coarse):
    law = DugdaleLaw(W, 4.5e6)
    smooth = coarse
    flat = _line(law, 128, roughness=np.full(128, 3e-9))
    assert flat.cycle.pull_off_force == pytest.approx(smooth.cycle.pull_off_force, rel=1e-9)
    with pytest.raises(ContactInputError, match="profile of 128"):
        _line(law, 128, roughness=np.zeros(64))


@pytest.mark.campaign
@pytest.mark.parametrize(("sigma0", "cells", "tol"), [(4.5e6, 1024, 0.01),
                                                     (1.5e7, 2048, 0.02)])
def test_maugis_dugdale_pull_off_fine(sigma0, cells, tol):
    """lambda 0.30 and 0.99 on fine grids (zone 527 and 121 cells): measured +0.7 %, +1.6 %."""
    res = _line(DugdaleLaw(W, sigma0), cells, steps=16, tol=1e-6)
    ref = md_line_pull_off(W, sigma0, R, E_STAR)
    assert res.cycle.pull_off_force == pytest.approx(ref, rel=tol)


@pytest.mark.campaign
def test_jkr_limit_pull_off_converges():
    """lambda 3.0 (sigma0 45 MPa), where Maugis-Dugdale is JKR's 3 (pi w^2 E* R / 16)^(1/3)
    within 0.03 %: 2048 and 4096 cells (zone 13 and 27 cells) measured +7.3 % and +4.1 %,
    first order; the extrapolation 2 P(4096) - P(2048) is within 2 % of JKR."""
    law = DugdaleLaw(W, 4.5e7)
    p1, p2 = (_line(law, n, steps=16, tol=1e-6).cycle.pull_off_force for n in (2048, 4096))
    jkr = jkr_line_pull_off(W, R, E_STAR)
    assert md_line_pull_off(W, 4.5e7, R, E_STAR) == pytest.approx(jkr, rel=1e-3)
    assert p2 < p1 and 2 * p2 - p1 == pytest.approx(jkr, rel=0.02)


def test_cli_line_json(capsys):
    assert main(["adhesion", "--line", "--radius", "10um", "--e-star", "1000GPa",
                 "--work-of-adhesion", "50mJ/m2", "--range", "50nm", "--interaction",
                 "exponential", "--grid", "128", "--steps", "8", "--size", "13.9um",
                 "--quiet", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["geometry"] == "line"
    assert rec["pull_off_force"]["unit"] == "N/m"
    assert rec["pull_off_force"]["value"] == pytest.approx(
        W * math.sqrt(2 * math.pi * R / 5e-8), rel=2e-3)
    assert rec["hysteresis_energy"]["unit"] == "J/m"
    assert rec["curve"]["out"]["contact_half_width"]["unit"] == "m"
    assert rec["jkr_pull_off_force"]["value"] == pytest.approx(
        jkr_line_pull_off(W, R, 1e12), rel=1e-12)
    assert rec["scans"] is None
    # the transition parameters stated with the result (Tabor 1977: (R w^2/(E*^2 z^3))^(1/3);
    # Maugis 1992 with the exponential law's peak w / rho as sigma0, K = 4 E* / 3)
    assert rec["tabor_parameter"] == {
        "value": pytest.approx((R * W**2 / (1e12**2 * 5e-8**3)) ** (1 / 3), rel=1e-12),
        "unit": ""}
    sigma0 = W / 5e-8
    assert rec["maugis_parameter"]["unit"] == ""
    assert rec["maugis_parameter"]["value"] == pytest.approx(
        2 * sigma0 * (R / (math.pi * W * (4e12 / 3) ** 2)) ** (1 / 3), rel=1e-12)
    solve = rec["solve"]
    assert solve["converged"] is True and solve["edge_contact"] is False
    assert solve["periodic"] is True  # the periodic cell has no edge: not applicable
    assert solve["iterations"] == rec["solver"]["iterations"] > 0


def test_cli_line_refuses_a_ball_scan(capsys, tmp_path):
    assert main(["adhesion", "--line", "--radius", "10um", "--e-star", "1GPa",
                 "--work-of-adhesion", "50mJ/m2", "--range", "5nm", "--ball",
                 str(tmp_path / "b.npz"), "--quiet"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "line contact" in err[0]


def _plate_run(radius, fn, **extra):
    from surfmet.mechanics.adhesion_line import line_adhesion

    law = DugdaleLaw(W, 4.5e6)
    size = 8 * max(line_scales(R, E_STAR, law))
    n, dx = 160, size / 128
    x = (np.arange(n) - 0.5 * (n - 1)) * dx
    plate = None if fn is None else Topography(fn(x[None, :], x[:, None]), dx, dx)
    kw = {"work": W, "range_": W / 4.5e6, "e_star": E_STAR, "grid": 128, "steps": 8,
          "size": size, **extra}
    return line_adhesion(radius, plate=plate, **kw)


def test_plate_scan_profile_on_a_line(coarse):
    """The plate's middle row is the profile: a plate tilted in x and y is levelled away
    (the smooth cylinder's cycle); a scan narrower than the period is one error."""
    tilted = _plate_run(R, lambda u, v: 1e-3 * u + 2e-3 * v)
    assert tilted.scans.plate_name == "(in memory)" and tilted.result.roughness_rms < 1e-15
    assert tilted.result.cycle.pull_off_force == pytest.approx(
        coarse.cycle.pull_off_force, rel=1e-9)
    with pytest.raises(SurfmetInputError, match="smaller than the adhesion domain"):
        _plate_run(R, lambda u, v: 0 * u * v, size=2 * tilted.result.size)


@pytest.mark.campaign
def test_grooved_plate_is_a_cylinder_of_half_the_radius():
    """A plate grooved like a cylinder of radius R, under a cylinder of R, closes the gap
    like a cylinder of R / 2 (curvatures add): same cells and period."""
    grooved = _plate_run(R, lambda u, v: -u * u / (2 * R) + 0 * v)
    half = _plate_run(R / 2, None)
    assert grooved.result.roughness_rms > 1e-9
    assert grooved.result.cycle.pull_off_force == pytest.approx(
        half.result.cycle.pull_off_force, rel=5e-3)
