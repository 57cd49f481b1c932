"""The confound budget's lateral creep takes the rig's own elastic constants: a rig file's
``e_star_Pa`` (and ``materials``) set the Hertz radius and the shear modulus of the creep,
and the record says which were used; only a rig that states neither falls back to the
paper's steel on aluminium. On main the rig file refused ``e_star_Pa`` and the creep took
steel on aluminium whatever the rig (``Rig.e_star`` reached the arm bound only).

Truth: Kalker's creep force F = G a^2 C22 nu (Kalker 1990, Table E.3), unsaturated below
mu N, with Hertz's a = (3 N R / (4 E*))^(1/3) (Johnson 1985, eq. 4.22): at a fixed G the
torque goes as a^2, E*^(-2/3); with G = (1 - nu) E* (one material) as E*^(1/3).
"""

from __future__ import annotations

import json
import math

import pytest

from contact._materials import material
from rotor import rig_from_mapping
from rotor._confounds import (
    FRICTION,
    KALKER_C22,
    LATERAL_CREEP,
    confound_budget,
    lateral_creep,
)
from surfmet.cli import main

GROUPS = {"as": {"ball_loads_N": [5.36, 3.97], "columns": ["as1", "as2", "as3"]},
          "s": {"ball_loads_N": [4.67, 4.67], "columns": ["s1", "s2", "s3"]}}
BASE = {"ball_radius_m": 0.02, "mass_kg": 0.954, "axial_inertia_kg_m2": 1.632e-4,
        "fps": 120, "step_deg": 90, "groups": GROUPS}


def _shear(ball: str, plate: str) -> float:
    m1, m2 = material(ball), material(plate)
    g1, g2 = m1.E / (2 * (1 + m1.nu)), m2.E / (2 * (1 + m2.nu))
    return 2.0 / (1.0 / g1 + 1.0 / g2)


def _by_hand(e_star: float, shear: float) -> float:
    """Both balls of group "as": the creep torque, unsaturated (checked)."""
    torque = 0.0
    for n in GROUPS["as"]["ball_loads_N"]:
        a = (3 * n * BASE["ball_radius_m"] / (4 * e_star)) ** (1 / 3)
        force = shear * a * a * KALKER_C22 * LATERAL_CREEP
        assert force < FRICTION * n  # Kalker's linear creep, not the friction limit
        torque += force * LATERAL_CREEP * BASE["ball_radius_m"]
    return torque


def _budget_row(rig):
    args = (rig, -0.05, 0.01, math.radians(1.0), 2.0, 0.01, 20.0, "s", "as")
    return next(c for c in confound_budget(*args) if c.name == "lateral_creep")


def test_a_rig_files_e_star_sets_the_creep_radius():
    """Steel on aluminium stated as the rig's materials (G fixed), its E* stated apart:
    doubling E* shrinks a^2 by 2^(-2/3), and so the creep torque."""
    g = _shear("steel", "aluminium")
    got = {}
    for e in (1e11, 2e11):
        rig = rig_from_mapping({**BASE, "e_star_Pa": e, "materials": ["steel", "aluminium"]})
        assert rig.e_star == e and rig.materials == ("steel", "aluminium")
        got[e] = lateral_creep(rig)
        assert got[e] == pytest.approx(_by_hand(e, g), rel=1e-9)
    assert got[2e11] / got[1e11] == pytest.approx(2 ** (-2 / 3), rel=1e-9)


def test_a_rig_with_e_star_alone_takes_g_from_it():
    """No materials: G = (1 - 0.3) E*, so the torque goes as E*^(1/3); the budget's row
    says which constants it used."""
    rows = {}
    for e in (3e9, 6e9):
        rig = rig_from_mapping({**BASE, "e_star_Pa": e, "plate": "PMMA plate"})
        row = _budget_row(rig)
        assert row.moduli.e_star == e and row.moduli.shear == pytest.approx(0.7 * e)
        assert "the rig's E* (PMMA plate)" in row.assumption
        assert lateral_creep(rig) == pytest.approx(_by_hand(e, 0.7 * e), rel=1e-9)
        rows[e] = row.equivalent_acceleration
    assert rows[6e9] / rows[3e9] == pytest.approx(2 ** (1 / 3), rel=1e-9)


def test_a_rig_that_says_nothing_keeps_the_papers_pair():
    rig = rig_from_mapping(BASE)
    row = _budget_row(rig)
    pair = (material("steel"), material("aluminium"))
    assert lateral_creep(rig) == lateral_creep(rig, pair)
    assert "steel on aluminium (the paper's pair" in row.moduli.basis


def test_the_command_records_the_rigs_moduli(tmp_path, capsys):
    """``surfmet rotor --rig`` with e_star_Pa: the JSON's lateral creep row holds the
    rig's E* and its basis, and its acceleration is the closed form over J + M R^2."""
    path = tmp_path / "rig.json"
    path.write_text(json.dumps({**BASE, "e_star_Pa": 3e9, "plate": "PMMA plate"}))
    assert main(["rotor", "paper2022", "--rig", str(path), "--json", "-q"]) == 0
    rec = json.loads(capsys.readouterr().out)["verdict"]
    row = next(c for c in rec["confounds"] if c["name"] == "lateral_creep")
    assert row["moduli"]["e_star"] == {"value": 3e9, "unit": "Pa"}
    assert "the rig's E*" in row["moduli"]["basis"]
    inertia = BASE["axial_inertia_kg_m2"] + BASE["mass_kg"] * BASE["ball_radius_m"] ** 2
    want = _by_hand(3e9, 0.7 * 3e9) / inertia
    assert row["equivalent_acceleration"]["value"] == pytest.approx(want, rel=1e-9)


def test_bad_rig_materials_are_refused():
    from contact._errors import ContactInputError

    with pytest.raises(ContactInputError, match="materials"):
        rig_from_mapping({**BASE, "materials": ["steel"]})
    with pytest.raises(ContactInputError, match="e_star_Pa"):
        rig_from_mapping({**BASE, "e_star_Pa": -1.0})


def test_judge_table_takes_the_rig_dataclass_e_star():
    """A Rig built with its own E* (as tests/test_rotor_soft_rig.py builds its PMMA rig):
    judge_table's lateral creep follows it (main: steel on aluminium, the same creep for
    every E*), as the arm bound already did."""
    import dataclasses

    import numpy as np

    from rotor import judge_table, paper_rig, table3

    groups = {"as": ["as1", "as2", "as3"], "s": ["s1", "s2", "s3"]}
    rig = dataclasses.replace(paper_rig(), e_star=3e9, plate="PMMA plate")
    v = judge_table(table3(), groups, fps=120.0, step=np.pi / 2, rig=rig, permutation=False)
    row = next(c for c in v.confounds if c.name == "lateral_creep")
    torque = 0.0
    for n in rig.groups[0].ball_loads:
        a = (3 * n * rig.ball_radius / (4 * 3e9)) ** (1 / 3)
        force = 0.7 * 3e9 * a * a * KALKER_C22 * LATERAL_CREEP
        assert force < FRICTION * n
        torque += force * LATERAL_CREEP * rig.ball_radius
    assert row.equivalent_acceleration == pytest.approx(torque / rig.rolling_inertia, rel=1e-9)
    assert row.moduli.e_star == 3e9 and "PMMA plate" in row.assumption
    assert v.arm.e_star == 3e9
