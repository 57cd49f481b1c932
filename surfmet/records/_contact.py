"""JSON records of contact solves (``surfmet contact``, the demo's contact step): the
result, its materials, its grid and the paired roughness it was solved on."""

from __future__ import annotations

from typing import Any

from surfmet.records._solve import solve_record
from surfmet.units import quantity


def material_record(m: Any) -> dict[str, Any]:
    """Name, Young's modulus and Poisson's ratio of a :class:`contact._materials.Material`."""
    return {"name": m.name, "E": quantity(m.E, "Pa"), "nu": quantity(m.nu, "")}


def contact_record(res: Any, ball: Any, plate: Any, pair: Any, *, radius: float,
                   plate_file: str | None = None, ball_file: str | None = None) -> dict:
    """The ``surfmet contact`` record of a contact result (every value with its unit).

    Parameters
    ----------
    res : contact.ContactResult
    ball, plate : contact._materials.Material
    pair : surfmet.mechanics.pairing.PairedRoughness or None
        The paired scans, when the solve used them.
    radius : float
        Ball radius (m).
    plate_file, ball_file : str, optional
        The scan files, for the record.
    """
    hz = res.hertz
    rec: dict[str, Any] = {
        "load": quantity(res.load, "N"),
        "pmax": quantity(res.pmax, "Pa"),
        "mean_pressure": quantity(res.mean_pressure, "Pa"),
        "contact_radius": quantity(res.contact_radius, "m"),
        "effective_radius": quantity(res.effective_radius, "m"),
        "radius_95": quantity(res.radius_95, "m"),
        "approach": quantity(res.approach, "m"),
        "contact_area": quantity(res.contact_area, "m^2"),
        "area_fraction": quantity(res.area_fraction, ""),
        "centroid": quantity(list(res.centroid), "m"),
        "n_clusters": res.n_clusters,
        "plastic_area": quantity(res.plastic_area, "m^2"),
        "regime": res.regime,
        "iterations": res.iterations,
        "residual": quantity(res.residual, ""),
        "converged": res.converged,
        "touches_edge": res.touches_edge,
        "solve": solve_record(res.solve),
        "hertz": {
            "a": quantity(hz.a if hz else None, "m"),
            "delta": quantity(hz.delta if hz else None, "m"),
            "p0": quantity(hz.p0 if hz else None, "Pa"),
        },
        "grid": {"nx": res.shape[1], "ny": res.shape[0], "dx": quantity(res.dx, "m"),
                 "size": quantity(res.shape[1] * res.dx, "m"), "periodic": res.periodic},
        "materials": {
            "ball": material_record(ball),
            "plate": material_record(plate),
            "e_star": quantity(res.e_star, "Pa"),
        },
        "hardness": quantity(res.hardness, "Pa"),
        "radius": quantity(radius, "m"),
        "scans": {"plate": plate_file, "ball": ball_file},
        "notes": list(res.notes),
    }
    if pair is not None:
        rec["roughness"] = {
            "composite_rms": quantity(pair.rms, "m"),
            "plate_rms": quantity(pair.plate_rms, "m"),
            "ball_rms": quantity(pair.ball_rms, "m"),
            "ball_fit_radius": quantity(pair.ball_radius, "m"),
            "filled_fraction": quantity(pair.filled_fraction, ""),
            "notes": list(pair.notes),
        }
    return rec


def ball_contact_record(run: Any) -> dict[str, Any]:
    """The ``surfmet contact`` record of a :class:`surfmet.mechanics.ball_contact.BallContact`
    (every value with its unit), with what was done to the scans and the warnings.

    Parameters
    ----------
    run : BallContact
        What :func:`surfmet.mechanics.ball_contact.ball_contact` returned.

    Returns
    -------
    dict
        The record of ``surfmet contact --json`` (JSON types, values with their units).

    Examples
    --------
    >>> from surfmet.mechanics.ball_contact import ball_contact
    >>> from surfmet.records import ball_contact_record
    >>> rec = ball_contact_record(ball_contact(radius=0.02, load=10.0, grid=64))
    >>> print(f"{rec['pmax']['value'] / 1e6:.0f} MPa", rec["warnings"])
    255 MPa []
    """
    from surfmet.records._preparation import preparation_record

    rec = contact_record(run.result, run.ball_material, run.plate_material, run.pair,
                         radius=run.radius, plate_file=run.plate_file,
                         ball_file=run.ball_file)
    if run.preparation is not None:
        rec["scan_preparation"] = preparation_record(run.preparation)
    rec["warnings"] = list(run.warnings)
    return rec


def grid_record(shape: tuple[int, ...], dx: float, pixel_source: str) -> dict[str, Any]:
    """The grid a contact was solved on: cells, pixel and where the pixel came from."""
    return {"nx": shape[1], "ny": shape[0], "dx": quantity(dx, "m"),
            "pixel_source": pixel_source}
