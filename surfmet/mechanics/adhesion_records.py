"""The JSON records of an adhesive run (:func:`surfmet.mechanics.adhesion.adhesion` and the
line contact's): the run, its jumps and the scans it used, every value with its unit."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from surfmet.units import quantity

if TYPE_CHECKING:
    import numpy as np

    from contact.adhesion.cycle import Branch, Jump
    from surfmet.mechanics._types import ScanSource
    from surfmet.mechanics.scan_preparation import PreparedScans

__all__ = ["adhesion_record", "jump_record", "scans_record"]


def scans_record(prep: PreparedScans, plate: ScanSource | None, ball: ScanSource | None,
                 dx: float, z: np.ndarray) -> dict[str, Any]:
    """What scans were used, what was done to them, and the roughness on the grid.

    Parameters
    ----------
    prep : PreparedScans
        The prepared scans.
    plate, ball : Topography, path or None
        The scans as given.
    dx : float
        The grid's pixel (m).
    z : ndarray
        The roughness on the grid (m).

    Returns
    -------
    dict
        The scans, their preparation, the pixel and the rms of the roughness on the grid.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.adhesion import rough_grid
    >>> from surfmet.mechanics.adhesion_records import scans_record
    >>> from surfmet.mechanics.scan_preparation import prepare_scans
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy)
    >>> z, _ = rough_grid(patch, None, 32, 3e-4)
    >>> sorted(scans_record(prepare_scans(patch), patch, None, 1e-5, z))
    ['ball', 'pixel', 'plate', 'preparation', 'roughness_rms']
    """
    import math

    from surfmet.units import quantity

    pair = prep.pair
    notes = list(prep.notes)
    if dx < pair.dx * (1 - 1e-9):
        notes.append(f"the solver's pixel ({dx * 1e9:.4g} nm) is finer than the scans' "
                     f"({pair.dx * 1e9:.4g} nm): the roughness is interpolated between "
                     "measured points")
    record: dict[str, Any] = {
        "plate": _scan_name(plate),
        "ball": _scan_name(ball),
        "pixel": quantity(pair.dx, "m"),
        "roughness_rms": quantity(float(math.sqrt(float(((z - z.mean()) ** 2).mean()))),
                                  "m"),
        "preparation": prep.record(),
    }
    record["preparation"]["notes"] = notes
    return record


def _scan_name(scan: ScanSource | None) -> str | None:
    """A scan's file name, "(in memory)" for a Topography, None when not given."""
    if scan is None:
        return None
    from surfmet.model import Topography

    if isinstance(scan, Topography):  # read by the caller: its file, when it has one
        return scan.metadata.get("source") or "(in memory)"
    return str(scan)


def _leg(branch: Branch) -> dict[str, Any]:
    return {"approach": quantity(branch.surface_approach, "m"),
            "load": quantity(branch.load, "N"),
            "contact_radius": quantity(branch.contact_radius, "m")}


def jump_record(jump: Jump | None, force_unit: str = "N") -> dict[str, Any] | None:
    """A jump-in or jump-out, loads in ``force_unit`` (N, or N/m for a line).

    Parameters
    ----------
    jump : Jump or None
        A jump of the cycle.
    force_unit : str
        ``"N"`` or ``"N/m"``.

    Returns
    -------
    dict or None
        Approach, step and the loads before and after, with units (None without a jump).

    Examples
    --------
    >>> from surfmet.mechanics.adhesion import adhesion
    >>> from surfmet.mechanics.adhesion_records import jump_record
    >>> run = adhesion(1e-5, work=0.05, range_=2e-9, e_star=1e9, grid=16, steps=6)
    >>> rec = jump_record(run.result.cycle.jump_in)
    >>> rec["load_after"]["unit"], rec["load_after"]["value"] < 0
    ('N', True)
    """
    if jump is None:
        return None
    return {"approach": quantity(jump.approach, "m"), "step": quantity(jump.step, "m"),
            "load_before": quantity(jump.load_before, force_unit),
            "load_after": quantity(jump.load_after, force_unit), "abrupt": jump.abrupt,
            "resolved": jump.resolved}


def adhesion_record(run: Any) -> dict[str, Any]:
    """The JSON record of an :class:`surfmet.mechanics.adhesion.Adhesion` run.

    Parameters
    ----------
    run : surfmet.mechanics.adhesion.Adhesion
        A run.

    Returns
    -------
    dict
        Every value as ``{"value": v, "unit": u}``.

    See Also
    --------
    adhesion

    Examples
    --------
    >>> from surfmet.mechanics.adhesion import adhesion
    >>> from surfmet.mechanics.adhesion_records import adhesion_record
    >>> rec = adhesion_record(adhesion(1e-5, work=0.05, range_=2e-9, e_star=1e9, grid=16,
    ...                                steps=6))
    >>> rec["geometry"], rec["pull_off_force"]["unit"]
    ('sphere', 'N')
    """
    from surfmet.mechanics.adhesion_laws import interaction_name

    ball = run.result
    cyc, law = ball.cycle, ball.law
    return {
        "geometry": "sphere",
        "radius": quantity(ball.radius, "m"),
        "e_star": quantity(ball.e_star, "Pa"),
        "interaction": interaction_name(law),
        "work_of_adhesion": quantity(law.work, "J/m^2"),
        "range": quantity(law.range, "m"),
        "peak_tension": quantity(law.peak, "Pa"),
        "step_smoothing": quantity(law.smoothing, "m"),
        "maugis_parameter": quantity(ball.maugis_parameter, ""),
        "tabor_parameter": quantity(ball.tabor_parameter, ""),
        "pull_off_force": quantity(cyc.pull_off_force, "N"),
        "pull_off_approach": quantity(cyc.pull_off_approach, "m"),
        "jkr_pull_off_force": quantity(ball.jkr_pull_off, "N"),
        "dmt_pull_off_force": quantity(ball.dmt_pull_off, "N"),
        "jump_in": jump_record(cyc.jump_in),
        "jump_out": jump_record(cyc.jump_out),
        "hysteresis_energy": quantity(cyc.hysteresis_energy, "J"),
        "grid": {"cells": ball.grid, "size": quantity(ball.size, "m"),
                 "pixel": quantity(ball.dx, "m"), "periodic": True,
                 "process_zone": quantity(ball.process_zone, "m"),
                 "process_zone_pixels": quantity(ball.process_zone / ball.dx, ""),
                 "why": run.grid_why},
        "solver": {"iterations": int(cyc.solve.iterations)},  # the curve's and pull-off's
        "solve": cyc.solve.to_json(),
        "curve": {"in": _leg(cyc.approach_leg), "out": _leg(cyc.retraction_leg)},
        "scans": run.scans,
        "warnings": list(ball.warnings),
    }
