"""3D steady rolling tractions on a viscoelastic half-space (contact.viscoelastic.traction3d).

Independent truths: the elastic tangential solver of contact.tangential with the relaxed
and glassy moduli (the limits V tau/a -> 0 and -> inf), Coulomb's full-slip limit
|F_x| = mu N, and Kalker's linear creep coefficient C11 = 4.12 of a circular contact at
nu = 0.25 (Kalker 1990, Table E.3).
"""

from __future__ import annotations

import numpy as np
import pytest

from contact.errors import ContactInputError
from contact.tangential import Creepage, steady_rolling
from contact.tangential.grid import Grid
from contact.viscoelastic.rheology import StandardLinearSolid
from contact.viscoelastic.traction3d import (
    constants_at,
    rolling_sphere_tractions,
    visco_steady_tractions,
)

R, N, V = 0.01, 10.0, 1.0
TAUS = {"relaxed": 1e-9, "glassy": 1e3}


def _sls(tau: float, nu: float = 0.3):
    return StandardLinearSolid(3e9, 1e9, tau, nu)


def _hertz_a(c) -> float:
    return (3 * N * R / (4 * c.e_star)) ** (1 / 3)


@pytest.mark.parametrize("limit", ["relaxed", "glassy"])
def test_elastic_limits_force_creepage_curve(limit):
    """tau -> 0 and tau -> inf: F_x(xi) of the elastic solver with E_r or E_g, to 1 %,
    on 64 x 64 (the elastic solver solves its own pressure on the same grid)."""
    nu, mu = 0.3, 0.3
    cr = _sls(TAUS[limit], nu).creep()
    c = constants_at(cr.relaxed if limit == "relaxed" else cr.glassy, nu)
    a = _hertz_a(c)
    for xi in (-3e-4, 4e-3):
        _, tr = rolling_sphere_tractions(R, N, cr, nu, V, mu, n=64, creepage=xi,
                                         half_width=1.3 * a)
        el = steady_rolling(tr.grid, c, N, mu, Creepage(xi))
        assert tr.fx == pytest.approx(el.fx, rel=0.01)
        assert tr.stick_area == pytest.approx(el.stick_area, rel=0.03, abs=4 * tr.grid.area)


def test_full_slip_reaches_mu_n():
    """At a creepage far above mu p0/G every element slips: F_x = -mu N (sign: a positive
    creepage of body 1 meets a backward force)."""
    mu = 0.2
    cr = _sls(2e-4).creep()
    _, tr = rolling_sphere_tractions(R, N, cr, 0.3, V, mu, n=64, creepage=0.2)
    assert tr.fx == pytest.approx(-mu * tr.fn, rel=1e-3)
    assert tr.n_stick == 0
    assert tr.fn == pytest.approx(N, rel=1e-6)


@pytest.mark.parametrize("limit", ["relaxed", "glassy"])
def test_linear_creep_coefficient_kalker(limit):
    """Full adhesion (mu = 1e4) at xi = 1e-5, nu = 0.25: -F_x/(G a^2 xi) within 2.5 % of
    Kalker's C11 = 4.12 with the limit's modulus and Hertz radius."""
    nu = 0.25
    cr = _sls(TAUS[limit], nu).creep()
    c = constants_at(cr.relaxed if limit == "relaxed" else cr.glassy, nu)
    a = _hertz_a(c)
    small = 1e-5
    _, tr = rolling_sphere_tractions(R, N, cr, nu, V, 1e4, n=64, creepage=small,
                                     half_width=1.1 * a)
    assert -tr.fx / (c.G * a * a * small) == pytest.approx(4.12, rel=0.025)


def test_prescribed_force_gives_its_creepage():
    """Prescribing the force F_x that a creepage produced returns that creepage."""
    cr = _sls(2e-4).creep()
    _, tr = rolling_sphere_tractions(R, N, cr, 0.3, V, 0.3, n=48, creepage=-1.5e-3)
    back = visco_steady_tractions(tr.grid, tr.p, cr, 0.3, V, 0.3, fx=tr.fx)
    assert back.creepage.xi == pytest.approx(-1.5e-3, rel=2e-3)
    assert back.fx == pytest.approx(tr.fx, rel=1e-4)


def test_bad_input():
    cr = _sls(1e-3).creep()
    x = (np.arange(16) - 7.5) * 1e-5
    grid = Grid(x=x, y=x.copy(), h=(x[None, :] ** 2 + x[:, None] ** 2) / (2 * R))
    p = np.zeros((16, 16))
    p[6:10, 6:10] = 1e8
    with pytest.raises(ContactInputError, match="mu must be positive"):
        visco_steady_tractions(grid, p, cr, 0.3, V, 0.0)
    with pytest.raises(ContactInputError, match="friction limit"):
        visco_steady_tractions(grid, p, cr, 0.3, V, 0.3, fx=1e9)
    with pytest.raises(ContactInputError, match="speed"):
        visco_steady_tractions(grid, p, cr, 0.3, -1.0, 0.3, creepage=1e-3)
    with pytest.raises(ContactInputError, match="not both"):
        visco_steady_tractions(grid, p, cr, 0.3, V, 0.3, creepage=1e-3, fx=0.0)
