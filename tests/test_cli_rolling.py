"""``surfmet rolling``: the exponent of a smooth ball (4/3), the JSON record, the plastic
model, the figure, and clear refusals."""

from __future__ import annotations

import json

import numpy as np
import pytest
from contact_synth import rough_surface
from scipy import stats

import surfmet
from contact import composite_modulus, hertz_sphere, material
from surfmet._model import Topography
from surfmet.cli import main

E_STAR = composite_modulus(material("steel"), material("aluminium"))
BASE = ["rolling", "--radius", "20mm", "--materials", "steel,aluminium"]


def test_smooth_ball_json(capsys):
    assert main([*BASE, "--loads", "1N:100N:4", "--grid", "96", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert {"lambda_eff", "lambda_ci", "loads", "moments", "local_lambda", "model"} <= set(rec)
    assert rec["model"] == "hysteresis"
    assert rec["lambda_eff"] == {"value": pytest.approx(4 / 3, abs=0.01), "unit": ""}
    assert rec["loads"]["unit"] == "N" and rec["moments"]["unit"] == "N m"
    loads = np.array(rec["loads"]["value"])
    # the exponent and its interval are the least-squares fit of ln M on ln N with a
    # Student-t interval: checked against scipy's own regression (was lo < λ < hi, which
    # holds for any symmetric interval)
    fit = stats.linregress(np.log(loads), np.log(rec["moments"]["value"]))
    t = stats.t.ppf(0.975, len(loads) - 2)
    assert rec["lambda_eff"]["value"] == pytest.approx(fit.slope, rel=1e-12)
    assert rec["lambda_ci"]["value"] == pytest.approx(
        [fit.slope - t * fit.stderr, fit.slope + t * fit.stderr], rel=1e-9)
    assert np.allclose(loads, np.geomspace(1, 100, 4))
    a = np.array([hertz_sphere(0.02, w, E_STAR).a for w in loads])
    # alpha_h = 1: M_r = (3/16) N a (Johnson eq. 9.19)
    assert np.allclose(rec["moments"]["value"], 3 / 16 * loads * a, rtol=5e-3)
    assert len(rec["local_lambda"]["value"]) == 4
    assert rec["settings"]["kinematics"] == "rolling"


def test_alpha_h_and_lossy_body_scale_the_moment(capsys):
    assert main([*BASE, "--loads", "1N:10N:3", "--grid", "64", "--json"]) == 0
    full = json.loads(capsys.readouterr().out)
    assert main([*BASE, "--loads", "1N:10N:3", "--grid", "64", "--json", "--alpha-h", "0.1",
                 "--lossy", "plate"]) == 0
    part = json.loads(capsys.readouterr().out)
    share = part["settings"]["displacement_share"]["value"]
    al, st = material("aluminium"), material("steel")
    c_al, c_st = (1 - al.nu**2) / al.E, (1 - st.nu**2) / st.E
    assert share == pytest.approx(c_al / (c_al + c_st), rel=1e-12)
    ratio = np.array(part["moments"]["value"]) / np.array(full["moments"]["value"])
    assert np.allclose(ratio, 0.1 * share, rtol=1e-9)
    assert part["lambda_eff"]["value"] == pytest.approx(full["lambda_eff"]["value"], abs=1e-9)


def test_rough_plate_plastic_model_and_figure(tmp_path, capsys):
    hz = hertz_sphere(5e-3, 1.0, E_STAR)
    z = rough_surface(256, 2e-6, 1.0 * hz.delta, seed=4, corr=10e-6)
    plate = surfmet.write(Topography(z, 2e-6, 2e-6), tmp_path / "plate.npz")
    png = tmp_path / "lam.png"
    argv = ["rolling", "--plate", str(plate), "--radius", "5mm", "--materials",
            "steel,aluminium", "--loads", "0.5N:2N:3", "--model", "plastic", "--grid", "96",
            "--plot", str(png)]
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "model          plastic (first pass, hardness 1.049 GPa)" in out
    assert "lambda_eff" in out and "local λ" in out
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    lam = float(out.split("lambda_eff")[1].split()[0])
    assert 0.5 < lam < 3.0


@pytest.mark.parametrize("extra, needle", [
    (["--loads", "1N:10N:2"], "at least 3"),
    (["--loads", "10N:1N"], "0 < START < END"),
    (["--loads", "1N:10N:3", "--hardness", "1GPa"], "--model plastic"),
    (["--loads", "1N:10N:3", "--alpha-h", "0"], "--alpha-h"),
    (["--loads", "1N:10N:3", "--plate", "absent.x3p"], "absent.x3p"),
    (["--loads", "1N:10N:3", "--model", "plastic", "--materials", "steel:H=1GPa,pmma:nu=0.6"],
     "Poisson"),
])
def test_user_errors_exit_1(capsys, extra, needle):
    argv = [*BASE, *extra]
    if "--materials" in extra:
        argv = ["rolling", "--radius", "20mm", *extra]
    assert main(argv) == 1
    out, err = capsys.readouterr()
    assert needle in err and "Traceback" not in err and out == ""
