"""The demo's figures: each drawn by :mod:`surfmet.plots` and recorded under its name in
:data:`surfmet.demo._outputs.FIGURES`."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

from surfmet.demo._outputs import FIGURES


def write_figure(out: Path, key: str, draw: Callable[[Path], Any], written: dict[str, str]
                 ) -> None:
    """Draw figure ``key`` into ``out`` and record its file name in ``written``."""
    from surfmet.plots._style import close

    path = out / FIGURES[key]
    close(draw(path))
    written[key] = FIGURES[key]


def height_map(topo: Any, path: Path, title: str) -> Any:
    """Height map of a scan."""
    from surfmet.plots.areal import height_map as draw

    return draw(topo, path, title=title)


def profile(analysis: Any, path: Path, title: str) -> Any:
    """One analysed profile with its mean line."""
    from surfmet.plots.profile import profile_figure

    return profile_figure(analysis, path, title=title)


def abbott(clean: Any, path: Path) -> Any:
    """The plate's material ratio (Abbott-Firestone) curve."""
    from surfmet.plots.areal import abbott_firestone

    return abbott_firestone(clean.surface, path, parameters=clean.parameters,
                            title="aluminium plate: material ratio curve (ISO 25178-2)")


def psd(plate_surface: Any, ball_residual: Any, path: Path) -> Any:
    """Radially averaged PSDs of the plate and of the ball's sphere residual."""
    from surfmet.plots.areal import psd_figure
    from surfmet.psd import psd as areal_psd

    return psd_figure([areal_psd(plate_surface), areal_psd(ball_residual)], path,
                      labels=["aluminium plate (5 µm pitch)",
                              "steel ball minus its sphere (50 µm pitch)"],
                      title="radially averaged PSD")


def pressure(res: Any, path: Path) -> Any:
    """Pressure map of a contact solve."""
    from surfmet.plots.contact import pressure_map

    return pressure_map(res, path)



def law_of_motion(analysis: Any, path: Path) -> Any:
    """The rotor's angle against time with the fitted laws of motion."""
    from surfmet.plots.rotor import law_of_motion_figure

    return law_of_motion_figure(analysis, path)


def residuals(analysis: Any, path: Path) -> Any:
    """The residuals of the rotor's fitted laws of motion."""
    from surfmet.plots.rotor import residual_figure

    return residual_figure(analysis, path)
