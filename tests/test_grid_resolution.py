"""A grid too coarse for the contact is said, in text and JSON (issue 16, item 4).

The stated rule: at least 5 cells per Hertz contact radius a0 (surfmet.mechanics.ball_contact
.MIN_CELLS_PER_RADIUS). a0 is computed here from Hertz's closed form (Johnson 1985, eq.
4.22), independently of the code under test.
"""

from __future__ import annotations

import json
import math

import pytest

from contact._materials import composite_modulus, material
from surfmet.cli import main
from surfmet.mechanics.ball_contact import MIN_CELLS_PER_RADIUS

R, W = 0.02, 10.0
E_STAR = composite_modulus(material("steel"), material("aluminium"))
A0 = (3 * W * R / (4 * E_STAR)) ** (1 / 3)  # 136.8 µm


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("grid", [8, 16, 64])
def test_contact_warns_below_the_stated_cells_per_radius(capsys, grid):
    rec = _json(capsys, ["contact", "--radius", "20mm", "--load", "10N", "--materials",
                         "steel,aluminium", "--grid", str(grid), "--json"])
    cells = A0 / rec["grid"]["dx"]["value"]
    coarse = [w for w in rec["warnings"] if "too coarse" in w]
    assert bool(coarse) == (cells < MIN_CELLS_PER_RADIUS)
    if grid == 8:  # the case
        assert coarse and f"{MIN_CELLS_PER_RADIUS} are needed" in coarse[0]


def test_contact_text_carries_the_warning(capsys):
    assert main(["contact", "--radius", "20mm", "--load", "10N", "--materials",
                 "steel,aluminium", "--grid", "8"]) == 0
    out = capsys.readouterr().out
    assert "warning" in out and "too coarse" in out


def test_hertz_check_warns_on_a_coarse_grid(capsys):
    data = "surfmet/data/"
    rec = _json(capsys, ["hertz-check", data + "paper_plate.x3p", "--radius", "20mm",
                         "--load", "10N", "--materials", "steel,aluminium", "--grid", "8",
                         "--json"])
    assert A0 / rec["grid"]["dx"]["value"] < MIN_CELLS_PER_RADIUS
    assert any("too coarse" in w for w in rec["warnings"])


def test_default_grid_is_fine_enough(capsys):
    rec = _json(capsys, ["contact", "--radius", "20mm", "--load", "10N", "--materials",
                         "steel,aluminium", "--json"])
    assert A0 / rec["grid"]["dx"]["value"] >= MIN_CELLS_PER_RADIUS
    assert not any("too coarse" in w for w in rec["warnings"])
    assert math.isclose(rec["hertz"]["a"]["value"], A0, rel_tol=1e-12)
