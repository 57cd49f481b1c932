"""``hertz-check --work-of-adhesion``: Tabor's and Pastewka & Robbins' parameters.

Truths: the closed forms of Tabor (1977) and of Pastewka & Robbins (2014, PNAS 111:3298,
eq. 10 with kappa_rep = 2, d_rep = 4 h'_rms / h''_rms) evaluated by hand; the rms gradient
and half-Laplacian of a periodic surface computed directly from its Fourier derivatives,
against the ones the spectral moments give.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from contact_synth import rough_surface

import surfmet
from contact import composite_modulus, hertz_sphere, material
from contact.adhesion.stickiness import pastewka_robbins, rms_gradient_curvature
from contact.roughcontact import summit_parameters
from surfmet._model import Topography
from surfmet.cli import main
from surfmet.mechanics.hertz_adhesion import assess_adhesion
from surfmet.psd import areal_psd

E_STAR = composite_modulus(material("steel"), material("aluminium"))
R, LOAD = 5e-3, 1.0


def test_pastewka_robbins_by_hand():
    # l_a = w / E* = 5e-11 m, d_rep = 4 h'/h'' = 0.4 um: Pi = (0.1 * 1e-9 / 1e-10) * 10^(2/3)
    assert pastewka_robbins(0.1, 1e6, 1e9, 0.05, 1e-9) == pytest.approx(10 ** (2 / 3), rel=1e-12)
    # stronger adhesion makes a surface stickier: Pi falls as 1/w
    assert pastewka_robbins(0.1, 1e6, 1e9, 0.5, 1e-9) == pytest.approx(10 ** (2 / 3) / 10)


def test_gradient_and_curvature_from_the_moments():
    """h'_rms and h''_rms (half the Laplacian) from the moments of a periodic surface
    equal the ones its Fourier derivatives give directly."""
    n, dx = 128, 1e-6
    z = rough_surface(n, dx, 0.3e-6, seed=4, corr=8e-6)
    q = 2 * np.pi * np.fft.fftfreq(n, dx)
    qy, qx = np.meshgrid(q, q, indexing="ij")
    zf = np.fft.fft2(z - z.mean())
    gx, gy = np.fft.ifft2(1j * qx * zf).real, np.fft.ifft2(1j * qy * zf).real
    lap = np.fft.ifft2(-(qx ** 2 + qy ** 2) * zf).real
    _, m2, m4 = areal_psd(Topography(z, dx, dx), window=None).profile_moments()
    hp, hpp = rms_gradient_curvature(m2, m4)
    assert hp == pytest.approx(math.sqrt(np.mean(gx ** 2 + gy ** 2)), rel=0.02)
    assert hpp == pytest.approx(math.sqrt(np.mean((lap / 2) ** 2)), rel=0.05)


def test_assessment_tabor_and_verdicts():
    w, z0 = 0.1, 0.3e-9
    smooth = assess_adhesion(None, radius=R, load=LOAD, e_star=E_STAR, work=w, range_=z0)
    assert smooth.tabor_contact == pytest.approx(
        (R * w * w / (E_STAR ** 2 * z0 ** 3)) ** (1 / 3), rel=1e-12)
    assert smooth.dmt_pull_off == pytest.approx(2 * math.pi * w * R)
    assert smooth.pastewka_robbins is None and not smooth.changes_contact  # 0.31 % of 1 N
    assert assess_adhesion(None, radius=R, load=0.01, e_star=E_STAR, work=w).changes_contact
    # a gentle roughness (h'_rms 1e-3, summit radius ~1 mm) on a soft pair is sticky
    gentle = summit_parameters(1e-5, 5e-7, 1e-7)
    soft = assess_adhesion(gentle, radius=R, load=LOAD, e_star=1e6, work=w, range_=z0)
    hp, hpp = math.sqrt(1e-6), math.sqrt(2e-7 / 3)
    assert soft.pastewka_robbins == pytest.approx(
        hp * z0 * 1e6 / (2 * w) * (hp * hp / (hpp * z0)) ** (2 / 3), rel=1e-12)
    assert soft.sticky and soft.changes_contact
    assert soft.tabor_asperity == pytest.approx(
        (gentle.radius * w * w / (1e12 * z0 ** 3)) ** (1 / 3), rel=1e-12)
    stiff = assess_adhesion(gentle, radius=R, load=LOAD, e_star=E_STAR, work=w, range_=z0)
    assert stiff.sticky is False and not stiff.changes_contact


@pytest.fixture
def plate(tmp_path):
    hz = hertz_sphere(R, LOAD, E_STAR)
    rough = rough_surface(192, 2e-6, 0.5 * hz.delta, seed=2, corr=10e-6)
    return surfmet.write(Topography(rough, 2e-6, 2e-6), tmp_path / "rough.npz")


def _args(path, *extra):
    return ["hertz-check", str(path), "--radius", "5mm", "--load", "1N",
            "--materials", "steel,aluminium", "--grid", "64", *extra]


def test_cli_adhesion_section(plate, capsys):
    assert main(_args(plate, "--work-of-adhesion", "100mJ/m2", "--json")) == 0
    ad = json.loads(capsys.readouterr().out)["adhesion"]
    assert ad["work_of_adhesion"] == {"value": pytest.approx(0.1), "unit": "J/m^2"}
    assert ad["range"] == {"value": pytest.approx(0.3e-9), "unit": "m"}  # the default
    assert ad["tabor_parameter_contact"]["value"] == pytest.approx(
        (R * 0.01 / (E_STAR ** 2 * 0.027e-27)) ** (1 / 3), rel=1e-9)
    assert ad["tabor_parameter_contact"]["unit"] == ""
    assert ad["summit_radius"]["unit"] == "m" and ad["summit_radius"]["value"] > 0
    pr = ad["pastewka_robbins_parameter"]["value"]
    assert pr > 1 and ad["sticky"] is False and ad["adhesion_changes_contact"] is False
    assert ad["dmt_pull_off_force"] == {"value": pytest.approx(2 * math.pi * 0.1 * R),
                                        "unit": "N"}
    assert main(_args(plate, "--work-of-adhesion", "0.1J/m^2", "--range", "0.5nm")) == 0
    out = capsys.readouterr().out
    assert "adhesion: w = 0.1 J/m²" in out and "does not change the contact" in out
    assert "Pastewka-Robbins parameter" in out


def test_cli_without_work_leaves_the_section_out(plate, capsys):
    assert main(_args(plate, "--json")) == 0
    out, err = capsys.readouterr()
    assert "adhesion" not in json.loads(out) and "adhesion not assessed" in err


@pytest.mark.parametrize("extra", [["--range", "1nm"], ["--work-of-adhesion", "0J/m2"],
                                   ["--work-of-adhesion", "0.1J/m2", "--range", "0nm"]])
def test_cli_bad_adhesion_input(plate, capsys, extra):
    assert main(_args(plate, *extra)) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "Traceback" not in err[0]
