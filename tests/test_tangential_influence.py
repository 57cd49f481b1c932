"""Cerruti/Boussinesq element influence and the combined constants of a pair.

Independent truths: numerical quadrature of the point-load kernels over an element, the
composite modulus of :mod:`contact._materials`, Dundurs' beta written from its own
definition, and the numpy twin of the compiled friction-law update.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import dblquad, quad

from contact._materials import composite_modulus, material
from contact.halfspace.cerruti import element_integrals, line_integrals
from contact.halfspace.constants import pair_constants, shear_modulus
from contact.tangential._kernels import update_states

KERNELS = {
    "one": lambda x, y: 1.0 / math.hypot(x, y),
    "xx": lambda x, y: x * x / math.hypot(x, y) ** 3,
    "yy": lambda x, y: y * y / math.hypot(x, y) ** 3,
    "xy": lambda x, y: x * y / math.hypot(x, y) ** 3,
    "x": lambda x, y: x / (x * x + y * y),
    "y": lambda x, y: y / (x * x + y * y),
}


@pytest.mark.parametrize("offset", [(2.3, 0.7), (-1.6, 3.1), (0.0, 2.0), (5.0, -4.0)])
def test_element_integrals_match_quadrature(offset):
    """Corner-function integrals over a 1 x 0.8 element equal dblquad to 1e-7."""
    dx, dy = 1.0, 0.8
    x0, y0 = offset
    got = element_integrals(np.array(x0), np.array(y0), dx, dy)
    for name, f in KERNELS.items():
        ref, _ = dblquad(lambda t, s, f=f: f(x0 - s, y0 - t), -dx / 2, dx / 2,
                         -dy / 2, dy / 2, epsabs=1e-11, epsrel=1e-11)
        assert float(got[name]) == pytest.approx(ref, rel=1e-7, abs=1e-9), name


def test_self_element_integral_is_love_value():
    """Over its own square element, 1/rho integrates to 4 dx asinh(1) (Love 1929)."""
    got = element_integrals(np.array(0.0), np.array(0.0), 1.0, 1.0)
    assert float(got["one"]) == pytest.approx(4.0 * math.asinh(1.0), rel=1e-12)
    assert float(got["x"]) == pytest.approx(0.0, abs=1e-14)


def test_line_integrals_match_quadrature():
    """Plane strain: -2 ln|x| and pi sign(x) over a strip, against quad."""
    dx, x0 = 0.5, 1.3
    got = line_integrals(np.array(x0), dx)
    ref_log, _ = quad(lambda s: -2.0 * math.log(abs(x0 - s)), -dx / 2, dx / 2)
    assert float(got["log"]) == pytest.approx(ref_log, rel=1e-10)
    assert float(got["sign"]) == pytest.approx(math.pi * dx, rel=1e-12)


def test_pair_constants_steel_aluminium():
    """(1 - nu)/G is 1/E* of contact._materials; K/(1 - nu) is Dundurs' beta."""
    steel, al = material("steel"), material("aluminium")
    c = pair_constants(steel, al)
    assert c.e_star == pytest.approx(composite_modulus(steel, al), rel=1e-12)
    g1, g2 = shear_modulus(steel), shear_modulus(al)
    k1, k2 = 3 - 4 * steel.nu, 3 - 4 * al.nu  # Kolosov constants, plane strain
    beta = (g1 * (k2 - 1) - g2 * (k1 - 1)) / (g1 * (k2 + 1) + g2 * (k1 + 1))
    # Dundurs' beta with body 1 = steel: the sign flips with the order of the bodies
    assert c.beta == pytest.approx(-beta, rel=1e-12)
    assert pair_constants(steel, steel).K == 0.0


def _update_reference(q, s, g, state, e, dxx, dyy, slack, allow):
    """numpy twin of :func:`contact.tangential._kernels.update_states`."""
    state, e = state.copy(), e.copy()
    if dxx > 0:
        t = np.stack([-(s[0] - dxx * q[0]) / dxx, -(s[1] - dyy * q[1]) / dyy])
        fits = np.hypot(t[0], t[1]) <= g * (1 + slack)
    else:
        t = np.where(state == 1, q, -s)
        fits = np.where(state == 1, np.hypot(q[0], q[1]) <= g * (1 + slack),
                        (s * e).sum(axis=0) > 0)
    tn = np.hypot(t[0], t[1])
    to_stick = (state == 2) & fits & bool(allow & 2)
    to_slip = (state == 1) & ~fits & bool(allow & 1)
    re_aim = (state == 2) & ~fits & bool(allow & 4)
    changes = int(to_stick.sum() + to_slip.sum())
    new_e = t / np.where(tn > 0, tn, 1.0)
    de = np.hypot(*(new_e - e))
    de_max = float(de[re_aim].max()) if re_aim.any() else 0.0
    e[:, to_slip | re_aim] = new_e[:, to_slip | re_aim]
    state[to_stick] = 1
    state[to_slip] = 2
    return state, e, changes, de_max


@pytest.mark.parametrize("allow", [1, 2, 3, 7])
@pytest.mark.parametrize("local", [True, False])
def test_update_states_matches_numpy_twin(allow, local):
    rng = np.random.default_rng(7)
    shape = (9, 11)
    q = rng.normal(size=(2, *shape))
    s = rng.normal(size=(2, *shape))
    g = np.abs(rng.normal(size=shape)) * 2
    g[0, :] = 0.0
    state = rng.integers(1, 3, size=shape).astype(np.int8)
    state[g == 0] = 0
    e = rng.normal(size=(2, *shape))
    e /= np.hypot(e[0], e[1])
    dxx, dyy = (0.7, 0.9) if local else (0.0, 0.0)
    ref_state, ref_e, ref_changes, ref_de = _update_reference(q, s, g, state, e, dxx, dyy,
                                                              1e-9, allow)
    st, ee = state.copy(), e.copy()
    changes, de = update_states(q[0], q[1], s[0], s[1], g, st, ee[0], ee[1], dxx, dyy,
                                1e-9, allow)
    assert changes == ref_changes
    np.testing.assert_array_equal(st, ref_state)
    np.testing.assert_allclose(ee, ref_e, atol=1e-14)
    assert de == pytest.approx(ref_de, abs=1e-14)
