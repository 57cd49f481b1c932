"""Interaction laws are plug-ins (issue 37 item 3): one table (contact.adhesion.laws.LAWS),
each law states its own name, parameters and kernel arguments, and nothing else switches
on a law's type. A law registered inside this test runs through the API and the command
with no other file edited; an object that is not a registered law is refused, never run as
another (main solved an unknown law as the exponential one and named it "exponential")."""

from __future__ import annotations

import argparse
import json
import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import numpy as np
import pytest
from scipy import integrate

from contact._errors import ContactInputError
from contact._geometry import DomainSpec
from contact.adhesion import adhesive_ball
from contact.adhesion.laws import (
    LAWS,
    DugdaleLaw,
    InteractionLaw,
    LawParameter,
    register_law,
)
from contact.adhesion.line import adhesive_line, rigid_line_pull_off
from contact.adhesion.solver import adhesive_problem, law_code, solve_adhesive
from surfmet._errors import SurfmetInputError
from surfmet.cli import build_parser, main
from surfmet.mechanics.adhesion import adhesion, default_grid, interaction_name
from surfmet.records._adhesion import adhesion_record

ROOT = Path(__file__).resolve().parents[1]
R, E_STAR = 1e-5, 1e9
#: A value of each unit a law's parameter may have, to build every registered law.
EXAMPLE = {"J/m^2": 0.05, "N/m": 0.05, "m": 2e-9, "Pa": 25e6, "rad": 0.3}


@pytest.fixture
def well():
    """A square-well law of this test's own, registered for the test and removed after:
    tension ``well_tension`` for gaps below ``well_width``, its own parameters."""
    from contact.adhesion import kernels

    @register_law
    @dataclass(frozen=True)
    class WellLaw(InteractionLaw):
        name: ClassVar[str] = "square_well"
        summary: ClassVar[str] = "a square well (a test's own law)"
        parameters: ClassVar[tuple[LawParameter, ...]] = (
            LawParameter("well_tension", "Pa", "the well's tension"),
            LawParameter("well_width", "m", "the well's width in gap"))

        well_tension: float
        well_width: float

        work = property(lambda self: self.well_tension * self.well_width)
        peak = property(lambda self: self.well_tension)
        range = property(lambda self: self.well_width)
        reach = property(lambda self: self.well_width)

        def traction(self, g):
            return np.where(np.asarray(g, dtype=float) < self.well_width,
                            self.well_tension, 0.0)

        def potential(self, g):
            return -self.well_tension * np.maximum(self.well_width - np.asarray(g, float), 0)

        def kernel_args(self, single=False):
            return kernels.DUGDALE, self.well_width, 0.0

    yield WellLaw
    del LAWS["square_well"]


def _law(cls):
    """A law of each registered class, of example parameters (:data:`EXAMPLE`)."""
    return cls.from_parameters(**{p.keyword: EXAMPLE[p.unit] for p in cls.parameters})


def test_a_law_registered_in_the_test_solves_through_the_api(well):
    """The well of tension 25 MPa and width 2 nm is Dugdale's step of w = 50 mJ/m^2: the
    same kernel arguments, so the same cycle; the facade names it by its name, picks its
    default grid by its own flag, and the rigid cylinder's pull-off by quadrature is the
    closed form 2 sqrt(2 R w sigma0)."""
    law, step = well(25e6, 2e-9), DugdaleLaw(0.05, 25e6)
    a = adhesive_ball(R, E_STAR, law, domain=DomainSpec(grid=16, size=2e-6), steps=4)
    b = adhesive_ball(R, E_STAR, step, domain=DomainSpec(grid=16, size=2e-6), steps=4)
    assert a.cycle.pull_off_force == b.cycle.pull_off_force > 0.0
    assert np.array_equal(a.cycle.retraction_leg.load, b.cycle.retraction_leg.load)
    run = adhesion(R, e_star=E_STAR, interaction=law, grid=16, size=2e-6, steps=4)
    assert adhesion_record(run)["interaction"] == interaction_name(law) == "square_well"
    assert default_grid(2e-6, E_STAR, law, 4).why == "default for the square_well law: 128 cells"
    assert rigid_line_pull_off(law, R) == pytest.approx(
        2.0 * math.sqrt(2.0 * R * 0.05 * 25e6), rel=1e-9)


