"""Influence coefficients of two half-spaces under surface tractions: Boussinesq, Cerruti
and Kalker's normal-tangential coupling, on rectangular elements and on strips.

What the contact conditions need is the *difference* of the surface displacements of
the two bodies, u = u(1) - u(2) (body 1 receives +t), with the normal component counted
positive into the bodies (it opens the gap, as in :mod:`contact._hertz`). With the
combined constants G, nu, K of :mod:`contact.halfspace.constants`, a unit point load at
the origin gives, at rho = |(x, y)| (Johnson 1985, *Contact Mechanics*, eqs. 3.19 and
3.86-3.87; Kalker 1990, *Three-Dimensional Elastic Bodies in Rolling Contact*, sec. 1.5)::

    u_n  from p  : (1 - nu)/(pi G rho)
    u_x  from qx : [(1 - nu)/rho + nu x^2/rho^3]/(pi G)    u_y from qx: nu x y/(pi G rho^3)
    u_n  from qx : +K x/(pi G rho^2)                        u_x from p : -K x/(pi G rho^2)

(the pressure pulls the surface of the more compliant body towards the load: with
K > 0 body 1 moves more; the two coupling terms are opposite, by reciprocity).

Each element carries uniform tractions. The integrals of the point-load kernels over a
rectangle are corner sums (:func:`contact.halfspace.influence.corner_sum`) of functions F
with d^2 F/dx dy equal to the kernel:

    1/rho     : x asinh(y/|x|) + y asinh(x/|y|)  (Love's; :func:`~.influence.love_corner`)
    x^2/rho^3 : y asinh(x/|y|)        y^2/rho^3 : x asinh(y/|x|)
    x y/rho^3 : -rho                  x/rho^2   : x atan(y/x) + (y/2) ln(x^2 + y^2)

so the normal block is (1 - nu)/G times Love's coefficients of
:mod:`contact.halfspace.influence`, computed by the same corner terms.

Plane strain (a line contact along y) integrates the point loads over y: 1/rho gives
-2 ln|x| and x/rho^2 gives pi sign(x); displacements of a 2D half-space are then defined
up to a constant, which drops out of every quantity the solvers compute (slip in rolling
is a difference along x; a shift carries its own rigid term).
"""

from __future__ import annotations

import math

import numpy as np

from contact.halfspace.alias import SYMBOLS, alias_sums
from contact.halfspace.constants import PairConstants
from contact.halfspace.influence import corner_sum, love_corner
from contact.halfspace.plane_strain import strip_log


