"""Sphere fits of synthetic ball scans: the radius comes back within its uncertainty."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.fitting import fit_sphere


def _cap(rng, R, half_angle_deg, n, noise, holes=0.0, concave=False):
    """A spherical cap of radius R seen from above, n x n points, z noise σ = noise."""
    half_width = R * np.sin(np.radians(half_angle_deg)) / np.sqrt(2)  # cap inside the disc
    dx = 2 * half_width / (n - 1)
    j, i = np.mgrid[:n, :n]
    X, Y = i * dx, j * dx
    xc = half_width + rng.uniform(-0.1, 0.1) * half_width
    yc = half_width + rng.uniform(-0.1, 0.1) * half_width
    zc = rng.uniform(-1e-3, 1e-3)
    root = np.sqrt(R**2 - (X - xc) ** 2 - (Y - yc) ** 2)
    z = (zc - root if concave else zc + root) + noise * rng.standard_normal(X.shape)
    if holes:
        z[rng.random(z.shape) < holes] = np.nan
    return Topography(z, dx, dx), (xc, yc, zc)


@pytest.mark.parametrize("seed", range(8))
def test_radius_within_its_uncertainty(seed):
    rng = np.random.default_rng(seed)
    R = rng.uniform(0.5e-3, 25e-3)
    angle = rng.uniform(3, 30)
    noise = rng.uniform(5e-9, 200e-9)
    topo, centre = _cap(rng, R, angle, int(rng.integers(60, 160)), noise,
                        holes=rng.uniform(0, 0.3), concave=bool(seed % 3 == 0))
    f = fit_sphere(topo)
    assert abs(f.radius - R) < 3.5 * f.radius_uncertainty
    assert np.allclose(f.center, centre, atol=4 * max(f.center_uncertainty))
    assert f.rms_residual == pytest.approx(noise, rel=0.1)
    assert f.convex == (seed % 3 != 0)
    assert f.pv_form_deviation > 4 * noise
    assert np.isnan(f.residuals).sum() == np.isnan(topo.heights).sum()


def test_uncertainty_matches_the_scatter_of_repeated_fits():
    # The Jacobian uncertainty must be realistic, not just large: compare with the
    # standard deviation of the radius over independent noise draws.
    rng = np.random.default_rng(10)
    R, radii, uncs = 10e-3, [], []
    for _ in range(40):
        topo, _ = _cap(rng, R, 8.0, 60, 50e-9)
        f = fit_sphere(topo)
        radii.append(f.radius)
        uncs.append(f.radius_uncertainty)
    assert np.std(radii, ddof=1) == pytest.approx(np.mean(uncs), rel=0.3)
    assert abs(np.mean(radii) - R) < 3 * np.std(radii) / np.sqrt(len(radii)) + 1e-9


def test_robust_loss_resists_spikes():
    rng = np.random.default_rng(3)
    R = 10e-3  # a 20 mm ball, as in Alaci et al. 2022
    topo, _ = _cap(rng, R, 10, 100, 20e-9)
    z = topo.heights.copy()
    idx = rng.choice(z.size, 60, replace=False)
    z.ravel()[idx] += rng.uniform(2e-6, 10e-6, idx.size)
    spiky = topo.replace(heights=z)
    plain = fit_sphere(spiky)
    robust = fit_sphere(spiky, loss="soft_l1")
    assert abs(robust.radius - R) < abs(plain.radius - R) / 5
    assert abs(robust.radius - R) < 1e-3 * R


def test_plane_and_too_few_points_are_refused():
    j, i = np.mgrid[:20, :20]
    with pytest.raises(SurfmetInputError):
        fit_sphere(Topography(np.full((20, 20), np.nan), 1e-6, 1e-6))
    z = np.full((3, 3), np.nan)
    z[0, :2] = 1.0
    with pytest.raises(SurfmetInputError):
        fit_sphere(Topography(z, 1e-6, 1e-6))
    with pytest.raises(SurfmetInputError):
        fit_sphere(Topography(1e-6 * (i + j), 1e-6, 1e-6), loss="l2")


@pytest.mark.parametrize("kind", ["zeros", "tilted", "flat_noise"])
def test_unresolved_curvature_is_refused_not_a_huge_radius(kind):
    # issue 16 item 3: all-zero heights gave a radius of 24 m, a tilted plane 3.2e8 m,
    # both "± 0 nm" with exit 0
    rng = np.random.default_rng(4)
    j, i = np.mgrid[:60, :60] * 1e-6
    z = {"zeros": 0 * i, "tilted": 1e-3 * i + 2e-4 * j,
         "flat_noise": 1e-8 * rng.standard_normal(i.shape)}[kind]
    with pytest.raises(SurfmetInputError, match="curvature not resolved"):
        fit_sphere(Topography(z, 1e-6, 1e-6))
    # form removal goes on, flagged
    flagged = fit_sphere(Topography(z, 1e-6, 1e-6), require_curvature=False)
    assert flagged.curvature_resolved is False


def test_cylinder_on_a_plane_is_refused():
    from surfmet.fitting import fit_cylinder

    rng = np.random.default_rng(5)
    _, i = np.mgrid[:60, :60] * 1e-6
    z = 1e-3 * i + 1e-8 * rng.standard_normal(i.shape)
    with pytest.raises(SurfmetInputError, match=r"curvature not resolved|no curvature"):
        fit_cylinder(Topography(z, 1e-6, 1e-6))


def test_form_deviation_is_the_quadratic_component_not_the_spikes():
    # issue 16 item 6: one definition of the form deviation. A cap with astigmatism
    # c (x'² - y'²) (orthogonal to the sphere's own x'² + y'² over a square, so the sphere
    # fit leaves it in the residual): its PV over the square of half width h is 2 c h²,
    # whatever spikes are added; the PV of all residuals is set by the spikes
    rng = np.random.default_rng(8)
    R, n, dx = 10e-3, 101, 10e-6
    j, i = np.mgrid[:n, :n]
    u, v = (i - 50) * dx, (j - 50) * dx
    c = 2.0  # 1/m: 0.5 µm of astigmatism at the corners
    z = np.sqrt(R**2 - u**2 - v**2) + c * (u**2 - v**2) + 5e-9 * rng.standard_normal(u.shape)
    spiky = z.copy()
    spiky.ravel()[rng.choice(z.size, 20, replace=False)] += 20e-6
    h = 50 * dx
    clean, dirty = (fit_sphere(Topography(a, dx, dx)) for a in (z, spiky))
    assert clean.form_pv == pytest.approx(2 * c * h**2, rel=0.03)
    assert dirty.form_pv == pytest.approx(2 * c * h**2, rel=0.1)
    assert dirty.pv_form_deviation > 15e-6 > 10 * dirty.form_pv


def test_demo_and_fit_state_the_same_form_deviation(capsys):
    # issue 16 item 6: `surfmet fit` said 37.96 µm (PV of all residuals) and the demo 3.41
    # µm (its own quadratic) for the same ball; both now state SphereFit.form_pv and the
    # record names the other value "residual PV (all points)"
    import json
    import re

    import surfmet
    from surfmet.cli import main
    from surfmet.demo._outputs import data_file
    from surfmet.demo._story import _ball, _Text
    from surfmet.demo._surfaces import ball_form

    path = data_file("paper_ball.x3p")
    assert main(["fit", str(path), "--shape", "sphere", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["names"]["form_pv"].startswith("form deviation") and \
        rec["form_pv"]["unit"] == "m"
    assert rec["names"]["pv_form_deviation"] == "residual PV (all points)"
    summary, _ = ball_form(surfmet.read(path))
    text = _Text()
    _ball(text, {"ball": summary})
    line = next(s for s in text.lines if "form deviation" in s)
    demo_um = re.search(r"form deviation ([0-9.]+ µm) \(PV", line).group(1)
    # the same number in the same words as surfmet fit prints it (surfmet.units)
    from surfmet.units import format_quantity

    assert demo_um == format_quantity(rec["form_pv"]["value"], "m")
    assert main(["fit", str(path), "--shape", "sphere"]) == 0
    assert f"form deviation      {demo_um} PV" in capsys.readouterr().out
    # the residual PV is set by the ball's spikes, an order of magnitude above the form
    assert rec["pv_form_deviation"]["value"] > 5 * rec["form_pv"]["value"]


def test_heights_beyond_any_surface_are_refused_in_one_line(tmp_path, capsys):
    """Issue 25 item 11: ``fit`` on a ball scan with heights x 1e300 (OverflowError, exit 2,
    on main) is one line, exit 1, through the API and the CLI."""
    import surfmet
    from surfmet.cli import main

    ball = surfmet.read(Path(surfmet.__file__).parent / "data" / "paper_ball.x3p")
    huge = ball.replace(heights=np.asarray(ball.heights) * 1e300)
    with pytest.raises(SurfmetInputError, match="peak to valley"):
        fit_sphere(huge)
    path = tmp_path / "huge.npz"
    surfmet.write(huge, path)
    assert main(["fit", str(path), "--shape", "sphere"]) == 1
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "peak to valley" in err
