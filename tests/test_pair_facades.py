"""Every contact facade takes the resolved material pair where it takes E*, and a pair gives
the very solve its E* gives (bit for bit); the surfmet facades resolve the user's materials
themselves, so the command line never builds E*."""

from __future__ import annotations

import ast
import math
from pathlib import Path

import numpy as np
import pytest

from contact import Dissipation, DomainSpec
from contact._grid import gap_grid
from contact._hertzcheck import check_sphere
from contact._material_pair import MaterialPair, modulus, resolve_pair
from contact._materials import material
from contact.adhesion.ball import adhesive_ball
from contact.adhesion.flat import adhesive_flat
from contact.adhesion.laws import DugdaleLaw, ExponentialLaw
from contact.adhesion.line import adhesive_line
from contact.setups._ball_on_plate import solve_sphere
from contact.setups._flat import flat_contact
from contact.setups._line import solve_cylinder, solve_line

CLI = Path(__file__).resolve().parents[1] / "surfmet" / "cli"


@pytest.fixture(scope="module")
def pair() -> MaterialPair:
    return resolve_pair(material("steel"), material("aluminium"))


@pytest.fixture(scope="module")
def soft() -> MaterialPair:
    # two compliant custom bodies, E* = 1/(0.91/1 GPa + 0.84/2 GPa) = 0.752 GPa
    return resolve_pair(material("a", E=1e9, nu=0.3), material("b", E=2e9, nu=0.4))


def _same(a, b) -> None:
    """Equal bit for bit: arrays element by element (NaN where NaN), scalars exactly."""
    a, b = np.asarray(a), np.asarray(b)
    assert a.shape == b.shape
    assert np.array_equal(a, b, equal_nan=a.dtype.kind == "f")


def test_modulus_reads_a_pair_and_passes_a_number_through(pair):
    assert modulus(pair) == pair.e_star
    assert modulus(58.6e9) == 58.6e9
    assert modulus(-1.0) == -1.0  # left for the facade's own check (and its message)


def test_sphere_and_hertz_check(pair):
    rng = np.random.default_rng(3)
    from contact.setups._composite import CompositeRoughness

    rough = CompositeRoughness(rng.normal(0, 2e-7, (64, 64)), 5e-6)
    a = solve_sphere(0.02, 5.0, pair, roughness=rough, domain=DomainSpec(grid=32))
    b = solve_sphere(0.02, 5.0, pair.e_star, roughness=rough, domain=DomainSpec(grid=32))
    assert a.e_star == b.e_star == pair.e_star
    _same(a.pressure, b.pressure)
    assert (a.approach, a.load, a.iterations) == (b.approach, b.load, b.iterations)
    a = check_sphere(0.02, 5.0, pair, hardness=pair.hardness, domain=DomainSpec(grid=32))
    b = check_sphere(0.02, 5.0, pair.e_star, hardness=pair.hardness, domain=DomainSpec(grid=32))
    _same(a.elastic.pressure, b.elastic.pressure)
    _same(a.plastic.pressure, b.plastic.pressure)
    for name in ("pmax", "elastic_pmax", "effective_radius", "approach", "area_fraction",
                 "plastic_fraction", "profile_deviation", "hertz_holds"):
        assert getattr(a.comparison, name) == getattr(b.comparison, name), name
    # the pair's default hardness is not applied silently: without one, elastic only
    assert check_sphere(0.02, 5.0, pair, domain=DomainSpec(grid=32)).plastic is None


def test_rolling_sweep(pair):
    from contact._rolling import sphere_sweep

    a = sphere_sweep(
        0.02,
        pair,
        [2.0, 4.0, 8.0],
        dissipation=Dissipation(alpha_h=0.01),
        domain=DomainSpec(grid=32),
    )
    b = sphere_sweep(
        0.02,
        pair.e_star,
        [2.0, 4.0, 8.0],
        dissipation=Dissipation(alpha_h=0.01),
        domain=DomainSpec(grid=32),
    )
    _same(a.moments, b.moments)
    assert a.settings == b.settings and a.settings["e_star"] == pair.e_star


def test_line_and_cylinder(pair):
    x = (np.arange(128) - 64) * 1e-6
    a = solve_line(x * x / 0.04, 1e-6, e_star=pair, load=2e3)
    b = solve_line(x * x / 0.04, 1e-6, e_star=pair.e_star, load=2e3)
    _same(a.pressure, b.pressure)
    assert a.approach == b.approach and a.e_star == b.e_star
    a, b = solve_cylinder(0.02, 1e5, pair, n=64), solve_cylinder(0.02, 1e5, pair.e_star, n=64)
    _same(a.pressure, b.pressure)
    assert a.approach == b.approach


def test_flat(pair):
    z = np.random.default_rng(5).normal(0, 1e-6, (16, 16))
    kw = dict(pressures=[1e6, 5e6], hardness=2e9)
    grid = gap_grid(z.max() - z, 1e-6, periodic=True)
    a = flat_contact(grid, e_star=pair, **kw)
    b = flat_contact(grid, e_star=pair.e_star, **kw)
    assert a.e_star == b.e_star == pair.e_star
    for pa, pb in zip(a.points, b.points):
        for name in ("area_fraction", "corrected_area_fraction", "mean_gap", "stiffness"):
            assert getattr(pa, name) == getattr(pb, name), name


