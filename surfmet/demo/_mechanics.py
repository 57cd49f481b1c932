"""The demo's mechanics steps: the Hertz check, the rotor's loads, a contact solve and a
rolling-resistance sweep on the shipped scans."""

from __future__ import annotations

from typing import Any

from rotor import BALL_RADIUS as RADIUS
from rotor import HERTZ_CHECK, HERTZ_CHECK_LOAD
from surfmet.demo._settings import MATERIALS
from surfmet.records._contact import ball_contact_record
from surfmet.records._demo import demo_hertz_record
from surfmet.records._rolling import rolling_record


def hertz_step(plate: Any, ball: Any, load: float = HERTZ_CHECK_LOAD) -> tuple[dict[str, Any], Any]:
    """The Hertz check of the ball on the plate at ``load`` (both scans, spikes removed)."""
    from surfmet.mechanics.hertz_check import hertz_check

    check = hertz_check(plate, ball=ball, radius=RADIUS, load=load, materials=MATERIALS)
    return demo_hertz_record(check, HERTZ_CHECK), check


def rotor_loads() -> dict[str, float]:
    """Normal load per ball of the paper's rotor on a level plate (Eqs. 41-42, 50-51), N."""
    from rotor import paper_ball_loads

    return paper_ball_loads()


def contact_step(check: Any, load: float) -> tuple[dict[str, Any], Any]:
    """Elastic-perfectly-plastic contact at ``load`` on the Hertz check's paired roughness
    (:mod:`surfmet.mechanics.ball_contact`)."""
    from surfmet.mechanics.ball_contact import BallContact, solve_on_pair

    pair = check.scans.pair
    res, found = solve_on_pair(pair, radius=RADIUS, load=load, e_star=check.materials,
                               hardness=check.materials.hardness)
    sol = BallContact(result=res, ball_material=check.ball_material,
                      plate_material=check.plate_material, pair=pair, radius=RADIUS,
                      plate_file="paper_plate.x3p", ball_file="paper_ball.x3p", warnings=found)
    rec = ball_contact_record(sol)
    rec["notes"] = [*rec["notes"], *found]
    return rec, res


def rolling_step(plate: Any, ball: Any, loads: str) -> tuple[dict[str, Any], Any]:
    """The hysteresis rolling-resistance sweep over ``loads`` ("F1:F2:N")."""
    from surfmet.mechanics.rolling_resistance import rolling_resistance

    rep = rolling_resistance(plate, ball, radius=RADIUS, materials=MATERIALS, loads=loads,
                             model="hysteresis")
    return rolling_record(rep), rep

