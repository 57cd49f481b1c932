"""JSON record of the rotor verdict's decisive argument: the friction arm ``s_r = M_r / N``
against the contact radius that bounds it (:func:`rotor.arm_bound`: Hertz's, or the scanned
rough contact's a*, :mod:`surfmet.mechanics.rotor_rough_bound`), the least lambda the
offset needs there, and what lambda = 4/3 would need.
"""

from __future__ import annotations

from typing import Any

from surfmet.mechanics._rotor_argument import LOWER_BOUND
from surfmet.mechanics.rotor_rough_bound import (
    MATERIALS,
    RoughArmBound,
    deciding_bound,
    rough_basis,
)
from surfmet.units import quantity

__all__ = ["argument_record", "rough_bound_record"]


def _interval(value: float, low: float, high: float, unit: str) -> dict[str, Any]:
    q = quantity(value, unit)
    q.update(ci_low=quantity(low, unit)["value"], ci_high=quantity(high, unit)["value"])
    return q


def argument_record(v: Any, rough: Any = None) -> dict[str, Any]:
    """The arm fields of ``verdict``: ``friction_arm``, ``arm_bound`` (with the rough
    contact's extent, a :class:`~surfmet.mechanics.rotor_rough_bound.RoughArmBound`, where
    given), ``lambda_at_arm_bound``, ``slope_lambda_4_3`` (and ``arm_lambda_4_3``)."""
    b = v.arm
    if b is None:
        return {"friction_arm": None, "arm_bound": None, "lambda_at_arm_bound": None,
                "slope_lambda_4_3": None, "arm_lambda_4_3": None}
    ends = "at the offset's interval ends nearer to and farther from zero"
    d = deciding_bound(v, rough)  # the lambda at the bound is at the radius that decides
    return {
        "friction_arm": {"arm": quantity(b.friction_arm, "m"), "lambda": 1,
                         "slope": quantity(b.slope, "rad"),
                         "ratio_to_bound": quantity(b.arm_ratio, ""),
                         "formula": "s_r = (M g R sin(theta) - eps_mean (J + M R^2)) / sum N"},
        "arm_bound": {"radius": quantity(b.arm_bound, "m"), "basis": b.bound_basis,
                      "load": quantity(b.bound_load, "N"), "group": b.bound_group,
                      "e_star": quantity(b.e_star, "Pa"),
                      **({} if rough is None else rough_bound_record(rough, b.friction_arm))},
        "lambda_at_arm_bound": {
            "lambda": {**_interval(d.lambda_at_bound, d.lambda_low, d.lambda_high, ""),
                       "level": v.offset.level},
            "interval": "over the offset's interval, at the slope where s_r = a",
            "meaning": LOWER_BOUND, "slope": quantity(d.slope_at_bound, "rad"),
            "radius": quantity(d.arm_bound, "m"), "basis": d.bound_basis,
            "slope_lambda_infinite": quantity(d.slope_lambda_infinite, "rad")},
        "slope_lambda_4_3": {"slope": _interval(b.slope_4_3, b.slope_4_3_low,
                                                b.slope_4_3_high, "rad"), "interval": ends},
        "arm_lambda_4_3": {"arm": _interval(b.arm_4_3, b.arm_4_3_low, b.arm_4_3_high, "m"),
                           "interval": ends},
    }


def rough_bound_record(rb: RoughArmBound, friction_arm: float) -> dict[str, Any]:
    """The fields :func:`~surfmet.records._rotor_verdict.verdict_record` adds to
    ``arm_bound``: ``rough`` {radius, basis, files, grid, cell, warnings}, ``decides``
    and ``deciding_radius``, ``friction_arm_ratio_to_deciding``.

    Examples
    --------
    >>> from surfmet.mechanics.rotor_rough_bound import RoughArmBound
    >>> from surfmet.records._rotor_arm import rough_bound_record
    >>> rb = RoughArmBound(radius=318e-6, hertz_radius=106e-6, load=4.67, ball_radius=0.02,
    ...                    plate_file="plate.x3p", ball_file=None, grid=(64, 64),
    ...                    cell=2e-5, warnings=())
    >>> rec = rough_bound_record(rb, 0.258e-3)
    >>> rec["decides"], round(rec["friction_arm_ratio_to_deciding"]["value"], 2)
    ('rough', 0.81)
    """
    return {
        "rough": {"radius": quantity(rb.radius, "m"), "quantity": "effective_radius a*",
                  "basis": rough_basis(rb), "load": quantity(rb.load, "N"),
                  "files": {"plate": rb.plate_file, "ball": rb.ball_file},
                  "grid": list(rb.grid), "cell": quantity(rb.cell, "m"),
                  "materials": MATERIALS, "warnings": list(rb.warnings)},
        "decides": rb.decides,
        "deciding_radius": quantity(rb.deciding_radius, "m"),
        "friction_arm_ratio_to_deciding": quantity(friction_arm / rb.deciding_radius, ""),
        "why": "the larger radius is the physical bound: the normal force's resultant lies "
               "inside the region that carries the load",
    }
