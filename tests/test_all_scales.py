"""Contact from all scales: the isotropic PSD from a profile PSD (inverse Abel transform),
and ``spectrum`` / ``flat-contact`` on several measurements of one surface.

Truths: the closed form of the self-affine conversion (Jacobs, Junge & Pastewka 2017), the
forward projection of a known areal spectrum by numerical quadrature, and a synthetic
surface generated from a known isotropic spectrum, cut into measurements of different
sizes and pixels, whose rms slope over the measured band has a closed form.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import erf

import surfmet
from contact._errors import ContactInputError
from contact.roughcontact import isotropic_moments
from contact.roughcontact._isotropic import iso_from_profile_psd, log_quadrature
from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography
from surfmet.cli import main
from surfmet.mechanics.all_scales import all_scales_spectrum, persson_all_scales
from surfmet.scale_dependent import analyze_scales

# --- the engine: C_iso from C_1D ---------------------------------------------------------------


@pytest.mark.parametrize("hurst", [0.2, 0.5, 0.8])
def test_self_affine_conversion_is_the_closed_form(hurst):
    q = np.geomspace(1e3, 1e6, 16)
    c1 = 3e-20 * q ** (-1 - 2 * hurst)
    factor = 2 * math.sqrt(math.pi) * math.gamma(1 + hurst) / math.gamma(0.5 + hurst)
    at = np.geomspace(2e3, 3e6, 9)  # between the points and beyond the last one
    np.testing.assert_allclose(iso_from_profile_psd(q, c1, at),
                               3e-20 * at ** (-1 - 2 * hurst) / at * factor, rtol=1e-10)


def _project(c_iso, qx: float) -> float:
    """C_1D(qx) = (1/π) ∫₀^∞ C_iso(√(qx² + qy²)) dqy, by quadrature (qy = qx t)."""
    return quad(lambda t: c_iso(qx * math.hypot(1.0, t)) * qx, 0, np.inf, limit=200,
                epsabs=0, epsrel=1e-11)[0] / math.pi


def test_roll_off_spectrum_round_trips_through_its_projection():
    hurst, q_r = 0.7, 1e4

    def c_iso(k):
        return 1.0 / (1.0 + (k / q_r) ** 2) ** (1 + hurst)

    q = np.geomspace(1e2, 1e7, 5 * 20 + 1)  # 20 points per decade
    c1 = np.array([_project(c_iso, v) for v in q])
    back = iso_from_profile_psd(q, c1)
    # log-log interpolation between the points bends less than the roll-off does: at 20
    # points per decade the knee comes back within 1.2 % (3.3 % at 10 per decade)
    np.testing.assert_allclose(back, c_iso(q), rtol=0.015)
    np.testing.assert_allclose(back[q < 3e2], c_iso(q[q < 3e2]), rtol=0.003)
    np.testing.assert_allclose(back[q > 1e5], c_iso(q[q > 1e5]), rtol=0.003)
    # the profile Parseval sum equals the areal one over the whole spectrum
    qq, w, dq = log_quadrature(1e-1, 1e10, 40)
    m0 = isotropic_moments(qq, c_iso(qq), w, dq)[0]
    assert m0 == pytest.approx(q_r**2 / (4 * math.pi * hurst), rel=1e-3)


def test_a_rising_profile_psd_gives_negative_values_and_bad_arrays_are_refused():
    q = np.geomspace(1e3, 1e5, 9)
    c1 = q ** -2.0
    c1[4:6] *= 30.0  # a step up, as where two measurements of different levels meet
    assert iso_from_profile_psd(q, c1).min() < 0
    with pytest.raises(ContactInputError):
        iso_from_profile_psd(q, c1[:-1])
    with pytest.raises(ContactInputError):
        iso_from_profile_psd(q, -c1)


# --- several measurements of one synthetic surface ---------------------------------------------


def _surface(n: int, pixel: float, hurst: float, c0: float, seed: int) -> np.ndarray:
    """Periodic surface with |FFT|² = C_iso N²/Δ² exactly (random phases), C_iso = c0
    q^(-2-2H) for every wavevector of the grid (Jacobs et al.'s convention)."""
    rng = np.random.default_rng(seed)
    qx = 2 * np.pi * np.fft.fftfreq(n, d=pixel)
    q = np.hypot(qx[None, :], qx[:, None])
    c = np.zeros_like(q)
    c[q > 0] = c0 * q[q > 0] ** (-2 - 2 * hurst)
    spec = np.fft.fft2(rng.standard_normal((n, n)))
    return np.fft.ifft2(spec / np.abs(spec) * np.sqrt(c * n * n / pixel**2)).real


def _measurements(hurst: float, seed: int) -> tuple[list[Topography], float]:
    """Three measurements of a 1024² surface: pixels 2, 4 and 8 times the generator's,
    sizes a quarter, half and all of it (every one sampled, as an instrument does)."""
    a, c0 = 1e-8, 1.6e-5 if hurst == 0.8 else 1e-9
    z = _surface(1024, a, hurst, c0, seed)
    return [Topography(z[:256:2, :256:2].copy(), 2 * a, 2 * a),
            Topography(z[500:1012:4, 500:1012:4].copy(), 4 * a, 4 * a),
            Topography(z[::8, ::8].copy(), 8 * a, 8 * a)], c0


@pytest.mark.parametrize("hurst, seed", [(0.8, 4), (0.5, 1)])
def test_persson_from_three_measurements_matches_the_known_spectrum(hurst, seed):
    scans, c0 = _measurements(hurst, seed)
    s = all_scales_spectrum(analyze_scales(scans, per_decade=10))
    lo, hi = s.band
    # the band runs from the largest measurement's first wavevector to the finest's last
    assert lo == pytest.approx(2 * np.pi / 10.24e-6, rel=0.26)
    assert hi == pytest.approx(np.pi / 2e-8, rel=0.26)
    e = 2 - 2 * hurst
    slope = math.sqrt(c0 / (2 * math.pi) * (hi**e - lo**e) / e)  # closed form over the band
    # every measurement is sampled, so its top octave holds aliased power, and the PSD is
    # kept up to the last DFT point below Nyquist (contact.engineering's rule, no cut-off
    # without a tip radius): over 10 realisations (benchmarks/all_scales_persson.py, H =
    # 0.5 and 0.8) the rms slope came out +3.9 % .. +7.7 % from the closed form, the area
    # -7.1 % .. -3.7 %; tolerance 9 %
    assert s.slope_rms == pytest.approx(slope, rel=0.09)
    p, e_star = np.array([0.05, 0.2]) * slope * 1e10, 1e10
    curve = persson_all_scales(s, p, e_star)
    np.testing.assert_allclose(curve.area_fraction,
                               erf(math.sqrt(2) * p / (e_star * slope)), rtol=0.09)


def test_profiles_alone_give_a_spectrum_too():
    z = _surface(512, 1e-8, 0.8, 1.6e-5, 2)
    scans = [Profile(z[7, :256].copy(), 1e-8), Profile(z[100, ::2].copy(), 2e-8)]
    s = all_scales_spectrum(analyze_scales(scans, per_decade=10))
    assert s.slope_rms > 0 and s.band[0] < s.band[1]
    bands = s.measurement_bands()
    assert min(b[0] for b in bands) == s.band[0] and max(b[1] for b in bands) == s.band[1]


# --- the CLI ------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("several")
    z = _surface(256, 1e-8, 0.8, 1.6e-5, 3)
    fine = surfmet.write(Topography(z[:64:2, :64:2].copy(), 2e-8, 2e-8), d / "fine.npz")
    coarse = surfmet.write(Topography(z[::8, ::8].copy(), 8e-8, 8e-8), d / "coarse.npz")
    line = surfmet.write(Profile(z[50, ::2].copy(), 2e-8), d / "line.npz")
    line2 = surfmet.write(Profile(z[120, :128].copy(), 1e-8), d / "line2.npz")
    rng = np.random.default_rng(0)
    far = surfmet.write(Profile(np.cumsum(rng.normal(size=300)) * 1e-9, 1e-3), d / "far.npz")
    return {k: str(v) for k, v in
            {"fine": fine, "coarse": coarse, "line": line, "line2": line2, "far": far}.items()}


def test_flat_contact_several_json(files, capsys):
    assert main(["flat-contact", files["line"], files["fine"], files["coarse"], "--e-star",
                 "10GPa", "--pressures", "1MPa,10MPa", "--json", "--quiet"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["files"] == [files["line"], files["fine"], files["coarse"]]
    assert rec["bem_scan"]["file"].endswith("fine.npz")  # the first height map named
    assert rec["bem_scan"]["results"][0]["persson"]["area_fraction"] > 0
    al = rec["all_scales"]
    band = al["psd"]["measured_band"]
    assert band["q"]["unit"] == "rad/m" and band["wavelength"]["unit"] == "m"
    lows = [m["psd_band"]["q"]["value"][0] for m in al["measurements"]]
    highs = [m["psd_band"]["q"]["value"][1] for m in al["measurements"]]
    assert band["q"]["value"] == [min(lows), max(highs)]
    assert len(al["measurements"][0]["contributes_psd"]) == len(al["psd"]["q_profile"]["value"])
    rows = al["persson"]
    assert [r["pressure"]["value"] for r in rows] == [1e6, 1e7]
    assert rows[0]["mean_gap"]["unit"] == "m" and rows[0]["stiffness"]["unit"] == "Pa/m"
    slope = al["slope_rms"]["value"]
    assert rows[0]["area_fraction"] == pytest.approx(erf(math.sqrt(2) * 1e6 / (1e10 * slope)),
                                                     rel=1e-12)


def test_flat_contact_several_profiles_leave_the_bem_out(files, tmp_path, capsys):
    out = tmp_path / "fc.png"
    assert main(["flat-contact", files["line"], files["line2"],
                 "--e-star", "10GPa", "--pressures", "1MPa", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["bem_scan"] is None
    assert any("no BEM" in n for n in rec["all_scales"]["notes"])
    assert main(["flat-contact", files["fine"], files["coarse"], "--e-star", "10GPa",
                 "--pressures", "1MPa", "--plot", str(out), "--quiet"]) == 0
    text = capsys.readouterr().out
    assert "BEM on" in text and "measured band" in text and "Persson, all scales" in text
    assert out.stat().st_size > 1000


def test_spectrum_several(files, tmp_path, capsys):
    out = tmp_path / "psd.png"
    assert main(["spectrum", files["fine"], files["coarse"], "--json", "--plot", str(out)]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["slope_rms"]["unit"] == "" and rec["h_rms"]["unit"] == "m"
    assert rec["psd"]["C_iso"]["unit"] == "m^4" and rec["psd"]["C_profile"]["unit"] == "m^3"
    assert [m["kind"] for m in rec["measurements"]] == ["map", "map"]
    assert out.stat().st_size > 1000
    assert main(["spectrum", files["fine"], files["coarse"]]) == 0
    assert "contributes over" in capsys.readouterr().out
    assert main(["spectrum", files["fine"], files["coarse"], "--json", "--materials",
                 "steel,aluminium", "--hardness", "1GPa"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["materials"] == ["steel", "aluminium"] and rec["hardness"]["value"] == 1e9
    sm = rec["summits"]
    assert sm["radius"]["unit"] == "m" and sm["density"]["unit"] == "1/m^2"
    # ψ = (E*/H) √(σ_s/R_s) (Greenwood & Williamson 1966) from the record's own numbers
    assert rec["plasticity_index"] == pytest.approx(
        rec["e_star"]["value"] / 1e9 * math.sqrt(sm["sigma_s"]["value"] / sm["radius"]["value"]),
        rel=1e-12)


@pytest.mark.parametrize("cmd", [["spectrum"], ["flat-contact", "--e-star", "1GPa",
                                                "--pressures", "1MPa"]])
def test_no_overlapping_band_is_one_line(cmd, files, capsys):
    assert main([cmd[0], files["fine"], files["far"], *cmd[1:]]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert err[-1].startswith("surfmet: error: no overlapping bandwidth")


def test_a_spectrum_with_no_points_is_refused():
    # a 4-pixel map has one DFT wavevector below Nyquist (the PSD's own sampling, not the
    # distance grid's, decides)
    a = analyze_scales([Topography(np.random.default_rng(1).normal(size=(4, 4)) * 1e-9,
                                   1e-8, 1e-8)], per_decade=1)
    with pytest.raises(SurfmetInputError, match="fewer than two points"):
        all_scales_spectrum(a)


@pytest.mark.realdata
def test_container_band_spans_its_three_measurements(realdata, capsys):
    assert main(["spectrum", str(realdata("container-2.zip")), "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    lo, hi = rec["psd"]["measured_band"]["wavelength"]["value"]
    sizes = [m["size"]["value"] for m in rec["measurements"]]
    pixels = [m["pixel"]["value"] for m in rec["measurements"]]
    assert len(sizes) == 3 and hi <= max(sizes) and lo >= min(pixels) * 0.99
    assert rec["slope_rms"]["value"] > 0
