"""The contact grid as the contact commands (``contact``, ``hertz-check``, ``rolling``) take
it: the ``--grid`` option and its check, and the ``--on-edge`` option. Where the pixel came from is
:func:`surfmet.mechanics.scan_preparation.pixel_source`."""

from __future__ import annotations

from typing import Any

from surfmet._errors import SurfmetInputError
from surfmet.mechanics.scan_preparation import pixel_source

__all__ = ["MIN_GRID", "add_grid_argument", "add_on_edge_argument", "check_grid", "pixel_source"]

#: The fewest cells per side a contact grid may have.
MIN_GRID = 8


def add_grid_argument(parser: Any, help: str) -> None:
    """The ``--grid N`` option (cells per side; checked by :func:`check_grid`)."""
    parser.add_argument("--grid", type=int, metavar="N", help=help)


def add_on_edge_argument(parser: Any, help: str) -> None:
    """The ``--on-edge {enlarge,warn,raise}`` option: a contact reaching the domain's edge."""
    parser.add_argument("--on-edge", choices=("enlarge", "warn", "raise"), default="enlarge",
                        help=help)


def check_grid(grid: int | None) -> None:
    """Refuse a ``--grid`` below :data:`MIN_GRID` cells per side."""
    if grid is not None and grid < MIN_GRID:
        raise SurfmetInputError(f"--grid needs at least {MIN_GRID} cells per side")
