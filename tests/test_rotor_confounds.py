"""The confound budget's lateral creep takes the ball's and the plate's materials as an input
(the paper's steel on aluminium by default), not a hard-coded pair.

Truth: the hand calculation of the budget's stated formula from the material table's E and
nu: the Hertz radius a = (3 N R / (4 E*))^(1/3) (Johnson 1985, eq. 4.22), Kalker's combined
shear modulus G = 2 / (1/G1 + 1/G2) with G_i = E_i / (2 (1 + nu_i)) and the lateral creep
force min(G a^2 C22 nu, mu N) (Kalker 1990, Table E.3), its torque F nu R per ball.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from contact._materials import material
from rotor import paper_rig
from rotor._confounds import FRICTION, KALKER_C22, LATERAL_CREEP, confound_budget, lateral_creep


def _by_hand(rig, ball: str, plate: str) -> float:
    m1, m2 = material(ball), material(plate)
    e_star = 1.0 / ((1 - m1.nu ** 2) / m1.E + (1 - m2.nu ** 2) / m2.E)
    g1, g2 = m1.E / (2 * (1 + m1.nu)), m2.E / (2 * (1 + m2.nu))
    g = 2.0 / (1.0 / g1 + 1.0 / g2)
    torque = 0.0
    for n in rig.groups[0].ball_loads:
        a = (3 * n * rig.ball_radius / (4 * e_star)) ** (1 / 3)
        torque += min(g * a * a * KALKER_C22 * LATERAL_CREEP, FRICTION * n) * LATERAL_CREEP \
            * rig.ball_radius
    return torque


@pytest.mark.parametrize(("ball", "plate"), [("steel", "aluminium"), ("steel", "steel"),
                                             ("steel", "pmma")])
def test_lateral_creep_follows_the_materials_given(ball, plate):
    rig = paper_rig()
    got = lateral_creep(rig, (material(ball), material(plate)))
    assert got == pytest.approx(_by_hand(rig, ball, plate), rel=1e-6)


def test_the_budget_states_the_pair_it_used():
    """A softer plate makes another lateral creep than the paper's pair, and the row's
    assumption names the pair."""
    rig = paper_rig()
    args = (rig, -0.05, 0.01, math.radians(1.0), 2.0, 0.01, 20.0, "s", "as")

    def row(pair):
        budget = confound_budget(*args, materials=(material(pair[0]), material(pair[1])))
        return next(c for c in budget if c.name == "lateral_creep")

    paper, soft = row(("steel", "aluminium")), row(("steel", "pmma"))
    assert "steel on aluminium" in paper.assumption and "steel on pmma" in soft.assumption
    ratio = soft.equivalent_acceleration / paper.equivalent_acceleration
    assert ratio == pytest.approx(_by_hand(rig, "steel", "pmma")
                                  / _by_hand(rig, "steel", "aluminium"), rel=1e-6)
    assert not np.isclose(ratio, 1.0)


def test_judge_table_passes_the_materials_and_defaults_to_the_papers():
    """judge_table's ``materials`` reach the budget; without them it is the paper's pair."""
    from rotor import judge_table, table3

    groups = {"as": ["as1", "as2", "as3"], "s": ["s1", "s2", "s3"]}

    def creep(**kw):
        v = judge_table(table3(), groups, fps=120.0, step=np.pi / 2, rig=paper_rig(),
                        permutation=False, **kw)
        return next(c for c in v.confounds if c.name == "lateral_creep")

    default = creep()
    paper = creep(materials=(material("steel"), material("aluminium")))
    soft = creep(materials=(material("steel"), material("pmma")))
    assert default.equivalent_acceleration == paper.equivalent_acceleration
    assert "steel on aluminium" in default.assumption and "steel on pmma" in soft.assumption
    assert soft.equivalent_acceleration != pytest.approx(paper.equivalent_acceleration)
