"""Influence coefficients of an elastic half-space: Love's uniform pressure on a rectangle.

A cell of size dx * dy carrying a uniform pressure p displaces the surface point (x, y)
(measured from the cell centre) by ``p * K(x, y) / E*`` into the body, with (Love 1929,
Phil. Trans. R. Soc. A 228:377; Johnson 1985, *Contact Mechanics*, eq. 3.25)::

    K(x, y) = 1/pi * sum over the four corners (xc, yc) = (x +- dx/2, y +- dy/2) of
              +- [ xc asinh(yc/|xc|) + yc asinh(xc/|yc|) ]

with sign + at (x+dx/2, y+dy/2) and (x-dx/2, y-dy/2), - at the other two. This is the
classical form ``x ln(y + r) + y ln(x + r)`` rewritten with asinh: the ``x ln|x|`` parts
cancel between corners, and asinh avoids the cancellation of ``ln(y + r)`` for y < 0.

Two kernel layouts are built from K here (both cached by grid, pitch and periodicity);
the convolution operators that apply them are in :mod:`contact.halfspace.convolution`:

- **free boundary** (DC-FFT; Liu, Wang & Liu 2000, Wear 243:101): the kernel is laid out on
  a grid of twice the size with wrap-around offsets, the pressure is zero-padded, and the
  first quadrant of the cyclic convolution is the exact linear convolution.
- **periodic**: the pressure repeats with the domain. The Fourier coefficients of the
  periodised Love kernel are the alias sum of the continuous half-space response
  2/|q| (Johnson 1985 sec. 13.2, the wavy surface; Stanley & Kato 1997, J. Tribol.
  119:481)
  times the transform of the uniform cell::

      K^(q) = sum_{m,n} 2/|q + G_mn| * sinc(qx' dx/2) * sinc(qy' dy/2),   q' = q + G_mn

  with G_mn = (2 pi m / dx, 2 pi n / dy); the sum is truncated at |m|, |n| <= n_alias. The
  terms alternate in sign, so the truncation error falls fast; the q = 0 term (the mean
  displacement, a rigid-body motion in a periodic problem) is zero.

All kernels here are for E* = 1; divide by E* to get displacements. The alias sum is
the one of :mod:`contact.halfspace.alias` (compiled with numba; the pair operator's
blocks use it too); the plain-numpy twin of :func:`periodic_love_spectrum` lives in the
tests (``tests/kernel_twins.py``).
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
import scipy.fft as sfft

from contact.halfspace.alias import alias_sums
from contact.halfspace.padding import padded_shape, wrapped_offsets


def love_corner(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Love's corner function x asinh(y/|x|) + y asinh(x/|y|) (the 1/rho integral)."""
    ax = np.abs(x)
    ay = np.abs(y)
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = np.where(ax > 0, x * np.arcsinh(y / np.where(ax > 0, ax, 1.0)), 0.0)
        t2 = np.where(ay > 0, y * np.arcsinh(x / np.where(ay > 0, ay, 1.0)), 0.0)
    return t1 + t2


def corner_sum(fun, x: np.ndarray, y: np.ndarray, hx: float, hy: float) -> np.ndarray:
    """F(x+hx, y+hy) - F(x+hx, y-hy) - F(x-hx, y+hy) + F(x-hx, y-hy) of a corner function F.

    The integral over the rectangle [-hx, hx] x [-hy, hy] of a kernel k(x - s, y - t) is
    this sum when d^2 F / dx dy = k.
    """
    return fun(x + hx, y + hy) - fun(x + hx, y - hy) - fun(x - hx, y + hy) + fun(x - hx, y - hy)


def love_coefficients(x: np.ndarray, y: np.ndarray, dx: float, dy: float) -> np.ndarray:
    """Displacement at (x, y) per unit pressure on the cell [-dx/2, dx/2] x [-dy/2, dy/2].

    For E* = 1 (divide by E*). ``x`` and ``y`` broadcast against each other.

    Parameters
    ----------
    x, y : array_like
        Positions relative to the cell centre, in metres.
    dx, dy : float
        Cell size in metres.
    """
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    return corner_sum(love_corner, x, y, 0.5 * dx, 0.5 * dy) / math.pi


def self_influence(dx: float, dy: float) -> float:
    """Displacement of a cell centre per unit pressure on the cell itself (E* = 1).

    Equals (2/pi) [dx asinh(dy/dx) + dy asinh(dx/dy)]; for a square cell,
    (4/pi) asinh(1) dx = 1.1222 dx.
    """
    return float(love_coefficients(np.array(0.0), np.array(0.0), dx, dy))


def _corner_lattice(xc: np.ndarray, yc: np.ndarray) -> np.ndarray:
    """:func:`love_corner` on the lattice (yc[i], xc[j]) of cell corners, bit for bit.

    No corner lies on an axis (the coordinates are odd multiples of half a cell), so the
    guards against |x| = 0 are not needed; the two terms are formed in place, and on a
    square lattice (xc == yc) the second is the transpose of the first,
    y asinh(x/|y|) at (i, j) being x asinh(y/|x|) at (j, i): one asinh a corner instead of
    two (the quadrant's cost, 1.3 s of the 4096^2 command, was mostly these).
    """
    t1 = np.arcsinh(yc[:, None] / np.abs(xc)[None, :])
    t1 *= xc[None, :]
    if xc.shape == yc.shape and np.array_equal(xc, yc):
        t1 += t1.T.copy()
        return t1
    t2 = np.arcsinh(xc[None, :] / np.abs(yc)[:, None])
    t2 *= yc[:, None]
    t1 += t2
    return t1


