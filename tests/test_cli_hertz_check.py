"""``surfmet hertz-check``: verdict and reasons on the terminal, the issue's JSON, the figure,
and clear refusals."""

from __future__ import annotations

import json

import numpy as np
import pytest
from contact_synth import rough_surface

import surfmet
from contact import DomainSpec, composite_modulus, hertz_sphere, material
from surfmet._model import Profile, Topography
from surfmet.cli import main

E_STAR = composite_modulus(material("steel"), material("aluminium"))
R, W = 5e-3, 1.0


@pytest.fixture
def plates(tmp_path):
    hz = hertz_sphere(R, W, E_STAR)
    smooth = rough_surface(192, 2e-6, 0.01 * hz.delta, seed=1, corr=10e-6)
    rough = rough_surface(256, 2e-6, 1.5 * hz.delta, seed=2, corr=10e-6)
    spikes = np.random.default_rng(3).choice(rough.size, 30, replace=False)
    rough.flat[spikes] += 40e-6  # single-pixel optical spikes on top of the roughness
    return {"smooth": surfmet.write(Topography(smooth, 2e-6, 2e-6), tmp_path / "smooth.npz"),
            "rough": surfmet.write(Topography(rough, 2e-6, 2e-6), tmp_path / "rough.x3p"),
            "profile": surfmet.write(Profile(smooth[0], 2e-6), tmp_path / "p.npz"),
            "tmp": tmp_path}


def _args(path, *extra):
    return ["hertz-check", str(path), "--radius", "5mm", "--load", "1N",
            "--materials", "steel,aluminium", "--grid", "96", *extra]


def test_verdicts_and_json(plates, capsys):
    assert main(_args(plates["smooth"], "--json")) == 0
    out, err = capsys.readouterr()
    rec = json.loads(out)
    assert rec["hertz_holds"] is True and rec["alpha"]["value"] < 0.05
    assert set(rec) == {"hertz_holds", "judged", "alpha", "sigma", "hertz", "bem", "reasons",
                        "radial_profile", "models", "verdict", "summits", "grid",
                        "scan_preparation", "warnings", "solve", "inputs"}
    assert rec["verdict"]["model"] == "hertz"
    # issue 26: the solve record (elastic then elastic-plastic solve, combined)
    assert rec["solve"]["converged"] is True and rec["solve"]["edge_contact"] is False
    assert rec["solve"]["iterations"] >= 1 and rec["solve"]["residual"]["unit"] == ""
    assert set(rec["models"]) == {"hertz", "bem", "greenwood_tripp", "greenwood_tripp_plastic"}
    assert "resolution" in rec["summits"]["note"]
    assert rec["grid"]["nx"] == 96 and rec["grid"]["pixel_source"] == "--grid 96"
    hz = hertz_sphere(R, W, E_STAR)
    assert rec["hertz"]["a"] == {"value": pytest.approx(hz.a, rel=1e-12), "unit": "m"}
    assert rec["bem"]["effective_radius"]["value"] == pytest.approx(hz.a, rel=0.05)
    assert not err.strip().startswith("{")

    assert main(_args(plates["rough"], "--json")) == 0
    out, err = capsys.readouterr()
    rec = json.loads(out)
    assert rec["hertz_holds"] is False and rec["alpha"]["value"] == pytest.approx(1.5, rel=0.1)
    assert rec["bem"]["plastic_fraction"]["value"] > 0
    models = rec["models"]
    for m in models.values():
        prof = m["radial_profile"]
        assert prof["r"]["unit"] == "m" and prof["p"]["unit"] == "Pa"
        assert len(prof["r"]["value"]) == len(prof["p"]["value"]) > 5
        assert m["effective_radius"]["unit"] == "m" and m["approach"]["unit"] == "m"
    # the errors are the Hertz comparison's own numbers for Hertz, 0 for the reference
    hz = hertz_sphere(R, W, E_STAR)
    a_bem = rec["bem"]["effective_radius"]["value"]
    assert models["hertz"]["radius_error"]["value"] == pytest.approx(hz.a / a_bem - 1, rel=1e-9)
    assert models["bem"]["profile_error"]["value"] == 0
    # α = 1.5: Hertz fails, and Greenwood-Tripp (the spectrum's summits) does better
    assert rec["verdict"]["model"] != "hertz"
    gt = models["greenwood_tripp"]
    assert abs(gt["radius_error"]["value"]) < abs(models["hertz"]["radius_error"]["value"])
    assert gt["profile_error"]["value"] < models["hertz"]["profile_error"]["value"]
    assert any(r.startswith(rec["verdict"]["model"]) or r.startswith("no model")
               for r in rec["verdict"]["reasons"])
    assert "spike(s) removed from the plate scan" in err  # spikes are not asperities


def test_human_output_and_figure(plates, capsys):
    png = plates["tmp"] / "hc.png"
    assert main(_args(plates["rough"], "--plot", str(png))) == 0
    out, err = capsys.readouterr()
    assert out.startswith("Hertz does not hold (α = ")
    assert "α = σR/a0²" in out and "peak pressure" in out and "yielded / πa0²" in out
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and "figure written" in err
    assert main(_args(plates["smooth"], "--elastic")) == 0
    out, _ = capsys.readouterr()
    assert out.startswith("Hertz holds") and "hardness" not in out


