"""Influence coefficients of two elastic half-spaces in contact: Boussinesq and Cerruti.

Two bodies touch over a plane; body 1 receives the surface tractions (p, q_x, q_y) and
body 2 the opposite ones. What the contact conditions need is the *difference* of the
surface displacements of the two bodies, u = u(1) - u(2), with the normal component
counted positive into the bodies (it opens the gap, as in :mod:`contact.hertz`). For
point loads on the surface of a half-space (Boussinesq and Cerruti; Johnson 1985,
*Contact Mechanics*, eqs. 3.19 and 3.86-3.87) the two bodies combine into three constants
(Kalker 1990, *Three-Dimensional Elastic Bodies in Rolling Contact*, sec. 1.5):

    1/G = (1/G1 + 1/G2)/2,  nu/G = (nu1/G1 + nu2/G2)/2,
    K/G = ((1 - 2 nu1)/G1 - (1 - 2 nu2)/G2)/4,

G the combined modulus of rigidity, nu the combined Poisson ratio and K Kalker's
difference parameter; (1 - nu)/G = 1/E* and Dundurs' beta = K/(1 - nu). A unit point
load at the origin then gives, at rho = |(x, y)| ::

    u_n  from p  : (1 - nu)/(pi G rho)
    u_x  from qx : [(1 - nu)/rho + nu x^2/rho^3]/(pi G)    u_y from qx: nu x y/(pi G rho^3)
    u_n  from qx : +K x/(pi G rho^2)                        u_x from p : -K x/(pi G rho^2)

(the pressure pulls the surface of the more compliant body towards the load: with
K > 0 body 1 moves more; the two coupling terms are opposite, by reciprocity).

Each element of the grid carries uniform tractions. The integrals of the point-load
kernels over a rectangle [-hx, hx] x [-hy, hy] are sums of corner functions F over its
four corners, F(x+hx, y+hy) - F(x+hx, y-hy) - F(x-hx, y+hy) + F(x-hx, y-hy), with
d^2 F/dx dy equal to the kernel:

    1/rho   : x asinh(y/|x|) + y asinh(x/|y|)     (Love 1929)
    x^2/rho^3 : y asinh(x/|y|)        y^2/rho^3 : x asinh(y/|x|)
    x y/rho^3 : -rho                  x/rho^2   : x atan(y/x) + (y/2) ln(x^2 + y^2)

Plane strain (a line contact along y) integrates the point loads over y: 1/rho gives
-2 ln|x| and x/rho^2 gives pi sign(x); displacements of a 2D half-space are then defined
up to a constant, which drops out of every quantity computed here (slip in rolling is a
difference along x; a shift carries its own rigid term).

The operator :class:`HalfSpacePair` applies these kernels by FFT on a zero-padded grid
(DC-FFT; Liu, Wang & Liu 2000, Wear 243:101): the linear convolution over the grid with
no dense matrix.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import scipy.fft as sfft

from contact.errors import ContactInputError
from contact.materials import Material


@dataclass(frozen=True)
class PairConstants:
    """Combined elastic constants of two bodies (Kalker 1990, sec. 1.5).

    Attributes
    ----------
    G : float
        Combined modulus of rigidity (Pa), 2/G = 1/G1 + 1/G2.
    nu : float
        Combined Poisson ratio.
    K : float
        Kalker's difference parameter (dimensionless); zero for quasi-identical bodies.
    """

    G: float
    nu: float
    K: float

    @property
    def e_star(self) -> float:
        """Composite modulus E* = G/(1 - nu) in Pa."""
        return self.G / (1.0 - self.nu)

    @property
    def beta(self) -> float:
        """Dundurs' second parameter beta = K/(1 - nu)."""
        return self.K / (1.0 - self.nu)


def shear_modulus(m: Material) -> float:
    """G = E / (2 (1 + nu)) in Pa."""
    return m.E / (2.0 * (1.0 + m.nu))


def pair_constants(body1: Material, body2: Material) -> PairConstants:
    """The combined constants G, nu, K of body 1 (receives +q) and body 2."""
    g1, g2 = shear_modulus(body1), shear_modulus(body2)
    inv_g = 0.5 * (1.0 / g1 + 1.0 / g2)
    G = 1.0 / inv_g
    nu = 0.5 * G * (body1.nu / g1 + body2.nu / g2)
    K = 0.25 * G * ((1.0 - 2.0 * body1.nu) / g1 - (1.0 - 2.0 * body2.nu) / g2)
    return PairConstants(G=G, nu=nu, K=K)


def pair_constants_from(g1: float, nu1: float, g2: float, nu2: float) -> PairConstants:
    """As :func:`pair_constants`, from the moduli of rigidity G1, G2 (Pa) and nu1, nu2."""
    for g in (g1, g2):
        if not (math.isfinite(g) and g > 0):
            raise ContactInputError("modulus of rigidity must be a positive number in Pa")
    inv_g = 0.5 * (1.0 / g1 + 1.0 / g2)
    G = 1.0 / inv_g
    return PairConstants(G=G, nu=0.5 * G * (nu1 / g1 + nu2 / g2),
                         K=0.25 * G * ((1.0 - 2.0 * nu1) / g1 - (1.0 - 2.0 * nu2) / g2))


