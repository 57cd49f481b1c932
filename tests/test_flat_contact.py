"""Flat contact: the BEM's κ against the published band, the sweep's physics, the CLI."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import surfmet
from contact._errors import ContactInputError
from contact._grid import gap_grid
from contact.setups._flat import flat_contact
from surfmet.cli import main
from surfmet.synth import self_affine

N = 256
SLOPE = 0.1


def _surface(z, dx):
    """The periodic grid of heights z pressed by a flat: the separation z.max() - z."""
    z = np.asarray(z, dtype=float)
    return gap_grid(z.max() - z, dx, periodic=True)


def _kappa(hurst: float, seed: int) -> float:
    # Hyun et al. (2004)'s set-up: no roll-off (λ_r = L), a short cut-off of 4 pixels so
    # that each shortest wavelength is resolved, periodic; A/A0 ≈ 5 %
    topo = self_affine(N, 1.0, hurst=hurst, slope_rms=SLOPE, short_cutoff=4.0, seed=seed)
    p = 0.02 * SLOPE
    r = flat_contact(_surface(topo.heights, 1.0), pressures=[p], e_star=1.0)
    pt = r.points[0]
    assert pt.converged and 0.02 < pt.area_fraction < 0.08
    # the perimeter-corrected area (Yastrebov et al. 2015) removes the pixel bias that
    # inflates the raw cell count by 10-20 % at this resolution
    assert pt.area_fraction > pt.corrected_area_fraction
    return pt.corrected_area_fraction / p * SLOPE


def test_bem_kappa_lies_in_the_published_band():
    rng = np.random.default_rng(11)
    hs = np.sort(rng.uniform(0.3, 0.8, 3))
    hs[0], hs[-1] = 0.3 + 0.05 * rng.random(), 0.75 + 0.05 * rng.random()
    ks = [_kappa(h, seed=3) for h in hs]
    # Prodanov, Dapp & Müser (2014): κ = 2 ± 0.2; Hyun et al. (2004): 2.0-2.2
    for h, k in zip(hs, ks):
        assert 1.8 <= k <= 2.25, f"κ = {k:.3f} at H = {h:.2f}"
    # Hyun et al.: κ decreases with H
    assert ks[0] > ks[-1]


def test_sweep_is_monotonic_and_stiffness_is_the_gap_slope():
    topo = self_affine(128, 1e-6, hurst=0.6, slope_rms=0.05, short_cutoff=4e-6, seed=5)
    e = 10e9
    p = np.array([2e6, 5e6, 1e7, 1e7 * 1.05])
    r = flat_contact(_surface(topo.heights, 1e-6), pressures=p[::-1], e_star=e,
                     stiffness="solve")
    assert np.all(np.diff(r.pressure) > 0)  # returned in increasing order
    assert np.all(np.diff(r.area_fraction) > 0) and np.all(np.diff(r.mean_gap) < 0)
    # K = -dp/dū from the step solve against a finite difference over 5 %
    fd = -(p[3] - p[2]) / (r.mean_gap[3] - r.mean_gap[2])
    assert r.stiffness[2] == pytest.approx(fd, rel=0.05)
    # the default reads K off the computed curve (no extra solve): same slope within 5 %
    rc = flat_contact(_surface(topo.heights, 1e-6), pressures=p, e_star=e)
    np.testing.assert_allclose(rc.mean_gap, r.mean_gap, rtol=1e-9)
    np.testing.assert_allclose(rc.stiffness[1:], r.stiffness[1:], rtol=0.05)
    # the mean gap stays below the flat's start height above the mean plane
    assert np.all(r.mean_gap < topo.heights.max() - topo.heights.mean())


def test_curve_stiffness_is_exact_on_the_exponential_law():
    from contact.setups._flat import curve_stiffness

    rng = np.random.default_rng(20)
    u0, p0 = rng.uniform(0.1e-6, 2e-6), rng.uniform(1e5, 1e7)
    u = np.sort(rng.uniform(0.0, 5 * u0, rng.integers(2, 7)))[::-1]
    p = p0 * np.exp(-u / u0)
    np.testing.assert_allclose(curve_stiffness(p, u), p / u0, rtol=1e-9)
    # on p = c/ū² (not exponential) the three-point slope is still close where dense
    u = np.linspace(2e-6, 1e-6, 9)
    p = 1.0 / u**2
    k = curve_stiffness(p, u)
    np.testing.assert_allclose(k[1:-1], 2.0 / u[1:-1] ** 3, rtol=0.01)


def test_sweep_rejects_bad_input():
    z = np.random.default_rng(0).standard_normal((32, 32)) * 1e-7
    with pytest.raises(ContactInputError):
        flat_contact(_surface(z, 1e-6), pressures=[-1.0], e_star=1e9)
    with pytest.raises(ContactInputError):
        flat_contact(_surface(np.zeros((32, 32)), 1e-6), pressures=[1e6], e_star=1e9)
    with pytest.raises(ContactInputError):
        flat_contact(_surface(z, 1e-6), pressures=[2e9], e_star=1e9, hardness=1e9)


@pytest.fixture(scope="module")
def scan(tmp_path_factory):
    topo = self_affine(64, 1e-6, hurst=0.7, slope_rms=0.05, short_cutoff=4e-6, seed=2)
    return str(surfmet.write(topo, tmp_path_factory.mktemp("fc") / "sa.npz"))


def test_cli_json_units_and_errors(scan, tmp_path, capsys):
    out = tmp_path / "fc.png"
    assert main(["flat-contact", scan, "--e-star", "10GPa", "--pressures", "1MPa:20MPa:3",
                 "--json", "--plot", str(out)]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["boundary"] == "periodic" and len(rec["results"]) == 3
    r0 = rec["results"][0]
    assert r0["pressure"] == {"value": pytest.approx(1e6), "unit": "Pa"}
    assert r0["bem"]["mean_gap"]["unit"] == "m" and r0["bem"]["stiffness"]["unit"] == "Pa/m"
    assert r0["persson"]["mean_gap"]["unit"] == "m" and r0["bgt"]["mean_gap"]["value"] is None
    for name in ("persson", "gw", "bgt"):
        err = r0[name]["relative_error"]["area_fraction"]
        assert err == pytest.approx(r0[name]["area_fraction"] / r0["bem"]["area_fraction"] - 1)
    assert r0["persson"]["kappa"] == pytest.approx(math.sqrt(8 / math.pi), rel=1e-3)
    # closed forms beside the records' own ratios: the scan's rms slope is the synthetic
    # surface's 0.05 (its spectral gradient; measured 0.0510 from the PSD), Persson's area
    # erf(sqrt(2) p / (E* h'_rms)) and BGT's sqrt(2 pi) p / (E* h'_rms) at it
    from scipy.special import erf

    slope = rec["spectrum"]["slope_rms"]["spectrum"]["value"]
    assert slope == pytest.approx(0.05, rel=0.03)
    for r in rec["results"]:
        x = r["pressure"]["value"] / (10e9 * slope)
        assert r["persson"]["area_fraction"] == pytest.approx(erf(math.sqrt(2) * x), rel=1e-3)
        assert r["bgt"]["area_fraction"] == pytest.approx(math.sqrt(2 * math.pi) * x, rel=1e-3)
    assert out.stat().st_size > 1000


def test_cli_free_boundary_and_materials(scan, capsys):
    assert main(["flat-contact", scan, "--materials", "aluminium", "--pressures", "20MPa",
                 "--periodic", "no", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["boundary"] == "free" and rec["materials"] == ["aluminium"]
    # a rigid flat: 1/E* = (1 - ν²)/E of aluminium alone (Johnson 1985, eq. 4.22, the
    # counterface's term vanishing), with the paper's E = 70 GPa, ν = 0.33 (Alaci et al.
    # 2022): 78.55 GPa
    assert rec["e_star"]["value"] == pytest.approx(70e9 / (1.0 - 0.33**2), rel=1e-12)
    assert rec["e_star"]["unit"] == "Pa"


@pytest.mark.parametrize("argv", [
    ["flat-contact", "{scan}", "--e-star", "1GPa", "--pressures", "-3MPa"],
    ["flat-contact", "{scan}", "--e-star", "1GPa", "--pressures", "5MPa:1MPa:3"],
    ["flat-contact", "{scan}", "--pressures", "1MPa"],
    ["flat-contact", "{scan}", "--e-star", "1GPa", "--materials", "steel", "--pressures", "1MPa"],
    ["flat-contact", "{scan}", "--e-star", "1GPa", "--pressures", "2GPa", "--hardness", "1GPa"],
    ["flat-contact", "absent.npz", "--e-star", "1GPa", "--pressures", "1MPa"],
])
def test_cli_bad_input_exits_1(argv, scan, capsys):
    assert main([a.format(scan=scan) for a in argv]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "Traceback" not in err[0]


@pytest.mark.parametrize("level", [0.0, 3e-6])
@pytest.mark.parametrize("argv", [
    ["spectrum", "{scan}"],
    ["flat-contact", "{scan}", "--materials", "steel,aluminium", "--pressures", "1MPa"],
])
def test_a_flat_scan_is_one_clear_line(argv, level, tmp_path, capsys):
    # constant heights (issue 16 item 9: was exit 2, "ValueError: zero-size array")
    flat = surfmet._model.Topography(np.full((64, 48), level), 1e-6, 1e-6)
    path = str(surfmet.write(flat, tmp_path / "flat.npz"))
    assert main([a.format(scan=path) for a in argv]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "flat" in err[0] and "internal error" not in err[0]


def test_the_engine_names_a_flat_surface():
    from contact.roughcontact import persson, summit_parameters

    with pytest.raises(ContactInputError, match="flat"):
        flat_contact(_surface(np.full((32, 32), 2e-6), 1e-6), pressures=[1e6], e_star=1e9)
    with pytest.raises(ContactInputError, match="flat"):
        summit_parameters(0.0, 0.0, 0.0)
    q = np.linspace(1e4, 1e6, 20)
    with pytest.raises(ContactInputError, match="flat"):
        persson([1e6], 1e9, q, np.zeros_like(q), np.ones_like(q), 1e4)


def test_curve_stiffness_never_reports_a_negative_stiffness():
    """Issue 25 item 4: three pressures a decade apart on a non-exponential curve bend the
    quadratic the wrong way at the first point (K < 0 on main); the secant through the
    neighbours is given there, and the point is named."""
    from contact.setups._flat import bent_points, curve_stiffness

    p = np.array([1e6, 1e7, 1e8])
    u = np.array([5.781e-6, 1.507e-6, 0.2468e-6])  # the paper ball's BEM gaps
    k = curve_stiffness(p, u)
    assert np.all(k > 0)
    assert bent_points(p, u).tolist() == [True, False, False]
    assert k[0] == pytest.approx(-p[0] * math.log(10) / (u[1] - u[0]), rel=1e-12)


def test_a_ball_on_flat_contact_loses_its_form_and_says_so(capsys):
    """Issue 25 item 4: the paper's ball, plane-levelled, gave a mean gap of 232 µm (its
    cap) and a negative stiffness without a caveat. Its second-order form is removed and
    said; the gap is the texture's, every stiffness positive; a pressure above the
    hardness gets a caveat."""
    from pathlib import Path

    ball = Path(surfmet.__file__).parent / "data" / "paper_ball.x3p"
    assert main(["flat-contact", str(ball), "--materials", "steel,aluminium",
                 "--pressures", "1MPa,100MPa,2GPa", "--json", "--quiet"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["levelling"] == "poly:2"
    assert any("curved form dominated" in c for c in rec["caveats"])
    assert any("at or above the hardness" in c and "2 GPa" in c for c in rec["caveats"])
    bem = [r["bem"] for r in rec["results"]]
    # the ball's roughness is microns (Sq after the sphere ~ 1 µm), not its 150 µm cap
    assert bem[0]["mean_gap"]["value"] < 20e-6
    assert all(b["stiffness"]["value"] > 0 for b in bem)
