"""``surfmet adhesion --plate/--ball``: the scans' roughness on the adhesive sphere.

Truths used: geometry, not the package's numbers. A tilted flat plate is levelled to
nothing, so the cycle is the smooth sphere's; a plate domed with radius R under a sphere
of radius R closes the gap like a sphere of radius R / 2 (curvatures add), so the cycle is
that sphere's; the scans are read and checked before any solve.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

import surfmet
from contact.adhesion.ball import default_size
from contact.adhesion.laws import DugdaleLaw
from surfmet._model import Topography
from surfmet.cli import main
from surfmet.mechanics.adhesion import adhesion
from surfmet.records._adhesion import adhesion_record

R, E_STAR, W, H0 = 10e-6, 1e9, 0.05, 10e-9
KW = {"work": W, "range_": H0, "e_star": E_STAR, "grid": 32, "steps": 6}
SIZE = default_size(R, E_STAR, DugdaleLaw.from_range(W, H0))


def _scan(fn, n=96, dx=None, dy=None):
    dx = SIZE / 48 if dx is None else dx
    dy = dx if dy is None else dy
    x = (np.arange(n) - 0.5 * (n - 1)) * dx
    y = (np.arange(n) - 0.5 * (n - 1)) * dy
    return Topography(fn(x[None, :], y[:, None]), dx, dy)


@pytest.fixture(scope="module")
def smooth():
    return adhesion(R, **KW).result


def test_tilted_flat_plate_is_levelled_away(smooth):
    run = adhesion(R, plate=_scan(lambda x, y: 2e-3 * x - 1e-3 * y + 5e-9), **KW)
    assert run.result.roughness_rms < 1e-15
    assert run.result.cycle.pull_off_force == pytest.approx(smooth.cycle.pull_off_force,
                                                            rel=1e-9)
    rec = adhesion_record(run)
    assert rec["scans"]["plate"] == "(in memory)" and rec["scans"]["ball"] is None
    assert "levelled" in " ".join(rec["scans"]["preparation"]["notes"])


def test_domed_plate_is_a_sphere_of_half_the_radius(smooth):
    """Curvatures add: 1/R + 1/R = 1/(R/2). Same grid and cell; the approach steps differ
    (the rough run goes 3 z_rms deeper) but the pull-off is refined: measured -0.04 %."""
    dome = adhesion(R, plate=_scan(lambda x, y: -(x * x + y * y) / (2 * R)), size=SIZE,
                    **KW).result
    half = adhesion(R / 2, size=SIZE, **KW).result
    assert dome.roughness_rms > H0  # the dome is far from negligible
    assert dome.cycle.pull_off_force == pytest.approx(half.cycle.pull_off_force, rel=5e-3)
    assert smooth.size == SIZE
    assert dome.cycle.pull_off_force < 0.8 * smooth.cycle.pull_off_force


def _cli(capsys, *extra):
    rc = main(["adhesion", "--radius", "10um", "--e-star", "1GPa", "--work-of-adhesion",
               "50mJ/m2", "--range", "10nm", "--grid", "32", "--steps", "6", "--quiet",
               *extra])
    return rc, capsys.readouterr()


def test_cli_records_the_scan(capsys, tmp_path):
    path = surfmet.write(_scan(lambda x, y: 1e-3 * x + 0 * y), tmp_path / "plate.npz")
    rc, out = _cli(capsys, "--plate", str(path), "--json")
    assert rc == 0
    rec = json.loads(out.out)
    assert rec["scans"]["plate"] == str(path)
    assert rec["scans"]["roughness_rms"]["unit"] == "m"
    assert rec["pull_off_force"]["unit"] == "N"


@pytest.mark.parametrize(("make", "words"), [
    (lambda d: str(d / "missing.x3p"), "missing.x3p"),
    (lambda d: str(surfmet.write(_scan(lambda x, y: 0 * x * y, n=24), d / "small.npz")),
     "smaller than the adhesion domain"),
])
def test_cli_bad_scans_are_one_line_before_the_work(capsys, tmp_path, make, words):
    rc, out = _cli(capsys, "--plate", make(tmp_path), "--plot", str(tmp_path / "c.png"))
    err = out.err.strip().splitlines()
    assert rc == 1 and len(err) == 1 and words in err[0] and "Traceback" not in err[0]
    assert not (tmp_path / "c.png").exists()


def test_non_square_pixels_are_resampled(smooth):
    """prepare_pair puts both scans on one square grid: a tilted plane scanned with
    rectangular pixels is levelled away just the same."""
    run = adhesion(R, plate=_scan(lambda x, y: 1e-3 * x + 2e-3 * y, dy=SIZE / 32), **KW)
    assert run.result.cycle.pull_off_force == pytest.approx(smooth.cycle.pull_off_force,
                                                            rel=1e-9)
