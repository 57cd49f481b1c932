"""The coupled operator of two half-spaces: u = A t for the tractions t = (p, q_x, q_y).

The blocks of A are the influence coefficients of :mod:`contact.halfspace.cerruti`
(Boussinesq's normal block, which is Love's of :mod:`contact.halfspace.influence` over
E*, Cerruti's tangential blocks and Kalker's coupling K), applied by FFT on the
zero-padded grids of :mod:`contact.halfspace.padding` (DC-FFT; Liu, Wang & Liu 2000, Wear
243:101): the linear convolution over the grid, with no dense matrix. Domains: the free
boundary in 3D, plane strain (one row, a line contact along y), the grid extended
``ahead`` cells in +x (displacements also beyond the last column, for the hereditary
integrals of steady rolling on a viscoelastic body, :mod:`contact.viscoelastic`), and
the periodic grid in 3D (the unpadded cyclic product with the periodised blocks).

The float32 products (``single``) serve the loose inner solves of the tangential solver:
relative error about 1e-7, two to three times faster than float64.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
import scipy.fft as sfft

from contact._errors import ContactInputError
from contact.halfspace.cerruti import influence_blocks, periodic_spectra
from contact.halfspace.constants import PairConstants
from contact.halfspace.padding import forward, inverse, padded_shape, wrapped_offsets


@lru_cache(maxsize=16)
def _spectra(ny: int, nx: int, dx: float, dy: float, c: PairConstants, line: bool,
             ahead: int = 0):
    """The blocks' spectra on the padded grid (free, or extended ``ahead`` cells: the
    compact layout of :func:`contact.halfspace.padding.padded_shape`), and the blocks at
    its wrapped offsets."""
    py, px = padded_shape(ny, nx, ahead, line)
    ox, used_x = wrapped_offsets(nx, px, dx, ahead)
    oy, used_y = (np.zeros(1), np.ones(1, dtype=bool)) if line else wrapped_offsets(ny, py, dy)
    blocks = influence_blocks(ox[None, :], oy[:, None], dx, dy, c, line)
    spec = {}
    for key, k in blocks.items():
        k = np.array(np.broadcast_to(k, (py, px)))
        # offsets that never occur in the linear convolution over the grid
        k[:, ~used_x] = 0.0
        k[~used_y, :] = 0.0
        spec[key] = sfft.rfft2(k)
    return spec, blocks


@lru_cache(maxsize=8)
def _periodic(ny: int, nx: int, dx: float, dy: float, c: PairConstants):
    """The periodised blocks' spectra and their real-space kernels (offsets wrapped)."""
    spec = periodic_spectra(ny, nx, dx, dy, c)
    return spec, {k: sfft.irfft2(v, s=(ny, nx)) for k, v in spec.items()}


