"""Shared figure conventions: a headless backend, unit scaling and labels."""

from __future__ import annotations

import math
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
    """Save ``fig`` to ``path`` when given (whole or not at all, :mod:`surfmet.atomic`),
    and return it."""
    if path is not None:
        save(fig, path, dpi=dpi)
    return fig


def save(fig: Any, path: str | Path, dpi: int = 120) -> None:
    """Write ``fig`` to ``path`` (format from the extension) whole or not at all."""
    from surfmet.atomic import atomic_path

    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=dpi)


def close(fig: Any) -> None:
    """Release a figure's memory (batch runs make many)."""
    pyplot().close(fig)


def lateral_unit(extent: float) -> tuple[float, str]:
    """Scale (metres per unit) and name of the unit for lateral axes: µm up to 2 mm, mm
    beyond, so that tick labels stay short."""
    return (MM, "mm") if abs(extent) > 2e-3 else (UM, "µm")


def nice_length(target: float) -> float:
    """The 1-2-5 × 10ⁿ length closest below ``target`` (for scale bars)."""
    if not target > 0:
        return 0.0
    e = math.floor(math.log10(target))
    for m in (5.0, 2.0, 1.0):
        if m * 10**e <= target:
            return m * 10**e
    return 10.0 ** (e - 1) * 5.0  # pragma: no cover - unreachable


def add_scale_bar(ax: Any, extent_m: float, scale: float, unit: str, color: str = "white"
                  ) -> Any:
    """A lateral scale bar of a round length (about a fifth of ``extent_m``) in the lower
    right corner of ``ax`` (whose data units are ``scale`` metres)."""
    from mpl_toolkits.axes_grid1.anchored_artists import AnchoredSizeBar

    length = nice_length(extent_m / 5.0)
    if length <= 0:
        return None
    # labelled in the axes' own unit, so the bar and the ticks never disagree
    bar = AnchoredSizeBar(ax.transData, length / scale, f"{length / scale:g} {unit}",
                          "lower right",
                          pad=0.4, color=color, frameon=False, size_vertical=0,
                          label_top=True, sep=3)
    ax.add_artist(bar)
    return bar
