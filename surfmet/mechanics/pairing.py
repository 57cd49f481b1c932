"""Prepare a plate scan and a ball scan for the contact engine.

:func:`prepare_pair` turns the two scans into one composite roughness map on one grid:

1. the plate is levelled (least-squares plane removed: a tilt of the specimen under the
   profilometer is not roughness);
2. the ball's best-fit sphere is removed (:func:`surfmet.areal._form.remove_form` with
   ``"sphere"``); what remains is its roughness and form error, positive outward;
3. the ball residual is mirrored (x -> -x): the ball was scanned from above and is turned
   over onto the plate, which reverses one in-plane axis;
4. both are resampled (bilinear) onto one square grid of the finer pitch, over the
   central region the two scans share; non-measured points are filled with the nearest
   measured value (the fraction is reported);
5. the composite roughness is the sum of the two, each measured outward from its own body,
   so that it closes the gap: h = r^2/(2R) - z (the convention of
   :mod:`contact.setups._ball_on_plate`).

The result holds plain arrays and SI floats, ready for
:class:`contact.setups.CompositeRoughness`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography

#: Largest ratio of the coarsest to the finest pixel of a pair (either axis) accepted.
MAX_PITCH_RATIO = 10.0


@dataclass(frozen=True, eq=False)
class PairedRoughness:
    """Composite roughness of a ball-plate pair on one grid.

    Attributes
    ----------
    roughness : ndarray (ny, nx)
        Composite roughness z (m), no NaN: plate (levelled) + ball (sphere removed).
    dx, dy : float
        Grid pitch (m).
    plate_rms, ball_rms : float or None
        Rms of each surface's residual on the common grid (m); None if not given.
    ball_radius : float or None
        Radius of the best-fit sphere of the ball scan (m).
    filled_fraction : float
        Fraction of the common grid that was not measured in at least one scan and was
        filled.
    notes : tuple of str
        What was done, for the user.

    See Also
    --------
    prepare_pair : makes it.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.pairing import prepare_pair
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> pair = prepare_pair(plate, surfmet.read(path("paper_ball.x3p")))
    >>> pair.roughness.shape, pair.dx
    ((512, 1024), 5e-06)
    """

    roughness: np.ndarray
    dx: float
    dy: float
    plate_rms: float | None
    ball_rms: float | None
    ball_radius: float | None
    filled_fraction: float
    notes: tuple[str, ...] = ()
    fits: dict[str, Any] = field(default_factory=dict)

    @property
    def rms(self) -> float:
        """Rms of the composite roughness (m)."""
        z = self.roughness
        return float(np.sqrt(np.mean((z - z.mean()) ** 2)))

    def composite(self, offset: tuple[float, float] | None = None) -> Any:
        """The pair as the engine's :class:`contact.setups.CompositeRoughness`, with the
        ball's apex ``offset`` (m) from the middle of the map (a track position; None: the
        middle)."""
        from contact.setups import CompositeRoughness

        return CompositeRoughness(self.roughness, self.dx, self.dy,
                                  centre=apex_centre(self, offset))


def _areal(scan: object, what: str) -> Topography:
    if not isinstance(scan, Topography):
        kind = getattr(scan, "kind", type(scan).__name__)
        raise SurfmetInputError(f"the {what} must be an areal scan (Topography), got {kind}")
    if not np.isfinite(scan.heights).any():
        raise SurfmetInputError(f"the {what} scan has no measured point")
    return scan


def fill_nearest(z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``z`` with each non-finite point given its nearest finite neighbour's value, and the
    mask of the points filled.

    Parameters
    ----------
    z : ndarray
        Heights, NaN where not measured.

    Returns
    -------
    (ndarray, ndarray)
        The filled heights and the mask of the filled points.

    Examples
    --------
    >>> import numpy as np
    >>> from surfmet.mechanics.pairing import fill_nearest
    >>> filled, mask = fill_nearest(np.array([[1.0, np.nan, 3.0]]))
    >>> filled.tolist(), mask.tolist()
    ([[1.0, 1.0, 3.0]], [[False, True, False]])
    """
    from scipy.ndimage import distance_transform_edt

    bad = ~np.isfinite(z)
    if not bad.any():
        return z, bad
    idx = distance_transform_edt(bad, return_distances=False, return_indices=True)
    return z[tuple(idx)], bad


