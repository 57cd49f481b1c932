"""The rough contact's extent as a bound on the rotor's friction arm.

The arm argument (:mod:`rotor._arm`) bounds the friction arm ``s_r = M_r / N`` by the
contact radius, since the normal force's resultant lies inside the contact. Its bound is
Hertz's radius at the symmetric group's ball load. Where the plate (and ball) are scanned, the
rough contact at the same load spreads over a region of its own: :func:`rough_arm_bound` asks
the one function that answers it, :func:`surfmet.mechanics.hertz_check.hertz_check` (the
rig's ball radius, the symmetric ball load, the paper's materials steel on aluminium), and
takes its boundary-element radius ``a*`` (the second-moment radius of the pressure, the
radius of the Hertz distribution with the same spread of load; the same ``a*`` as
``surfmet hertz-check`` prints). The larger of the two radii is the physical bound on the arm:
the resultant lies inside whichever region carries the load.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from rotor import ArmBound, RotorVerdict
    from surfmet.mechanics._types import ScanSource

__all__ = ["MATERIALS", "RoughArmBound", "deciding_bound", "rough_arm_bound",
           "rough_basis", "rough_bound_line"]

MATERIALS = "steel,aluminium"
"""The paper's ball and plate materials (:data:`rotor._arm.PAPER_PAIR`)."""


@dataclass(frozen=True)
class RoughArmBound:
    """The rough contact's extent at the arm bound's load (SI).

    ``radius``: the BEM second-moment radius a*; ``hertz_radius``: the Hertz radius it is
    set beside; ``load``, ``ball_radius``; ``plate_file``, ``ball_file`` (None when not
    scanned); ``grid`` (cells per side, ny, nx) and ``cell`` (m) of the contact solution;
    ``warnings``: a grid or scan too coarse for the contact.

    Examples
    --------
    >>> from surfmet.mechanics.rotor_rough_bound import RoughArmBound
    >>> rb = RoughArmBound(radius=318e-6, hertz_radius=106e-6, load=4.67, ball_radius=0.02,
    ...                    plate_file="plate.x3p", ball_file=None, grid=(64, 64),
    ...                    cell=2e-5, warnings=())
    >>> rb.decides, round(rb.deciding_radius * 1e6)
    ('rough', 318)
    """

    radius: float
    hertz_radius: float
    load: float
    ball_radius: float
    plate_file: str | None
    ball_file: str | None
    grid: tuple[int, int]
    cell: float
    warnings: tuple[str, ...]

    @property
    def decides(self) -> str:
        """``"rough"`` or ``"hertz"``: the larger radius bounds the arm."""
        return "rough" if self.radius > self.hertz_radius else "hertz"

    @property
    def deciding_radius(self) -> float:
        return max(self.radius, self.hertz_radius)


def _label(scan: ScanSource | None) -> str | None:
    if scan is None:
        return None
    if isinstance(scan, (str, bytes)) or hasattr(scan, "__fspath__"):
        return str(scan)
    return scan.metadata.get("source") or scan.metadata.get("container") or "scan"


def rough_arm_bound(arm: ArmBound, ball_radius: float, plate: ScanSource,
                    ball: ScanSource | None = None, *,
                    grid: int | None = None) -> RoughArmBound:
    """The rough contact's radius a* at the arm bound's load.

    Parameters
    ----------
    arm : rotor.ArmBound
        The Hertz arm bound (its ``bound_load`` and ``arm_bound``).
    ball_radius : float
        The rig's ball radius (m).
    plate, ball : Topography or path
        The scans (the ball optional).
    grid : int, optional
        Contact grid, cells per side (default :func:`hertz_check`'s).

    Returns
    -------
    RoughArmBound

    Examples
    --------
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.rotor_rough_bound import rough_arm_bound
    >>> from surfmet.mechanics.rotor_verdict import paper_verdict
    >>> v = paper_verdict()
    >>> rb = rough_arm_bound(v.arm, 0.02, path("paper_plate.x3p"), path("paper_ball.x3p"),
    ...                      grid=32)
    >>> rb.decides, round(rb.hertz_radius * 1e6)
    ('rough', 106)
    """
    from surfmet.mechanics.hertz_check import hertz_check

    check = hertz_check(plate, radius=ball_radius, load=arm.bound_load, materials=MATERIALS,
                        ball=ball, grid=grid)
    res = check.result
    ny, nx = res.shape
    return RoughArmBound(radius=float(check.comparison.effective_radius),
                         hertz_radius=float(arm.arm_bound), load=float(arm.bound_load),
                         ball_radius=float(ball_radius), plate_file=_label(plate),
                         ball_file=_label(ball), grid=(int(ny), int(nx)),
                         cell=float(res.dx), warnings=tuple(check.warnings))


