"""The capillary law (contact/adhesion/laws/_capillary.py): a meniscus of Laplace pressure
gamma / r_K where the gap is below h_c = 2 r_K cos(theta), added as a plug-in in three
files (the law, this test, its section of docs/adhesion.md).

Truths: w = 2 gamma cos(theta) and the rigid sphere's pull-off 4 pi R gamma cos(theta)
(Israelachvili, Intermolecular and Surface Forces, 3rd ed., section 17.9; Orowan); between
rigid and soft, Maugis-Dugdale with w = 2 gamma cos(theta), sigma0 = gamma / r_K
(tests/maugis_reference.py, solved independently of the package).
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest
from maugis_reference import md_pull_off

from contact._errors import ContactInputError
from contact._geometry import DomainSpec
from contact.adhesion import adhesive_ball
from contact.adhesion.ball import default_size
from contact.adhesion.laws import law_class
from surfmet.cli import main
from surfmet.mechanics.adhesion import adhesion

ROOT = Path(__file__).resolve().parents[1]
R = 1e-5
GAMMA, THETA, R_K = 0.072, math.radians(30.0), 1e-9  # water on a 30 degree surface
CapillaryLaw = law_class("capillary")


def _e_star(lam: float, law) -> float:
    """E* of Maugis' lambda ``lam`` for the sphere R: lambda = 2 sigma0 (R / (pi w K^2))^(1/3)."""
    k = math.sqrt(8.0 * law.peak ** 3 * R / (math.pi * law.work)) / lam ** 1.5
    return 0.75 * k


def test_work_range_and_pressure_are_the_meniscus():
    """w = 2 gamma cos(theta), h_c = 2 r_K cos(theta), dp = gamma / r_K; the traction
    integrates to w over the gap and the potential is -w at contact."""
    law = CapillaryLaw(GAMMA, THETA, R_K)
    assert law.work == pytest.approx(2 * GAMMA * math.cos(THETA), rel=1e-14)
    assert law.range == pytest.approx(2 * R_K * math.cos(THETA), rel=1e-14)
    assert law.peak == pytest.approx(GAMMA / R_K, rel=1e-14)
    g = np.linspace(0.0, 2.0 * law.range, 400001)
    t = law.traction(g)
    assert np.sum(0.5 * (t[1:] + t[:-1]) * np.diff(g)) == pytest.approx(law.work, rel=1e-4)
    assert float(law.potential(0.0)) == pytest.approx(-law.work, rel=1e-14)
    assert float(law.traction(1.01 * law.range)) == 0.0


def test_rigid_sphere_pull_off_is_four_pi_r_gamma_cos_theta():
    """DMT limit (Maugis lambda 0.02) through contact.adhesion.adhesive_ball on 64^2: the
    pull-off is 4 pi R gamma cos(theta) to 2 % (measured -1.3 %: the meniscus' disc of
    radius sqrt(2 R h_c) counted in pixels, 16 across its radius; Maugis-Dugdale itself is
    -0.2 % below DMT at this lambda)."""
    law = CapillaryLaw(GAMMA, THETA, R_K)
    e = _e_star(0.02, law)
    size = default_size(R, e, law)
    res = adhesive_ball(R, e, law.on_grid(size / 64, e), domain=DomainSpec(grid=64, size=size),
                        steps=8)
    assert res.maugis_parameter == pytest.approx(0.02, rel=1e-9)
    dmt = 4.0 * math.pi * R * GAMMA * math.cos(THETA)
    assert res.cycle.pull_off_force == pytest.approx(dmt, rel=0.02)
    assert res.dmt_pull_off == pytest.approx(dmt, rel=1e-14)


def test_soft_sphere_is_maugis_dugdale_with_w_two_gamma_cos_theta():
    """Maugis lambda 1 through the facade surfmet.mechanics.adhesion.adhesion (the law
    given as an object, its step smoothed on the grid): the pull-off is Maugis-Dugdale's
    with w = 2 gamma cos(theta) and sigma0 = gamma / r_K to 3 % on 48^2 (measured +1.7 %,
    a cohesive zone of 5 pixels)."""
    law = CapillaryLaw(GAMMA, THETA, R_K)
    e = _e_star(1.0, law)
    run = adhesion(R, e_star=e, interaction=law, grid=48, steps=16)
    assert run.result.law.smoothing > 0.0  # smoothed on the grid, as the Dugdale law is
    assert run.result.maugis_parameter == pytest.approx(1.0, rel=1e-9)
    md = md_pull_off(1.0) * math.pi * (2 * GAMMA * math.cos(THETA)) * R
    assert run.result.cycle.pull_off_force == pytest.approx(md, rel=0.03)