@pytest.mark.parametrize("argv, needle", [
    (["hertz-check", "{smooth}", "--radius", "5mm", "--load=-1N", "--materials",
      "steel,aluminium"], "positive"),
    (["hertz-check", "{smooth}", "--radius", "5mm", "--load", "1N", "--materials",
      "steel"], "BALL,PLATE"),
    (["hertz-check", "{smooth}", "--radius", "5mm", "--load", "1N", "--materials",
      "steel,aluminium", "--grid", "4"], "--grid"),
    (["hertz-check", "{profile}", "--radius", "5mm", "--load", "1N", "--materials",
      "steel,aluminium"], "areal"),
    (["hertz-check", "{smooth}", "--radius", "20mm", "--load", "100N", "--materials",
      "steel,aluminium"], "larger scan"),
    (["hertz-check", "{tmp}/absent.x3p", "--radius", "5mm", "--load", "1N", "--materials",
      "steel,aluminium"], "absent.x3p"),
])
def test_user_errors_exit_1(plates, capsys, argv, needle):
    argv = [a.format(**{k: str(v) for k, v in plates.items()}) for a in argv]
    assert main(argv) == 1
    out, err = capsys.readouterr()
    assert needle in err and "Traceback" not in err and out == ""


def test_smooth_scan_is_checked_without_scan_noise(tmp_path, capsys):
    # a perfectly flat plate gives alpha = 0 and Hertz to a fraction of a percent
    flat = surfmet.write(Topography(np.zeros((128, 128)), 2e-6, 2e-6), tmp_path / "f.npz")
    assert main(_args(flat, "--json")) == 0
    rec = json.loads(capsys.readouterr().out)
    hz = hertz_sphere(R, W, E_STAR)
    assert rec["alpha"]["value"] == 0 and rec["hertz_holds"] is True
    assert rec["bem"]["pmax"]["value"] == pytest.approx(hz.p0, rel=5e-3)
    assert rec["bem"]["approach"]["value"] == pytest.approx(hz.delta, rel=5e-3)


def test_a_scan_coarser_than_the_contact_gets_no_verdict(realdata, capsys):
    """Issue 25 item 1: frt-2's 200 µm pixel against a 137 µm Hertz radius. The boundary
    elements agree with Hertz only because they see the interpolation between scan points:
    the verdict, ``hertz_holds``, the model hierarchy and the warnings must all say so."""
    path = realdata("frt-2.frt")
    assert main(["hertz-check", str(path), "--radius", "20mm", "--load", "10N",
                 "--materials", "steel,aluminium", "--grid", "64", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    a0 = rec["hertz"]["a"]["value"]
    assert a0 < 200e-6  # the premise: the file's pixel is coarser than the contact radius
    assert rec["hertz_holds"] is False and rec["judged"] is False
    assert any("does not resolve the contact" in w for w in rec["warnings"])
    assert "does not resolve the contact" in rec["reasons"][0]
    head = rec["verdict"]["reasons"][0]
    assert "do not resolve the contact" in head
    assert "no model of the hierarchy is within tolerance" not in head
    # the text output leads with the same verdict
    main(["hertz-check", str(path), "--radius", "20mm", "--load", "10N",
          "--materials", "steel,aluminium", "--grid", "64"])
    out = capsys.readouterr().out
    assert out.startswith("Hertz cannot be judged")


def test_hierarchy_head_never_denies_a_model_within_tolerance():
    """Issue 25 item 1: when Hertz matches the boundary elements on a* and profile but
    fails another criterion (here α), the named model's reason says which, instead of
    "no model of the hierarchy is within tolerance"."""
    from contact._hertzcheck import compare_with_hertz
    from contact.roughcontact._hierarchy import model_hierarchy
    from contact.setups._ball_on_plate import SphereContact

    e_star = composite_modulus(material("steel"), material("aluminium"))
    res = SphereContact(0.02, e_star, 10.0, domain=DomainSpec(grid=64)).solve(10.0)
    # a smooth solve with a large σ: every measured criterion passes, α alone fails
    comp = compare_with_hertz(res, radius=0.02, sigma=5e-6, scan_pixel=1e-6)
    assert comp.judged and not comp.hertz_holds
    h = model_hierarchy(comp, res, {})
    assert h.models["hertz"].within_tolerance
    assert "no model of the hierarchy is within tolerance" not in h.reasons[0]
    assert "hertz is within tolerance" in h.reasons[0] and "alpha" in h.reasons[0]


def test_report_and_demo_say_an_unresolved_scan_has_no_verdict():
    """Issue 25 item 1: every entry point gives the same answer: the report and the demo's
    story do not print "does not hold" for a scan that cannot be judged."""
    from surfmet._report_hertz import hertz_html

    html = hertz_html({"hertz_holds": False, "judged": False, "alpha": None}, None, None)
    assert "no verdict: the scan's pixel does not resolve the contact" in html
    assert "does not hold" not in html
    html = hertz_html({"hertz_holds": False, "judged": True, "alpha": None}, None, None)
    assert "Hertz does not hold" in html