def _asinh_ratio(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """a asinh(b/|a|), zero where a = 0."""
    aa = np.abs(a)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(aa > 0, a * np.arcsinh(b / np.where(aa > 0, aa, 1.0)), 0.0)


def _f_xx(x, y):
    return _asinh_ratio(y, x)


def _f_yy(x, y):
    return _asinh_ratio(x, y)


def _f_xy(x, y):
    return -np.hypot(x, y)


def _f_x(x, y):
    r2 = x * x + y * y
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = np.where(x != 0, x * np.arctan(y / np.where(x != 0, x, 1.0)), 0.0)
        t2 = np.where(r2 > 0, 0.5 * y * np.log(np.where(r2 > 0, r2, 1.0)), 0.0)
    return t1 + t2


def _f_y(x, y):
    return _f_x(y, x)


def element_integrals(x: np.ndarray, y: np.ndarray, dx: float, dy: float) -> dict[str, np.ndarray]:
    """Integrals of the point-load kernels over the element [-dx/2, dx/2] x [-dy/2, dy/2].

    Returns ``one`` (1/rho), ``xx`` (x^2/rho^3), ``yy``, ``xy`` (x y/rho^3), ``x``
    (x/rho^2) and ``y`` (y/rho^2), at the offsets (x, y) of the field point from the
    element centre (broadcast), in metres.
    """
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    hx, hy = 0.5 * dx, 0.5 * dy
    return {name: corner_sum(f, x, y, hx, hy) for name, f in
            (("one", love_corner), ("xx", _f_xx), ("yy", _f_yy), ("xy", _f_xy),
             ("x", _f_x), ("y", _f_y))}


def line_integrals(x: np.ndarray, dx: float) -> dict[str, np.ndarray]:
    """Plane strain: integrals over the strip [-dx/2, dx/2] of -2 ln|x| and pi sign(x)."""
    x = np.asarray(x, dtype=float)
    hx = 0.5 * dx
    # the strip integral of the log kernel has one home (the normal line contact's too)
    return {"log": strip_log(x, dx),
            "sign": math.pi * (np.abs(x + hx) - np.abs(x - hx))}


def influence_blocks(x, y, dx, dy, c: PairConstants, line: bool = False) -> dict[str, np.ndarray]:
    """Displacement differences per unit traction on one element (keys ``nn, xx, yy, xy,
    nx, ny, xn, yn``: ``ab`` = u_a from traction b), at offsets (x, y), in m/Pa."""
    f = 1.0 / (math.pi * c.G)
    if line:
        li = line_integrals(x, dx)
        zero = np.zeros_like(li["log"])
        # antiplane u_y from q_y: (1 - nu) and nu parts both take -2 ln|x|
        return {"nn": f * (1 - c.nu) * li["log"], "xx": f * (1 - c.nu) * li["log"],
                "yy": f * li["log"], "xy": zero, "nx": f * c.K * li["sign"],
                "xn": -f * c.K * li["sign"], "ny": zero, "yn": zero}
    e = element_integrals(x, y, dx, dy)
    return {"nn": f * (1 - c.nu) * e["one"],
            "xx": f * ((1 - c.nu) * e["one"] + c.nu * e["xx"]),
            "yy": f * ((1 - c.nu) * e["one"] + c.nu * e["yy"]),
            "xy": f * c.nu * e["xy"],
            "nx": f * c.K * e["x"], "xn": -f * c.K * e["x"],
            "ny": f * c.K * e["y"], "yn": -f * c.K * e["y"]}


def periodic_spectra(ny: int, nx: int, dx: float, dy: float, c: PairConstants,
                     n_alias: int = 8) -> dict[str, np.ndarray]:
    """Spectra, shape (ny, nx//2 + 1), of the blocks periodised over the (ny, nx) grid.

    As Love's periodic spectrum (:func:`contact.halfspace.influence.periodic_kernel_spectrum`),
    from the one alias sum (:func:`contact.halfspace.alias.alias_sums`): the sums over
    q' = q + G_mn, |m|, |n| <= ``n_alias``, of the continuum symbols times the transform
    of the uniform element, sinc(qx' dx/2) sinc(qy' dy/2). The symbols
    are the Fourier transforms (e^{-i q.x}) of the point-load kernels over pi
    (Johnson 1985, eqs. 3.19, 3.86-3.87; Kalker 1990 sec. 1.5)::

        1/rho -> 2/|q|,  x^2/rho^3 -> 2 qy^2/|q|^3,  y^2/rho^3 -> 2 qx^2/|q|^3,
        x y/rho^3 -> -2 qx qy/|q|^3,  x/rho^2 -> -2i qx/|q|^2,  y/rho^2 -> -2i qy/|q|^2

    (from FT(1/rho) = 2 pi/|q|, FT(rho) = -2 pi/|q|^3, FT(ln rho) = -2 pi/|q|^2 and their
    derivatives). q = 0 (a rigid displacement of a periodic problem) is zero. The truncated
    sums are made Hermitian, so that the real-space kernels are real.
    """
    # the one alias sum of every symbol (contact.halfspace.alias)
    acc = dict(zip(SYMBOLS, alias_sums(int(ny), int(nx), float(dx), float(dy), int(n_alias),
                                       True)))
    f = 1.0 / c.G
    blocks = {"nn": f * (1 - c.nu) * acc["one"],
              "xx": f * ((1 - c.nu) * acc["one"] + c.nu * acc["xx"]),
              "yy": f * ((1 - c.nu) * acc["one"] + c.nu * acc["yy"]),
              "xy": f * c.nu * acc["xy"] + 0j,
              "nx": 1j * f * c.K * acc["x"], "xn": -1j * f * c.K * acc["x"],
              "ny": 1j * f * c.K * acc["y"], "yn": -1j * f * c.K * acc["y"]}
    # the projection irfft2 -> rfft2 drops the anti-Hermitian rest of the truncation
    return {k: np.fft.rfft2(np.fft.irfft2(v, s=(ny, nx))) for k, v in blocks.items()}
