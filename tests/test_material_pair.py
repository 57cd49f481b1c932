"""The resolved material pair against constants worked out by hand (Johnson 1985)."""

from __future__ import annotations

import math

import pytest

from contact._errors import ContactInputError
from contact._material_pair import MaterialPair, resolve_pair
from contact._materials import material

# steel E = 210 GPa, nu = 0.30; aluminium E = 70 GPa, nu = 0.33 (the table's values)
C_STEEL = (1 - 0.30**2) / 210e9   # 0.91 / 210 GPa   = 4.3333e-12 1/Pa
C_ALU = (1 - 0.33**2) / 70e9      # 0.8911 / 70 GPa  = 1.2730e-11 1/Pa


def test_steel_on_aluminium_by_hand():
    pair = resolve_pair(material("steel"), material("aluminium"))
    assert isinstance(pair, MaterialPair)
    # Johnson (1985) eq. 4.22: 1/E* = 4.3333e-12 + 1.2730e-11 -> E* = 58.605 GPa
    assert pair.e_star == pytest.approx(58.605e9, rel=1e-4)
    assert pair.e_star == pytest.approx(1 / (C_STEEL + C_ALU), rel=1e-14)
    # each body deflects in proportion to its own compliance: 0.2540 and 0.7460
    assert pair.shares == pytest.approx((0.25396, 0.74604), abs=1e-5)
    assert sum(pair.shares) == pytest.approx(1.0, rel=1e-15)
    assert pair.nu == (0.30, 0.33)
    g1, g2 = 210e9 / 2.6, 70e9 / 2.66   # G = E / (2 (1 + nu)): 80.769 and 26.316 GPa
    assert pair.shear_moduli == pytest.approx((g1, g2), rel=1e-15)
    # Dundurs' beta (Johnson 1985, sec. 5.1):
    # beta = 1/2 [(1-2nu1)/G1 - (1-2nu2)/G2] / [(1-nu1)/G1 + (1-nu2)/G2] = -0.1167
    beta = 0.5 * (0.4 / g1 - 0.34 / g2) / (0.7 / g1 + 0.67 / g2)
    assert beta == pytest.approx(-0.11674, abs=1e-5)
    assert pair.beta == pytest.approx(beta, rel=1e-12)
    # Kalker's K = beta (1 - nu) with his combined nu = G/2 (nu1/G1 + nu2/G2), 2/G = 1/G1 + 1/G2
    g = 2 / (1 / g1 + 1 / g2)
    nu = 0.5 * g * (0.30 / g1 + 0.33 / g2)
    assert pair.kalker_k == pytest.approx(beta * (1 - nu), rel=1e-12)
    # the PairConstants the tangential solver takes carry the same K
    assert pair.constants().K == pytest.approx(pair.kalker_k, rel=0, abs=0)


def test_default_hardness_is_the_softer_body_and_says_so():
    pair = resolve_pair(material("steel"), material("aluminium"))
    assert pair.hardness == pytest.approx(107 * 9.807e6, rel=1e-15)  # 6061-T6, HV 107
    assert pair.hardness_source == "material: aluminium"
    given = resolve_pair(material("steel"), material("aluminium"), hardness=0.9e9)
    assert (given.hardness, given.hardness_source) == (0.9e9, "given")
    assert given.e_star == pair.e_star


def test_on_a_rigid_flat_and_from_e_star():
    one = resolve_pair(material("aluminium"))
    assert one.e_star == pytest.approx(70e9 / (1 - 0.33**2), rel=1e-15)
    assert one.shares == (1.0, 0.0)
    assert one.hardness_source == "material: aluminium"
    bare = resolve_pair(e_star=80e9)
    assert (bare.e_star, bare.hardness, bare.hardness_source) == (80e9, None, "none")
    with pytest.raises(ContactInputError, match="materials"):
        bare.constants()
    with pytest.raises(ContactInputError, match="materials"):
        _ = bare.shares


@pytest.mark.parametrize("kwargs", [
    {},
    {"e_star": -1.0},
    {"e_star": math.inf},
    {"e_star": 80e9, "body1": "steel"},
    {"e_star": 80e9, "hardness": 0.0},
])
def test_bad_pairs_are_refused(kwargs):
    if "body1" in kwargs:
        kwargs["body1"] = material(kwargs["body1"])
    with pytest.raises(ContactInputError):
        resolve_pair(**kwargs)


def test_the_surfmet_spelling_resolves_through_the_same_pair():
    from surfmet._errors import SurfmetInputError
    from surfmet.mechanics.material_spec import material_pair, parse_materials

    pair = material_pair("steel,al:H=0.9GPa")
    assert pair.e_star == resolve_pair(material("steel"), material("aluminium")).e_star
    assert (pair.hardness, pair.hardness_source) == (0.9e9, "material: aluminium")
    assert material_pair(pair) is pair
    assert material_pair(pair, hardness=1e9).hardness_source == "given"
    assert material_pair("aluminium", rigid_flat=True).body2 is None
    with pytest.raises(SurfmetInputError, match="two names"):
        material_pair("aluminium")  # a ball needs a plate
    assert material_pair(e_star=3e9).e_star == 3e9
    with pytest.raises(SurfmetInputError):
        material_pair("steel,aluminium", e_star=3e9)
    with pytest.raises(SurfmetInputError, match="both bodies"):
        parse_materials(material_pair(e_star=3e9))
