"""Resolution study (contact/_resolution.py, surfmet/mechanics/resolution_study.py,
--resolution-study)."""

from __future__ import annotations

import json
import math
from importlib import resources

import numpy as np
import pytest

from contact import hertz_sphere
from contact._convergence import trend
from contact._errors import ContactInputError
from contact._fields import PERIMETER_COEFFICIENT, block_average, corrected_area
from contact._resolution import CRITERION_QUANTITY, sphere_study
from contact._roughstats import rms_slope
from surfmet.cli import main

E_STAR, RADIUS, LOAD = 70e9, 0.01, 2.0


def self_affine(n: int, dx: float, rms: float, hurst: float, rng: np.random.Generator
                ) -> np.ndarray:
    """Gaussian self-affine surface: PSD ~ q^-2(1+H) from 4 wavelengths per side up to
    the Nyquist frequency (no small-scale cut-off, so the slopes keep growing)."""
    q = np.hypot(np.fft.fftfreq(n, dx)[None, :], np.fft.fftfreq(n, dx)[:, None])
    psd = np.where(q > 0, np.maximum(q, 4 / (n * dx)) ** (-2 * (1 + hurst)), 0.0)
    z = np.fft.ifft2(np.fft.fft2(rng.standard_normal((n, n))) * np.sqrt(psd)).real
    return (z - z.mean()) / z.std() * rms


