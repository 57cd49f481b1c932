"""One normal-solve loop for 3D contact (issue 37, item 2).

Two checks, neither the solver checking itself:

- an AST scan of ``contact/`` counts the ``for``/``while`` loops whose body takes a
  normal-solve iteration step (a Polonsky-Keer step of :mod:`contact.bem._steps`, the
  adhesive gradient kernel, or a method's ``step()``): one, the driver's
  (:func:`contact.bem._loop.drive`); the line contact, Greenwood-Tripp and the
  tangential and viscoelastic couplings keep their own discretisation and loops;
- every 3D entry point (the elastic and the plastic ``solve_normal``, the adhesive
  solve at an approach and under a load) is patched into counting its calls of the
  driver, and its answer is checked against a closed form: Hertz's p0 and radius,
  the fully plastic radius sqrt(W / (pi H)), Westergaard's wavy surface at w -> 0 under
  both controls, and Johnson's adhesive wavy surface (1995, Proc. R. Soc. A 451:99).
"""

from __future__ import annotations

import ast
import math
from pathlib import Path

import numpy as np
import pytest
from adhesion_cases import strip_half_width, wavy_problem
from johnson_wavy import mean_pressure

from contact import hertz_sphere
from contact._geometry import sphere_gap
from contact._grid import gap_grid
from contact.adhesion import _descent as descent
from contact.adhesion.solver import solve_adhesive, solve_adhesive_at_pressure
from contact.bem import PressureBounds, SolveOptions, solve_normal
from contact.bem import _iteration as iteration
from contact.bem import _loop as loop

ROOT = Path(__file__).resolve().parents[1] / "contact"
#: the loops that keep their own iteration (issue 37: their own discretisation)
OWN_LOOPS = ("bem/_line.py", "adhesion/line.py", "roughcontact/_greenwood_tripp.py",
             "tangential/", "viscoelastic/")
#: what a normal-solve iteration step calls
STEP_CALLS = {"conjugate_gradient_step", "projected_gradient_step", "gradient_step",
              "pk_step_length", "pk_update_pressure", "momentum_into",
              "momentum_shift_into", "step"}


def _called(node: ast.AST) -> set[str]:
    names = set()
    for sub in ast.walk(node):
        if isinstance(sub, ast.Call):
            f = sub.func
            names.add(f.attr if isinstance(f, ast.Attribute) else getattr(f, "id", ""))
    return names


def _stepping_loops() -> list[str]:
    found = []
    for path in sorted(ROOT.rglob("*.py")):
        rel = path.relative_to(ROOT).as_posix()
        if rel.startswith(OWN_LOOPS) or "/kernels" in rel or rel.endswith("kernels.py"):
            continue  # the kernels' loops run over cells, not iterations
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, (ast.For, ast.While)) and _called(node) & STEP_CALLS:
                found.append(f"{rel}:{node.lineno}")
    return found


def test_one_loop_steps_the_3d_normal_solves():
    """On main: three (bem/_iteration.py and two copies in adhesion/solver.py)."""
    found = _stepping_loops()
    assert len(found) == 1 and found[0].startswith("bem/_loop.py:"), found


@pytest.fixture
def drives(monkeypatch):
    """The methods the driver ran, in order (the driver itself runs them)."""
    methods = []
    real = loop.drive

    def counting(method, budget, callback=None):
        methods.append(type(method))
        return real(method, budget, callback)

    monkeypatch.setattr(loop, "drive", counting)
    return methods


E_STAR, R, W = 1e11, 0.02, 1.0


