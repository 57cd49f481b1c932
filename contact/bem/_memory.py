"""Memory model of a contact solve: estimate the peak before allocating, refuse what cannot fit.

A solve on an n x n grid holds a fixed number of n^2 arrays at its peak. Counting them in
bytes per cell (free boundary, :func:`contact.bem.solve_normal` with mixed precision,
called through :class:`contact.setups._ball_on_plate.SphereContact`):

=========================================================  ==============
array (:class:`contact.bem._state.Workspace`)               bytes per cell
=========================================================  ==============
gap h (the iteration's own: pressures in E* units), p, u,
d, t                                                       5 x 8 = 40
float32 search direction (Workspace.direction_fft, also
where many corrections are scattered)                      4
correction index and value (int32 + float64; mostly never
touched, so not resident)                                  12
kernel: even half of the padded spectrum (f64), quadrant   8 + 8
preconditioner stiffness (f32)                             2
complex work array of the grid's own rows (complex128),
the convolution's result                                   16 + 8
result fields (pressure, gap, displacement, plastic)       32 per result
nested coarse grids (n/2, n/4, ...; kernels cached)        + 1/3 of the kernels
=========================================================  ==============

(issue 37: the padded grid is transformed by blocks and never held whole, the spectrum's
even half only, no separate dense or preconditioned work array; the float64 re-sync
written over the displacement it replaces, the coarse answer dropped before the fine
solve: a nested free 512^2 solve peaks at 97 B/cell under tracemalloc). Measured: the whole
``surfmet contact`` command on the bundled plate at 4096^2 peaks at 1.78 GB resident
(106 B/cell, the interpreter and the scans included; 207 B/cell before issue 37), and a
1024^2 rough solve alone adds 110 MB to the resident set size (126 MB before the in-place
re-sync); :data:`BYTES_PER_CELL` holds 110 and :data:`BASE_BYTES` 16 MiB, a little above
both. The estimate is within 1.5x of the measured peak (a test checks it at 1024^2).

An elastic-plastic solve adds p_old, u_old, the projected step and its candidates
(4 x 8 B) and doubles the correction buffers (+16 B):
:data:`PLASTIC_EXTRA_PER_CELL`. Every further result kept alive (the elastic and the
plastic solution of ``hertz-check``, one per load of a rolling sweep) adds
:data:`RESULT_BYTES_PER_CELL`.

The available memory is the kernel's ``MemAvailable`` (``/proc/meminfo``), bounded by the
cgroup limit where one is set; only :data:`SAFETY` of it is planned for, so that the
out-of-memory killer never has to choose this process.
"""

from __future__ import annotations

import math

from contact._errors import ContactMemoryError
from contact._sysmem import SAFETY, available_bytes

#: Peak bytes per grid cell of one elastic solve (measured; see the module notes).
BYTES_PER_CELL = 110
#: Extra peak bytes per cell of an elastic-plastic solve.
PLASTIC_EXTRA_PER_CELL = 48
#: Bytes per cell of each further result kept (four float64 fields).
RESULT_BYTES_PER_CELL = 32
#: Fixed overhead of a solve beyond the interpreter (bytes): FFT plans, small arrays.
BASE_BYTES = 16 * 2**20
# SAFETY (the fraction of the available memory a solve may plan to use) and
# available_bytes live in contact._sysmem, light enough for a file reader to import.


def estimate_peak_bytes(n: int, *, ny: int | None = None, plastic: bool = False,
                        results: int = 1) -> int:
    """Estimated peak memory (bytes) that a solve on an (ny, n) grid adds to the process.

    Parameters
    ----------
    n : int
        Cells per side (columns).
    ny : int, optional
        Rows (default ``n``).
    plastic : bool
        Elastic-perfectly-plastic solve (a hardness is given).
    results : int
        Number of results kept alive together (at least 1).
    """
    cells = int(n) * int(n if ny is None else ny)
    per = BYTES_PER_CELL + (PLASTIC_EXTRA_PER_CELL if plastic else 0)
    per += RESULT_BYTES_PER_CELL * max(int(results) - 1, 0)
    return BASE_BYTES + per * cells


def largest_grid(budget: float, *, plastic: bool = False, results: int = 1) -> int:
    """The largest even, FFT-friendly square grid whose estimate fits in ``budget`` bytes.

    Returns 0 when not even an 8 x 8 grid fits.
    """
    from contact._geometry import fast_even

    per = (BYTES_PER_CELL + (PLASTIC_EXTRA_PER_CELL if plastic else 0)
           + RESULT_BYTES_PER_CELL * max(int(results) - 1, 0))
    room = budget - BASE_BYTES
    if room <= per * 64:
        return 0
    n = 2 * math.floor(math.sqrt(room / per) / 2)
    while n >= 8 and fast_even(n) != n:
        n -= 2
    return max(n, 0)


def check_grid_memory(n: int, *, ny: int | None = None, plastic: bool = False,
                      results: int = 1, available: int | None = None) -> int:
    """Refuse a grid whose estimated peak does not fit in the available memory.

    Parameters
    ----------
    n, ny, plastic, results
        As for :func:`estimate_peak_bytes`.
    available : int, optional
        Available memory (bytes); default :func:`available_bytes` (no check if unknown).

    Returns
    -------
    int
        The estimate (bytes).

    Raises
    ------
    ContactMemoryError
        The estimate exceeds :data:`SAFETY` times the available memory; the message names
        the largest grid that fits.
    """
    need = estimate_peak_bytes(n, ny=ny, plastic=plastic, results=results)
    avail = available_bytes() if available is None else int(available)
    if avail is None:
        return need
    budget = SAFETY * avail
    if need <= budget:
        return need
    best = largest_grid(budget, plastic=plastic, results=results)
    gb = 1e9
    fits = (f"the largest grid that fits is {best} x {best} cells: use grid={best} "
            f"(CLI --grid {best}) or smaller" if best >= 8
            else "not even an 8 x 8 grid fits: free some memory")
    shape = f"{n} x {n if ny is None else ny}"
    raise ContactMemoryError(
        f"a {shape} contact grid needs about {need / gb:.3g} GB, but only "
        f"{avail / gb:.3g} GB of memory is available ({100 * SAFETY:.0f} % of it may be "
        f"used); {fits}"
    )