def _resample(z: np.ndarray, dx: float, dy: float, nx: int, ny: int, pitch: float
              ) -> tuple[np.ndarray, np.ndarray]:
    """Resampling of a centred (ny, nx) window of pitch ``pitch``
    (:func:`contact._sampling.sample_roughness`); also returns where the source was not
    measured (nearest-neighbour of the NaN mask)."""
    from scipy.ndimage import map_coordinates

    from contact._grid import Grid
    from contact._sampling import sample_roughness

    filled, bad = fill_nearest(z)
    sy, sx = z.shape
    cx, cy = 0.5 * (sx - 1) * dx, 0.5 * (sy - 1) * dy
    grid = Grid(x=(np.arange(nx) - 0.5 * (nx - 1)) * pitch,
                y=(np.arange(ny) - 0.5 * (ny - 1)) * pitch, pitch=(pitch, pitch))
    out = sample_roughness(filled, dx, dy, grid, centre=(cx, cy))
    coords = np.meshgrid(np.clip((cy + grid.y) / dy, 0, sy - 1),
                         np.clip((cx + grid.x) / dx, 0, sx - 1), indexing="ij")
    holes = map_coordinates(bad.astype(float), coords, order=0, mode="nearest") > 0.5
    return out, holes


def prepare_pair(
    plate: Topography | None = None,
    ball: Topography | None = None,
    *,
    pitch: float | None = None,
    mirror_ball: bool = True,
    max_filled: float = 0.5,
) -> PairedRoughness:
    """Composite roughness of a plate scan and a ball scan on one grid.

    Parameters
    ----------
    plate : Topography, optional
        Scan of the flat counter-face (levelled here).
    ball : Topography, optional
        Scan of the ball's cap (its best-fit sphere is removed here).
    pitch : float, optional
        Grid pitch (m); default the finest pitch of the scans given.
    mirror_ball : bool
        Mirror the ball residual in x (the ball is turned over onto the plate).
    max_filled : float
        Largest acceptable fraction of non-measured points on the common grid.

    Raises
    ------
    SurfmetInputError
        No scan, a profile instead of an areal scan, an all-NaN scan, too few measured
        points, a bad pitch, or pixels differing by more than :data:`MAX_PITCH_RATIO`.

    See Also
    --------
    surfmet.mechanics.scan_preparation.prepare_scans : spikes and levelling first, then this.
    contact.CompositeRoughness : what the engine takes.

    Examples
    --------
    The bundled plate and ball: the ball's best-fit sphere (R ≈ 20 mm) is removed and its
    residual resampled onto the plate's 5 µm grid:

    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.pairing import prepare_pair
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> pair = prepare_pair(plate, surfmet.read(path("paper_ball.x3p")))
    >>> print(f"R = {pair.ball_radius * 1e3:.2f} mm, plate rms = {pair.plate_rms * 1e6:.2f} µm")
    R = 19.96 mm, plate rms = 2.42 µm
    """
    from surfmet.areal._form import remove_form

    if plate is None and ball is None:
        raise SurfmetInputError("give a plate scan, a ball scan, or both")
    notes: list[str] = []
    fits: dict[str, Any] = {}
    parts: list[tuple[str, np.ndarray, float, float]] = []
    ball_radius = None
    if plate is not None:
        plate = _areal(plate, "plate")
        lev, fit = remove_form(plate, "plane")
        fits["plate"] = fit
        notes.append("plate levelled (least-squares plane removed)")
        parts.append(("plate", np.asarray(lev.heights), plate.dx, plate.dy))
    if ball is not None:
        ball = _areal(ball, "ball")
        res, fit = remove_form(ball, "sphere")
        fits["ball"] = fit
        ball_radius = float(fit.shape["radius"])
        z = np.asarray(res.heights)
        if mirror_ball:
            z = z[:, ::-1]
        notes.append(f"ball: best-fit sphere of radius {ball_radius * 1e3:.5g} mm removed"
                     + (", residual mirrored in x" if mirror_ball else ""))
        parts.append(("ball", z, ball.dx, ball.dy))

    pitches = [d for _, _, dx, dy in parts for d in (dx, dy)]
    if max(pitches) > MAX_PITCH_RATIO * min(pitches) * (1 + 1e-9):
        raise SurfmetInputError(
            f"the scans' pixels differ by {max(pitches) / min(pitches):.3g}x "
            f"({min(pitches) * 1e6:.4g} µm against {max(pitches) * 1e6:.4g} µm), more than "
            f"{MAX_PITCH_RATIO:g}x: resampling would invent the coarse scan's detail; "
            "measure both at comparable resolution"
        )
    if pitch is None:
        pitch = min(pitches)
    elif not (math.isfinite(pitch) and pitch > 0):
        raise SurfmetInputError(f"the pitch must be a positive length, got {pitch!r}")
    width = min((z.shape[1] - 1) * dx for _, z, dx, _ in parts)
    height = min((z.shape[0] - 1) * dy for _, z, _, dy in parts)
    nx = math.floor(width / pitch + 1e-9) + 1
    ny = math.floor(height / pitch + 1e-9) + 1
    if nx < 8 or ny < 8:
        raise SurfmetInputError(
            f"the common area of the scans holds only {nx} x {ny} points at pitch "
            f"{pitch:.3g} m; use larger scans or a finer pitch"
        )
    total = np.zeros((ny, nx))
    holes = np.zeros((ny, nx), dtype=bool)
    rms: dict[str, float] = {}
    for name, z, dx, dy in parts:
        zr, bad = _resample(z, dx, dy, nx, ny, pitch)
        zr = zr - zr[~bad].mean() if (~bad).any() else zr
        rms[name] = float(np.sqrt(np.mean(zr[~bad] ** 2))) if (~bad).any() else math.nan
        total += zr
        holes |= bad
    filled = float(holes.mean())
    if filled > max_filled:
        raise SurfmetInputError(
            f"{100 * filled:.1f} % of the common grid was not measured in at least one scan "
            f"(limit {100 * max_filled:.0f} %)"
        )
    if filled > 0:
        notes.append(f"{100 * filled:.2f} % of the common grid not measured; filled with the "
                     "nearest measured value")
    if len(parts) == 2:
        notes.append(f"scans resampled onto a common {nx} x {ny} grid of pitch "
                     f"{pitch * 1e6:.4g} µm")
    return PairedRoughness(
        roughness=total, dx=float(pitch), dy=float(pitch), plate_rms=rms.get("plate"),
        ball_rms=rms.get("ball"), ball_radius=ball_radius, filled_fraction=filled,
        notes=tuple(notes), fits=fits,
    )