def test_elastic_solve_normal_runs_the_driver_and_is_hertz(drives):
    hz = hertz_sphere(R, W, E_STAR)
    n = 128
    dx = 2.5 * hz.a / n
    res = solve_normal(gap_grid(sphere_gap(n, dx, R), dx, origin=(-(n // 2) * dx, -(n // 2) * dx)),
                       e_star=E_STAR, load=W, options=SolveOptions(tol=1e-8))
    assert drives and set(drives) == {iteration.PolonskyKeer}
    assert abs(res.pmax / hz.p0 - 1.0) < 1e-3
    assert abs(res.contact_radius - hz.a) < res.dx


def test_plastic_solve_normal_runs_the_driver_and_is_fully_plastic(drives):
    """p0 / H = 20: nearly the whole contact carries H, its radius sqrt(W / (pi H))."""
    hz = hertz_sphere(R, W, E_STAR)
    hardness = hz.p0 / 20.0
    radius = math.sqrt(W / (math.pi * hardness))
    n = 96
    dx = 2.6 * radius / n
    res = solve_normal(gap_grid(sphere_gap(n, dx, R), dx, origin=(-(n // 2) * dx, -(n // 2) * dx)),
                       e_star=E_STAR, load=W, bounds=PressureBounds.elastic(hardness),
                       options=SolveOptions(tol=1e-8))
    assert drives and set(drives) == {iteration.PolonskyKeer}
    assert res.pmax == pytest.approx(hardness, rel=1e-9)
    assert res.contact_radius == pytest.approx(radius, rel=0.05)


DELTA = 0.01  # the sinusoid's amplitude (wavelength 1, E* = 1, tests/adhesion_cases.py)
P_STAR = math.pi * DELTA  # Westergaard's full-contact pressure pi E* Delta / L


def _mean_pressure(st, dx: float) -> float:
    return st.load / (st.gap.size * dx * dx) / P_STAR


def test_adhesive_solve_at_an_approach_runs_the_driver_and_is_westergaard(drives):
    """w -> 0: p / p* = sin^2(pi a / L) to 2e-3 (tests/test_adhesion_validation.py)."""
    prob = wavy_problem(1e-3, 1024, 0.005)
    st = solve_adhesive(prob, 0.3 * DELTA, tol=1e-6)
    assert drives == [descent.AcceleratedGradient]
    a = strip_half_width(st.gap, prob.dx)
    assert 0.05 < a < 0.2
    assert _mean_pressure(st, prob.dx) == pytest.approx(math.sin(math.pi * a) ** 2, abs=2e-3)


@pytest.mark.parametrize("single", [False, True])
def test_adhesive_solve_under_a_load_runs_the_driver_and_is_westergaard(drives, single):
    """The load-controlled solve at w -> 0 and p = 0.3 p*: the strips' half-width is
    Westergaard's, asin(sqrt(0.3)) / pi, to a cell (float64 and float32 transforms)."""
    prob = wavy_problem(1e-3, 1024, 0.005)
    st = solve_adhesive_at_pressure(prob, 0.3 * P_STAR, np.maximum(prob.gap0 - 0.003, 0.0),
                                    tol=1e-4 if single else 1e-6, single=single)
    assert drives and set(drives) == {descent.AcceleratedGradient}
    a = strip_half_width(st.gap, prob.dx)
    assert a == pytest.approx(math.asin(math.sqrt(0.3)) / math.pi, abs=prob.dx)
    assert _mean_pressure(st, prob.dx) == pytest.approx(0.3, rel=1e-9)


def test_adhesive_wavy_surface_follows_johnson_through_the_driver(drives):
    """alpha = 0.3: p(a) within 0.03 p* of Johnson's sin^2 - alpha sqrt(tan) (the
    validation's bound) at both controls, the adhesive term 0.12-0.18 p* of it."""
    alpha = 0.3
    prob = wavy_problem(alpha, 1024, 0.005)
    st = solve_adhesive(prob, 0.15 * DELTA, None, tol=1e-6)
    p = _mean_pressure(st, prob.dx)
    assert p == pytest.approx(float(mean_pressure(strip_half_width(st.gap, prob.dx), alpha)),
                              abs=0.03)
    under_load = solve_adhesive_at_pressure(prob, p * P_STAR, st.gap, tol=1e-6)
    a = strip_half_width(under_load.gap, prob.dx)
    assert p == pytest.approx(float(mean_pressure(a, alpha)), abs=0.03)
    assert abs(p - math.sin(math.pi * a) ** 2) > 0.1
    assert drives == [descent.AcceleratedGradient] * 2


def test_adhesive_stiffness_is_the_inverse_of_the_normal_solves_operator():
    """The adhesive elastic term undoes the periodic operator of solve_normal: the pressure
    of u = K * p / E* is p (its mean held by no spring under load control), and the
    stiffness is E* |q| / 2 at long wavelengths (Westergaard)."""
    from contact.adhesion.laws import DugdaleLaw
    from contact.adhesion.solver import adhesive_problem
    from contact.halfspace.convolution import convolution

    n, dx, e_star = 64, 1e-6, 2e9
    prob = adhesive_problem(np.zeros((n, n)), dx, e_star, DugdaleLaw(0.05, 1e7))
    assert prob.operator is convolution(n, n, dx, dx, True)
    rng = np.random.default_rng(3)
    p = rng.normal(size=(n, n)) * 1e6
    p -= p.mean()
    u = prob.operator(p) / e_star
    back = prob.operator.spectral(u, prob.elastic_stiffness(False))
    assert np.abs(back - p).max() < 1e-9 * np.abs(p).max()
    q = 2.0 * math.pi / (n * dx)
    assert prob.stiffness[0, 1] == pytest.approx(e_star * q / 2.0, rel=1e-3)
    assert prob.stiffness[1, 0] == pytest.approx(e_star * q / 2.0, rel=1e-3)
