"""Shared figure conventions: a headless backend, unit scaling and labels."""

from __future__ import annotations

from pathlib import Path
from typing import Any

UM = 1e-6
MM = 1e-3
MPA = 1e6


def pyplot() -> Any:
    """matplotlib.pyplot on the non-interactive Agg backend (works with no display)."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt


def new_figure(nrows: int = 1, ncols: int = 1, size: tuple[float, float] = (6.4, 4.2)) -> Any:
    """A figure and its axes with the house style (constrained layout)."""
    plt = pyplot()
    fig, ax = plt.subplots(nrows, ncols, figsize=size, layout="constrained")
    return fig, ax


def finish(fig: Any, path: str | Path | None = None, dpi: int = 120) -> Any:
    """Save ``fig`` to ``path`` when given, and return it."""
    if path is not None:
        fig.savefig(Path(path), dpi=dpi)
    return fig


def close(fig: Any) -> None:
    """Release a figure's memory (batch runs make many)."""
    pyplot().close(fig)