def _asinh_ratio(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """a asinh(b/|a|), zero where a = 0."""
    aa = np.abs(a)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(aa > 0, a * np.arcsinh(b / np.where(aa > 0, aa, 1.0)), 0.0)


def _corners(fun, x: np.ndarray, y: np.ndarray, hx: float, hy: float) -> np.ndarray:
    return fun(x + hx, y + hy) - fun(x + hx, y - hy) - fun(x - hx, y + hy) + fun(x - hx, y - hy)


def _f_one(x, y):
    return _asinh_ratio(x, y) + _asinh_ratio(y, x)


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
    return {name: _corners(f, x, y, hx, hy) for name, f in
            (("one", _f_one), ("xx", _f_xx), ("yy", _f_yy), ("xy", _f_xy),
             ("x", _f_x), ("y", _f_y))}


def line_integrals(x: np.ndarray, dx: float) -> dict[str, np.ndarray]:
    """Plane strain: integrals over the strip [-dx/2, dx/2] of -2 ln|x| and pi sign(x)."""
    x = np.asarray(x, dtype=float)
    hx = 0.5 * dx

    def f_log(t):
        at = np.abs(t)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(at > 0, t * np.log(np.where(at > 0, at, 1.0)) - t, 0.0)

    return {"log": -2.0 * (f_log(x + hx) - f_log(x - hx)),
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


def _wrapped_offsets(n: int, pitch: float) -> np.ndarray:
    """Offsets 0..n-1, (n: unused), -(n-1)..-1 of a cyclic grid of 2n, in metres."""
    k = np.arange(2 * n)
    k = np.where(k < n, k, k - 2 * n).astype(float)
    return k * pitch


@lru_cache(maxsize=16)
def _spectra(ny: int, nx: int, dx: float, dy: float, c: PairConstants, line: bool):
    sy = 1 if line else 2 * ny
    ox = _wrapped_offsets(nx, dx)
    oy = np.zeros(1) if line else _wrapped_offsets(ny, dy)
    blocks = influence_blocks(ox[None, :], oy[:, None], dx, dy, c, line)
    spec = {}
    for key, k in blocks.items():
        k = np.array(np.broadcast_to(k, (sy, 2 * nx)))
        k[:, nx] = 0.0  # offset +-n never occurs in a linear convolution over n cells
        if not line:
            k[ny, :] = 0.0
        spec[key] = sfft.rfft2(k)
    return spec, blocks


class HalfSpacePair:
    """u = A t for the tractions t = (p, q_x, q_y) on a regular grid (free boundary).

    Parameters
    ----------
    ny, nx : int
        Grid shape (``ny = 1`` with ``line=True`` for plane strain).
    dx, dy : float
        Element size (m); ``dy`` is ignored in plane strain.
    constants : PairConstants
        Combined elastic constants of the pair.
    line : bool
        Plane strain: a line contact uniform along y.
    """

    def __init__(self, ny: int, nx: int, dx: float, dy: float, constants: PairConstants,
                 line: bool = False):
        if line and ny != 1:
            raise ContactInputError("a plane-strain grid has a single row")
        self.ny, self.nx, self.dx, self.dy = int(ny), int(nx), float(dx), float(dy)
        self.c = constants
        self.line = bool(line)
        self.shape = (self.ny, self.nx)
        self._pad = (1 if self.line else 2 * self.ny, 2 * self.nx)
        self.spec, self.real = _spectra(self.ny, self.nx, self.dx, self.dy, constants,
                                        self.line)
        self.coupled = constants.K != 0.0
        # threads pay off only on large transforms (their start-up dominates small ones)
        self._inv_spec: tuple[np.ndarray, ...] | None = None
        self._stiff: tuple[np.ndarray, ...] | None = None
        self._spec32: dict[str, np.ndarray] | None = None
        self._workers = 1 if self._pad[0] * self._pad[1] < 512 * 512 else -1

    def _fwd(self, a: np.ndarray, single: bool = False) -> np.ndarray:
        # along x first, on the ny rows that hold data, then along y over the padded
        # length: the zero rows of the padding are never transformed (the mirror of _inv)
        if single:
            a = np.asarray(a, dtype=np.float32)
        b = sfft.rfft(a, n=self._pad[1], axis=-1, workers=self._workers)
        return sfft.fft(b, n=self._pad[0], axis=-2, workers=self._workers)

    def _spectra32(self) -> dict[str, np.ndarray]:
        if self._spec32 is None:
            self._spec32 = {k: v.astype(np.complex64) for k, v in self.spec.items()}
        return self._spec32

    def _inv(self, a: np.ndarray) -> np.ndarray:
        # the inverse along y first, then only the ny rows that are kept go through the
        # real inverse along x: a quarter less work, and pocketfft's one-axis transforms
        # run two to four times faster here than its 2D c2r (measured, issue 19)
        b = sfft.ifft(a, axis=-2, workers=self._workers)[..., : self.ny, :]
        return sfft.irfft(b, n=self._pad[1], axis=-1, workers=self._workers)[..., : self.nx]

    def tangential(self, qx: np.ndarray, qy: np.ndarray | None = None,
                   single: bool = False) -> np.ndarray:
        """(u_x, u_y), shape (2, ny, nx), of the tangential tractions alone (m).

        ``single`` runs the transforms in float32 (relative error about 1e-7, two to three
        times faster): for the products of loose inner solves, never for a residual."""
        s = self._spectra32() if single else self.spec
        if qy is None or not np.any(qy):
            fx = self._fwd(qx, single)
            out = self._inv(np.stack([s["xx"] * fx, s["xy"] * fx]))
        else:
            # both components in one transform call each way (half the call overhead)
            f = self._fwd(np.stack([qx, qy]), single)
            out = self._inv(np.stack([s["xx"] * f[0] + s["xy"] * f[1],
                                      s["xy"] * f[0] + s["yy"] * f[1]]))
        return out.astype(float, copy=False)

    def tangential_inverse(self, ux: np.ndarray, uy: np.ndarray) -> np.ndarray:
        """Approximately the tractions (q_x, q_y) that displace the grid by (u_x, u_y):
        the 2 x 2 inverse of the padded kernel spectra (a preconditioner, not a solve)."""
        s = self.spec
        if self._inv_spec is None:
            sxx, syy, sxy = s["xx"].real, s["yy"].real, s["xy"].real
            det = sxx * syy - sxy * sxy
            with np.errstate(divide="ignore", invalid="ignore"):
                ok = np.abs(det) > 1e-300
                self._inv_spec = tuple(np.where(ok, v / np.where(ok, det, 1.0), 0.0)
                                       for v in (syy, sxx, -sxy))
        ixx, iyy, ixy = self._inv_spec
        fx, fy = self._fwd(ux), self._fwd(uy)
        return np.stack([self._inv(ixx * fx + ixy * fy), self._inv(ixy * fx + iyy * fy)])

    def tangential_stiffness(self, ux: np.ndarray, uy: np.ndarray) -> np.ndarray:
        """Approximately the tractions of the displacements (u_x, u_y): the inverse of the
        continuum Cerruti symbol, (G|k|/2) [I + nu/(1 - nu) k k^T/|k|^2], applied by FFT on
        the unpadded (periodic) grid (a preconditioner, as the |k|/2 filter of the normal
        solver)."""
        if self._stiff is None:
            kx = 2 * np.pi * np.fft.rfftfreq(self.nx, self.dx)[None, :]
            ky = (np.zeros((1, 1)) if self.line
                  else 2 * np.pi * np.fft.fftfreq(self.ny, self.dy)[:, None])
            k2 = kx**2 + ky**2
            k = np.sqrt(k2)
            c = self.c.nu / (1.0 - self.c.nu)
            with np.errstate(divide="ignore", invalid="ignore"):
                f = 0.5 * self.c.G * k
                kk = np.where(k2 > 0, 1.0 / np.where(k2 > 0, k2, 1.0), 0.0)
                # float32: a preconditioner needs no more
                self._stiff = tuple(v.astype(np.float32) for v in (
                    f * (1 + c * kx**2 * kk), f * (1 + c * ky**2 * kk), f * c * kx * ky * kk))
        sxx, syy, sxy = self._stiff
        f = sfft.rfft2(np.stack([ux, uy]).astype(np.float32), workers=self._workers)
        b = sfft.ifft(np.stack([sxx * f[0] + sxy * f[1], sxy * f[0] + syy * f[1]]), axis=-2,
                      workers=self._workers)
        return sfft.irfft(b, n=self.nx, axis=-1, workers=self._workers).astype(float)

    def normal(self, p: np.ndarray) -> np.ndarray:
        """u_n of the pressure alone (m)."""
        return self._inv(self.spec["nn"] * self._fwd(p))

    def normal_from_tangential(self, qx: np.ndarray, qy: np.ndarray) -> np.ndarray:
        """u_n of the tangential tractions (m): zero for quasi-identical bodies."""
        if not self.coupled:
            return np.zeros(self.shape)
        return self._inv(self.spec["nx"] * self._fwd(qx) + self.spec["ny"] * self._fwd(qy))

    def tangential_from_normal(self, p: np.ndarray) -> np.ndarray:
        """(u_x, u_y) of the pressure (m): zero for quasi-identical bodies."""
        if not self.coupled:
            return np.zeros((2, *self.shape))
        fp = self._fwd(p)
        return np.stack([self._inv(self.spec["xn"] * fp), self._inv(self.spec["yn"] * fp)])

    def self_normal(self) -> float:
        """u_n of an element under its own unit pressure (m/Pa): the diagonal of A_nn."""
        return float(self.real["nn"][0, 0])
