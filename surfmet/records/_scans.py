"""JSON records of scans and of form fits (``surfmet info``, ``surfmet fit``)."""

from __future__ import annotations

from typing import Any

from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography
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
    out["units"] = calibration_record(scan.calibration)  # which units the file states
    out["metadata"] = md
    return out


def calibration_record(cal: Any) -> dict[str, Any]:
    """JSON of a :class:`surfmet._model.Calibration`: each unit with who stated it
    (``"file"``, ``"assumed"``, ``"user"``), and the caveats."""
    from surfmet._model import SOURCE_WORDS

    return {"height_unit": {"unit": cal.height_unit, "source": cal.height,
                            "stated_by": SOURCE_WORDS[cal.height]},
            "pixel": {"dx": quantity(cal.dx, "m"), "dy": quantity(cal.dy, "m"),
                      "lateral_unit": cal.lateral_unit or None,
                      "source": cal.lateral, "stated_by": SOURCE_WORDS[cal.lateral]},
            "caveats": cal.caveats()}


def channel_record(scan: Any) -> dict[str, Any]:
    """One channel's or measurement's record (``surfmet info``'s ``channels_read``):
    kind, grid, pixel and units."""
    return {"kind": scan.kind, "nx": scan.nx, "ny": scan.ny,
            "dx": quantity(scan.dx, "m"), "dy": quantity(getattr(scan, "dy", None), "m"),
            "units": calibration_record(scan.calibration)}


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
            "form_pv": quantity(f.form_pv, "m"),
            "names": {"form_pv": "form deviation: PV of the quadratic component of the "
                      "sphere residual", "pv_form_deviation": "residual PV (all points)"},
            "convex": f.convex,
            "loss": loss,
        }
    import numpy as np

    import profiles

    if isinstance(scan, Topography):
        if profile is None:
            raise SurfmetInputError("a circle fit of an areal scan needs --profile row:K "
                                    "or col:K")
        from surfmet._extract import extract_profile

        prof = extract_profile(scan, profile)
    elif isinstance(scan, Profile):
        if profile is not None:
            raise SurfmetInputError("--profile applies to areal scans; this file is a profile")
        prof = scan
    else:  # pragma: no cover
        raise SurfmetInputError(f"cannot fit {type(scan).__name__}")
    fc = profiles.fit_circle(np.asarray(prof.positions), np.asarray(prof.z), loss=loss)
    return {
        "shape": "circle",
        "profile": prof.metadata.get("profile"),
        **_fit_fields(fc),
        "form_pv": quantity(fc.form_pv, "m"),
        "names": {"form_pv": "form deviation: PV of the degree-4 component of the "
                  "circle residual", "pv_form_deviation": "residual PV (all points)"},
        "loss": loss,
    }