def test_block_average_keeps_the_mean_and_lowers_the_slope():
    rng = np.random.default_rng(7)
    offset = rng.uniform(-5e-6, 5e-6)  # hidden mean
    z = self_affine(128, 1e-6, 0.2e-6, rng.uniform(0.5, 0.9), rng) + offset
    for k in (2, 4, 8):
        zc = block_average(z, k)
        assert zc.shape == (128 // k, 128 // k)
        assert zc.mean() == pytest.approx(z.mean(), abs=1e-15)
        assert rms_slope(zc, k * 1e-6) < 0.8 * rms_slope(z, 1e-6)
        assert zc.std() <= z.std()  # why a failed alpha survives refinement
    # one block by hand: the mean of its four pixels
    a = np.arange(16.0).reshape(4, 4)
    assert block_average(a, 2)[0, 1] == pytest.approx((2 + 3 + 6 + 7) / 4)
    with pytest.raises(ContactInputError):
        block_average(a, 0)


def test_corrected_area_of_a_rectangle():
    mask = np.zeros((20, 30), dtype=bool)
    mask[4:9, 3:15] = True  # 5 x 12 cells: 2 (5 + 12) = 34 switches
    assert PERIMETER_COEFFICIENT == pytest.approx(0.118114, abs=1e-6)
    assert corrected_area(mask, 2.0) == pytest.approx((60 - PERIMETER_COEFFICIENT * 34) * 4)


def test_trend_orders_and_exponents():
    h = np.array([8.0, 4.0, 2.0, 1.0]) * 1e-6
    conv = trend("a_star", h, 1.0 + 1e6**2 * 0.001 * h**2)  # second order in the pixel
    assert conv.converged and conv.order == pytest.approx(2.0, rel=1e-9)
    assert conv.extrapolated == pytest.approx(1.0, rel=1e-12)
    moving = trend("pmax", h, (h / 1e-6) ** -0.5)
    assert not moving.converged and moving.exponent == pytest.approx(-0.5)
    assert trend("yielded_fraction", h, [0.0, 0.0, 0.0, 0.0]).converged
    assert not trend("yielded_fraction", h, [0.0, 0.0, 0.0, 0.01]).converged


def test_smooth_sphere_converges_to_hertz():
    study = sphere_study(RADIUS, LOAD, E_STAR, np.zeros((400, 400)), 1e-6)
    hz = hertz_sphere(RADIUS, LOAD, E_STAR)
    assert set(study.moving) == set()
    fine = study.finest.values
    assert fine["a_star"] == pytest.approx(hz.a, rel=0.01)
    assert fine["approach"] == pytest.approx(hz.delta, rel=0.01)
    assert fine["pmax"] == pytest.approx(hz.p0, rel=0.01)
    assert fine["area"] == pytest.approx(math.pi * hz.a**2, rel=0.02)
    assert study.pixels == pytest.approx([8e-6, 4e-6, 2e-6, 1e-6])
    holds, _, left = study.verdict()
    assert holds is True and not left


def test_self_affine_plate_area_keeps_moving_while_a_star_converges():
    # hidden Hurst exponent and rms; the rms is small against the Hertz approach (0.36 µm)
    # so that the highest summits, which rise slowly as finer pixels sample more extremes,
    # move the approach by less than the 2 % criterion
    rng = np.random.default_rng(20261125)
    hurst = rng.uniform(0.6, 0.85)
    z = self_affine(400, 1e-6, rng.uniform(0.024, 0.036) * 1e-6, hurst, rng)
    study = sphere_study(RADIUS, LOAD, E_STAR, z, 1e-6)
    t = study.trends
    assert t["a_star"].converged and t["approach"].converged
    assert not t["area"].converged and not t["pmax_elastic"].converged
    # the area shrinks and the elastic peak grows as the pixel shrinks (A ~ 1 / h'_rms)
    assert t["area"].exponent > 0 and t["pmax_elastic"].exponent < 0
    assert t["rms_slope"].exponent < 0
    holds, reasons, left = study.verdict()
    comp = study.finest.comparison
    used = [c for c in comp.criteria if c.reason in reasons]
    assert used and all(CRITERION_QUANTITY[c.name] is None
                        or t[CRITERION_QUANTITY[c.name]].converged for c in used)
    assert any(x.startswith("area") for x in left) and any(x.startswith("peak") for x in left)
    # alpha rests on sigma, which converges; it fails for this rough surface
    assert comp.criterion("alpha").reason in reasons and holds is False


def _data(name: str) -> str:
    return str(resources.files("surfmet").joinpath("data", name))


def test_cli_hertz_check_study_json(capsys):
    rc = main(["hertz-check", _data("paper_plate.x3p"), "--ball", _data("paper_ball.x3p"),
               "--radius", "20mm", "--load", "10N", "--materials", "steel,aluminium",
               "--resolution-study", "--json"])
    assert rc == 0
    out = json.loads(capsys.readouterr().out)["resolution_study"]
    assert [lv["factor"] for lv in out["levels"]] == [8, 4, 2, 1]
    assert out["levels"][-1]["pixel"] == {"value": pytest.approx(5e-6), "unit": "m"}
    assert out["levels"][0]["a_star"]["unit"] == "m"
    assert out["levels"][0]["area"]["unit"] == "m^2"
    assert set(out["converged"]) | set(out["keeps_moving"]) == set(out["trends"])
    assert out["verdict"]["decided"] == (out["verdict"]["hertz_holds"] is not None)
    for item in out["verdict"]["not_used"]:
        assert item.split(" (")[1].split(" ")[0] in out["keeps_moving"]
    # sigma keeps moving on this plate, but alpha fails at every pixel and can only grow
    assert "sigma" in out["keeps_moving"] and out["verdict"]["hertz_holds"] is False
    assert any(r.startswith("α") and "survives refinement" in r
               for r in out["verdict"]["reasons"])


def test_cli_contact_study_text_and_errors(capsys):
    rc = main(["contact", "--plate", _data("paper_plate.x3p"), "--radius", "20mm",
               "--load", "5N", "--materials", "steel,aluminium", "--resolution-study"])
    assert rc == 0
    text = capsys.readouterr().out
    assert "resolution study" in text and "corrected area" in text and "converged" in text
    rc = main(["contact", "--radius", "20mm", "--load", "5N", "--materials",
               "steel,aluminium", "--resolution-study"])
    assert rc == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "scan" in err[0]
    rc = main(["contact", "--plate", _data("paper_plate.x3p"), "--radius", "20mm",
               "--load", "5N", "--materials", "steel,aluminium", "--resolution-study",
               "--grid", "64"])
    assert rc == 1 and "--grid" in capsys.readouterr().err


def test_cli_rolling_study_json(capsys):
    rc = main(["rolling", "--plate", _data("paper_plate.x3p"), "--radius", "20mm",
               "--materials", "steel,aluminium", "--loads", "2N:20N:5", "--resolution-study",
               "--json"])
    assert rc == 0
    out = json.loads(capsys.readouterr().out)["resolution_study"]
    lam = [lv["lambda_eff"] for lv in out["levels"]]
    assert len(lam) == 4 and all(0.5 < v < 3 for v in lam)
    assert "lambda_eff" in out["trends"] and "verdict" not in out


def test_smooth_rolling_study_gives_four_thirds():
    from contact._resolution import rolling_study

    study = rolling_study(RADIUS, E_STAR, [1.0, 2.0, 4.0], np.zeros((300, 300)), 1e-6)
    lam = study.trends["lambda_eff"]
    assert lam.converged
    assert all(v == pytest.approx(4 / 3, rel=0.02) for v in lam.values)
    with pytest.raises(ContactInputError):
        rolling_study(RADIUS, E_STAR, [1.0, 2.0], np.zeros((300, 300)), 1e-6)


def test_a_scan_too_small_for_the_study_is_refused():
    with pytest.raises(ContactInputError, match="too small for a resolution study"):
        sphere_study(RADIUS, LOAD, E_STAR, np.zeros((60, 60)), 1e-6)
    with pytest.raises(ContactInputError, match="decrease to 1"):
        sphere_study(RADIUS, LOAD, E_STAR, np.zeros((400, 400)), 1e-6, factors=(2, 4, 1))
