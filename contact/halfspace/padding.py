"""The zero-padded FFT of a grid: where a kernel's offsets sit, and the pruned transforms.

A linear convolution u = K * t over a grid of n cells is the cyclic convolution over a
longer, zero-padded grid of L cells, provided every offset it needs maps to its own
cell of the cyclic grid (Liu, Wang & Liu 2000, Wear 243:101, the DC-FFT). Offsets
0 .. n+m-1 sit at cells 0 .. n+m-1 and offsets -1, -2, ... at L-1, L-2, ... The domains
(the periodic one needs no padding):

- **free**: L = 2n, displacements on the n cells; the cell at L/2 (offset +-n, which no
  product uses) is left zero (:func:`wrapped_offsets` marks it unused);
- **plane strain**: one row, padded along x only;
- **extended ahead**: displacements also on m cells beyond the last column (+x), for the
  hereditary integrals of steady rolling, which look ahead: L = the next fast FFT length
  of 2n + m along x (and of 2n along y), the kernel evaluated in every cell that an
  offset -(n-1) .. n+m-1 maps to. The normal operator
  (:class:`contact.halfspace.convolution.Convolution`) and the tangential pair
  (:class:`contact.halfspace.pair.HalfSpacePair`) both use it. (The pair used the free
  padding of the grid extended by m cells, L = 2(n + m), until issue 26: the same
  convolution up to rounding, which moved the viscoelastic tractions by at most 1.4e-10
  of their largest value.)

The transforms are pruned: forward, only the rows that carry data are transformed along
x (the padding rows stay zero); backward, only the rows kept are transformed along x.
Both run on stacked inputs (leading axes), in float64 or float32.
"""

from __future__ import annotations

import os
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import scipy.fft as sfft


def padded_shape(ny: int, nx: int, ahead: int = 0, line: bool = False) -> tuple[int, int]:
    """The (rows, columns) of the cyclic grid of a (ny, nx) grid extended ``ahead`` cells.

    Free (``ahead = 0``): exactly (2 ny, 2 nx); extended ahead, compact: the next fast FFT
    lengths of 2 ny and 2 nx + ahead; plane strain (``line``): a single row.
    """
    if ahead == 0:
        px = 2 * nx
        py = 2 * ny
    else:
        px = sfft.next_fast_len(2 * nx + ahead)
        py = sfft.next_fast_len(2 * ny)
    return (1 if line else py), px


def wrapped_offsets(n: int, length: int, pitch: float, ahead: int = 0) -> tuple[np.ndarray,
                                                                               np.ndarray]:
    """Offsets (m) of the cells of a cyclic grid of ``length``, and which of them are used.

    Cell k holds offset k for k < n + ahead and k - length otherwise; ``used`` is False
    where the offset lies outside -(n-1) .. n+ahead-1 (never in the linear convolution).
    """
    k = np.arange(length)
    cells = np.where(k < n + ahead, k, k - length)
    used = (cells > -n) & (cells < n + ahead)
    return cells.astype(float) * pitch, used


def real_types(single: bool) -> tuple[type, type]:
    """The real and complex dtypes of a float32 (``single``) or float64 transform."""
    return (np.float32, np.complex64) if single else (np.float64, np.complex128)


