"""Memory model of a steady-rolling solve: estimate the peak before allocating.

The tangential solver (:func:`contact.tangential._steady.steady_rolling`) holds, per
element, the pressure and its normal problem's workspace, the tractions, slips and their
previous values (2 components each), the Cerruti operator's padded spectra (four
kernels on a 2n x 2n grid), the Krylov basis of the Newton steps' GMRES and, with
nested grids, the coarse grids (+1/3). Measured (peak resident set size added by one
free-rolling solve of steel on aluminium, 3D): 1944 B/element at 128^2, 1794 at 256^2,
1612 at 512^2; plane strain 1127 B/element at 100,000 elements. :data:`BYTES_PER_CELL`
and :data:`LINE_BYTES_PER_CELL` round these up. The viscoelastic solves of the same
command (:mod:`contact.viscoelastic`) fit the same model in 3D (1848 B/element at 128^2);
in plane strain they hold dense n x n influence matrices: 23 B per matrix entry at
n = 2048, :data:`DENSE_BYTES_PER_ENTRY` (``dense=True``). The available memory and the share of
it that may be planned for are those of the normal solver (:mod:`contact.bem._memory`).
"""

from __future__ import annotations

import math

from contact._errors import ContactMemoryError
from contact.bem._memory import SAFETY, available_bytes

#: Fixed overhead of a rolling solve beyond the interpreter (bytes): its FFT plans and the
#: normal solves' small arrays (the normal solve's own base is smaller since issue 37).
BASE_BYTES = 64 * 2**20

#: Peak bytes per element of a 3D rolling solve (measured; see the module notes).
BYTES_PER_CELL = 2000
#: Peak bytes per element of a plane-strain (line) rolling solve.
LINE_BYTES_PER_CELL = 1200
#: Peak bytes per entry of the dense n x n matrices of a plane-strain viscoelastic solve.
DENSE_BYTES_PER_ENTRY = 24


def _per_cell(line: bool, dense: bool) -> tuple[int, bool]:
    """(bytes per unit, whether the units grow as n^2)."""
    if line and not dense:
        return LINE_BYTES_PER_CELL, False
    return (DENSE_BYTES_PER_ENTRY if line else BYTES_PER_CELL), True


def estimate_rolling_bytes(n: int, *, line: bool = False, dense: bool = False) -> int:
    """Estimated peak memory (bytes) a rolling solve on n x n elements (n in plane
    strain; ``dense``: with n x n matrices) adds to the process."""
    per, square = _per_cell(line, dense)
    return BASE_BYTES + per * (int(n) ** 2 if square else int(n))


def largest_rolling_grid(budget: float, *, line: bool = False, dense: bool = False) -> int:
    """The most elements per side (even) whose estimate fits in ``budget`` bytes; 0 when
    not even 8 fit."""
    per, square = _per_cell(line, dense)
    room = int(max(budget - BASE_BYTES, 0) // per)
    n = math.isqrt(room) if square else room
    n -= n % 2
    return n if n >= 8 else 0


def check_rolling_memory(n: int, *, line: bool = False, dense: bool = False,
                         available: int | None = None) -> int:
    """Refuse a rolling grid whose estimated peak does not fit in the available memory.

    Parameters
    ----------
    n : int
        Elements per side (3D) or elements along x (plane strain).
    line : bool
        Plane strain.
    dense : bool
        A plane-strain solve with dense n x n matrices (viscoelastic).
    available : int, optional
        Available memory (bytes); default :func:`contact.bem._memory.available_bytes` (no
        check if unknown).

    Returns
    -------
    int
        The estimate (bytes).

    Raises
    ------
    ContactMemoryError
        The estimate exceeds :data:`contact.bem._memory.SAFETY` of the available memory; the
        message names the largest grid that fits.
    """
    need = estimate_rolling_bytes(n, line=line, dense=dense)
    avail = available_bytes() if available is None else int(available)
    if avail is None or need <= SAFETY * avail:
        return need
    best = largest_rolling_grid(SAFETY * avail, line=line, dense=dense)
    most = f"{best} elements" if line else f"{best} x {best} elements"
    fits = (f"the largest grid that fits is {most}: use grid={best} (CLI --grid "
            f"{best}) or smaller" if best else "not even 8 elements fit: free some memory")
    shape = f"{n} elements" if line else f"{n} x {n} elements"
    raise ContactMemoryError(
        f"a rolling-contact grid of {shape} needs about {need / 1e9:.3g} GB, but only "
        f"{avail / 1e9:.3g} GB of memory is available ({100 * SAFETY:.0f} % of it may be "
        f"used); {fits}")
