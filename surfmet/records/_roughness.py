"""The JSON records of a roughness evaluation (:mod:`surfmet.roughness`): the parameters
with their units, the settings (a profile's SI lengths written with their unit here, at the
edge), the evaluation conditions of a profile, the spikes removed, the filters applied.
The form removed is :mod:`surfmet.records._form`."""

from __future__ import annotations

from typing import Any

from surfmet._profile_roughness import STANDARD_NAMES
from surfmet.units import jsonable

__all__ = ["areal_settings_record", "conditions_record", "cutoff_record", "filter_record",
           "parameters_record", "profile_settings_record", "roughness_record",
           "spike_report_record"]


def roughness_record(res: Any) -> dict[str, Any]:
    """``{"parameters": {sym: {"value", "unit"}}, "settings": {...}}`` (JSON types) of a
    :class:`surfmet._roughness_result.RoughnessResult`.

    Lengths in a profile's settings (SI floats in its ``settings``) become
    ``{"value", "unit"}`` here (:func:`profile_settings_record`).

    Parameters
    ----------
    res : RoughnessResult
        What :func:`surfmet.roughness.roughness` returned.

    Returns
    -------
    dict
        The record of ``surfmet roughness --json`` for the scan (JSON types, values with
        their units).

    Examples
    --------
    >>> from surfmet.data import path
    >>> from surfmet.roughness import roughness
    >>> from surfmet.records import roughness_record
    >>> roughness_record(roughness(path("paper_plate.x3p")))["parameters"]["Sa"]["unit"]
    'm'
    """
    settings = res.settings
    if res.kind == "profile":
        settings = profile_settings_record(settings)
    return {"parameters": parameters_record(res), "settings": jsonable(settings)}


def parameters_record(res: Any, plain: bool = False) -> dict[str, Any]:
    """Each parameter of a result as ``{"value", "unit"}``; ``plain`` leaves the values
    as computed (NumPy scalars, NaN) for a caller that writes them itself."""
    return {k: {"value": v if plain else jsonable(v), "unit": u}
            for k, (v, u) in res.parameters.items()}


def areal_settings_record(kind: str, standard: str, topo: Any,
                          window: Any | None) -> dict[str, Any]:
    """The head of an areal result's settings: its kind and standard, the grid, the pixel
    and the window evaluated (m; None: the whole scan)."""
    return {"kind": kind, "standard": standard, "grid": {"nx": topo.nx, "ny": topo.ny},
            "dx": {"value": topo.dx, "unit": "m"}, "dy": {"value": topo.dy, "unit": "m"},
            "window": None if window is None else {"value": list(window), "unit": "m"}}


def cutoff_record(length: float | None) -> dict[str, Any] | None:
    """A filter's nesting index (m) in an areal result's settings (None: not applied)."""
    return None if length is None else {"value": length, "unit": "m"}


def spike_report_record(report: Any, max_positions: int = 1000) -> dict[str, Any]:
    """What :func:`surfmet._spikes.remove_spikes` removed (:class:`surfmet._spikes.
    SpikeReport`), lengths as value/unit pairs, at most ``max_positions`` positions."""
    return {
        "removed": True,
        "count": report.count,
        "n_points": report.n_points,
        "fraction": report.fraction,
        "threshold": {"value": report.threshold, "unit": "m"},
        "robust_sigma": {"value": report.sigma, "unit": "m"},
        "k": report.k,
        "window": report.size,
        "positions": {"value": report.positions[:max_positions].tolist(), "unit": "m"},
        "heights": {"value": report.heights[:max_positions].tolist(), "unit": "m"},
    }


def filter_record(info: Any) -> dict[str, Any]:
    """How an areal filter was applied (:class:`surfmet.areal._filters.FilterInfo`)."""
    from surfmet.areal._filters import EDGE_MEANING

    return {
        "kind": info.kind,
        "nesting_index": {"value": info.nesting_index, "unit": "m"},
        "standard": info.standard,
        "edge": info.edge,
        "edge_meaning": EDGE_MEANING.get(info.edge, ""),
        "truncation": info.truncation,
        "discarded_points_each_edge": {"rows": info.discarded[0],
                                       "columns": info.discarded[1]},
    }


def conditions_record(cond: Any, settings: dict[str, Any],
                      stated: dict[str, Any]) -> dict[str, Any]:
    """The ``settings["conditions"]`` block: what was used and why, with units."""
    lc_used = settings.get("lc")
    lc_block: dict[str, Any] = {"value": lc_used, "unit": "m", "why": cond.why["lc"]}
    if cond.prefiltered:
        lc_block = {"value": stated.get("lc"), "unit": "m", "why": cond.why["lc"],
                    "applied": False,
                    "note": "the file holds the instrument's R-profile, already filtered "
                    "with this λc; it is not filtered again and sets the sampling length"}
    elif cond.lc == "auto" and lc_used is None:
        lc_block["note"] = settings.get("lc_note", "")
    ls_block: dict[str, Any] = {"value": settings.get("ls"), "unit": "m", "why": cond.why["ls"]}
    if cond.prefiltered and stated.get("ls"):
        ls_block = {"value": stated["ls"], "unit": "m", "why": cond.why["ls"], "applied": False}
    return {
        "standard": {"value": cond.standard, "name": STANDARD_NAMES[cond.standard],
                     "why": cond.why["standard"]},
        "lc": lc_block,
        "ls": ls_block,
        "n_sampling": {"value": settings.get("n_sampling"), "why": cond.why["n_sampling"]},
        "rk_line": {"value": cond.rk_line, "why": cond.why["rk_line"]},
        "element_start": {"value": cond.element_start, "why": cond.why["element_start"]},
    }


_LENGTH_KEYS = ("dx", "profile_length", "lc", "ls", "discarded_each_end", "sampling_length",
                "evaluation_length", "evaluation_range", "window", "window_extent")

_POSITION_LENGTHS = ("position_resolution", "max_position_deviation", "min_step", "max_step")


def profile_settings_record(settings: dict[str, Any]) -> dict[str, Any]:
    """Profile engine settings (SI floats) as JSON with ``{value, unit}`` for every length."""
    out: dict[str, Any] = {}
    for key, value in settings.items():
        if key in _LENGTH_KEYS and value is not None:
            out[key] = {"value": value, "unit": "m"}
        elif key == "level_coefficients":
            out[key] = {"value": value,
                        "unit": [_power_unit(1 - k) for k in range(len(value))],
                        "meaning": "ascending powers of x (m) of the removed form"}
        elif key == "lc_iso4288" and isinstance(value, dict):
            out[key] = _iso4288_units(value)
        elif key == "positions" and isinstance(value, dict):
            out[key] = {k: ({"value": v, "unit": "m"} if k in _POSITION_LENGTHS else v)
                        for k, v in value.items()}
        else:
            out[key] = value
    return out


def _power_unit(p: int) -> str:
    return {1: "m", 0: "", -1: "1/m"}.get(p, f"m^{p}")


def _iso4288_units(choice: dict[str, Any]) -> dict[str, Any]:
    unit = "m"
    out = dict(choice)
    for key in ("lc", "ls", "evaluation_length"):
        out[key] = {"value": choice[key], "unit": "m"}
    out["value"] = {"value": choice["value"], "unit": unit}
    out["history"] = {"value": choice["history"], "unit": "m",
                      "meaning": "[λc tried, parameter measured with it]"}
    return out
