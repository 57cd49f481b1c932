"""Chunked passes of the boundary-element kernels (:mod:`contact.bem._kernels`) on numba's threads.

A pass over the grid runs one chunk of cells a thread at a time. The chunks depend on the
grid's size only (never on the thread count) and each reduction is summed chunk by chunk
in chunk order, so a result is the same whatever the threads; a grid below one chunk is
summed in the plain serial order. Lists of corrections are written by each chunk from its
own first cell on, then compacted in chunk order: the serial pass's list.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

import numba as nb
import numpy as np

_CHUNK = 32768  # cells a chunk at least: a thread's start-up is small next to its pass
_MAX_CHUNKS = 64


@contextmanager
def kernel_threads(workers: int) -> Iterator[None]:
    """Run the passes of the block on ``workers`` threads (at most numba's own number).

    numba's thread count is per calling thread; the one before is restored on leaving.
    """
    before = nb.get_num_threads()
    nb.set_num_threads(max(1, min(int(workers), nb.config.NUMBA_NUM_THREADS)))
    try:
        yield
    finally:
        nb.set_num_threads(before)


@nb.njit(cache=True)
def n_chunks(n):  # pragma: no cover - compiled
    """How many chunks a pass over n cells is cut into (1 .. _MAX_CHUNKS)."""
    return max(1, min(_MAX_CHUNKS, n // _CHUNK))


@nb.njit(cache=True)
def bounds(c, nch, n):  # pragma: no cover - compiled
    """The cells [lo, hi) of chunk c of nch."""
    return c * n // nch, (c + 1) * n // nch


@nb.njit(cache=True)
def compact(index, value, start, counts, nch, n):  # pragma: no cover - compiled
    """Move chunk c's corrections, written at ``start + lo_c``, down to follow each other
    from ``start`` in chunk order (the serial pass's order); return their number."""
    k = start
    for c in range(nch):
        lo, _ = bounds(c, nch, n)
        src = start + lo
        for j in range(counts[c]):
            index[k] = index[src + j]
            value[k] = value[src + j]
            k += 1
    return k


# the three passes of capped_scale (contact.bem._kernels.capped_scale)


@nb.njit(cache=True, parallel=True)
def uncapped_total(p, hmax):  # pragma: no cover - compiled
    """(sum of p below the cap, #points at the cap)."""
    nch = n_chunks(p.size)
    sums = np.zeros(nch)
    counts = np.zeros(nch, dtype=np.int64)
    for c in nb.prange(nch):
        lo, hi = bounds(c, nch, p.size)
        total = 0.0
        n_cap = 0
        for i in range(lo, hi):
            if p[i] >= hmax:
                n_cap += 1
            else:
                total += p[i]
        sums[c] = total
        counts[c] = n_cap
    total = 0.0
    n_cap = 0
    for c in range(nch):
        total += sums[c]
        n_cap += counts[c]
    return total, n_cap


@nb.njit(cache=True, parallel=True)
def scaled_total(p, s, hmax):  # pragma: no cover - compiled
    """(sum over the uncapped points of min(s p, hmax), sum of p where s p < hmax)."""
    nch = n_chunks(p.size)
    sums = np.zeros((nch, 2))
    for c in nb.prange(nch):
        lo, hi = bounds(c, nch, p.size)
        f = 0.0
        df = 0.0
        for i in range(lo, hi):
            pi = p[i]
            if pi >= hmax:
                continue
            v = s * pi
            if v >= hmax:
                f += hmax
            else:
                f += v
                df += pi
        sums[c, 0] = f
        sums[c, 1] = df
    f = 0.0
    df = 0.0
    for c in range(nch):
        f += sums[c, 0]
        df += sums[c, 1]
    return f, df


@nb.njit(cache=True, parallel=True)
def apply_scale(p, s, hmax, index, value, nc):  # pragma: no cover - compiled
    """p = min(s p, hmax) off the cap; append the corrections after ``nc``; return #."""
    nch = n_chunks(p.size)
    counts = np.zeros(nch, dtype=np.int64)
    for c in nb.prange(nch):
        lo, hi = bounds(c, nch, p.size)
        k = nc + lo
        for i in range(lo, hi):
            pi = p[i]
            if pi >= hmax:
                if s != 1.0:
                    index[k] = i
                    value[k] = (1.0 - s) * hmax
                    k += 1
                continue
            v = s * pi
            if v > hmax:
                index[k] = i
                value[k] = hmax - v
                k += 1
                v = hmax
            p[i] = v
        counts[c] = k - nc - lo
    return compact(index, value, nc, counts, nch, p.size)