def apex_centre(pair: PairedRoughness | None,
                offset: tuple[float, float] | None) -> tuple[float, float] | None:
    """Scan coordinates of the ball's apex displaced by ``offset`` (m) from the middle of
    the paired roughness map (a track position); None keeps the engine's default (the
    middle).

    Parameters
    ----------
    pair : PairedRoughness or None
        The paired scans.
    offset : (float, float) or None
        Displacement (x, y) of the apex from the middle of the map (m).

    Returns
    -------
    (float, float) or None
        Scan coordinates of the apex (m); None without an offset.

    Raises
    ------
    SurfmetInputError
        An offset without a scan, or one that is not two finite lengths.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.pairing import apex_centre, prepare_pair
    >>> pair = prepare_pair(surfmet.read(path("paper_plate.x3p")))
    >>> [round(v * 1e3, 4) for v in apex_centre(pair, (1e-4, 0.0))]
    [2.6575, 1.2775]
    """
    if offset is None:
        return None
    if pair is None:
        raise SurfmetInputError("a track position needs a scan (a smooth pair has no track)")
    ox, oy = (float(v) for v in offset)
    if not (math.isfinite(ox) and math.isfinite(oy)):
        raise SurfmetInputError(f"the track position must be finite, got {offset!r}")
    ny, nx = pair.roughness.shape
    return (0.5 * (nx - 1) * pair.dx + ox, 0.5 * (ny - 1) * pair.dy + oy)