@lru_cache(maxsize=8)
def free_kernel_quadrant(ny: int, nx: int, dx: float, dy: float) -> np.ndarray:
    """K at the non-negative offsets (i dy, j dx), 0 <= i < ny, 0 <= j < nx (read-only).

    K is even in x and in y, so this quadrant holds the whole free-boundary kernel.
    """
    # Neighbouring cells share their corners: Love's corner function on the (ny+1, nx+1)
    # lattice of cell corners, once, and its corner sums (:func:`corner_sum`) by
    # differences, a quarter of the asinh of love_coefficients. The same values to
    # rounding (7e-13 of the largest at 2048^2, where the far field's cancellation, the
    # same in both, sets the error).
    xc = (np.arange(nx + 1) - 0.5) * dx
    yc = (np.arange(ny + 1) - 0.5) * dy
    f = _corner_lattice(xc, yc)
    q = f[1:, 1:] - f[:-1, 1:]
    q -= f[1:, :-1]
    q += f[:-1, :-1]
    q /= math.pi
    q.setflags(write=False)
    return q


@lru_cache(maxsize=8)
def free_kernel_spectrum(ny: int, nx: int, dx: float, dy: float) -> np.ndarray:
    """Rows 0 .. ny of the real spectrum of the zero-padded free-boundary kernel (E* = 1).

    On the (2ny, 2nx) cyclic grid the kernel sits at the cells (+-i, +-j) mod 2n (the
    offset +-n, which no product uses, left zero). It is even along both axes, so its
    rfft2 is real, of shape (2ny, nx + 1), and even along y: row 2ny - k is row k. This
    returns rows 0 .. ny, shape (ny + 1, nx + 1) (half the memory of the whole);
    :func:`contact.halfspace.padding.convolve_padded` takes it as it is.
    """
    # the transform of an even layout is the type-I cosine transform of the quadrant
    # with the zero row and column of the offset n appended: the same numbers as rfft2 of
    # the (2ny, 2nx) layout to rounding (1e-16), without building the layout or its
    # complex transform (a tenth of the time, a fifth of the memory at 2048^2)
    quadrant = np.zeros((ny + 1, nx + 1))
    quadrant[:ny, :nx] = free_kernel_quadrant(ny, nx, dx, dy)
    out = sfft.dctn(quadrant, type=1, overwrite_x=True, workers=-1)
    out.setflags(write=False)
    return out


@lru_cache(maxsize=8)
def extended_kernel_spectrum(ny: int, nx: int, ahead: int, dx: float,
                             dy: float) -> np.ndarray:
    """Complex spectrum of the Love kernel laid out for a grid extended ``ahead`` cells.

    On the cyclic grid of :func:`contact.halfspace.padding.padded_shape`,
    ``irfft2(rfft2(p, s) * spectrum)[:ny, :nx + ahead]`` is the displacement of the
    pressure ``p`` (ny, nx) on the grid and ``ahead`` cells beyond its last column (E* = 1).
    The layout is not symmetric in x, so the spectrum is complex.
    """
    py, px = padded_shape(ny, nx, ahead)
    ox, _ = wrapped_offsets(nx, px, dx, ahead)
    oy, _ = wrapped_offsets(ny, py, dy)
    # K everywhere, the offsets no product uses included (unlike the free layout, which
    # leaves the cell at +-n zero): either is exact, and this is the layout the rolling
    # solver has always used, so its answers stay bitwise
    spec = sfft.rfft2(love_coefficients(ox[None, :], oy[:, None], dx, dy))
    spec.setflags(write=False)
    return spec


def periodic_love_spectrum(ny: int, nx: int, dx: float, dy: float,
                           n_alias: int) -> np.ndarray:
    """Alias sum of 2/|q'| sinc(qx' dx/2) sinc(qy' dy/2) on the rfft grid (E* = 1).

    The normal symbol of the one alias sum, :func:`contact.halfspace.alias.alias_sums`.
    """
    return alias_sums(int(ny), int(nx), float(dx), float(dy), int(n_alias), False)[0]


@lru_cache(maxsize=8)
def periodic_kernel_spectrum(
    ny: int, nx: int, dx: float, dy: float, n_alias: int = 8
) -> np.ndarray:
    """Real spectrum, shape (ny, nx//2 + 1), of the periodised Love kernel (E* = 1).

    ``irfft2(rfft2(p) * spectrum, s=(ny, nx))`` is the displacement of the periodic
    pressure ``p``, up to its mean (the q = 0 coefficient is zero).
    """
    spec = periodic_love_spectrum(ny, nx, float(dx), float(dy), int(n_alias))
    spec.setflags(write=False)
    return spec


@lru_cache(maxsize=8)
def periodic_kernel_real(ny: int, nx: int, dx: float, dy: float, n_alias: int = 8) -> np.ndarray:
    """The periodic kernel in real space, shape (ny, nx), offsets wrapped (read-only)."""
    k = sfft.irfft2(periodic_kernel_spectrum(ny, nx, dx, dy, n_alias), s=(ny, nx))
    k.setflags(write=False)
    return k