def test_the_command_takes_the_law_and_its_parameters(capsys):
    """``surfmet adhesion --interaction capillary`` with the law's own options, with no
    line of the command written for it: the record names the law and states w, h_c, dp
    and the DMT pull-off 4 pi R gamma cos(theta)."""
    assert main(["adhesion", "--radius", "10um", "--e-star", "1GPa", "--interaction",
                 "capillary", "--surface-tension", "72mN/m", "--contact-angle", "30deg",
                 "--kelvin-radius", "1nm", "--grid", "16", "--steps", "4", "--json",
                 "--quiet"]) == 0
    rec = json.loads(capsys.readouterr().out)
    cos = math.cos(THETA)
    assert rec["interaction"] == "capillary"
    assert rec["work_of_adhesion"]["value"] == pytest.approx(2 * GAMMA * cos, rel=1e-12)
    assert rec["range"]["value"] == pytest.approx(2 * R_K * cos, rel=1e-12)
    assert rec["peak_tension"] == {"value": pytest.approx(GAMMA / R_K, rel=1e-12),
                                   "unit": "Pa"}
    assert rec["dmt_pull_off_force"]["value"] == pytest.approx(4 * math.pi * R * GAMMA * cos,
                                                               rel=1e-12)


@pytest.mark.parametrize("extra, words", [
    (["--surface-tension", "72mN/m", "--contact-angle", "30deg", "--kelvin-radius", "1nm",
      "--range", "2nm"], "the capillary law does not take --range"),
    (["--surface-tension", "72mN/m", "--kelvin-radius", "1nm"],
     "the capillary law needs --contact-angle"),
    (["--surface-tension", "72mN/m", "--contact-angle", "95deg", "--kelvin-radius", "1nm"],
     "contact angle must be at least 0 and below 90 degrees"),
])
def test_bad_capillary_input_is_one_line(capsys, extra, words):
    assert main(["adhesion", "--radius", "10um", "--e-star", "1GPa", "--interaction",
                 "capillary", *extra, "--quiet"]) == 1
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err and "Traceback" not in err


def test_a_contact_angle_of_ninety_degrees_or_more_is_refused():
    with pytest.raises(ContactInputError, match="below 90 degrees"):
        CapillaryLaw(GAMMA, 0.5 * math.pi, R_K)


def test_the_capillary_law_is_in_three_files():
    """Adding a law touches the law's file, its test and its doc: the files of contact/,
    surfmet/, tests/ and docs/ that name the capillary law are these three."""
    word = re.compile(r"\bcapillary\b", re.IGNORECASE)
    files = sorted(
        str(p.relative_to(ROOT)) for top in ("contact", "surfmet", "tests", "docs")
        for p in (ROOT / top).rglob("*")
        if p.is_file() and p.suffix in {".py", ".md", ".rst", ".json", ".txt", ".toml"}
        # the project's own files, not what a build writes from them (docs/_build, the
        # generated API pages)
        and not {"__pycache__", "_build", "generated"} & set(p.parts)
        and word.search(p.read_text(encoding="utf-8")))
    assert files == ["contact/adhesion/laws/_capillary.py", "docs/adhesion.md",
                     "tests/test_capillary_law.py"]


def test_the_text_echoes_the_contact_angle_in_degrees(capsys):
    """The inputs' text states the contact angle in degrees, as given (30deg), not
    0.523599 rad; the JSON keeps SI with its unit (on main the text read 0.523599 rad)."""
    argv = ["adhesion", "--radius", "10um", "--e-star", "1GPa", "--interaction",
            "capillary", "--surface-tension", "72mN/m", "--contact-angle", "30deg",
            "--kelvin-radius", "1nm", "--grid", "16", "--steps", "4", "--quiet"]
    assert main(argv) == 0
    line = [s for s in capsys.readouterr().out.splitlines() if "contact angle" in s]
    assert len(line) == 1 and line[0].split()[-1] == "30°" and "rad" not in line[0]
    assert main([*argv, "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["inputs"]["contact_angle"] == {"value": pytest.approx(THETA, rel=1e-12),
                                              "unit": "rad"}
