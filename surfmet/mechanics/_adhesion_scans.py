"""The scans' roughness on the adhesion solver's grid, and the line refusing scans smaller
than its domain (re-exported by :mod:`surfmet.mechanics.adhesion`, the facade)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from surfmet._errors import SurfmetInputError
from surfmet.mechanics._spike_choice import SPIKES

if TYPE_CHECKING:
    from surfmet.mechanics._types import ScanSource, Spikes
    from surfmet.mechanics.pairing import PairedRoughness
    from surfmet.mechanics.scan_preparation import ScansUsed


def rough_grid(plate: ScanSource | None, ball: ScanSource | None, grid: int, size: float,
               spikes: Spikes = SPIKES) -> tuple[Any, ScansUsed | None]:
    """The scans' composite roughness on the solver's ``grid`` x ``grid`` cells of side
    ``size`` (m), centred on the middle of the scans, and the scans used.

    The scans are prepared as for every contact command
    (:func:`surfmet.mechanics.scan_preparation.prepare_scans`: spikes, the plate levelled,
    the ball's best-fit sphere removed, both paired on one square grid, so non-square
    pixels are resampled) and sampled with the engine's
    :func:`contact._sampling.sample_roughness`. (None, None) without scans.

    Parameters
    ----------
    plate, ball : Topography, path or None
        The scans.
    grid : int
        Cells per side.
    size : float
        Domain side (m).
    spikes : {"remove", "keep"} or bool
        Spike handling.

    Returns
    -------
    (ndarray or None, ScansUsed or None)
        The roughness on the grid (m) and the scans used (their record is
        :func:`surfmet.records._adhesion.scans_record`).

    Raises
    ------
    SurfmetInputError
        A scan smaller than the domain, or a grid that is not an integer of at least 16.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.adhesion import rough_grid
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> z, used = rough_grid(surfmet.Topography(plate.heights[:128, :128], plate.dx,
    ...                                         plate.dy), None, 32, 3e-4)
    >>> z.shape, used.plate_name
    ((32, 32), '(in memory)')
    """
    if plate is None and ball is None:
        return None, None
    from contact._geometry import max_centred_cells
    from contact._grid import centred_grid
    from contact._sampling import sample_roughness
    from surfmet.mechanics.scan_preparation import ScansUsed, prepare_scans

    if int(grid) != grid or grid < 16:
        raise SurfmetInputError(f"the grid must be an integer of at least 16, got {grid!r}")
    prep = prepare_scans(plate, ball, spikes=spikes)
    pair = prep.paired()
    ny, nx = pair.roughness.shape
    centre = (0.5 * (nx - 1) * pair.dx, 0.5 * (ny - 1) * pair.dy)
    dx = size / grid
    if max_centred_cells(pair.roughness.shape, pair.dx, pair.dy, centre, dx) < grid:
        raise SurfmetInputError(scan_too_small(pair, size))
    z = sample_roughness(pair.roughness, pair.dx, pair.dy, centred_grid(int(grid), dx),
                         centre=centre)
    return z, ScansUsed(prep, plate, ball, dx, z)


def scan_too_small(pair: PairedRoughness, size: float) -> str:
    """The one line refusing scans smaller than the domain of side ``size`` (m).

    Parameters
    ----------
    pair : PairedRoughness
        The paired scans.
    size : float
        The domain's side (m).

    Returns
    -------
    str
        The message.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.adhesion import scan_too_small
    >>> from surfmet.mechanics.pairing import prepare_pair
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> pair = prepare_pair(surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy))
    >>> print(scan_too_small(pair, 1e-3))
    the scans (635 x 635 µm in common) are smaller than the adhesion domain (1000 µm a
    side): give a smaller --size or larger scans
    """
    ny, nx = pair.roughness.shape
    return (f"the scans ({(nx - 1) * pair.dx * 1e6:.4g} x {(ny - 1) * pair.dy * 1e6:.4g} µm "
            f"in common) are smaller than the adhesion domain ({size * 1e6:.4g} µm a side): "
            "give a smaller --size or larger scans")
