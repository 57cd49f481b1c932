"""Memory model of an adhesive approach-retraction cycle: estimate the peak before allocating.

A cycle (:func:`contact.adhesion.cycle.approach_retraction`) holds the solver's workspace
on the periodic grid (the gap, the pressure, the interaction's tractions, the projected
gradient's search direction and step candidates, the kernel's spectrum and the FFT
buffers) and, for every equilibrium of the two legs, the state's gap and pressure: at
least two per approach step (one on the way in, one on the way out), more where a step
is split. Measured (peak resident set size added by ``adhesive_ball`` with the Dugdale
law of the ``surfmet adhesion`` help's first example at 256^2): 143 MB with 4 steps (83
equilibria after the splits), 172 MB with 40 steps (132 equilibria): about 9 B/cell per
equilibrium kept. With the solver's fixed :data:`contact.bem._memory.BASE_BYTES`,
:data:`BYTES_PER_CELL` and :data:`STATE_BYTES_PER_CELL` are set, and the count of
equilibria taken at its least (two per step), so that the estimate stays below both
measured peaks (130 and 168 MB): a grid refused would not have fitted. The available
memory and the share of it that may be planned for are those of the normal solver
(:mod:`contact.bem._memory`). A line contact's cells are counted with the same figures
(not measured separately: its solves at 2^18 cells took over five minutes each here),
so only grids of millions of cells are refused there.
"""

from __future__ import annotations

import math

from contact._errors import ContactMemoryError
from contact.bem._memory import BASE_BYTES, SAFETY, available_bytes

#: Peak bytes per cell of the solver's workspace (from the measured peaks: module notes).
BYTES_PER_CELL = 900
#: Bytes per cell of each equilibrium a cycle keeps.
STATE_BYTES_PER_CELL = 8


def estimate_adhesion_bytes(cells: int, steps: int) -> int:
    """Estimated peak memory (bytes) of a cycle of ``steps`` approach steps on each leg over
    ``cells`` grid cells (n^2 for a sphere, n for a line contact)."""
    per = BYTES_PER_CELL + STATE_BYTES_PER_CELL * 2 * int(steps)
    return BASE_BYTES + per * int(cells)


def largest_adhesion_grid(*, steps: int, line: bool = False,
                          available: int | None = None) -> int | None:
    """The largest even grid (cells per side; along x for a ``line``) whose estimated peak
    fits in :data:`contact.bem._memory.SAFETY` of the available memory; None when the
    available memory is unknown (no limit)."""
    avail = available_bytes() if available is None else int(available)
    if avail is None:
        return None
    per = BYTES_PER_CELL + STATE_BYTES_PER_CELL * 2 * int(steps)
    room = int(max(SAFETY * avail - BASE_BYTES, 0) // per)
    best = room if line else math.isqrt(room)
    return best - best % 2


def check_adhesion_memory(n: int, *, steps: int, line: bool = False,
                          available: int | None = None) -> int:
    """Refuse an adhesion grid whose estimated peak does not fit in the available memory.

    Parameters
    ----------
    n : int
        Cells per side (sphere) or along x (``line``: plane strain).
    steps : int
        Approach steps on each leg.
    line : bool
        A line contact (one row of n cells).
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
    cells = int(n) if line else int(n) ** 2
    need = estimate_adhesion_bytes(cells, steps)
    avail = available_bytes() if available is None else int(available)
    if avail is None or need <= SAFETY * avail:
        return need
    best = largest_adhesion_grid(steps=steps, line=line, available=avail)
    shape = f"{n} cells" if line else f"{n} x {n} cells"
    least = 64 if line else 16  # the solvers' smallest grids
    fits = (f"the largest grid that fits is {best}{'' if line else f' x {best}'} cells: use "
            f"grid={best} (CLI --grid {best}) or smaller" if best >= least
            else f"not even a grid of {least} cells fits: free some memory")
    raise ContactMemoryError(
        f"an adhesion grid of {shape} with {int(steps)} steps needs about {need / 1e9:.3g} "
        f"GB, but only {avail / 1e9:.3g} GB of memory is available ({100 * SAFETY:.0f} % of "
        f"it may be used); {fits}")