class HalfSpacePair:
    """u = A t for the tractions t = (p, q_x, q_y) on a regular grid: free boundary, plane
    strain, extended ahead or periodic.

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
    ahead : int
        Displacements also on this many cells beyond the last column (+x): the products
        then have nx + ahead columns (the tractions are zero there).
    periodic : bool
        Periodic domain (3D only): the tractions repeat with the grid
        (:func:`contact.halfspace.cerruti.periodic_spectra`).
    """

    def __init__(self, ny: int, nx: int, dx: float, dy: float, constants: PairConstants,
                 line: bool = False, ahead: int = 0, periodic: bool = False):
        if line and ny != 1:
            raise ContactInputError("a plane-strain grid has a single row")
        if int(ahead) != ahead or ahead < 0:
            raise ContactInputError("the grid extends ahead by a whole number of cells >= 0")
        if periodic and (line or ahead):
            raise ContactInputError("a periodic pair is 3D, with nothing ahead of the grid")
        self.ny, self.nx, self.dx, self.dy = int(ny), int(nx), float(dx), float(dy)
        self.c = constants
        self.line = bool(line)
        self.ahead = int(ahead)
        self.shape = (self.ny, self.nx)
        # the shape of a product: the grid and the cells ahead of it
        self.out_shape = (self.ny, self.nx + self.ahead)
        # ahead: the compact layout, as the normal Convolution's (contact.halfspace.padding)
        self.periodic = bool(periodic)
        if self.periodic:
            self._pad = self.shape
            self.spec, self.real = _periodic(self.ny, self.nx, self.dx, self.dy, constants)
        else:
            self._pad = padded_shape(self.ny, self.nx, self.ahead, self.line)
            self.spec, self.real = _spectra(self.ny, self.nx, self.dx, self.dy, constants,
                                            self.line, self.ahead)
        self.coupled = constants.K != 0.0
        # threads pay off only on large transforms (their start-up dominates small ones)
        self._inv_spec: tuple[np.ndarray, ...] | None = None
        self._stiff: tuple[np.ndarray, ...] | None = None
        self._spec32: dict[str, np.ndarray] | None = None
        self._workers = 1 if self._pad[0] * self._pad[1] < 512 * 512 else -1

    def _fwd(self, a: np.ndarray, single: bool = False) -> np.ndarray:
        # along x first, on the ny rows that hold data, then along y over the padded
        # length: the zero rows of the padding are never transformed (the mirror of _inv)
        return forward(a, self._pad, single=single, workers=self._workers)

    def _spectra32(self) -> dict[str, np.ndarray]:
        if self._spec32 is None:
            self._spec32 = {k: v.astype(np.complex64) for k, v in self.spec.items()}
        return self._spec32

    def _inv(self, a: np.ndarray) -> np.ndarray:
        # the inverse along y first, then only the ny rows that are kept go through the
        # real inverse along x: a quarter less work, and pocketfft's one-axis transforms
        # run two to four times faster here than its 2D c2r (measured, issue 19)
        return inverse(a, self.ny, self._pad[1], self.nx + self.ahead, self._workers)

    def tangential(self, qx: np.ndarray, qy: np.ndarray | None = None,
                   single: bool = False) -> np.ndarray:
        """(u_x, u_y), shape (2, *out_shape), of the tangential tractions alone (m).

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
        the 2 x 2 inverse of the padded kernel spectra (a preconditioner, not a solve; for
        a grid with none ahead)."""
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
        solver; of the grid's own operator, none ahead)."""
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
        # unpadded: a quarter of the padded products' transform, so threads pay off
        # only on grids four times as large
        workers = 1 if self.ny * self.nx < 512 * 512 else -1
        f = forward(np.stack([ux, uy]), self.shape, single=True, workers=workers)
        b = np.stack([sxx * f[0] + sxy * f[1], sxy * f[0] + syy * f[1]])
        return inverse(b, self.ny, self.nx, self.nx, workers).astype(float)

    def normal(self, p: np.ndarray) -> np.ndarray:
        """u_n of the pressure alone (m)."""
        return self._inv(self.spec["nn"] * self._fwd(p))

    def normal_from_tangential(self, qx: np.ndarray, qy: np.ndarray) -> np.ndarray:
        """u_n of the tangential tractions (m): zero for quasi-identical bodies."""
        if not self.coupled:
            return np.zeros(self.out_shape)
        return self._inv(self.spec["nx"] * self._fwd(qx) + self.spec["ny"] * self._fwd(qy))

    def tangential_from_normal(self, p: np.ndarray) -> np.ndarray:
        """(u_x, u_y) of the pressure (m): zero for quasi-identical bodies."""
        if not self.coupled:
            return np.zeros((2, *self.out_shape))
        fp = self._fwd(p)
        return np.stack([self._inv(self.spec["xn"] * fp), self._inv(self.spec["yn"] * fp)])

    def self_normal(self) -> float:
        """u_n of an element under its own unit pressure (m/Pa): the diagonal of A_nn."""
        return float(self.real["nn"][0, 0])
