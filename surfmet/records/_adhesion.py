"""The JSON records of an adhesive run (:func:`surfmet.mechanics.adhesion.adhesion` and the
line contact's, :func:`surfmet.mechanics.adhesion_line.line_adhesion`): the run, its jumps
and the scans it used, every value with its unit."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from surfmet.mechanics.adhesion_laws import interaction_name
from surfmet.records._preparation import preparation_record
from surfmet.records._solve import solve_record
from surfmet.units import quantity

if TYPE_CHECKING:
    from contact.adhesion.cycle import Branch, Jump

__all__ = ["adhesion_record", "jump_record", "line_record", "scans_record"]


def scans_record(used: Any) -> dict[str, Any] | None:
    """What scans were used, what was done to them, and the roughness on the grid.

    Parameters
    ----------
    used : surfmet.mechanics.scan_preparation.ScansUsed or None
        The scans an adhesive run was sampled from (None: smooth surfaces).

    Returns
    -------
    dict or None
        The scans, their preparation, the pixel and the rms of the roughness on the grid
        (and, for a line contact, the profile used).

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.adhesion import rough_grid
    >>> from surfmet.records._adhesion import scans_record
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy)
    >>> z, used = rough_grid(patch, None, 32, 3e-4)
    >>> sorted(scans_record(used))
    ['ball', 'pixel', 'plate', 'preparation', 'roughness_rms']
    """
    if used is None:
        return None
    record: dict[str, Any] = {
        "plate": used.plate_name,
        "ball": used.ball_name,
        "pixel": quantity(used.prep.pair.dx, "m"),
        "roughness_rms": quantity(used.roughness_rms, "m"),
        "preparation": preparation_record(used.prep),
    }
    record["preparation"]["notes"] = used.notes
    if used.profile is not None:
        record["profile"] = used.profile
    return record


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
    >>> from surfmet.records._adhesion import jump_record
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
    >>> from surfmet.records._adhesion import adhesion_record
    >>> rec = adhesion_record(adhesion(1e-5, work=0.05, range_=2e-9, e_star=1e9, grid=16,
    ...                                steps=6))
    >>> rec["geometry"], rec["pull_off_force"]["unit"]
    ('sphere', 'N')
    """
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
        "hysteresis_resolution": quantity(cyc.hysteresis_resolution, "J"),
        "discretisation": "axisymmetric" if run.axisymmetric else "3d",
        "grid": _grid(run),
        "solver": {"iterations": int(cyc.solve.iterations)},  # the curve's and pull-off's
        "solve": solve_record(cyc.solve),
        "curve": {"in": _leg(cyc.approach_leg), "out": _leg(cyc.retraction_leg)},
        "scans": scans_record(run.scans),
        "warnings": list(ball.warnings),
    }


def _grid(run: Any) -> dict[str, Any]:
    """The discretisation of a sphere's run: the rings (axisymmetric, free half-space) or
    the periodic 3D grid, with the cohesive zone's width in rings or pixels."""
    ball = run.result
    zone = quantity(ball.process_zone, "m")
    if run.axisymmetric:
        return {"discretisation": "axisymmetric", "rings": ball.rings,
                "graded": ball.graded, "ring_width": quantity(ball.dr, "m"),
                "outer_radius": quantity(ball.outer_radius, "m"), "periodic": False,
                "process_zone": zone,
                "process_zone_rings": quantity(ball.process_zone / ball.dr, ""),
                "why": run.grid_why}
    return {"discretisation": "3d", "cells": ball.grid, "size": quantity(ball.size, "m"),
            "pixel": quantity(ball.dx, "m"), "periodic": True, "process_zone": zone,
            "process_zone_pixels": quantity(ball.process_zone / ball.dx, ""),
            "why": run.grid_why}


def _line_leg(branch: Branch) -> dict[str, Any]:
    return {"approach": quantity(branch.surface_approach, "m"),
            "load": quantity(branch.load, "N/m"),
            "contact_half_width": quantity(0.5 * branch.contact_area, "m")}


def line_record(run: Any) -> dict[str, Any]:
    """The JSON record of a line-contact run (forces per unit length).

    Parameters
    ----------
    run : surfmet.mechanics.adhesion.Adhesion
        A line run.

    Returns
    -------
    dict
        Every value as ``{"value": v, "unit": u}``, forces per unit length.

    Examples
    --------
    >>> from surfmet.mechanics.adhesion_line import line_adhesion
    >>> from surfmet.records._adhesion import line_record
    >>> rec = line_record(line_adhesion(1e-5, work=0.05, range_=2e-9, e_star=1e9, grid=64,
    ...                                 steps=8))
    >>> rec["pull_off_force"]["unit"], rec["work_of_adhesion"]
    ('N/m', {'value': 0.05, 'unit': 'J/m^2'})
    """
    res = run.result
    cyc, law = res.cycle, res.law
    return {
        "geometry": "line",
        "radius": quantity(res.radius, "m"),
        "e_star": quantity(res.e_star, "Pa"),
        "interaction": interaction_name(law),
        "work_of_adhesion": quantity(law.work, "J/m^2"),
        "range": quantity(law.range, "m"),
        "peak_tension": quantity(law.peak, "Pa"),
        "maugis_parameter": quantity(res.maugis_parameter, ""),
        "tabor_parameter": quantity(res.tabor_parameter, ""),
        "pull_off_force": quantity(cyc.pull_off_force, "N/m"),
        "pull_off_approach": quantity(cyc.pull_off_approach, "m"),
        "jkr_pull_off_force": quantity(res.jkr_pull_off, "N/m"),
        "rigid_pull_off_force": quantity(res.rigid_pull_off, "N/m"),
        "jump_in": jump_record(cyc.jump_in, "N/m"),
        "jump_out": jump_record(cyc.jump_out, "N/m"),
        "hysteresis_energy": quantity(cyc.hysteresis_energy, "J/m"),
        "hysteresis_resolution": quantity(cyc.hysteresis_resolution, "J/m"),
        "grid": {"cells": res.cells, "size": quantity(res.size, "m"),
                 "pixel": quantity(res.dx, "m"), "periodic": True, "plane_strain": True,
                 "process_zone": quantity(res.process_zone, "m"),
                 "process_zone_pixels": quantity(res.process_zone / res.dx, "")},
        "solver": {"iterations": int(cyc.solve.iterations)},  # the curve's and pull-off's
        "solve": solve_record(cyc.solve),
        "curve": {"in": _line_leg(cyc.approach_leg), "out": _line_leg(cyc.retraction_leg)},
        "scans": scans_record(run.scans),
        "warnings": list(res.warnings),
    }