def test_adhesive_ball_line_and_flat(soft):
    law = DugdaleLaw(0.05, 1e8)  # small grids and loose tolerances: only equality matters
    a = adhesive_ball(10e-6, soft, law, steps=4, tol=1e-4, domain=DomainSpec(grid=16))
    b = adhesive_ball(10e-6, soft.e_star, law, steps=4, tol=1e-4, domain=DomainSpec(grid=16))
    assert a.e_star == b.e_star == soft.e_star
    assert a.cycle.pull_off_force == b.cycle.pull_off_force
    _same(a.cycle.approach_leg.load, b.cycle.approach_leg.load)
    a = adhesive_line(10e-6, soft, law, cells=64, steps=4, tol=1e-5)
    b = adhesive_line(10e-6, soft.e_star, law, cells=64, steps=4, tol=1e-5)
    assert a.cycle.pull_off_force == b.cycle.pull_off_force
    _same(a.cycle.retraction_leg.load, b.cycle.retraction_leg.load)
    gap = np.zeros((16, 16))
    flaw = ExponentialLaw(0.05, 3e-9)
    a = adhesive_flat(gap, 1e-6, soft, flaw, [1e6], [0.0], [1e15])
    b = adhesive_flat(gap, 1e-6, soft.e_star, flaw, [1e6], [0.0], [1e15])
    assert a.e_star == b.e_star
    assert a.points[0] == b.points[0]


def test_mechanisms_take_the_pair_and_its_hardness(pair):
    from contact.viscoelastic._mechanisms import compare_mechanisms

    kw = dict(loads=[3.0, 6.0], rotor_loads=(4.0, 3.0, 5.0), rolling_inertia=1e-4,
              speed=0.1, loss=(3e-4, 5e-4), grid=16)
    a = compare_mechanisms(0.02, pair, **kw)
    b = compare_mechanisms(0.02, material("steel"), material("aluminium"),
                           hardness=pair.hardness, **kw)
    assert a.assumptions == b.assumptions and a.assumptions["hardness"] == pair.hardness
    for ma, mb in zip(a.mechanisms, b.mechanisms):
        assert ma.name == mb.name and ma.rotor_moments == mb.rotor_moments


def test_surfmet_facades_resolve_the_materials_text():
    import surfmet
    from surfmet.mechanics.flat_contact import flat_contact as surf_flat
    from surfmet.mechanics.spectrum import prepared_scan, spectrum

    plate = Path(surfmet.__file__).parent / "data" / "paper_plate.x3p"
    full, per, _, _ = prepared_scan(surfmet.read(str(plate)))
    scan = surfmet._model.Topography(np.asarray(full.heights)[:96, :96], full.dx, full.dy)
    pair = resolve_pair(material("steel"), material("aluminium"))
    s = spectrum(scan, periodic=per, materials="steel,aluminium")
    assert s.materials.names == ["steel", "aluminium"] and s.materials.e_star == pair.e_star
    ref = spectrum(scan, periodic=per, e_star=pair.e_star, hardness=pair.hardness)
    assert s.plasticity == ref.plasticity and math.isfinite(s.plasticity)
    # a rigid flat: the scan's own E/(1 - nu^2) (as the compliance sum with a rigid body)
    alu = material("aluminium")
    s1 = spectrum(scan, periodic=per, materials="aluminium", hardness=1e9)
    assert s1.materials.e_star == 1.0 / ((1 - alu.nu**2) / alu.E)
    assert s1.materials.hardness == 1e9
    sub = surfmet._model.Topography(np.asarray(full.heights)[:32, :32], full.dx, full.dy)
    a = surf_flat(sub, materials="steel,aluminium", pressures=[2e7], periodic=True)
    b = surf_flat(sub, e_star=pair.e_star, pressures=[2e7], periodic=True)
    assert a.materials.names == ["steel", "aluminium"] and b.materials is None
    assert a.bem.points == b.bem.points


# The names that turn materials into E*, hardness or shares: a CLI module that imports or
# calls one of them resolves the pair itself, which the surfmet facades alone must do
# (scan_pair included: spectrum and flat-contact on several measurements resolved their
# pair themselves with it; the facade surfmet.mechanics.all_scales.all_scales does now).
BUILDERS = {"resolve_pair", "composite_modulus", "contact_hardness", "displacement_shares",
            "compliance", "pair_constants", "material_pair", "parse_material",
            "parse_materials", "materials_e_star", "MaterialPair", "Material", "scan_pair"}
MODULES = {"contact._materials", "contact._material_pair", "contact.halfspace.constants"}


def pair_builders(source: str) -> list[str]:
    """The pair-building imports and calls in a module's source, as ``line: name``."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.ImportFrom):
            names = {a.name for a in node.names}
            if node.module in MODULES or names & BUILDERS:
                found.append(f"{node.lineno}: from {node.module} import {sorted(names)}")
        elif isinstance(node, ast.Import):
            found += [f"{node.lineno}: import {a.name}" for a in node.names if a.name in MODULES]
        elif isinstance(node, ast.Call):
            f = node.func
            name = f.id if isinstance(f, ast.Name) else f.attr if isinstance(
                f, ast.Attribute) else None
            if name in BUILDERS:
                found.append(f"{node.lineno}: {name}(...)")
    return found


def test_the_checker_finds_a_cli_that_builds_e_star():
    bad = ("from contact._materials import composite_modulus, material\n"
           "def run(args):\n"
           "    import contact._material_pair\n"
           "    from surfmet.mechanics.material_spec import material_pair\n"
           "    return material_pair(args.materials).e_star, contact._materials.compliance(a, b)\n")
    assert len(pair_builders(bad)) == 5
    assert len(pair_builders("from surfmet.mechanics.material_spec import scan_pair\n")) == 1
    assert pair_builders("from surfmet.mechanics.all_scales import all_scales\n") == []


def test_no_cli_module_builds_e_star():
    files = sorted(CLI.glob("*.py"))
    assert len(files) > 10  # the CLI package was found
    offenders = {f.name: pair_builders(f.read_text()) for f in files}
    assert {k: v for k, v in offenders.items() if v} == {}