def rough_basis(rb: RoughArmBound) -> str:
    """How the rough bound was reached, in words (the text and the JSON's ``basis``).

    Examples
    --------
    >>> from surfmet.mechanics.rotor_rough_bound import RoughArmBound, rough_basis
    >>> rb = RoughArmBound(radius=318e-6, hertz_radius=106e-6, load=4.67, ball_radius=0.02,
    ...                    plate_file="plate.x3p", ball_file=None, grid=(64, 64),
    ...                    cell=2e-5, warnings=())
    >>> rough_basis(rb)[:56]
    'boundary-element contact of the scans (plate plate.x3p, '
    """
    ball = rb.ball_file if rb.ball_file else "a smooth ball"
    return (f"boundary-element contact of the scans (plate {rb.plate_file}, ball {ball}) at "
            f"the same ball load {rb.load:.3g} N, R = {rb.ball_radius * 1e3:.3g} mm, "
            f"{MATERIALS.replace(',', ' on ')} (surfmet hertz-check); a* = sqrt(5/2 <r^2>_p), "
            f"the radius of the region the load spreads over, on a {rb.grid[1]} x "
            f"{rb.grid[0]} grid of {rb.cell * 1e6:.3g} µm cells")


def deciding_bound(v: RotorVerdict, rb: RoughArmBound | None) -> ArmBound:
    """The arm argument (:class:`rotor.ArmBound`) at the radius that bounds
    the arm: the verdict's own (Hertz's) unless the rough contact's a* is the larger, then
    recomputed there (:func:`rotor.arm_bound` with ``radius=``): the least
    lambda the offset needs, its slope, and the friction arm's ratio to the bound.

    Examples
    --------
    A bound three times Hertz's radius allows a larger torque, so a smaller lambda:

    >>> from surfmet.mechanics.rotor_rough_bound import RoughArmBound, deciding_bound
    >>> from surfmet.mechanics.rotor_verdict import paper_verdict
    >>> v = paper_verdict()
    >>> rb = RoughArmBound(radius=3 * v.arm.arm_bound, hertz_radius=v.arm.arm_bound,
    ...                    load=v.arm.bound_load, ball_radius=0.02, plate_file="plate.x3p",
    ...                    ball_file=None, grid=(64, 64), cell=2e-5, warnings=())
    >>> round(v.arm.lambda_at_bound, 2), round(deciding_bound(v, rb).lambda_at_bound, 2)
    (3.76, 2.4)
    """
    if rb is None or rb.decides != "rough":
        return v.arm
    from rotor import arm_bound

    o = v.offset
    return arm_bound(v.rig, o.minuend, o.subtrahend, v.arm.slope, v.mean_acceleration,
                     o.value, o.ci_low, o.ci_high, e_star=v.arm.e_star, radius=rb.radius,
                     radius_basis=f"the rough contact's extent a* ({rough_basis(rb)})")


def rough_bound_line(rb: RoughArmBound, friction_arm: float) -> list[str]:
    """The rough bound in words (after the friction arm's line).

    Examples
    --------
    >>> from surfmet.mechanics.rotor_rough_bound import RoughArmBound, rough_bound_line
    >>> rb = RoughArmBound(radius=318e-6, hertz_radius=106e-6, load=4.67, ball_radius=0.02,
    ...                    plate_file="plate.x3p", ball_file=None, grid=(64, 64),
    ...                    cell=2e-5, warnings=())
    >>> rough_bound_line(rb, 0.258e-3)[0][:38]
    "  rough contact's extent a* = 318 µm ("
    """
    ratio = friction_arm / rb.deciding_radius
    which = ("the rough contact's a* decides (larger than Hertz)" if rb.decides == "rough"
             else "Hertz decides (larger than the rough a*)")
    inside = "impossible at lambda = 1" if ratio > 1 else "inside the bound at lambda = 1"
    out = [f"  rough contact's extent a* = {rb.radius * 1e6:.0f} µm ({rough_basis(rb)}): "
           f"{which}; "
           f"s_r = {ratio:.2g} x {rb.deciding_radius * 1e6:.0f} µm: {inside}"
           + ("; the lambda lines below are at this a*" if rb.decides == "rough" else "")]
    out += [f"    warning: {w}" for w in rb.warnings]
    return out
