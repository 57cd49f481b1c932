"""The figure of ``surfmet scales``: scale-dependent rms slope, rms curvature and the PSD,
one curve per measurement and their average (as contact.engineering shows them).

Distances in µm and the PSD in µm³ against rad/µm, the units contact.engineering and
SurfaceTopography plot in; each measurement is drawn only where it contributes (above its
reliability cut-off and inside its bandwidth).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from surfmet.plots._style import UM, finish, new_figure


def scales_figure(a: Any, path: str | Path | None = None) -> Any:
    """Three log–log panels of a :class:`surfmet.scale_dependent.ScaleAnalysis`."""
    fig, axes = new_figure(1, 3, size=(14.0, 4.4))
    d = a.distance / UM
    panels = (
        (axes[0], "variance_slope", a.rms_slope, 1.0, "rms slope (1)"),
        (axes[1], "variance_curvature", a.rms_curvature, UM, "rms curvature (1/µm)"),
    )
    for ax, key, mean, unit, label in panels:
        for m in a.measurements:
            ax.loglog(d, np.sqrt(getattr(m, key)) / (1 / unit), ".-", lw=1, ms=3,
                      label=Path(m.file).name)
        ax.loglog(d, mean * unit, "k--", lw=1.5, label="average")
        ax.set_xlabel("distance $d$ (µm)")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.25)
    for m in a.measurements:
        axes[2].loglog(a.q * UM, m.psd / UM**3, ".-", lw=1, ms=3, label=Path(m.file).name)
    axes[2].loglog(a.q * UM, a.psd / UM**3, "k--", lw=1.5, label="average")
    axes[2].set_xlabel("wavevector $q$ (rad/µm)")
    axes[2].set_ylabel(r"PSD $C^{1\mathrm{D}}(q)$ (µm$^3$)")
    axes[2].grid(True, which="both", alpha=0.25)
    axes[0].legend(fontsize=7)
    return finish(fig, path)
