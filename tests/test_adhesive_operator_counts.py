"""The adhesive solves on the one operator protocol: the line contact's approach range
takes its displacement from the problem's operator, and every adhesive solve counts its
convolutions into its SolveRecord as the normal BEM does (issues 36/37, leftovers).

Truths used: a uniform pressure on a periodic domain displaces only the mean plane, by
p / (the mean-plane spring); the displacement the stiffness S defines is
irfft(rfft(p) / S), the solver's own definition (contact.adhesion.solver), here written
out with numpy's FFT; the convolutions run are counted by wrapping the operator's
``spectral``, not read from the solver.
"""

from __future__ import annotations

import numpy as np
import pytest

import contact.adhesion.line as line
from contact._record import combine
from contact.adhesion.laws import DugdaleLaw
from contact.adhesion.solver import (
    adhesive_problem,
    solve_adhesive,
    solve_adhesive_at_pressure,
)
from contact.halfspace.convolution import Convolution

E_STAR, R = 1e9, 10e-6
LAW = DugdaleLaw.from_range(0.05, 2e-9)


def _line_problem(cells: int = 512, dx: float = 2e-9):
    grid = line.periodic_line_grid(cells, dx)
    h = grid.x * grid.x / (2 * R)
    return line.line_problem(grid.with_gap(h.reshape(1, -1)), E_STAR, LAW), grid.x


def _by_stiffness(problem, pressure: np.ndarray) -> float:
    u = np.fft.irfft(np.fft.rfft(pressure) / problem.stiffness[0], n=pressure.size)
    k = int(np.argmin(problem.gap0))
    return float(problem.gap0[0, k] + u[k])


def test_line_approach_comes_from_the_operator(monkeypatch):
    """_approach_of applies the problem's operator (a call is seen) and gives the
    stiffness's displacement within 1e-8 (Hertz, punch-like and random pressures); a
    uniform pressure moves the apex by p / spring only."""
    problem, x = _line_problem()
    calls = []
    real = Convolution.__call__

    def counting(self, *a, **k):
        calls.append(self.shape)
        return real(self, *a, **k)

    monkeypatch.setattr(Convolution, "__call__", counting)
    a = 40e-9
    hertz = E_STAR / (2 * R) * np.sqrt(np.maximum(a * a - x * x, 0.0))
    punch = np.where(np.abs(x) < a, -1e7 / np.sqrt(np.maximum(a * a - x * x, 1e-24)), 0.0)
    noise = np.random.default_rng(7).normal(0.0, 1e7, x.size)
    for p in (hertz, hertz + punch, noise):
        want = _by_stiffness(problem, p)
        assert line._approach_of(problem, p) == pytest.approx(want, rel=1e-8, abs=0.0)
    assert calls and all(s == problem.gap0.shape for s in calls)
    uniform = np.full(x.size, 3e6)
    k = int(np.argmin(problem.gap0))
    assert line._approach_of(problem, uniform) == pytest.approx(
        problem.gap0[0, k] + 3e6 / problem.spring, rel=1e-12)


@pytest.fixture
def spectral_calls(monkeypatch):
    """Every stiffness application by the operator's transforms, by precision."""
    calls = {"single": 0, "double": 0}
    real = Convolution.spectral

    def counting(self, x, multiplier, single=False, *a, **k):
        calls["single" if single else "double"] += 1
        return real(self, x, multiplier, single, *a, **k)

    monkeypatch.setattr(Convolution, "spectral", counting)
    return calls


def _ball_problem(n: int = 32, dx: float = 5e-8):
    x = (np.arange(n) - n // 2) * dx
    return adhesive_problem((x[:, None] ** 2 + x[None, :] ** 2) / (2 * R), dx, E_STAR, LAW)


def test_an_adhesive_solve_counts_its_convolutions(spectral_calls):
    """Approach control (float64) and load control (float32) record in
    ``solve.counters`` the convolutions they ran, the record's float64 one included,
    their iterations and their grid level (no counters before)."""
    problem = _ball_problem()
    state = solve_adhesive(problem, 2e-9)
    c = state.solve.counters
    assert c is not None
    assert c["fft_double"] == spectral_calls["double"] and c["fft_single"] == 0
    assert c["iterations"] == state.solve.iterations == spectral_calls["double"] - 1
    assert c["levels"] == ((32, 32, state.solve.iterations),)

    spectral_calls.update(single=0, double=0)
    loaded = solve_adhesive_at_pressure(problem, 1e6, state.gap, tol=1e-4, single=True)
    c = loaded.solve.counters
    assert c["fft_single"] == spectral_calls["single"] == loaded.solve.iterations > 0
    assert c["fft_double"] == spectral_calls["double"] == 1


def test_a_line_cycle_counts_every_solve(spectral_calls):
    """A cycle's combined record sums the counters of its solves: every convolution the
    adhesive line ran is in ``cycle.solve.counters``."""
    res = line.adhesive_line(R, E_STAR, LAW, cells=128, steps=6)
    c = res.cycle.solve.counters
    assert c is not None and c["fft_single"] == spectral_calls["single"] == 0
    assert c["fft_double"] == spectral_calls["double"] > 0
    assert len(c["levels"]) == res.cycle.solve.solves
    assert c["iterations"] == res.cycle.solve.iterations


def test_combined_counters_need_every_solve():
    """A combination of records where one kept no counters has none (a partial sum would
    pass for the whole work); with all kept, counts add and levels follow one another."""
    state = solve_adhesive(_ball_problem(16), 2e-9)
    rec = state.solve
    both = combine([rec, rec])
    assert both.counters["fft_double"] == 2 * rec.counters["fft_double"]
    assert both.counters["levels"] == 2 * rec.counters["levels"]
    import dataclasses
    bare = dataclasses.replace(rec, counters=None)
    assert combine([rec, bare]).counters is None
