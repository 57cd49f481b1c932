"""JSON records of results, shared by the CLI, the demo and the report.

Every dimensional value is ``{"value": v, "unit": "..."}`` (dimensionless ratios with
``"unit": ""``); counts and flags are plain JSON numbers and booleans.
"""

from __future__ import annotations

from typing import Any

from surfmet.errors import SurfmetInputError
from surfmet.model import Profile, Topography
from surfmet.units import quantity


def scan_record(scan: Any) -> dict[str, Any]:
    """The ``surfmet info`` record of a scan, with every dimensional value as value/unit."""
    md = dict(scan.metadata)
    out: dict[str, Any] = {
        "file": md.pop("source", None),
        "format": md.pop("format", None),
        "kind": scan.kind,
        "nx": scan.nx,
        "ny": scan.ny,
        "dx": quantity(scan.dx, "m"),
        "dy": quantity(getattr(scan, "dy", None), "m"),
        "nan_fraction": scan.nan_fraction,
    }
    if scan.kind == "areal":
        out["size_x"] = quantity(scan.size_x, "m")
        out["size_y"] = quantity(scan.size_y, "m")
    else:
        out["length"] = quantity(scan.length, "m")
        out["uniform"] = scan.is_uniform
    out["metadata"] = md
    return out


def _fit_fields(f: Any) -> dict[str, Any]:
    """The fields a sphere fit and a circle fit share, with their units."""
    return {
        "radius": quantity(f.radius, "m"),
        "center": quantity(list(f.center), "m"),
        "rms_residual": quantity(f.rms_residual, "m"),
        "radius_uncertainty": quantity(f.radius_uncertainty, "m"),
        "center_uncertainty": quantity(list(f.center_uncertainty), "m"),
        "pv_form_deviation": quantity(f.pv_form_deviation, "m"),
        "n_points": f.n_points,
    }


def fit_record(scan: Any, shape: str, profile: str | None = None, loss: str = "linear"
               ) -> dict[str, Any]:
    """The fit as a JSON-ready dict (value/unit pairs)."""
    if shape == "sphere":
        if not isinstance(scan, Topography):
            raise SurfmetInputError("a sphere fit needs an areal scan; for a profile use "
                                    "--shape circle")
        if profile is not None:
            raise SurfmetInputError("--profile applies to --shape circle only")
        from surfmet.fitting import fit_sphere

        f = fit_sphere(scan, loss=loss)
        return {
            "shape": "sphere",
            **_fit_fields(f),
            "convex": f.convex,
            "loss": loss,
        }
    import numpy as np

    import profiles

    if isinstance(scan, Topography):
        if profile is None:
            raise SurfmetInputError("a circle fit of an areal scan needs --profile row:K "
                                    "or col:K")
        from surfmet.extract import extract_profile

        prof = extract_profile(scan, profile)
    elif isinstance(scan, Profile):
        if profile is not None:
            raise SurfmetInputError("--profile applies to areal scans; this file is a profile")
        prof = scan
    else:  # pragma: no cover
        raise SurfmetInputError(f"cannot fit {type(scan).__name__}")
    f = profiles.fit_circle(np.asarray(prof.positions), np.asarray(prof.z), loss=loss)
    return {
        "shape": "circle",
        "profile": prof.metadata.get("profile"),
        **_fit_fields(f),
        "loss": loss,
    }


def material_record(m: Any) -> dict[str, Any]:
    """Name, Young's modulus and Poisson's ratio of a :class:`contact.materials.Material`."""
    return {"name": m.name, "E": quantity(m.E, "Pa"), "nu": quantity(m.nu, "")}


def contact_record(res: Any, ball: Any, plate: Any, pair: Any, *, radius: float,
                   plate_file: str | None = None, ball_file: str | None = None) -> dict:
    """The ``surfmet contact`` record of a contact result (every value with its unit).

    Parameters
    ----------
    res : contact.ContactResult
    ball, plate : contact.materials.Material
    pair : surfmet.pairing.PairedRoughness or None
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
