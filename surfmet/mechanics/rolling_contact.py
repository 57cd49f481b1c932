"""Steady rolling with friction of a ball (or roller) on a plate: the facade of
:mod:`contact.tangential` for the ``surfmet rolling-contact`` command.

One solve: the normal load, the materials and the friction coefficient, with either a
prescribed longitudinal creepage or free rolling (zero tangential force, the creepage
solved for); a sphere on a flat (3D) or a cylinder on a flat in plane strain (``line``,
load per unit length); smooth, or rough from the plate and ball scans (their composite
roughness, prepared as for ``surfmet contact``).

Sign convention (stated once, in :data:`SIGN_CONVENTION`): body 1 is the ball, body 2
the plate; the contact moves over both in +x (the leading edge is at +x); creepage is
the rigid slip velocity of the ball relative to the plate over the rolling speed; forces
are those on the ball, so a positive creepage gives a negative F_x.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from surfmet._errors import SurfmetInputError

if TYPE_CHECKING:
    from contact.tangential import TangentialResult
    from surfmet.mechanics._types import Materials, RoughnessMap

SIGN_CONVENTION = (
    "body 1 = ball, body 2 = plate; the contact moves in +x (leading edge at +x); "
    "creepage = (rigid slip velocity of the ball relative to the plate) / rolling speed; "
    "forces are those on the ball (positive creepage gives negative fx)"
)

# one sentence for every record and text: what the two dimensionless numbers are
RESISTANCE_DEFINITION = (
    "rolling_resistance_coefficient = frictional dissipation per metre rolled / N "
    "(= M_r / (N R) of surfmet rolling --model microslip); pressure_moment_coefficient = "
    "the pressure's moment about the contact centre / (N R), the asymmetry of this "
    "pressure, not a dissipation for elastic bodies (rough contacts lean either way with "
    "the asperities under them)"
)


@dataclass(frozen=True)
class RollingContact:
    """A solved rolling contact and the set-up it came from.

    Attributes
    ----------
    result : contact.tangential._results.TangentialResult
        The normal and tangential solution (pressure, tractions, stick/slip, forces).
    radius, load : float
        Ball or cylinder radius (m) and load (N, or N/m for a line).
    line : bool
        Plane strain.
    speed : float or None
        Rolling speed (m/s).
    free_rolling : bool
        No creepage was imposed.
    grid : int
        Elements per side.
    side : float
        Domain side (m).
    notes : tuple of str
        Caveats.

    See Also
    --------
    solve_rolling_contact : makes it.

    Examples
    --------
    >>> from surfmet.mechanics.rolling_contact import solve_rolling_contact
    >>> rc = solve_rolling_contact(0.02, 10.0, "steel,steel", 0.3, creepage=1e-4, grid=32)
    >>> rc.line, rc.free_rolling, rc.grid
    (False, False, 32)
    """

    result: TangentialResult
    radius: float
    load: float
    line: bool
    speed: float | None
    free_rolling: bool
    grid: int
    side: float = math.nan
    notes: tuple[str, ...] = ()


def parse_line_load(text: str) -> float:
    """A load per unit length such as ``"100N/mm"`` or ``"2e4 N/m"`` -> N/m.

    Parameters
    ----------
    text : str
        A force per length with its unit.

    Returns
    -------
    float
        N/m.

    Raises
    ------
    SurfmetInputError
        Text that is not a force per length.

    Examples
    --------
    >>> from surfmet.mechanics.rolling_contact import parse_line_load
    >>> parse_line_load("100N/mm"), parse_line_load("2e4 N/m")
    (100000.0, 20000.0)
    """
    from surfmet import units

    if "/" not in str(text):
        raise SurfmetInputError(f"--line needs a load per length, e.g. 100N/mm; got {text!r}")
    num, den = str(text).split("/", 1)
    length = units.parse_length("1" + den.strip())
    value = units.parse_force(num) / length
    if not (math.isfinite(value) and value > 0):
        raise SurfmetInputError(f"load per length must be positive, got {text!r}")
    return value


#: Half-width of a rough contact's domain over the radius within which it may touch
#: (:func:`contact._geometry.contact_extent`), the margin ``surfmet contact`` takes.
ROUGH_MARGIN = 1.25
#: How often a domain the contact outgrows is enlarged (1.5x each time) before giving up.
ENLARGEMENTS = 3


def solve_rolling_contact(
    radius: float,
    load: float,
    materials: Materials,
    mu: float,
    *,
    creepage: float | None = None,
    line: bool = False,
    speed: float | None = None,
    grid: int | None = None,
    roughness: RoughnessMap | None = None,
    size: float | None = None,
) -> RollingContact:
    """Solve one steady-rolling case.

    The domain is sized as for ``surfmet contact``: 1.25 Hertz radii for a smooth ball;
    for a rough one, 1.25 times the radius within which asperities up to three standard
    deviations high may touch (:func:`contact._geometry.contact_extent`), since rough
    contact spreads well beyond the Hertz radius. A contact that still reaches the
    leading edge enlarges the domain (1.5x, up to :data:`ENLARGEMENTS` times, said in
    the notes) unless ``size`` fixes it.

    Parameters
    ----------
    radius : float
        Ball (or roller) radius R (m).
    load : float
        Normal load (N), or per unit length (N/m) when ``line``.
    materials : str or (Material, Material)
        ``"BALL,PLATE"`` or the two materials.
    mu : float
        Coefficient of friction (> 0).
    creepage : float, optional
        Longitudinal creepage xi; None solves free rolling (F_x = 0).
    line : bool
        Plane strain (a roller).
    speed : float, optional
        Rolling speed (m/s), to report the frictional power in watts as well.
    grid : int, optional
        Elements per side (default 64 in 3D, 256 in plane strain).
    roughness : (ndarray, dx, dy), optional
        Composite roughness map and its pitch (m), e.g. from
        :func:`surfmet.mechanics.pairing.prepare_pair`.
    size : float, optional
        Side of the (square) domain (m); default: automatic, as above.

    Returns
    -------
    RollingContact
        The solution and its set-up.

    Raises
    ------
    SurfmetInputError, ContactError
        Bad values or materials, a solver failure.

    See Also
    --------
    surfmet.records._rolling_contact.rolling_contact_record : its JSON record.

    References
    ----------
    .. [1] J. J. Kalker, Three-Dimensional Elastic Bodies in Rolling Contact, Kluwer
       (1990).
    .. [2] F. W. Carter, "On the action of a locomotive driving wheel", Proc. R. Soc.
       Lond. A 112 (1926) 151-157.
    .. [3] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), ch. 8.

    Examples
    --------
    A steel ball on steel at 10 N with a creepage of 1e-4: the tangential force stays
    within Coulomb's μN = 3 N:

    >>> from surfmet.mechanics.rolling_contact import solve_rolling_contact
    >>> from surfmet.records._rolling_contact import rolling_contact_record
    >>> rc = solve_rolling_contact(0.02, 10.0, "steel,steel", 0.3, creepage=1e-4, grid=32)
    >>> fx = rolling_contact_record(rc)["fx"]
    >>> print(fx["unit"], 0 < abs(fx["value"]) < 0.3 * 10.0)
    N True
    """
    from contact._errors import EdgeContactError
    from contact._record import LEADING_EDGE, raise_edge
    from contact.tangential import Creepage, steady_rolling
    from contact.tangential._memory import check_rolling_memory
    from surfmet.mechanics.material_spec import material_pair

    constants = material_pair(materials).constants()
    if speed is not None and not (math.isfinite(speed) and speed > 0):
        raise SurfmetInputError("--speed must be a positive speed in m/s")
    n = grid or (256 if line else 64)
    if n < 8:
        raise SurfmetInputError("--grid needs at least 8 elements a side")
    # before anything of the grid's size is allocated
    check_rolling_memory(n, line=line)
    if size is not None and not (math.isfinite(size) and size > 0):
        raise SurfmetInputError("--size must be a positive length")
    half = 0.5 * size if size is not None else _half_width(radius, load, constants.e_star,
                                                           line, roughness)
    notes: list[str] = []
    for attempt in range(ENLARGEMENTS + 1):
        g = _grid(radius, half, n, line, roughness)
        try:
            res = steady_rolling(g, constants, load, mu,
                                 Creepage(xi=0.0 if creepage is None else creepage),
                                 fx=0.0 if creepage is None else None)
            break
        except EdgeContactError:
            if size is not None or attempt == ENLARGEMENTS:
                raise_edge(f"{LEADING_EDGE}; give a larger --size (e.g. --size "
                           f"{3e3 * half:.3g}mm)", f"the {2e3 * half:.4g} mm domain")
            half *= 1.5
            notes.append(f"the contact reached the domain's edge: domain enlarged to "
                         f"{2e3 * half:.4g} mm")
    coarse = _coarser_than_scans(res.grid.dx, roughness)
    if coarse is not None:
        notes.append(coarse)
    return RollingContact(result=res, radius=radius, load=load, line=line, speed=speed,
                          free_rolling=creepage is None, grid=n, side=2.0 * half,
                          notes=tuple(notes))


#: Elements this many times the scans' pixel or more miss asperities between them (said).
COARSER_THAN_SCANS = 1.5


def _coarser_than_scans(element: float, roughness: RoughnessMap | None) -> str | None:
    """The note for elements much coarser than the scans' pixel, or None: the scans are
    sampled at the elements' centres, so the real contact area and the peak pressure are
    those of this element size (on rough contacts both change with it), not the scans'."""
    if roughness is None:
        return None
    pixel = max(float(roughness[1]), float(roughness[2]))
    if element < COARSER_THAN_SCANS * pixel:
        return None
    return (f"the scans (pixel {pixel * 1e6:.3g} µm) are sampled at the centres of elements "
            f"of {element * 1e6:.3g} µm ({element / pixel:.2g} x coarser): contact area and peak "
            f"pressure are those of this element size and change with it; a larger --grid "
            f"resolves more asperities (hertz-check and contact solve on the scans' own "
            f"pixel)")


