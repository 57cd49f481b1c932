"""3D steady rolling tractions on a viscoelastic half-space (contact.viscoelastic._traction3d).

Independent truths: the elastic tangential solver of contact.tangential with the relaxed
and glassy moduli (the limits V tau/a -> 0 and -> inf), Coulomb's full-slip limit
|F_x| = mu N, and Kalker's linear creep coefficient C11 = 4.12 of a circular contact at
nu = 0.25 (Kalker 1990, Table E.3).
"""

from __future__ import annotations

import functools

import numpy as np
import pytest

from contact._errors import ContactInputError
from contact.tangential import Creepage, steady_rolling
from contact.tangential._grid import Grid
from contact.viscoelastic._rheology import StandardLinearSolid
from contact.viscoelastic._traction3d import (
    ViscoRolling,
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
    back = visco_steady_tractions(tr.grid, tr.p, ViscoRolling(cr, 0.3, V), 0.3, fx=tr.fx)
    assert back.creepage.xi == pytest.approx(-1.5e-3, rel=2e-3)
    assert back.fx == pytest.approx(tr.fx, rel=1e-4)


def test_bad_input():
    cr = _sls(1e-3).creep()
    x = (np.arange(16) - 7.5) * 1e-5
    grid = Grid(x=x, y=x.copy(), h=(x[None, :] ** 2 + x[:, None] ** 2) / (2 * R))
    p = np.zeros((16, 16))
    p[6:10, 6:10] = 1e8
    with pytest.raises(ContactInputError, match="mu must be positive"):
        visco_steady_tractions(grid, p, ViscoRolling(cr, 0.3, V), 0.0)
    with pytest.raises(ContactInputError, match="friction limit"):
        visco_steady_tractions(grid, p, ViscoRolling(cr, 0.3, V), 0.3, fx=1e9)
    with pytest.raises(ContactInputError, match="speed"):
        visco_steady_tractions(grid, p, ViscoRolling(cr, 0.3, -1.0), 0.3, creepage=1e-3)
    with pytest.raises(ContactInputError, match="not both"):
        visco_steady_tractions(grid, p, ViscoRolling(cr, 0.3, V), 0.3, creepage=1e-3, fx=0.0)


@functools.lru_cache(maxsize=4)
def _slender_creepage(vt: float | None) -> tuple[float, float, float]:
    """(3D creepage, plane-strain creepage, a) at F_x = -0.6 mu N for a slender elliptical
    contact (R_y = 25 R_x, b/a ~ 7.8, 48 x 48) and the plane-strain roller with the same
    R and the same relaxed half-width a; V tau = vt a (None: relaxed, tau -> 0)."""
    import math

    from contact._grid import scan_grid
    from contact.tangential._grid import centres
    from contact.viscoelastic._line import influence_matrix, rolling_cylinder
    from contact.viscoelastic._surface import solve_surface
    from contact.viscoelastic._traction import steady_traction

    nu, mu, ratio, k = 0.3, 0.3, 0.6, 25.0
    a_r = 2.2196e-4  # relaxed centre half-width of this ellipse (its own solve, 48 x 48)
    cr = _sls(1e-12 if vt is None else vt * a_r / V, nu).creep()
    x, y = centres(48, 1.35 * a_r), centres(48, 1.3 * 1.733e-3)
    h = x[None, :] ** 2 / (2 * R) + y[:, None] ** 2 / (2 * k * R)
    res = solve_surface(scan_grid(h.shape, x[1] - x[0], y[1] - y[0], origin=(x[0], y[0]), h=h),
                        N, cr, V)
    grid = Grid(x=x, y=y, h=h)
    tr = visco_steady_tractions(
        grid, np.asarray(res.pressure), ViscoRolling(cr, nu, V), mu, fx=-ratio * mu * N
    )
    W = math.pi * a_r**2 / (4 * R * cr.relaxed)
    r2 = rolling_cylinder(R, W, cr, V, n=256)
    d2 = float(r2.x[1] - r2.x[0])
    t2 = steady_traction(influence_matrix(256, d2, cr, V), np.asarray(r2.pressure), d2, mu,
                         -ratio * mu * W)
    return tr.creepage.xi, t2.creepage, (res.leading - res.trailing) / 2


@pytest.mark.parametrize("vt", [0.3, 1.0])
def test_slender_contact_viscoelastic_factor_matches_plane_strain(vt):
    """The 2D limit. At equal F_x/(mu N) = -0.6 the viscoelastic factor of the creepage,
    xi(V tau/a)/xi(relaxed), of a slender elliptical contact (b/a ~ 7.8) matches that of
    plane strain (contact.viscoelastic._traction, Carter with creep) within 1 %. (The
    creepages themselves differ by ~14 % at b/a = 8 and at b/a = 18 alike: the approach
    of an ellipse to plane strain is logarithmic in b/a, out of reach of a fast test.)"""
    xi3_r, xi2_r, a = _slender_creepage(None)
    assert a == pytest.approx(2.2196e-4, rel=0.02)  # the half-width assumed above
    xi3, xi2, _ = _slender_creepage(vt)
    assert xi3 / xi3_r == pytest.approx(xi2 / xi2_r, rel=0.01)
    assert xi3 / xi3_r != pytest.approx(1.0, abs=0.008)  # creep does change it
