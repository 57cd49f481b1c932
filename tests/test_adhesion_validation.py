"""Adhesion validated against closed forms: JKR, Johnson's wavy JKR, Maugis' P(a), energy.

Truths: Westergaard's non-adhesive wavy contact and Johnson's (1995) JKR solution for a
sinusoid (tests/johnson_wavy.py, re-derived from the periodic flat punch's stress
intensity); the Maugis-Dugdale load against the inner contact radius (tests/
maugis_reference.py, Maugis 1992 in Johnson & Greenwood's 1997 notation), whose limits are
DMT's pull-off 2 pi w R and JKR's 3 pi w R / 2 and a0 = (9 pi w R^2 / (2 E*))^(1/3); the
energy balance of a displacement-controlled cycle.

Discretisation: with the plain Dugdale step a cell releases all of its tension at once
when its gap passes h0, so the end of the cohesive zone is trapped by the pixels (lattice
trapping); on retraction the contact stays larger than its equilibrium and the tension
comes out too large, by an error first order in the pixel over the cohesive zone's width
l = pi E* w / (4 sigma0^2) (about 0.7 dx / l on the pull-off, for the sphere and the wavy
surface alike; benchmarks/adhesion_convergence.py). Those tests use Richardson
extrapolation of two grids. Smoothing the step over about a cell's change of gap
(DugdaleLaw.on_grid: a ramp 5 sigma0 dx / E* wide, same work and peak) removes the
trapping, and Maugis' curve is then met on single grids (tests/maugis_sphere.py).

Contact radius: Maugis' a is the radius of the compressive (touching) zone, not the
cohesive zone's outer radius c. The older tests read it as the radius of the disc of the
touching cells' area (tests/adhesion_cases.contact_radius), the wavy strip's half-width
as half the touching length. Counting reads a only to about a pixel, and P(a) is steep
(dP/da about 3 pi w R / l_M at a = 1.5 l_M), so the smoothed-law tests read it sub-pixel
(contact.adhesion.ball.edge_radius: the zero of g^(2/3), linear in r at the edge).

Norm of the load-radius curve: md_curve_error = |P - P_MD(a)| / max(|P_MD(a)|, P_c), P_c
Maugis' pull-off: the load's relative error where |P| exceeds the pull-off, and the error
over the pull-off near zero load, where a relative error has no meaning. Its largest value
over the retraction states with a of four pixels or more and a <= 1.9 l_M is asserted
below 2 %. Measured (benchmarks/adhesion_maugis.py, smoothed step, 24 steps; pull-off error,
curve max / rms, the same with a counted; CPU s on 2 shared cores):

    lambda  grid  cell  zone px  pull-off  curve max  rms    counted max  CPU s
    0.1      72    6     252     -0.96 %    4.9 %   2.3 %    32.8 %        4
    0.1     144    6     504     -0.00 %    1.6 %   0.6 %     9.9 %       17
    0.3      72    6     48.5    +0.30 %    3.7 %   1.2 %    11.2 %        4
    0.3     144    6     97.1    +0.48 %    1.5 %   0.6 %     4.1 %       18
    1        48    6     3.30    +1.44 %    3.6 %   1.6 %    23.0 %        2
    1        72    6     4.95    +1.06 %    2.8 %   0.9 %    12.3 %        3
    1        96    6     6.60    +0.92 %    1.2 %   0.5 %     6.5 %        6
    1       144    6     9.91    +0.66 %    0.9 %   0.4 %     6.9 %       13
    3       256    4     2.94    +1.17 %    1.6 %   0.8 %     2.3 %       42
    5       256    4     1.06    +2.93 %    3.1 %   1.7 %     3.4 %       48
    5       384    4     1.58    +1.34 %    2.0 %   0.8 %     2.6 %      153
    5       512    4     2.11    +1.14 %    1.7 %   0.8 %     1.9 %      367
    3       384    4     4.40    +0.99 %    1.6 %   0.8 %     1.9 %      149

With the plain step, lambda = 1, cell 6: pull-off +24.8 %, +11.0 %, +6.2 % and curve max
30 %, 11 %, 8.0 % on 48^2, 96^2, 144^2 (first order); reading a sub-pixel alone does not
help there (rms 0.085 -> 0.080 pi w R at lambda 1 on 96^2, cell 4): the trapped states
are off the curve, not misread. The smoothed step's remaining pull-off error falls about
as the pixel with a coefficient some twenty times smaller, and includes the periodic
images' bending of the sphere (about +0.25 % at cell 6 and +0.7 % at cell 4 at lambda 1,
measured by varying the cell at fixed pixel).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from adhesion_cases import (
    A_SCALE,
    E_STAR,
    P_SCALE,
    R,
    W,
    contact_radius,
    dugdale,
    retraction,
    strip_half_width,
    wavy_problem,
)
from johnson_wavy import mean_pressure
from johnson_wavy import pull_off as johnson_pull_off
from maugis_reference import md_curve, md_load_at_radius, md_pull_off
from maugis_sphere import maugis_run

from contact import DomainSpec
from contact.adhesion.ball import adhesive_ball
from contact.adhesion.cycle import refine_pull_off, run_branch
from contact.adhesion.laws import ExponentialLaw
from contact.adhesion.solver import solve_adhesive

DELTA = 0.01  # the sinusoid's amplitude (wavelength 1, E* = 1)
P_STAR = math.pi * DELTA  # Westergaard's full-contact pressure pi E* Delta / L


def _mean_pressure(st, dx: float) -> float:
    return st.load / (st.gap.size * dx * dx) / P_STAR


def test_wavy_without_adhesion_is_westergaard():
    """w -> 0 on a 1024 x 4 grid: p / p* = sin^2(pi a / L) to 2e-3 (the setup's check)."""
    prob = wavy_problem(1e-3, 1024, 0.005)
    st = solve_adhesive(prob, 0.3 * DELTA, tol=1e-6)
    a = strip_half_width(st.gap, prob.dx)
    assert 0.05 < a < 0.2
    assert _mean_pressure(st, prob.dx) == pytest.approx(math.sin(math.pi * a) ** 2, abs=2e-3)
    assert np.array_equal(st.gap[0], st.gap[3])  # the rows agree: plane strain


def test_wavy_jkr_follows_johnson():
    """alpha = 0.3, 1024 x 4 grid, cohesive zone 5 pixels: p(a) within 0.03 p* of Johnson's
    sin^2 - alpha sqrt(tan) while the adhesive term is 0.12-0.18 p* (so the test tells it
    from Westergaard's); measured 0.021 p* at the unloaded state, the pixel pinning."""
    alpha = 0.3
    prob = wavy_problem(alpha, 1024, 0.005)
    st = None
    for d in (0.3, 0.15, 0.0):
        st = solve_adhesive(prob, d * DELTA, None if st is None else st.gap, tol=1e-6)
        a = strip_half_width(st.gap, prob.dx)
        p = _mean_pressure(st, prob.dx)
        assert p == pytest.approx(float(mean_pressure(a, alpha)), abs=0.03)
        assert abs(p - math.sin(math.pi * a) ** 2) > 0.1


def _wavy_pull_off(alpha: float, nx: int, zone: float) -> float:
    prob = wavy_problem(alpha, nx, zone)
    steps = np.linspace(0.3 * DELTA, -0.6 * DELTA, 31)
    br, gaps = run_branch(prob, steps, (1.2 * DELTA, None), tol=1e-7)
    force, _ = refine_pull_off(prob, br, gaps, tol=1e-7)
    return force / (prob.gap0.size * prob.dx ** 2) / P_STAR


@pytest.mark.slow
@pytest.mark.campaign
def test_wavy_jkr_pull_off_converges_to_johnson():
    """alpha = 0.3, zone 0.005 L: the pull-off on 1024 and 2048 cells (5 and 10 pixels of
    zone) overestimates Johnson's 0.0959 p* by +14.7 % and +8.4 % (measured), a first-order
    error; their Richardson extrapolation is Johnson's JKR value to 3 % (measured +2.0 %),
    a bound that also holds the Dugdale zone's own departure from JKR."""
    truth, _ = johnson_pull_off(0.3)
    coarse, fine = (_wavy_pull_off(0.3, n, 0.005) for n in (1024, 2048))
    assert truth < fine < coarse
    assert fine - truth < 0.7 * (coarse - truth)  # measured 0.57: first order
    assert 2 * fine - coarse == pytest.approx(truth, rel=0.03)  # measured +2.0 %


def _md_retraction(lam: float, n: int) -> tuple[np.ndarray, np.ndarray]:
    """(a, P) of the retraction states in Maugis' units (a over l_M, P over pi w R)."""
    prob, br, gaps = retraction(lam, n, steps=24)
    a = np.array([contact_radius(g, prob.dx) for g in gaps]) / A_SCALE
    return a, br.load / P_SCALE


def _zero_load_radius(a: np.ndarray, load: np.ndarray) -> float:
    """The contact radius where the retraction's load first turns tensile (interpolated)."""
    k = int(np.flatnonzero((load[:-1] > 0) & (load[1:] <= 0))[0])
    return float(a[k] + (a[k + 1] - a[k]) * load[k] / (load[k] - load[k + 1]))


def _md_zero_load_radius(lam: float) -> float:
    """Maugis-Dugdale's contact radius at zero load (over l_M)."""
    m = 1.0 + np.logspace(-9, 3, 40001)
    big_a, p = md_curve(lam, m)
    k = int(np.flatnonzero(np.diff(np.sign(p)))[0])
    return float(big_a[k] + (big_a[k + 1] - big_a[k]) * p[k] / (p[k] - p[k + 1]))


@pytest.mark.slow
@pytest.mark.campaign
@pytest.mark.parametrize("lam", [0.3, 1.0])
def test_maugis_load_against_contact_radius(lam):
    """The retraction's (a, P) pairs against Maugis-Dugdale's P(a), 48^2 and 96^2 cells
    (cell 4 x the JKR radius at zero load), over 0.3 <= a / l_M <= 1.9 (l_M the Maugis
    length): the RMS error is below 0.12 pi w R on 96^2 and halves with the pixel
    (measured 0.178 -> 0.085 at lambda 1, 0.084 -> 0.040 at 0.3); the error is a bias (the
    pinned contact is too large for its load) whose Richardson extrapolation, 2 e_96 - e_48
    of the mean signed error, is zero to 0.02 pi w R (measured +0.003 and -0.008). No single
    grid here is within 2 % of pi w R pointwise. The contact radius at zero load is
    Maugis' to 2 % on 96^2. Not asserted (measured, same grids): lambda 0.1, RMS 0.181 ->
    0.073, extrapolated bias +0.020, zero-load radius +1.4 %; lambda 2 (zone 1.2 and 2.5
    pixels, under-resolved), RMS 0.478 -> 0.285, bias -0.073, zero-load radius +4.9 %."""
    rms, bias = [], []
    for n in (48, 96):
        a, load = _md_retraction(lam, n)
        keep = (a >= 0.3) & (a <= 1.9)
        assert keep.sum() >= 8
        err = load[keep] - md_load_at_radius(lam, a[keep])
        rms.append(float(np.sqrt(np.mean(err ** 2))))
        bias.append(float(err.mean()))
    # the contact radius at zero load, 96^2: measured +0.3 % (0.3) and +0.9 % (1)
    assert _zero_load_radius(a, load) == pytest.approx(_md_zero_load_radius(lam), rel=0.02)
    assert rms[1] < 0.12
    assert rms[1] < 0.75 * rms[0]
    assert abs(2 * bias[1] - bias[0]) < 0.02


def _retraction_record(lam: float, n: int) -> tuple[np.ndarray, np.ndarray, float]:
    """(a, P, pull-off) of a retraction in Maugis' units; pull-off golden-section refined."""
    prob, br, gaps = retraction(lam, n, steps=24)
    force, _ = refine_pull_off(prob, br, gaps, tol=1e-6)
    a = np.array([contact_radius(g, prob.dx) for g in gaps]) / A_SCALE
    return a, br.load / P_SCALE, force / P_SCALE


#: lambda: (grids, pull-off tolerance against JKR's 3/2, zero-load radius tolerance against
#: JKR's a0). Maugis' own curve departs from JKR by +2.3 % / -4.4 % at lambda 2 and
#: +1.1 % / -2.3 % at lambda 3; the tolerances are those departures plus the 2 % (pull-off)
#: and 1 % (radius) asserted against Maugis.
JKR_SIDE = {2.0: ((128, 256), 0.04, 0.055), 3.0: ((256, 512), 0.015, 0.03)}


@pytest.mark.slow
@pytest.mark.campaign
@pytest.mark.parametrize("lam", sorted(JKR_SIDE))
def test_jkr_limit(lam):
    """The JKR end of the transition: Richardson extrapolation of two grids (cohesive zone
    3.3 and 6.6 pixels at lambda 2 on 128^2/256^2; 2.9 and 5.9 at lambda 3 on 256^2/512^2).

    Measured, lambda 2: pull-off +16.2 % and +8.6 % on the grids, extrapolated +0.9 % from
    Maugis-Dugdale and +3.3 % from JKR's 3 pi w R / 2; zero-load radius -0.05 % from
    Maugis'. lambda 3: pull-off +17.6 % and +8.5 %, extrapolated -0.6 % from Maugis and
    +0.5 % from 3 pi w R / 2; zero-load radius -0.02 % from Maugis' and -2.3 % from JKR's
    a0 = (9 pi w R^2 / (2 E*))^(1/3) (Maugis' own departure); P(a) bias extrapolated to
    -0.008 and -0.0005 pi w R. Asserted: pull-off within 2 % of Maugis and within the
    JKR_SIDE tolerance of 3 pi w R / 2; zero-load radius within 1 % of Maugis' and the
    JKR_SIDE tolerance of a0; P(a) bias within 0.02 pi w R. Measured run times on 2 shared
    cores: 51 s (lambda 2) and 221 s (lambda 3)."""
    grids, tol_pull, tol_radius = JKR_SIDE[lam]
    runs = [_retraction_record(lam, n) for n in grids]
    (a0, p0, coarse), (a1, p1, fine) = runs
    truth = md_pull_off(lam)
    assert truth < fine < coarse and fine - truth < 0.6 * (coarse - truth)
    assert 2 * fine - coarse == pytest.approx(truth, rel=0.02)
    assert 2 * fine - coarse == pytest.approx(1.5, rel=tol_pull)  # JKR: 3 pi w R / 2
    radii = [_zero_load_radius(a, p) for a, p in ((a0, p0), (a1, p1))]
    radius = 2 * radii[1] - radii[0]
    assert radius == pytest.approx(_md_zero_load_radius(lam), rel=0.01)
    assert radius == pytest.approx(6 ** (1 / 3), rel=tol_radius)  # JKR's a0 / l_M
    bias, rms = [], []
    for a, p in ((a0, p0), (a1, p1)):
        keep = (a >= 0.3) & (a <= 1.9)
        err = p[keep] - md_load_at_radius(lam, a[keep])
        bias.append(float(err.mean()))
        rms.append(float(np.sqrt(np.mean(err ** 2))))
    assert rms[1] < 0.75 * rms[0]
    assert abs(2 * bias[1] - bias[0]) < 0.02


def _released(cycle) -> tuple[np.ndarray, np.ndarray]:
    """Per step of both legs: (energy released, work done), J. The work is the trapezoidal
    integral of the load over the surface approach; the energy is read from the fields
    (elastic plus the interaction law integrated over the interface)."""
    released, work = [], []
    for leg in (cycle.approach_leg, cycle.retraction_leg):
        w = 0.5 * (leg.load[1:] + leg.load[:-1]) * np.diff(leg.surface_approach)
        released.append(w - np.diff(leg.energy))
        work.append(w)
    return np.concatenate(released), np.concatenate(work)


@pytest.mark.slow
@pytest.mark.campaign
@pytest.mark.parametrize("case", ["dugdale_2", "exponential_1"])
def test_cycle_energy_balance(case):
    """Per cycle (32^2, 24 steps a leg): the machine's work over the closed cycle (closed
    integral of P over the rigid approach, Cycle.hysteresis_energy) equals the energy
    released step by step as read from the interface's fields, to 1e-6 (measured 2e-14);
    no step creates energy beyond 2 % of the largest step's work (the trapezoidal rule's
    error; measured -1.6 %, -0.5 %). Dugdale at lambda = 2 jumps and loses energy; the
    exponential law at lambda = 1 has a single-valued P(delta) and loses none (measured
    1e-7 of the work done on a leg)."""
    law = (dugdale(2.0) if case == "dugdale_2"
           else ExponentialLaw(W, W / dugdale(1.0).sigma0))
    cycle = adhesive_ball(R, E_STAR, law, steps=24, domain=DomainSpec(grid=32)).cycle
    released, work = _released(cycle)
    scale = float(np.abs(work).sum())
    assert released.sum() == pytest.approx(cycle.hysteresis_energy, abs=1e-6 * scale)
    assert released.min() > -0.02 * np.abs(work).max()
    if case == "dugdale_2":
        assert cycle.hysteresis_energy > 0.1 * scale
    else:
        assert abs(cycle.hysteresis_energy) < 1e-4 * scale


def test_dmt_and_jkr_pull_offs_bracket_maugis():
    """The truth used above: Maugis' pull-off runs from DMT's 2 pi w R (lambda -> 0) to
    JKR's 3 pi w R / 2 (lambda -> infinity), 1.1 % above JKR at lambda = 3; its contact
    radius at zero load tends to JKR's a0 = (9 pi w R^2 / (2 E*))^(1/3) = 6^(1/3) l_M
    (0.9 % below at lambda = 5)."""
    assert md_pull_off(0.01) == pytest.approx(2.0, rel=0.01)
    assert md_pull_off(20.0) == pytest.approx(1.5, rel=0.001)
    assert md_pull_off(3.0) == pytest.approx(1.5, rel=0.012)
    a0 = (4.5 * math.pi * W * R * R / E_STAR) ** (1 / 3) / A_SCALE
    assert a0 == pytest.approx(6 ** (1 / 3), rel=1e-12)
    assert _md_zero_load_radius(20.0) == pytest.approx(a0, rel=1e-3)
    assert _md_zero_load_radius(5.0) == pytest.approx(a0, rel=0.01)


def test_maugis_curve_meets_jkr_and_dmt_curves():
    """The reference P(a) itself (tests/maugis_reference.py) against the closed-form ends:
    JKR's P = A^3 - sqrt(6 A^3) (Johnson, Kendall & Roberts 1971) at lambda = 50 and
    DMT's P = A^3 - 2 (Derjaguin, Muller & Toporov 1975) at lambda = 0.001, in Maugis'
    units, over 0.5 <= A <= 2 (measured 0.0013 and 0.012; at lambda = 10 and 0.01 the
    departures are 0.031 and 0.11, so the ends are approached, not assumed)."""
    big_a = np.linspace(0.5, 2.0, 16)
    jkr = big_a ** 3 - np.sqrt(6.0 * big_a ** 3)
    assert np.abs(md_load_at_radius(50.0, big_a) - jkr).max() < 0.002
    assert np.abs(md_load_at_radius(10.0, big_a) - jkr).max() > 0.02
    assert np.abs(md_load_at_radius(1e-3, big_a) - (big_a ** 3 - 2.0)).max() < 0.02


def test_smoothed_dugdale_pull_off_on_a_coarse_grid():
    """Fast check of the smoothed Dugdale step (DugdaleLaw.on_grid) at lambda = 1 on 40^2
    (cell 4, cohesive zone 4.1 pixels, 12 retraction steps): the pull-off is Maugis' to
    2 % (measured +1.25 %; the plain step gives +20.4 % on this grid) and the (a, P) pairs
    are on Maugis' curve to 3 % rms (md_curve_error, measured 2.1 %; the plain step 12.6 %)."""
    run = maugis_run(1.0, 40, cell=4.0, steps=12)
    assert abs(run.pull_off_error) < 0.02
    err = run.curve_error()
    assert err.size >= 20
    assert np.sqrt(np.mean(err ** 2)) < 0.03


@pytest.mark.slow
@pytest.mark.campaign
@pytest.mark.parametrize("lam", [0.1, 0.3, 1.0])
def test_maugis_pull_off_and_curve_to_two_percent(lam):
    """The transition's DMT side and middle on single grids: smoothed Dugdale step, cell 6
    x the larger of a0 and the zone's reach, 72^2 and 144^2, 24 retraction steps. On 144^2
    the pull-off is Maugis' to 2 % and every retraction state (a, P) with a >= 4 pixels and
    a <= 1.9 l_M is on Maugis' curve to 2 % in md_curve_error (|P - P_MD(a)| over the
    larger of |P_MD(a)| and the pull-off), with a read sub-pixel; the rms of that error
    falls from 72^2 to 144^2. See the module notes for the measured table. CPU time of
    both grids: 21 s, 22 s and 16 s (lambda 0.1, 0.3, 1; 28-45 s wall at load 3)."""
    coarse, fine = maugis_run(lam, 72), maugis_run(lam, 144)
    assert abs(fine.pull_off_error) < 0.02
    err = fine.curve_error()
    assert err.size >= 30
    assert err.max() < 0.02
    rms = [float(np.sqrt(np.mean(r.curve_error() ** 2))) for r in (coarse, fine)]
    assert rms[1] < 0.8 * rms[0]


def test_smoothed_dugdale_law_keeps_work_and_peak():
    """The ramp keeps the work (integral of t over the gap) and the peak; the potential is
    the traction's integral (finite differences); a ramp wider than h0 or negative is one
    input error."""
    from contact._errors import ContactInputError
    from contact.adhesion.laws import DugdaleLaw

    law = DugdaleLaw(2.0, 4.0, smoothing=0.3)  # h0 = 0.5
    g = np.linspace(0.0, 1.0, 200001)
    t = law.traction(g)
    assert t[0] == 4.0 and law.reach == pytest.approx(0.65)
    assert np.sum(0.5 * (t[1:] + t[:-1]) * np.diff(g)) == pytest.approx(2.0, rel=1e-9)
    phi = law.potential(g)
    assert phi[0] == pytest.approx(-2.0) and phi[-1] == 0.0
    assert np.allclose(np.diff(phi) / np.diff(g), 0.5 * (t[1:] + t[:-1]), atol=1e-6)
    assert DugdaleLaw(2.0, 4.0).traction(0.49) == 4.0  # the plain step is kept
    for bad in (-0.1, 0.6, math.nan):
        with pytest.raises(ContactInputError, match="smoothing"):
            DugdaleLaw(2.0, 4.0, smoothing=bad)


#: lambda: (grid, cell, tolerance of the curve's largest error). The JKR side's zone is
#: narrow (1 to 3 pixels here), so the cell is 4 x a0 to keep the grid affordable.
JKR_SIDE_SMOOTHED = {3.0: (256, 4.0, 0.02), 5.0: (512, 4.0, 0.02)}


@pytest.mark.slow
@pytest.mark.campaign
@pytest.mark.parametrize("lam", sorted(JKR_SIDE_SMOOTHED))
def test_maugis_jkr_side_smoothed(lam):
    """The transition's JKR side on single grids with the smoothed Dugdale step (24
    retraction steps): lambda 3 on 256^2 (zone 2.9 pixels), lambda 5 on 512^2 (2.1
    pixels), cell 4 x a0. The pull-off is Maugis' to 2 % (measured +1.17 % and +1.14 %;
    the plain step gives +17.6 % at lambda 3 on 256^2) and the (a, P) pairs' rms
    md_curve_error is below 2 % (measured 0.8 % and 0.8 %); their largest error is below
    2 % (measured 1.6 % and 1.7 %; at lambda 5 3.1 % on 256^2 and 2.0 % on 384^2, the
    grid's convergence). Measured CPU time on 2 shared cores: 42 s and 367 s."""
    n, cell, tol = JKR_SIDE_SMOOTHED[lam]
    run = maugis_run(lam, n, cell)
    assert abs(run.pull_off_error) < 0.02
    err = run.curve_error()
    assert err.size >= 30
    assert np.sqrt(np.mean(err ** 2)) < 0.02
    assert err.max() < tol
