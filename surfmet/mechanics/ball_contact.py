"""``surfmet contact``'s facade: the normal contact of a (rough) ball on a (rough) plate from
scans, solved by the FFT boundary-element method of :mod:`contact`.

:func:`ball_contact` reads and pairs the scans (:func:`surfmet.mechanics.pairing.prepare_pair`),
resolves the materials (:func:`surfmet.mechanics.material_spec.parse_materials`), and solves
the ball-on-plate set-up; :class:`BallContact` holds the result with what it was computed
from, and gives its JSON record (:func:`surfmet.records.contact_record`) and its figure.
Without a scan the smooth (Hertz) case is solved.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from surfmet.errors import SurfmetInputError


@dataclass(frozen=True, eq=False)
class BallContact:
    """A solved ball-on-plate contact and what it was solved from.

    Attributes
    ----------
    result : contact.ContactResult
        The solution (pressure, gap, contact area, Hertz's values for comparison).
    ball_material, plate_material : contact.materials.Material
    pair : surfmet.mechanics.pairing.PairedRoughness or None
        The paired scans; None for smooth surfaces.
    radius : float
        Ball radius (m).
    plate_file, ball_file : str or None
        The scan files, for the record.
    warnings : tuple of str
        Warnings of the solve (a contact reaching the domain's edge).
    """

    result: Any
    ball_material: Any
    plate_material: Any
    pair: Any
    radius: float
    plate_file: str | None = None
    ball_file: str | None = None
    warnings: tuple[str, ...] = ()

    def to_json(self) -> dict[str, Any]:
        """The ``surfmet contact`` record (every value with its unit)."""
        from surfmet.records import contact_record

        return contact_record(self.result, self.ball_material, self.plate_material,
                              self.pair, radius=self.radius, plate_file=self.plate_file,
                              ball_file=self.ball_file)

    def figure(self, path: str | Path | None = None) -> Any:
        """The pressure map (:func:`surfmet.plots.contact.pressure_map`)."""
        from surfmet.plots.contact import pressure_map

        return pressure_map(self.result, path)


def _hardness(hardness: float | None, plastic: bool, ball_m: Any, plate_m: Any
              ) -> float | None:
    from contact.materials import contact_hardness

    if hardness is not None and plastic:
        raise SurfmetInputError("give a hardness or plastic=True, not both")
    if not plastic:
        return hardness
    h = contact_hardness(ball_m, plate_m)
    if h is None:
        raise SurfmetInputError("--plastic: neither material has a hardness; give --hardness")
    return h


def _file(obj: Any) -> str | None:
    return None if obj is None else str(obj) if isinstance(obj, (str, Path)) else None


def _read(obj: Any) -> Any:
    import surfmet

    return surfmet.read(obj) if isinstance(obj, (str, Path)) else obj


def solve_on_pair(pair: Any, *, radius: float, load: float, e_star: float,
                  hardness: float | None = None, **options: Any) -> tuple[Any, tuple[str, ...]]:
    """Solve the ball-on-plate set-up on a paired roughness (None: smooth surfaces).

    ``options`` go to the set-up and the solver (``grid``, ``size``, ``periodic``,
    ``max_grid``, ``on_edge``, ``tol``, ``max_iter``, ``callback``). Returns the result and
    the warnings of the solve as text (a contact reaching the domain's edge).
    """
    from contact.errors import EdgeContactWarning
    from contact.setups.ball_on_plate import solve_sphere

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", EdgeContactWarning)
        res = solve_sphere(
            radius, load, e_star,
            roughness=None if pair is None else pair.composite(),
            hardness=hardness, **options,
        )
    found = tuple(str(w.message) for w in caught if issubclass(w.category, EdgeContactWarning))
    return res, found


def ball_contact(
    plate: Any = None,
    ball: Any = None,
    *,
    radius: float,
    load: float,
    materials: Any = "steel,aluminium",
    hardness: float | None = None,
    plastic: bool = False,
    grid: int | None = None,
    size: float | None = None,
    periodic: bool = False,
    on_edge: str = "enlarge",
    tol: float = 1e-6,
    max_iter: int = 2000,
    max_grid: int | None = None,
    callback: Callable[[int, float], None] | None = None,
) -> BallContact:
    """Normal contact of a ball on a plate from their scans.

    Parameters
    ----------
    plate, ball : Topography or path, optional
        The scans (either, both or none: smooth surfaces). The plate is levelled, the
        ball's best-fit sphere removed, and both paired on one grid
        (:func:`surfmet.mechanics.pairing.prepare_pair`).
    radius, load : float
        Ball radius (m) and normal load (N).
    materials : str or pair of Material
        Ball and plate, e.g. ``"steel,aluminium"``.
    hardness : float, optional
        Cap the pressure at this hardness (Pa): elastic-perfectly-plastic.
    plastic : bool
        Cap the pressure at the softer material's table hardness.
    grid, size, periodic, on_edge, tol, max_iter, max_grid, callback
        The set-up and the solver (:func:`contact.setups.ball_on_plate.solve_sphere`);
        ``max_grid=None`` lets the scans' own pixel through whatever the grid.

    Returns
    -------
    BallContact
    """
    from contact.materials import composite_modulus
    from surfmet.mechanics.material_spec import parse_materials
    from surfmet.mechanics.pairing import prepare_pair

    ball_m, plate_m = parse_materials(materials)
    e_star = composite_modulus(ball_m, plate_m)
    cap = _hardness(hardness, plastic, ball_m, plate_m)
    if not (tol > 0):
        raise SurfmetInputError("--tol must be positive")
    pair = None
    if plate is not None or ball is not None:
        pair = prepare_pair(_read(plate), _read(ball))
    res, found = solve_on_pair(pair, radius=radius, load=load, e_star=e_star, hardness=cap,
                               periodic=periodic, grid=grid, size=size, max_grid=max_grid,
                               tol=tol, max_iter=max_iter, callback=callback,
                               on_edge=on_edge)
    return BallContact(result=res, ball_material=ball_m, plate_material=plate_m, pair=pair,
                       radius=radius, plate_file=_file(plate), ball_file=_file(ball),
                       warnings=found)
