"""The contact grid as the contact commands (``contact``, ``hertz-check``, ``rolling``) take
it and report it: the ``--grid`` option, its check, and where the pixel came from."""

from __future__ import annotations

from typing import Any

from surfmet.errors import SurfmetInputError

#: The fewest cells per side a contact grid may have.
MIN_GRID = 8


def add_grid_argument(parser: Any, help: str) -> None:
    """The ``--grid N`` option (cells per side; checked by :func:`check_grid`)."""
    parser.add_argument("--grid", type=int, metavar="N", help=help)


def check_grid(grid: int | None) -> None:
    """Refuse a ``--grid`` below :data:`MIN_GRID` cells per side."""
    if grid is not None and grid < MIN_GRID:
        raise SurfmetInputError(f"--grid needs at least {MIN_GRID} cells per side")


def pixel_source(dx: float, pair: Any, grid: int | None) -> str:
    """Where the contact grid's pixel came from, for the output."""
    if grid is not None:
        return f"--grid {grid}"
    if pair is not None and abs(dx - pair.dx) <= 1e-9 * pair.dx:
        return "the scans' own pixel"
    if pair is not None:
        return "finer than the scans' pixel: 16 cells per Hertz radius"
    return "automatic, smooth ball"