def forward(x: np.ndarray, shape: tuple[int, int], rows: tuple[int, int] | None = None,
            single: bool = False, workers: int = -1,
            out: np.ndarray | None = None) -> np.ndarray:
    """Spectrum (..., py, px//2 + 1) of x (..., ny, nx) zero-padded to ``shape`` = (py, px).

    ``rows = (lo, hi)`` says x is zero outside rows [lo, hi): only those are transformed
    along x. ``out`` is an optional complex work array of the spectrum's shape (its rows
    outside [lo, hi) are zeroed here); ``single`` transforms in float32.
    """
    py, px = shape
    lo, hi = (0, x.shape[-2]) if rows is None else rows
    real_type, complex_type = real_types(single)
    if out is None:
        out = np.zeros((*x.shape[:-2], py, px // 2 + 1), dtype=complex_type)
    else:
        out[..., :lo, :] = 0
        out[..., hi:, :] = 0
    out[..., lo:hi, :] = sfft.rfft(np.asarray(x[..., lo:hi, :], dtype=real_type), n=px,
                                   axis=-1, workers=workers)
    return sfft.fft(out, axis=-2, overwrite_x=True, workers=workers)


def inverse(spec: np.ndarray, ny: int, px: int, keep: int, workers: int = -1) -> np.ndarray:
    """The first ``ny`` rows and ``keep`` columns of the real inverse of ``spec``.

    The inverse along y runs first, so that only the ``ny`` rows kept go through the real
    inverse along x (``spec`` is overwritten).
    """
    b = sfft.ifft(spec, axis=-2, overwrite_x=True, workers=workers)[..., :ny, :]
    return sfft.irfft(b, n=px, axis=-1, overwrite_x=True, workers=workers)[..., :keep]


#: Columns (forward x rows) transformed together in :func:`convolve_padded`: few enough
#: that a block's padded copy stays in cache.
BLOCK = 32

_POOL: dict[tuple[int, int], ThreadPoolExecutor] = {}


def _threads(workers: int) -> int:
    """The threads a ``workers`` argument asks for (-1: every core)."""
    return max(1, os.cpu_count() or 1) if workers < 0 else max(1, int(workers))


def _run_blocks(fun, starts: range, workers: int) -> None:
    """fun(start) for every block start, spread over ``workers`` threads.

    The blocks write disjoint parts of the arrays, and the FFT and numpy's copies and
    products release the GIL: by block in threads, the copies and the multiply (a third of
    a padded convolution's time in one thread) run in parallel too.
    """
    n = _threads(workers)
    if n == 1 or len(starts) < 2:
        for start in starts:
            fun(start)
        return
    # by process: a forked child inherits the dict but not the threads (a batch run's
    # workers), and an executor without its threads would never run a block
    key = (os.getpid(), n)
    pool = _POOL.get(key)
    if pool is None:
        pool = _POOL[key] = ThreadPoolExecutor(n, thread_name_prefix="surfmet-fft")
    for _ in pool.map(fun, starts):
        pass


def convolve_padded(x: np.ndarray, spectrum: np.ndarray, shape: tuple[int, int],
                    rows: tuple[int, int], keep: int, work: np.ndarray,
                    workers: int = -1, out: np.ndarray | None = None) -> np.ndarray:
    """The first ``keep`` columns of the cyclic convolution of x (ny, nx) zero-padded to
    ``shape``, by blocks: the (ny, nx) grid's own rows and columns are all that is kept.

    ``spectrum`` is the kernel's (py, px//2 + 1) spectrum (real or complex, float64; a
    float32 transform rounds each block of it to float32, as a float32 copy would), or
    only its rows 0 .. py/2 for a kernel even along y (row py - k is row k); ``work`` a
    complex (ny, px//2 + 1) array in the transform's precision (overwritten). x is zero
    outside rows ``rows = (lo, hi)``. The padded grid is never held whole:

    - forward along x, the rows [lo, hi) (zero-padded to px), into ``work``;
    - along y, a block of columns at a time: the block's rows [lo, hi) transformed to the
      py points, multiplied, transformed back, and the ny rows kept written back in place.
      The block is transformed from row 0, not row lo: the convolution shifts with its
      input, so output row r is the block's row (r - lo) mod py (exact, because every
      offset a kept row needs, -(ny-1) .. ny-1, has its own cell of the cyclic grid);
    - inverse along x, a block of rows at a time, into the (ny, keep) result.

    The blocks run on ``workers`` threads. Compared with :func:`forward` and
    :func:`inverse` on the whole padded grid this halves the work array, and no strided
    copy of the padded result is made. ``out``, a C-contiguous (ny, keep) array in the
    transform's precision that does not overlap x, receives the result (the solver's
    float64 re-sync writes over the displacement it replaces: no second one at its peak).
    """
    ny = x.shape[0]
    py, px = shape
    lo, hi = rows
    real_type = np.float32 if work.dtype == np.complex64 else np.float64
    ncol = work.shape[1]
    if out is None:
        out = np.empty((ny, keep), dtype=real_type)

    def along_x(r0: int) -> None:
        r1 = min(r0 + BLOCK, hi)
        work[r0:r1] = sfft.rfft(np.asarray(x[r0:r1], dtype=real_type), n=px, axis=-1,
                                workers=1)

    def along_y(c0: int) -> None:
        c1 = min(c0 + BLOCK, ncol)
        block = sfft.fft(work[lo:hi, c0:c1], n=py, axis=0, workers=1)
        kernel = spectrum[:, c0:c1]
        if block.dtype == np.complex64 and kernel.dtype in (np.float64, np.complex128):
            # rounded to float32 by block: multiplying a complex64 block by float64 costs
            # twice as much (numpy's mixed-type loop), a float32 copy kept whole 4 bytes a
            # cell
            kernel = kernel.astype(np.complex64 if np.iscomplexobj(kernel) else np.float32)
        if spectrum.shape[0] == py:
            np.multiply(block, kernel, out=block)
        else:  # the even half: rows py/2+1 .. py-1 are rows py/2-1 .. 1
            half = py // 2
            np.multiply(block[:half + 1], kernel, out=block[:half + 1])
            np.multiply(block[half + 1:], kernel[half - 1:0:-1], out=block[half + 1:])
        block = sfft.ifft(block, axis=0, overwrite_x=True, workers=1)
        work[:lo, c0:c1] = block[py - lo:]
        work[lo:, c0:c1] = block[:ny - lo]

    def back_along_x(r0: int) -> None:
        r1 = min(r0 + BLOCK, ny)
        out[r0:r1] = sfft.irfft(work[r0:r1], n=px, axis=-1, workers=1)[:, :keep]

    _run_blocks(along_x, range(lo, hi, BLOCK), workers)
    _run_blocks(along_y, range(0, ncol, BLOCK), workers)
    _run_blocks(back_along_x, range(0, ny, BLOCK), workers)
    return out
