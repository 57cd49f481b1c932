"""How a cycle's jump-in and jump-out are classified (contact.adhesion.cycle.find_jump).

The stated criterion: a transition is abrupt when the load changes across its step by more
than 3 times what a continuous branch could, the elastic change at the touching area's
punch stiffness 2 E* sqrt(A / pi) (Sneddon 1965; Pharr, Oliver & Brotzen 1992) plus the
interaction's pull on the side without contact. The truths here are Hertz's continuous
rise (Johnson 1985, eq. 4.22-4.23) and hand-built branches whose bound is worked by hand.
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from contact import DomainSpec
from contact._record import SolveRecord
from contact.adhesion.cycle import Branch, find_jump

E_STAR = 1e9
_REC = SolveRecord(method="test", iterations=1, residual=0.0, tolerance=1.0, converged=True,
                   edge_contact=False)


def _branch(approach, load, area) -> Branch:
    a = np.asarray(approach, dtype=float)
    return Branch(approach=a, surface_approach=a, load=np.asarray(load, dtype=float),
                  contact_area=np.asarray(area, dtype=float), energy=np.zeros(a.size),
                  iterations=np.ones(a.size, dtype=int), solve=_REC)


def test_a_snap_among_large_neighbouring_steps_is_abrupt():
    """A rough contact's steps on the touching side are large (100 uN here); a 42 uN snap
    onto one tiny contact (A = 1e-14 m^2, stiffness 2 E* sqrt(A/pi) = 113 N/m, so 1.1e-8 N
    over the 0.1 nm step) is far faster than any continuous branch: abrupt. (The rule it
    replaces compared 42 uN with the 100 uN neighbours and called it smooth.)"""
    s, area = 1e-10, 1e-14
    br = _branch(s * np.arange(5), [0.0, -1e-9, 42e-6, 142e-6, 242e-6],
                 [0.0, 0.0, area, area, area])
    bound = 2 * E_STAR * math.sqrt(area / math.pi) * s + 1e-9
    assert 42e-6 > 3 * bound
    jump = find_jump(br, entering=True, e_star=E_STAR, reach=2e-9)
    assert jump.abrupt and jump.resolved and jump.load_after == 42e-6
    # leaving the same way round is abrupt too
    out = _branch(s * np.arange(5)[::-1], [242e-6, 142e-6, 42e-6, -1e-9, 0.0],
                  [area, area, area, 0.0, 0.0])
    assert find_jump(out, entering=False, e_star=E_STAR).abrupt


def test_hertz_first_contact_is_a_smooth_rise_and_a_wide_step_is_unresolved():
    """Hertz's sphere (P = 4/3 E* sqrt(R) d^1.5, A = pi R d) first touching inside a step is
    continuous: the step's load change is below 2 E* sqrt(A/pi) times the step."""
    R, s = 1e-5, 1e-9
    d = s * np.array([-2.0, -1.0, 0.3, 1.3, 2.3])
    pen = np.maximum(d, 0.0)
    br = _branch(d, 4 / 3 * E_STAR * math.sqrt(R) * pen**1.5, math.pi * R * pen)
    jump = find_jump(br, entering=True, e_star=E_STAR, reach=2e-9)
    assert not jump.abrupt and jump.resolved
    wide = find_jump(br, entering=True, e_star=E_STAR, reach=0.5e-9)
    assert not wide.abrupt and not wide.resolved  # a 1.3 nm step against a 0.5 nm range


def test_the_smooth_ball_snaps_in_and_out():
    """JKR-like ball (lambda ~ 1.6): the contact snaps in and out (Maugis 1992), and the
    steps are finer than the 2 nm range."""
    from contact.adhesion.ball import adhesive_ball
    from contact.adhesion.laws import DugdaleLaw

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        cyc = adhesive_ball(
            1e-5, E_STAR, DugdaleLaw.from_range(0.05, 2e-9), steps=6, domain=DomainSpec(grid=16)
        ).cycle
    for jump in (cyc.jump_in, cyc.jump_out):
        assert jump.abrupt and jump.resolved