def _half_width(radius: float, load: float, e_star: float, line: bool,
                roughness: RoughnessMap | None) -> float:
    """The automatic half-width of the domain (m): see :func:`solve_rolling_contact`."""
    import numpy as np

    from contact._geometry import contact_extent
    from contact._hertz import hertz_cylinder, hertz_sphere

    if line:
        return (1.5 if roughness is not None else 1.25) * hertz_cylinder(radius, load,
                                                                         e_star).a
    if roughness is None:
        return 1.25 * hertz_sphere(radius, load, e_star).a
    z = np.asarray(roughness[0], dtype=float)
    rms = float(np.nanstd(z)) if np.isfinite(z).any() else 0.0
    return ROUGH_MARGIN * contact_extent(radius, load, e_star, rms)


def _grid(radius: float, half: float, n: int, line: bool, roughness: RoughnessMap | None) -> Any:
    """The tangential grid of half-width ``half``, with the roughness sampled onto it."""
    from contact._grid import cylinder_grid, sphere_grid
    from contact._sampling import sample_roughness

    make = cylinder_grid if line else sphere_grid
    z = None
    if roughness is not None:
        zmap, zdx, zdy = roughness
        z = sample_roughness(zmap, zdx, zdy, make(radius, half, n), average=False)
        z = z - z.max()  # the highest summit touches first; only differences matter
    return make(radius, half, n, roughness=z)
