"""The viscoelastic 3D tractions of a dissimilar pair (Kalker's K != 0), one-way coupled
(issue 34 item 9: free rolling of steel on PMMA gave q = 0). The truth in the relaxed
(V tau << a) and glassy (V tau >> a) limits is the elastic tangential solver
(:func:`contact.tangential.steady_rolling`, validated against Kalker and CONTACT) with
the relaxed or glassy modulus, for the same pressure."""

from __future__ import annotations

import numpy as np
import pytest

from contact._grid import Grid
from contact._materials import Material
from contact.halfspace.constants import pair_constants
from contact.tangential import Creepage, steady_rolling
from contact.viscoelastic import StandardLinearSolid, pair_creep
from contact.viscoelastic._surface import rolling_sphere
from contact.viscoelastic._traction3d import ViscoRolling, pair_poisson, visco_steady_tractions

STEEL = Material("steel", 210e9, 0.3)
R, N, V, MU = 0.02, 5.0, 0.1, 0.3


@pytest.mark.parametrize("tau, modulus", [(1e-9, 1e9), (1e6, 3e9)])
@pytest.mark.parametrize("creepage", [None, 2e-3])
def test_limits_equal_the_elastic_solver(tau, modulus, creepage):
    sls = StandardLinearSolid(3e9, 1e9, tau, 0.37)
    creep = pair_creep(STEEL, sls)
    res = rolling_sphere(R, N, creep, V, n=40)
    x, y = np.asarray(res.x), np.asarray(res.y)
    grid = Grid(x=x, y=y, h=(x[None, :] ** 2 + y[:, None] ** 2) / (2 * R))
    p = np.asarray(res.pressure)
    tr = visco_steady_tractions(
        grid,
        p,
        ViscoRolling(creep, pair_poisson(STEEL, sls), V),
        MU,
        creepage=creepage,
        coupling=(STEEL, sls),
    )
    elastic = pair_constants(STEEL, Material("pmma", modulus, 0.37))
    assert elastic.K < -0.1  # a strongly dissimilar pair
    ref = steady_rolling(grid, elastic, N, MU, Creepage(creepage or 0.0),
                         fx=0.0 if creepage is None else None, pressure=p)
    # 1e-3: the viscoelastic operator's Poisson ratio weights the bodies by their mean
    # compliance (pair_poisson), Kalker's elastic one by the glassy or relaxed compliance:
    # 2.5e-4 apart on fx in the glassy limit with steel's 1.5 % share of the compliance
    assert tr.creepage.xi == pytest.approx(ref.creepage.xi, rel=1e-3)
    assert tr.fx == pytest.approx(ref.fx, rel=1e-3, abs=1e-6 * MU * N)
    assert tr.slip_area == pytest.approx(ref.slip_area, rel=1e-6)
    if creepage is None:
        assert abs(tr.creepage.xi) > 5e-4 and tr.slip_area > 0  # was 0 and 0


def test_between_the_limits_the_creepage_lies_between_them():
    values = []
    for tau in (1e-9, 1e-3, 1e6):
        sls = StandardLinearSolid(3e9, 1e9, tau, 0.37)
        creep = pair_creep(STEEL, sls)
        res = rolling_sphere(R, N, creep, V, n=40)
        x, y = np.asarray(res.x), np.asarray(res.y)
        grid = Grid(x=x, y=y, h=(x[None, :] ** 2 + y[:, None] ** 2) / (2 * R))
        tr = visco_steady_tractions(
            grid,
            np.asarray(res.pressure),
            ViscoRolling(creep, pair_poisson(STEEL, sls), V),
            MU,
            coupling=(STEEL, sls),
        )
        values.append(tr.creepage.xi)
    relaxed, middle, glassy = values
    assert min(relaxed, glassy) < middle < max(relaxed, glassy)
