"""Micro-slip rolling resistance: exact similarity of the smooth pair, no dissipation
without a difference in elastic constants, and ``surfmet rolling --model microslip``."""

from __future__ import annotations

import json

import numpy as np
import pytest

from contact._errors import ContactInputError
from contact._materials import material
from contact.tangential._microslip import microslip_dissipation, microslip_sweep
from surfmet.cli import main


def test_smooth_pair_exponent_is_four_thirds():
    """Hertz similarity: p0 ~ a, the slip (K/G) p ~ a/R and the tractions ~ mu p, so the
    dissipation per metre ~ mu p0 a^2 (a/R) ~ N a ~ N^(4/3) when every load has the same
    relative grid; lambda = 4/3 to 1e-6 over 3.97-5.36 N (the rotor's ball loads)."""
    s = microslip_sweep(0.02, material("steel"), material("aluminium"),
                        np.geomspace(3.97, 5.36, 3), 0.3, grid=16)
    assert s.lambda_eff == pytest.approx(4 / 3, abs=1e-6)
    assert np.all(s.forces > 0)
    assert np.all(np.asarray(s.settings["microslip"]["creepages"]) != 0)


def test_identical_bodies_do_not_dissipate_in_free_rolling():
    """K = 0 (same material): free rolling needs no traction and nothing slips."""
    r = microslip_dissipation(0.02, material("steel"), material("steel"), 5.0, 0.3, grid=16)
    assert r.frictional_power == pytest.approx(0.0, abs=1e-18)
    assert r.n_slip == 0


def test_edge_share_flags_a_slip_zone_the_grid_does_not_resolve():
    """Free rolling of the smooth steel-aluminium pair slips only in a band one element
    wide at the rim, where mu p -> 0: the dissipation then depends on the grid (it falls
    about threefold per halving of the element) and the result says so. A braking
    traction T/N = 0.1 opens a slip zone many elements deep: the share of the edge is
    small, no note is given and the dissipation changes little with the grid."""
    free = [microslip_dissipation(0.02, material("steel"), material("aluminium"), 4.67, 0.3,
                                  grid=n) for n in (32, 64)]
    assert all(r.edge_dissipation_share > 0.9 for r in free)
    assert 2.0 < free[0].frictional_power / free[1].frictional_power < 4.0
    s = microslip_sweep(0.02, material("steel"), material("aluminium"), [4.0, 4.67, 5.3],
                        0.3, grid=32)
    assert any("not resolved by this grid" in n for n in s.notes)
    braked = [microslip_dissipation(0.02, material("steel"), material("aluminium"), 4.67,
                                    0.3, traction_ratio=0.1, grid=n) for n in (64, 96)]
    assert all(r.edge_dissipation_share < 0.3 for r in braked)
    assert braked[1].frictional_power == pytest.approx(braked[0].frictional_power, rel=0.1)
    s = microslip_sweep(0.02, material("steel"), material("aluminium"), [4.0, 4.67, 5.3],
                        0.3, traction_ratio=0.1, grid=64)
    assert not any("not resolved" in n for n in s.notes)


def test_traction_above_friction_is_refused():
    with pytest.raises(ContactInputError, match="traction ratio"):
        microslip_dissipation(0.02, material("steel"), material("aluminium"), 5.0, 0.3,
                              traction_ratio=0.3)


def test_cli_model_microslip(capsys):
    assert main(["rolling", "--radius", "20mm", "--materials", "steel,aluminium", "--loads",
                 "3.97N:5.36N:3", "--model", "microslip", "--grid", "16", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["model"] == "microslip"
    assert rec["lambda_eff"]["value"] == pytest.approx(4 / 3, abs=1e-6)
    assert rec["moments"]["unit"] == "N m"
    assert rec["settings"]["microslip"]["mu"] == 0.3
