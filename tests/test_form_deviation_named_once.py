"""One definition of a ball's form deviation, everywhere (issue 16, item 6).

``surfmet fit --shape sphere`` printed the PV of all residuals (37.96 µm on the bundled ball,
spikes included) next to the demo's 3.41 µm PV of the quadratic component, both called a
form deviation. Now the fit's record carries ``form_pv`` (the PV of the quadratic component
of the sphere residual, :attr:`surfmet.fitting.SphereFit.form_pv`), the text names it, and
the demo reports that same field instead of a second computation.

Independent truth: a cap with astigmatism ``c (x² - y²)`` (orthogonal to the sphere's own
``x² + y²`` over a square, so the sphere fit leaves it whole) has a form PV of ``2 c h²``
over the square of half width ``h``, whatever spikes are added.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

import surfmet
from surfmet._model import Topography
from surfmet.cli import main

R, N, DX, C = 10e-3, 101, 10e-6, 2.0
TRUTH = 2 * C * (50 * DX) ** 2  # 1 µm


@pytest.fixture(scope="module")
def cap(tmp_path_factory):
    rng = np.random.default_rng(8)
    j, i = np.mgrid[:N, :N]
    u, v = (i - 50) * DX, (j - 50) * DX
    z = np.sqrt(R**2 - u**2 - v**2) + C * (u**2 - v**2) + 5e-9 * rng.standard_normal(u.shape)
    z.ravel()[rng.choice(z.size, 20, replace=False)] += 20e-6  # spikes
    topo = Topography(z, DX, DX)
    return topo, str(surfmet.write(topo, tmp_path_factory.mktemp("cap") / "cap.npz"))


def test_fit_json_and_text_name_the_form_deviation(cap, capsys):
    _, path = cap
    assert main(["fit", path, "--shape", "sphere", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["form_pv"]["unit"] == "m"
    assert rec["form_pv"]["value"] == pytest.approx(TRUTH, rel=0.1)
    assert rec["pv_form_deviation"]["value"] > 15e-6  # all residuals: the spikes' PV
    assert main(["fit", path, "--shape", "sphere"]) == 0
    out = capsys.readouterr().out
    line = next(s for s in out.splitlines() if s.startswith("form deviation"))
    assert "quadratic component" in line


def test_demo_reports_the_same_form_deviation(cap, capsys):
    from surfmet.demo._surfaces import ball_form

    topo, path = cap
    rec, _ = ball_form(topo)
    assert main(["fit", path, "--shape", "sphere", "--json"]) == 0
    cli = json.loads(capsys.readouterr().out)
    assert rec["sphere"]["form_pv"]["value"] == pytest.approx(cli["form_pv"]["value"],
                                                               rel=1e-12)
    # no second "form" quantity with another value anywhere in the demo's ball record
    forms = [k for k in rec if "form" in k]
    assert forms == []