def test_a_law_registered_in_the_test_is_a_choice_of_the_command(well, capsys):
    """``surfmet adhesion --interaction square_well --well-tension ... --well-width ...``:
    the command's choices and options come from the table, so the test's law runs from
    the command line; its pull-off is that of Dugdale's step of the same w and sigma0."""
    assert main(["adhesion", "--radius", "10um", "--e-star", "1GPa", "--interaction",
                 "square_well", "--well-tension", "25MPa", "--well-width", "2nm", "--grid",
                 "16", "--size", "2um", "--steps", "4", "--json", "--quiet"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["interaction"] == "square_well"
    assert rec["work_of_adhesion"]["value"] == pytest.approx(0.05, rel=1e-12)
    step = adhesive_ball(R, E_STAR, DugdaleLaw(0.05, 25e6),
                         domain=DomainSpec(grid=16, size=2e-6), steps=4)
    assert rec["pull_off_force"]["value"] == pytest.approx(step.cycle.pull_off_force, rel=1e-12)
    assert main(["adhesion", "--radius", "10um", "--e-star", "1GPa", "--interaction",
                 "square_well", "--well-tension", "25MPa", "--quiet"]) == 1
    assert "the square_well law needs --well-width" in capsys.readouterr().err


@dataclass(frozen=True)
class LookAlike:
    """An object with every attribute of the exponential law, not a registered law."""

    work: float = 0.05
    rho: float = 1e-9
    range: float = 1e-9
    reach: float = 3e-9
    peak: float = 5e7
    smoothing: float = 0.0

    def traction(self, g):
        return self.peak * np.exp(-np.asarray(g, dtype=float) / self.rho)

    def potential(self, g):
        return -self.work * np.exp(-np.asarray(g, dtype=float) / self.rho)


@dataclass(frozen=True)
class Tweaked(DugdaleLaw):
    """A subclass of a registered law, itself not registered."""


@pytest.mark.parametrize("law", [LookAlike(), Tweaked(0.05, 25e6)],
                         ids=["look-alike", "unregistered-subclass"])
def test_an_unregistered_law_is_refused_never_run_as_another(law):
    """One ContactInputError at every entry (the kernels' arguments, the solve, the
    sphere, the cylinder), one SurfmetInputError at the facade's naming."""
    words = "not a registered interaction law"
    with pytest.raises(ContactInputError, match=words):
        law_code(law)
    h = np.add.outer(np.linspace(-1, 1, 16) ** 2, np.linspace(-1, 1, 16) ** 2) * 1e-8
    problem = adhesive_problem(h, 1e-7, E_STAR, law)
    with pytest.raises(ContactInputError, match=words):
        solve_adhesive(problem, 0.0)
    with pytest.raises(ContactInputError, match=words):
        adhesive_ball(R, E_STAR, law, domain=DomainSpec(grid=16), steps=4)
    with pytest.raises(ContactInputError, match=words):
        adhesive_line(R, E_STAR, law, cells=64, steps=4)
    with pytest.raises(SurfmetInputError, match=words):
        interaction_name(law)


def test_an_unknown_name_is_refused(capsys):
    with pytest.raises(ContactInputError, match="unknown interaction law 'nonsense'"):
        from contact.adhesion.laws import build_law
        build_law("nonsense", work_of_adhesion=0.05, range_=2e-9)
    assert main(["adhesion", "--radius", "10um", "--e-star", "1GPa", "--work-of-adhesion",
                 "50mJ/m2", "--range", "2nm", "--interaction", "nonsense"]) != 0


@pytest.mark.parametrize("name", sorted(LAWS))
def test_every_registered_law_states_the_interface(name):
    """Each law of the table: its name, one-line summary and parameters; t(0) = peak,
    phi(0) = -w, phi' = t and the traction integrates to w; kernel arguments (code,
    reach, width) in either precision; its form on a grid is a law of the table."""
    from contact.adhesion import kernels

    cls = LAWS[name]
    law = _law(cls)
    assert cls.name == name and cls.summary and cls.parameters
    assert float(law.traction(0.0)) == pytest.approx(law.peak, rel=1e-12)
    assert float(law.potential(0.0)) == pytest.approx(-law.work, rel=1e-12)
    def t(u):  # the gap in units of the reach, so that quad sees the law's scale
        return float(law.traction(u * law.reach))

    total = (integrate.quad(t, 0.0, 1.0, limit=200, points=[law.range / law.reach])[0]
             + integrate.quad(t, 1.0, math.inf, limit=200)[0]) * law.reach
    assert total == pytest.approx(law.work, rel=1e-6)
    g = np.linspace(0.05, 0.95, 7) * law.range
    d = 1e-6 * law.range
    assert np.allclose((law.potential(g + d) - law.potential(g - d)) / (2 * d),
                       law.traction(g), rtol=1e-5)
    codes = {kernels.DUGDALE, kernels.DUGDALE_RAMP, kernels.EXPONENTIAL,
             kernels.EXPONENTIAL_SINGLE}
    for single in (False, True):
        code, reach, width = law.kernel_args(single)
        assert code in codes and reach > 0.0 and width >= 0.0
    assert type(law.on_grid(1e-8, E_STAR)) is cls
    assert law.reach >= law.range > 0.0 and law.maugis(R, E_STAR) > 0.0


def _choices(command: str) -> tuple[str, ...]:
    sub = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    action = next(a for a in sub.choices[command]._actions if "--interaction" in a.option_strings)
    return tuple(action.choices)


def test_the_commands_choices_are_the_table():
    assert _choices("adhesion") == _choices("flat-contact") == tuple(LAWS)
    assert {"dugdale", "exponential"} <= set(LAWS)


def test_nothing_outside_the_laws_switches_on_a_law_type():
    """No isinstance / hasattr / getattr on a law, and no comparison of a law's name,
    outside contact/adhesion/laws/ (main had twelve: four isinstance / hasattr, five getattr
    of the smoothing, three name comparisons)."""
    switch = re.compile(r"(isinstance|hasattr|getattr)\(law\b|isinstance\([^)]*"
                        r"(DugdaleLaw|ExponentialLaw)|interaction [!=]= \"")
    hits = [f"{p.relative_to(ROOT)}:{i}" for top in ("contact", "surfmet")
            for p in (ROOT / top).rglob("*.py") if "laws" not in p.relative_to(ROOT).parts
            for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
            if switch.search(line)]
    assert hits == []
