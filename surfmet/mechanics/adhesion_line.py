"""``surfmet adhesion --line``: an adhesive cylinder on a flat, per unit length.

:func:`line_adhesion` samples the plate scan's roughness along the cylinder's cross-section
and runs :func:`contact.adhesion.line.adhesive_line`;
:func:`surfmet.records._adhesion.line_record` is the JSON record
(forces per unit length in N/m, energies in J/m), :func:`line_plot` the figure. The
cylinder's axis lies along the scan's y; the profile is the row through the middle of the
levelled plate, sampled by the engine's
:func:`contact._sampling.sample_roughness` (as ``rolling-contact --line`` does).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from surfmet._errors import SurfmetInputError
from surfmet.mechanics.adhesion import (
    INTERACTION,
    Adhesion,
    adhesion_pair,
    interaction_law,
    scan_too_small,
)
from surfmet.mechanics.scan_preparation import SPIKES

if TYPE_CHECKING:
    from surfmet.mechanics._types import AdhesionLaw, Materials, PathLike, ScanSource, Spikes


def refuse_ball(ball: ScanSource | None) -> None:
    """A line contact takes no ball scan: refused (before any file is read).

    Parameters
    ----------
    ball : Topography, path or None
        The ball's scan, if any.

    Raises
    ------
    SurfmetInputError
        A ball scan was given.

    Examples
    --------
    >>> from surfmet.mechanics.adhesion_line import refuse_ball
    >>> refuse_ball(None)
    >>> refuse_ball("ball.x3p")
    Traceback (most recent call last):
    ...
    surfmet._errors.SurfmetInputError: --ball does not apply to a line contact ...
    """
    if ball is not None:
        raise SurfmetInputError("--ball does not apply to a line contact (the ball's sphere "
                                "would be removed from a cylinder): give the plate's scan only")


#: Cells across the period of a line contact, unless told.
LINE_CELLS = 2048


def line_adhesion(radius: float, *, work: float | None = None, range_: float | None = None,
                  materials: Materials | None = None, e_star: float | None = None,
                  interaction: str | AdhesionLaw = INTERACTION,
                  grid: int | None = None, size: float | None = None, steps: int = 40,
                  plate: ScanSource | None = None, ball: ScanSource | None = None,
                  spikes: Spikes = SPIKES,
                  progress: Callable[[int, int], None] | None = None) -> Adhesion:
    """The approach-retraction cycle of a cylinder of ``radius`` on a flat, per unit length,
    with the arguments of :func:`surfmet.mechanics.adhesion.adhesion` (``grid``: cells
    across the period, default :data:`LINE_CELLS`); ``plate`` is a scan whose middle row
    is the roughness profile.

    Returns
    -------
    Adhesion
        The cycle per unit length (loads in N/m) and the pull-off force.

    Raises
    ------
    SurfmetInputError
        A ball scan (a cylinder's scan is not a sphere's cap), or a plate scan narrower than
        the period.

    See Also
    --------
    surfmet.mechanics.adhesion.adhesion : the sphere.
    surfmet.records._adhesion.line_record : the JSON record.

    References
    ----------
    .. [1] D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale model",
       J. Colloid Interface Sci. 150 (1992) 243-269 (and its plane-strain analogue).

    Examples
    --------
    >>> from surfmet.mechanics.adhesion_line import line_adhesion
    >>> from surfmet.records._adhesion import line_record
    >>> run = line_adhesion(1e-5, work=0.05, range_=2e-9, e_star=1e9, grid=64, steps=8)
    >>> rec = line_record(run)
    >>> rec["geometry"], rec["pull_off_force"]["unit"], run.line
    ('line', 'N/m', True)
    """
    import numpy as np

    from contact.adhesion.line import CELL_WIDTHS, adhesive_line, line_scales

    mats = adhesion_pair(materials, e_star)
    law = interaction_law(interaction, work, range_)
    cells = grid
    refuse_ball(ball)
    cells = LINE_CELLS if cells is None else cells
    if int(cells) != cells or cells < 64:
        raise SurfmetInputError(f"the cells of a line contact must be an integer of at least "
                                f"64, got {cells!r}")
    if size is None:
        size = CELL_WIDTHS * max(line_scales(radius, mats.e_star, law))
    z, scans = None, None
    if plate is not None:
        from contact._grid import Grid
        from contact._sampling import sample_roughness
        from surfmet.mechanics.scan_preparation import ScansUsed, prepare_scans

        prep = prepare_scans(plate, None, spikes=spikes)
        pair = prep.paired()
        dx = size / cells
        x = (np.arange(cells) - cells // 2) * dx
        if (pair.roughness.shape[1] - 1) * pair.dx < 2.0 * max(-x[0], x[-1]):
            raise SurfmetInputError(scan_too_small(pair, size))
        z = sample_roughness(pair.roughness, pair.dx, pair.dy,
                             Grid(x=x, y=np.zeros(1), pitch=(dx, dx)), average=False)[0]
        scans = ScansUsed(prep, plate, None, dx, z,
                          profile="the row through the middle of the plate scan, along its x")
    res = adhesive_line(radius, mats, law, cells=cells, size=size, steps=steps,
                        roughness=z, progress=progress)
    return Adhesion(res, scans)


def line_plot(run: Adhesion, path: PathLike | None = None) -> Any:
    """Load per length against approach, and contact half-width against load.

    Parameters
    ----------
    run : Adhesion
        A line run.
    path : path-like, optional
        Image file to write; None returns the figure only.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    Examples
    --------
    >>> from surfmet.mechanics.adhesion_line import line_adhesion, line_plot
    >>> fig = line_plot(line_adhesion(1e-5, work=0.05, range_=2e-9, e_star=1e9, grid=64,
    ...                               steps=8))
    >>> type(fig).__name__
    'Figure'
    """
    from surfmet.plots._style import finish, new_figure

    res = run.result
    fig, (a1, a2) = new_figure(1, 2, size=(10, 4.2))
    for leg, style, name in ((res.cycle.approach_leg, "C0o-", "approach"),
                             (res.cycle.retraction_leg, "C3s-", "retraction")):
        a1.plot(leg.surface_approach * 1e9, leg.load, style, ms=3, label=name)
        a2.plot(leg.load, 0.5e6 * leg.contact_area, style, ms=3, label=name)
    a1.axhline(-res.jkr_pull_off, color="0.5", ls=":", label="JKR pull-off")
    a1.set_xlabel("approach (nm)")
    a1.set_ylabel("load per length (N/m)")
    a2.set_xlabel("load per length (N/m)")
    a2.set_ylabel("contact half-width (µm)")
    a1.set_title(f"cylinder, Maugis lambda = {res.maugis_parameter:.3g}")
    for ax in (a1, a2):
        ax.legend(fontsize=8)
    return finish(fig, path)
