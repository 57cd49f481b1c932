"""One half-space operator family (contact.halfspace): each block against an independent truth.

Truths:

- closed forms of the self-influence of a square element, from polar integration over its
  eight triangles: int 1/rho dA = 4 h ln(1 + sqrt 2) (Love 1929), and by symmetry
  int x^2/rho^3 dA = half of that, so a uniform shear q on the element moves its centre by
  u_x = (2 - nu) 2 h ln(1 + sqrt 2) q / (pi G) (Cerruti; Johnson 1985, *Contact Mechanics*,
  eq. 3.86a integrated; Kalker 1990, sec. 1.5 for the pair's G and nu); plane strain:
  int -2 ln|s| ds over a strip of width h = -2 h (ln(h/2) - 1);
- the point-load limit far from the element: Boussinesq, Cerruti and Kalker's coupling
  times the element area (Johnson 1985, eqs. 3.19, 3.86-3.87);
- direct dense sums over the grid of the element coefficients, with no FFT and no
  padding: the free, the extended-ahead and the plane-strain products must equal them;
- the pair's normal block against the normal Convolution (the same Love coefficients over
  E*), on the free grid and on the grid extended ahead (two different paddings);
- periodic: the normal block against the compiled periodic Love spectrum, and every
  block against the continuum half-space under a sinusoidal traction.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from contact._materials import material
from contact.halfspace.cerruti import element_integrals, influence_blocks, line_integrals
from contact.halfspace.constants import pair_constants, pair_constants_from
from contact.halfspace.convolution import Convolution
from contact.halfspace.influence import love_coefficients
from contact.halfspace.pair import HalfSpacePair

DX, DY = 1.0e-5, 1.3e-5
STEEL_AL = pair_constants(material("steel"), material("aluminium"))  # K != 0


def _dense(kernel, src_shape, out_cols, dx, dy):
    """Matrix (ny*out_cols, ny*nx) of u[i, j] = sum_kl kernel(x_j - x_l, y_i - y_k) t[k, l]."""
    ny, nx = src_shape
    i, j = np.meshgrid(np.arange(ny), np.arange(out_cols), indexing="ij")
    k, m = np.meshgrid(np.arange(ny), np.arange(nx), indexing="ij")
    ox = (j.ravel()[:, None] - m.ravel()[None, :]) * dx
    oy = (i.ravel()[:, None] - k.ravel()[None, :]) * dy
    return kernel(ox, oy)


def _fields(shape, seed=3):
    rng = np.random.default_rng(seed)
    return rng.random(shape), rng.standard_normal(shape), rng.standard_normal(shape)


def test_square_self_influence_closed_forms():
    h, nu, G = 2e-5, 0.3, 80e9
    c = pair_constants_from(G, nu, G, nu)
    b = influence_blocks(np.array(0.0), np.array(0.0), h, h, c)
    love = 4 * h * math.log(1 + math.sqrt(2))
    # abs=0 throughout: the coefficients are of order 1e-16 m/Pa
    assert float(b["nn"]) == pytest.approx((1 - nu) * love / (math.pi * G), rel=1e-13, abs=0)
    assert float(b["xx"]) == pytest.approx((2 - nu) * love / (2 * math.pi * G), rel=1e-13,
                                           abs=0)
    assert float(b["yy"]) == pytest.approx(float(b["xx"]), rel=1e-13, abs=0)
    for key in ("xy", "nx", "xn", "ny", "yn"):  # odd kernels vanish on their own element
        assert abs(float(b[key])) < 1e-12 * float(b["xx"])
    assert float(line_integrals(np.array(0.0), h)["log"]) == pytest.approx(
        -2 * h * (math.log(h / 2) - 1), rel=1e-13, abs=0)


def test_far_field_is_the_point_load_solution():
    """At 60 elements the blocks equal the point loads times the element area to 1e-3."""
    c = STEEL_AL
    x, y = 60 * DX, -35 * DY
    rho = math.hypot(x, y)
    area = DX * DY
    b = influence_blocks(np.array(x), np.array(y), DX, DY, c)
    f = area / (math.pi * c.G)
    point = {"nn": f * (1 - c.nu) / rho,
             "xx": f * ((1 - c.nu) / rho + c.nu * x * x / rho**3),
             "yy": f * ((1 - c.nu) / rho + c.nu * y * y / rho**3),
             "xy": f * c.nu * x * y / rho**3,
             "nx": f * c.K * x / rho**2, "xn": -f * c.K * x / rho**2,
             "ny": f * c.K * y / rho**2, "yn": -f * c.K * y / rho**2}
    for key, ref in point.items():
        assert float(b[key]) == pytest.approx(ref, rel=1e-3, abs=0), key
    e = element_integrals(np.array(x), np.array(y), DX, DY)
    assert float(e["one"]) == pytest.approx(
        math.pi * float(love_coefficients(np.array(x), np.array(y), DX, DY)), rel=1e-15, abs=0)


@pytest.mark.parametrize("ahead", [0, 5])
def test_normal_convolution_equals_dense_sum(ahead):
    """Free and extended-ahead Love convolution = the direct sum, to 1e-12 of its max."""
    ny, nx = 7, 9
    p, _, _ = _fields((ny, nx))
    p[:2] = 0.0  # rows without pressure (the pruned transforms skip them)
    A = _dense(lambda ox, oy: love_coefficients(ox, oy, DX, DY), (ny, nx), nx + ahead, DX, DY)
    ref = (A @ p.ravel()).reshape(ny, nx + ahead)
    conv = Convolution(ny, nx, DX, DY, periodic=False, ahead=ahead)
    got = conv(p, rows=(2, ny))
    assert got.shape == (ny, nx + ahead)
    assert np.abs(got - ref).max() <= 1e-12 * np.abs(ref).max()
    got32 = conv(p, rows=(2, ny), single=True)
    assert got32.dtype == np.float32
    assert np.abs(got32 - ref).max() <= 1e-5 * np.abs(ref).max()


@pytest.mark.parametrize("ahead", [0, 4])
def test_pair_blocks_equal_dense_sums(ahead):
    """Every block of the coupled pair (steel on aluminium, K != 0), free and extended
    ahead: the FFT products equal the dense sums of the element coefficients to 1e-12."""
    ny, nx = 6, 8
    c = STEEL_AL
    p, qx, qy = _fields((ny, nx))
    op = HalfSpacePair(ny, nx, DX, DY, c, ahead=ahead)
    cols = nx + ahead

    def dense(key, t):
        A = _dense(lambda ox, oy: influence_blocks(ox, oy, DX, DY, c)[key], (ny, nx), cols,
                   DX, DY)
        return (A @ t.ravel()).reshape(ny, cols)

    refs = {
        "normal": (op.normal(p), dense("nn", p)),
        "tangential": (op.tangential(qx, qy),
                       np.stack([dense("xx", qx) + dense("xy", qy),
                                 dense("xy", qx) + dense("yy", qy)])),
        "normal_from_tangential": (op.normal_from_tangential(qx, qy),
                                   dense("nx", qx) + dense("ny", qy)),
        "tangential_from_normal": (op.tangential_from_normal(p),
                                   np.stack([dense("xn", p), dense("yn", p)])),
    }
    for name, (got, ref) in refs.items():
        assert got.shape == ref.shape, name
        assert np.abs(got - ref).max() <= 1e-12 * np.abs(ref).max(), name
    got32 = op.tangential(qx, qy, single=True)
    ref = refs["tangential"][1]
    assert np.abs(got32 - ref).max() <= 1e-5 * np.abs(ref).max()


def test_plane_strain_pair_equals_dense_sum():
    nx = 40
    c = STEEL_AL
    p, qx, _ = _fields((1, nx))
    op = HalfSpacePair(1, nx, DX, DX, c, line=True)
    x = (np.arange(nx)[:, None] - np.arange(nx)[None, :]) * DX
    blocks = influence_blocks(x, np.zeros_like(x), DX, DX, c, line=True)
    for got, key, t in ((op.normal(p)[0], "nn", p), (op.tangential(qx)[0, 0], "xx", qx),
                        (op.normal_from_tangential(qx, 0 * qx)[0], "nx", qx),
                        (op.tangential_from_normal(p)[0, 0], "xn", p)):
        ref = blocks[key] @ t[0]
        assert np.abs(got - ref).max() <= 1e-12 * np.abs(ref).max(), key


@pytest.mark.parametrize("ahead", [0, 6])
def test_pair_normal_block_is_the_normal_convolution(ahead):
    """The pair's normal block over (1 - nu)/G is the Convolution's Love operator (E* = 1),
    to 1e-12: free, and extended ahead, where the two use different paddings."""
    ny, nx = 10, 12
    p, _, _ = _fields((ny, nx), seed=5)
    op = HalfSpacePair(ny, nx, DX, DY, STEEL_AL, ahead=ahead)
    conv = Convolution(ny, nx, DX, DY, periodic=False, ahead=ahead)
    ref = conv(p)
    got = op.normal(p) * STEEL_AL.e_star
    assert np.abs(got - ref).max() <= 1e-12 * np.abs(ref).max()
    assert op.self_normal() * STEEL_AL.e_star == pytest.approx(conv.self_influence, rel=1e-13,
                                                               abs=0)


def test_periodic_pair_normal_block_is_the_periodic_love_spectrum():
    """The periodised normal block over (1 - nu)/G is the periodic Love spectrum of
    contact.halfspace.influence (its own compiled alias sum) to 1e-12."""
    from contact.halfspace.influence import periodic_kernel_spectrum

    ny, nx = 12, 16
    op = HalfSpacePair(ny, nx, DX, DY, STEEL_AL, periodic=True)
    ref = periodic_kernel_spectrum(ny, nx, DX, DY)
    got = op.spec["nn"] * STEEL_AL.e_star
    assert np.abs(got - ref).max() <= 1e-12 * np.abs(ref).max()


def test_periodic_pair_on_a_sinusoid_is_the_continuum_solution():
    """q_x = cos(k.x) and p = cos(k.x) on the periodic 64 x 48 grid, k = (2, 1) periods:
    every block's response within 1 % of the continuum half-space (Cerruti and
    Boussinesq under a sinusoidal traction; Johnson 1985 sec. 13.2 for the normal one),
    u_x = 2/(G|k|) [(1 - nu) + nu ky^2/|k|^2] cos, u_y = -2 nu kx ky/(G|k|^3) cos,
    u_n from q_x = 2 K kx/(G|k|^2) sin, (u_x, u_y) from p = -2 K (kx, ky)/(G|k|^2) sin
    (measured: 0.2 to 0.6 %, the piecewise-constant tractions at k dx = 0.2)."""
    ny, nx = 48, 64
    c = STEEL_AL
    x = np.arange(nx) * DX
    y = np.arange(ny) * DY
    kx, ky = 2 * np.pi * 2 / (nx * DX), 2 * np.pi / (ny * DY)
    k = math.hypot(kx, ky)
    phase = kx * x[None, :] + ky * y[:, None]
    t = np.cos(phase)
    op = HalfSpacePair(ny, nx, DX, DY, c, periodic=True)
    u = op.tangential(t)
    un = op.normal_from_tangential(t, 0 * t)
    ut = op.tangential_from_normal(t)
    g = c.G
    refs = [(u[0], 2 / (g * k) * ((1 - c.nu) + c.nu * ky**2 / k**2) * t),
            (u[1], -2 * c.nu * kx * ky / (g * k**3) * t),
            (un, 2 * c.K * kx / (g * k**2) * np.sin(phase)),
            (ut[0], -2 * c.K * kx / (g * k**2) * np.sin(phase)),
            (ut[1], -2 * c.K * ky / (g * k**2) * np.sin(phase)),
            (op.normal(t), 2 / (c.e_star * k) * t)]
    for got, ref in refs:
        assert np.abs(got - ref).max() <= 0.01 * np.abs(ref).max()
