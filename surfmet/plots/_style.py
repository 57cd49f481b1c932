"""Shared figure conventions: a headless backend, unit scaling and labels."""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from surfmet._model import Profile, Topography

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
    """Save ``fig`` to ``path`` when given (whole or not at all, :mod:`surfmet._atomic`),
    and return it."""
    if path is not None:
        save(fig, path, dpi=dpi)
    return fig


def save(fig: Any, path: str | Path, dpi: int = 120) -> None:
    """Write ``fig`` to ``path`` (format from the extension) whole or not at all."""
    from surfmet._atomic import atomic_path

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


def round_ticks(lo: float, hi: float, n: int = 5) -> list[float]:
    """Round tick values (1, 2, 2.5 or 5 × 10ⁿ apart, at most about ``n + 1`` of them)
    within [lo, hi], for colour bars whose range is not round itself (the 3D view's
    1-99 % height range gave ticks at 1.07e+03, 146, −779 µm)."""
    from matplotlib.ticker import MaxNLocator

    if not (math.isfinite(lo) and math.isfinite(hi) and hi > lo):
        return [lo] if math.isfinite(lo) else []
    ticks = MaxNLocator(nbins=n, steps=[1, 2, 2.5, 5, 10]).tick_values(lo, hi)
    step = float(ticks[1] - ticks[0]) if len(ticks) > 1 else 0.0
    # snap to whole multiples of the step (tick_values carries float noise), keep inside
    digits = 2 - math.floor(math.log10(step)) if step > 0 else 12
    inside = [round(round(t / step) * step, digits) if step else float(t) for t in ticks]
    return [0.0 if abs(t) < 1e-9 * step else t for t in inside
            if lo - 1e-9 * (hi - lo) <= t <= hi + 1e-9 * (hi - lo)]


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


def scan_title(scan: Topography | Profile) -> str:
    """A scan's title: its file's name and its size (``name  (size)``), or the size."""
    from surfmet._model import Topography
    from surfmet.units import format_length, valid_text

    name = valid_text(Path(str(scan.metadata.get("source", ""))).name)
    if isinstance(scan, Topography):
        size = f"{format_length(scan.size_x)} × {format_length(scan.size_y)}"
    else:
        size = format_length(scan.length)
    return f"{name}  ({size})" if name else size
