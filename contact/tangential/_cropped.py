"""The tangential influence products of a Newton step, on the box that holds the contact.

The Newton steps of the tangential problem (:mod:`contact.tangential._newton`) only move
tractions on the loaded elements and only read the slip there. The operator is a linear
(zero-padded) convolution, so its products restricted to any rectangle of the grid that
holds those elements are the products of the same kernel on that rectangle alone: the
same numbers up to the rounding of a different FFT length. The grid of a rolling ball is
a square of 2.5 contact radii, so the box of the contact is about 0.8 of each side and
its padded transforms about two thirds of the work (the box sides are rounded up to
lengths whose padded transforms are fast, so that one box, and its kernel spectra,
serves every step of a solve).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
import scipy.fft as sfft

from contact.halfspace.pair import HalfSpacePair

# a box that is not at least this much smaller than the grid is not worth a second
# set of kernel spectra
WORTH = 0.85


def _fast_side(need: int, limit: int) -> int:
    """The smallest side >= need whose padded transform length 2 side is 5-smooth
    (at most ``limit``)."""
    side = need
    while side < limit and sfft.next_fast_len(2 * side, real=True) != 2 * side:
        side += 1
    return min(side, limit)


def _span(mask_any: np.ndarray, extra_high: int) -> tuple[int, int]:
    """The first and one-past-last index where ``mask_any`` holds, with ``extra_high``
    more after (clipped to the grid)."""
    idx = np.flatnonzero(mask_any)
    return int(idx[0]), min(int(idx[-1]) + 1 + extra_high, mask_any.size)


def _place(lo: int, hi: int, side: int, n: int) -> tuple[int, int]:
    """A window of ``side`` over [lo, hi), kept inside 0..n."""
    start = max(0, min(lo, n - side))
    return start, start + side


@lru_cache(maxsize=8)
def _box_pair(ny: int, nx: int, dx: float, dy: float, c) -> HalfSpacePair:
    """One operator per box shape, kept between Newton steps (its float32 spectra are
    made once, not once a step)."""
    return HalfSpacePair(ny, nx, dx, dy, c)


class BoxProducts:
    """``tangential(qx, qy, single)`` of a HalfSpacePair for tractions that vanish outside
    ``active``, exact on ``active`` and its upwind neighbours (the next element along x,
    which the rolling slip reads); the rest of the returned field is zero."""

    def __init__(self, op: HalfSpacePair, active: np.ndarray):
        self.op = op
        self.box: tuple[slice, slice] | None = None
        self.inner = op
        # only the elastic pair on a free domain is a plain zero-padded convolution here
        # (viscoelastic, periodic and extended-ahead operators keep their own products)
        if (type(op) is not HalfSpacePair or op.line or op.periodic or op.ahead
                or not active.any()):
            return
        ny, nx = active.shape
        r0, r1 = _span(active.any(axis=1), 0)
        c0, c1 = _span(active.any(axis=0), 1)
        sy, sx = _fast_side(r1 - r0, ny), _fast_side(c1 - c0, nx)
        if sy * sx > WORTH * ny * nx:
            return
        r0, r1 = _place(r0, r1, sy, ny)
        c0, c1 = _place(c0, c1, sx, nx)
        self.box = (slice(r0, r1), slice(c0, c1))
        self.inner = _box_pair(sy, sx, op.dx, op.dy, op.c)
        self._out = np.zeros((2, ny, nx))

    def tangential(self, qx: np.ndarray, qy: np.ndarray | None,
                   single: bool = False) -> np.ndarray:
        """(u_x, u_y) of the tractions (see the class docstring)."""
        if self.box is None:
            return self.op.tangential(qx, qy, single)
        b = self.box
        u = self.inner.tangential(qx[b], None if qy is None else qy[b], single)
        self._out[(slice(None), *b)] = u
        return self._out
