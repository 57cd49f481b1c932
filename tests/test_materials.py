"""Material table, user overrides and the composite modulus."""

from __future__ import annotations

import json
import math

import pytest

from contact._errors import ContactInputError
from contact._materials import (
    MATERIALS,
    Material,
    compliance,
    composite_modulus,
    contact_hardness,
    displacement_shares,
    material,
)


def test_paper_materials_come_from_paper_values(paperdata):
    vals = json.loads(paperdata("paper_values.json").read_text())
    assumed = vals["hertz_check_in_paper"]["materials_assumed_here"]
    for name in ("steel", "aluminium"):
        m = material(name)
        assert m.E == assumed[name]["E_Pa"]
        assert m.nu == assumed[name]["nu"]


def test_every_entry_is_plausible_and_cited():
    for name, m in MATERIALS.items():
        assert m.name == name
        assert 1e9 <= m.E <= 1e12
        assert 0.0 < m.nu < 0.5
        assert m.hardness is not None and 1e8 <= m.hardness <= 3e10
        assert m.source and m.source != "user"
    # ordering that any handbook agrees on
    assert MATERIALS["tungsten_carbide"].E > MATERIALS["steel"].E > MATERIALS["aluminium"].E
    hv = {k: MATERIALS[k].hardness for k in ("steel", "aluminium", "pmma")}
    assert hv["steel"] > hv["aluminium"] > hv["pmma"]


def test_aliases_and_case():
    assert material("Aluminum") is MATERIALS["aluminium"]
    assert material("AL") is MATERIALS["aluminium"]
    assert material("bearing-steel") is MATERIALS["steel"]


def test_user_values_override_the_table():
    m = material("steel", E=200e9, hardness=6e9)
    assert (m.E, m.nu, m.hardness) == (200e9, 0.30, 6e9)
    assert "user" in m.source
    assert MATERIALS["steel"].E == 210e9  # the table itself is untouched


@pytest.mark.parametrize("kwargs", [{"E": -1.0}, {"E": 0.0}, {"nu": 0.6}, {"nu": -1.0},
                                    {"hardness": -5.0}, {"E": math.nan}])
def test_bad_overrides_are_refused(kwargs):
    with pytest.raises(ContactInputError):
        material("steel", **kwargs)


def test_unknown_material_names_the_known_ones():
    with pytest.raises(ContactInputError, match="aluminium"):
        material("unobtainium")


def test_composite_modulus_of_the_paper_pair():
    steel, al = material("steel"), material("aluminium")
    P = (1 - 0.3**2) / 210e9 + (1 - 0.33**2) / 70e9  # Alaci et al. eq. (5)
    assert compliance(steel, al) == pytest.approx(P, rel=1e-15)
    assert composite_modulus(steel, al) == pytest.approx(1 / P, rel=1e-15)
    assert composite_modulus(steel, al) == pytest.approx(58.61e9, rel=1e-3)


def test_identical_bodies_halve_the_plane_strain_modulus():
    g = material("glass")
    assert composite_modulus(g, g) == pytest.approx(g.E / (2 * (1 - g.nu**2)), rel=1e-14)
    assert g.plane_strain_modulus == pytest.approx(g.E / (1 - g.nu**2))


def test_displacement_shares_and_softer_hardness():
    steel, al = material("steel"), material("aluminium")
    s1, s2 = displacement_shares(steel, al)
    assert s1 + s2 == pytest.approx(1.0, rel=1e-14)
    assert s2 > s1  # the softer aluminium takes most of the deflection
    assert contact_hardness(steel, al) == al.hardness
    assert contact_hardness(Material("a", 1e9, 0.3), Material("b", 1e9, 0.3)) is None


def test_a_material_with_all_its_constants_needs_no_table_entry():
    """Issue 25 item 10: ``polymer:E=3000MPa:nu=0.35`` is a custom material."""
    m = material("polymer", E=3e9, nu=0.35)
    assert (m.name, m.E, m.nu, m.hardness) == ("polymer", 3e9, 0.35, None)
    assert "user" in m.source
    with pytest.raises(ContactInputError, match="Poisson"):
        material("polymer", E=3e9)  # an unknown name without nu is still unknown


@pytest.mark.parametrize("spec, needle", [
    ("steel:E=200,aluminium", "has no unit"),
    ("steel,aluminium:H=1.1", "has no unit"),
])
def test_a_modulus_without_its_unit_is_refused(spec, needle):
    from surfmet._errors import SurfmetInputError
    from surfmet.mechanics.material_spec import parse_materials

    with pytest.raises(SurfmetInputError, match=needle):
        parse_materials(spec)


def test_custom_material_from_text_and_units():
    from surfmet.mechanics.material_spec import parse_materials

    ball, plate = parse_materials("steel,polymer:E=3000MPa:nu=0.35:H=200MPa")
    assert ball is MATERIALS["steel"]
    assert (plate.name, plate.E, plate.nu, plate.hardness) == ("polymer", 3e9, 0.35, 2e8)
