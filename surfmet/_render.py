"""3D rendering of an areal scan to a PNG with pyvista (VTK), off-screen.

Works on a machine with no display: the plotter is created with ``off_screen=True``, and
VTK falls back from X11 to EGL or OSMesa by itself (the plain pyvista/VTK wheels carry
both); the warning VTK logs on that fallback is silenced.

Large scans are decimated before rendering by NaN-aware block averaging to at most
``max_points`` vertices (a 2048 × 2048 scan becomes ~550 × 550 by default): a screen has
fewer pixels than that anyway, and VTK's software renderer stays fast. Lateral
coordinates are in µm (mm above 2 mm), heights in µm; as roughness is usually
a thousand times smaller than the scan, heights are exaggerated by a round factor
(stated in the picture) unless ``exaggeration`` is given. The exaggeration and the colour
range come from the 1–99 % height percentiles, so that spikes and a few deep pits stay
visible (as needles, in saturated colours) without flattening the rest. Non-measured
points leave holes.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography

UM = 1e-6


def decimate(topo: Topography, max_points: int) -> tuple[np.ndarray, float, float, tuple[int, int]]:
    """NaN-aware block means so that the grid holds at most ``max_points`` points.

    Returns ``(heights, dx, dy, (fy, fx))`` with the block factors used (1 = untouched).
    A block with no measured point stays NaN.
    """
    z = np.asarray(topo.heights, dtype=float)
    ny, nx = z.shape
    if max_points < 4:
        raise SurfmetInputError(f"max_points must be at least 4, got {max_points}")
    f = max(1, math.ceil(math.sqrt(nx * ny / max_points)))
    if f == 1:
        return z, topo.dx, topo.dy, (1, 1)
    my, mx = ny // f, nx // f
    if my < 2 or mx < 2:  # a very elongated scan: decimate along its long axis only
        fy = max(1, math.ceil(ny * nx / max_points)) if ny > nx else 1
        fx = max(1, math.ceil(ny * nx / max_points)) if nx >= ny else 1
    else:
        fy = fx = f
    my, mx = ny // fy, nx // fx
    blocks = z[: my * fy, : mx * fx].reshape(my, fy, mx, fx)
    valid = np.isfinite(blocks)
    n = valid.sum(axis=(1, 3))
    s = np.where(valid, blocks, 0.0).sum(axis=(1, 3))
    with np.errstate(invalid="ignore", divide="ignore"):
        out = np.where(n > 0, s / np.maximum(n, 1), np.nan)
    return out, topo.dx * fx, topo.dy * fy, (fy, fx)


def auto_exaggeration(height_range: float, lateral_extent: float, target: float = 0.25
                      ) -> float:
    """A round (1-2-5) vertical exaggeration that makes the height range about ``target``
    of the lateral extent; 1 when the relief is already that high."""
    if not (height_range > 0 and lateral_extent > 0):
        return 1.0
    f = target * lateral_extent / height_range
    if f <= 1:
        return 1.0
    e = math.floor(math.log10(f))
    for m in (5.0, 2.0, 1.0):
        if m * 10**e <= f:
            return m * 10**e
    return 10.0**e  # pragma: no cover


def _quiet_vtk() -> None:
    # With no X display VTK logs "bad X server connection" before falling back to EGL or
    # OSMesa; that line on stderr would only alarm a user.
    try:
        from vtkmodules.vtkCommonCore import vtkLogger

        vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_ERROR)
    except ImportError:  # pragma: no cover - older VTK
        pass


def render_3d(
    topo: Topography,
    path: str | Path | None = None,
    *,
    max_points: int = 300_000,
    exaggeration: float | None = None,
    cmap: str = "viridis",
    window_size: tuple[int, int] = (1200, 900),
    title: str | None = None,
    elevation: float = 35.0,
    azimuth: float = -25.0,
) -> np.ndarray:
    """Render a scan as a shaded, height-coloured 3D surface; return (and save) the image.

    Parameters
    ----------
    topo : Topography
        Heights in metres (level it first: a tilt dominates the picture).
    path : str or Path, optional
        Write a PNG there.
    max_points : int
        Decimation budget (see :func:`decimate`).
    exaggeration : float, optional
        Vertical exaggeration; default :func:`auto_exaggeration`.
    cmap : str
        Matplotlib colormap name for the heights.
    window_size : (width, height)
        Image size in pixels.
    title : str, optional
        Text in the upper left corner (default: file name, exaggeration, decimation).
    elevation, azimuth : float
        Camera angles in degrees: elevation above the scan plane; azimuth about the
        vertical, 0 looking along +y (x to the right), negative turning towards -x.

    Returns
    -------
    ndarray, shape (height, width, 3), uint8
        The rendered image.

    Raises
    ------
    SurfmetInputError
        A profile, fewer than 2 x 2 points, or no measured point.
    SurfmetError
        pyvista is not installed (``MissingExtraError``: the ``view`` extra).

    Examples
    --------
    >>> from surfmet.plots.areal import render_3d
    >>> from surfmet.synth import self_affine
    >>> topo = self_affine(64, 1e-6, hurst=0.8, h_rms=1e-7, seed=1)
    >>> render_3d(topo, window_size=(320, 240)).shape  # pyvista, off-screen
    (240, 320, 3)
    """
    if not isinstance(topo, Topography):
        raise SurfmetInputError(f"a 3D view needs an areal scan (Topography), got "
                                f"{type(topo).__name__}; plot a profile in 2D")
    if topo.nx < 2 or topo.ny < 2:
        raise SurfmetInputError(f"a 3D view needs at least 2 x 2 points, got "
                                f"{topo.nx} x {topo.ny}")
    z, dx, dy, factors = decimate(topo, max_points)
    valid = np.isfinite(z)
    if not valid.any():
        raise SurfmetInputError("the scan has no measured point")
    from surfmet._extras import require

    pv = require("pyvista", "view", "the 3D view (use --2d for a height map without it)")
    _quiet_vtk()

    ny, nx = z.shape
    lateral = max(nx * dx, ny * dy)
    unit_scale, unit = (1e-3, "mm") if lateral > 2e-3 else (UM, "µm")
    zv = z[valid]
    # robust range: a few spikes must not flatten the picture nor take the colours
    lo, hi = np.percentile(zv, [1.0, 99.0])
    zc = z - float(np.median(zv))
    if exaggeration is None:
        exaggeration = auto_exaggeration(float(hi - lo), lateral)
    if not (np.isfinite(exaggeration) and exaggeration > 0):
        raise SurfmetInputError(f"exaggeration must be positive, got {exaggeration!r}")
    xs = np.arange(nx) * dx / unit_scale
    ys = np.arange(ny) * dy / unit_scale
    X, Y = np.meshgrid(xs, ys)
    Z = np.where(valid, zc, 0.0) * exaggeration / unit_scale
    grid = pv.StructuredGrid(X, Y, Z)
    # point order of a StructuredGrid built from (ny, nx) arrays is Fortran-like over (nx, ny)
    heights_um = (zc + float(np.median(zv))) / UM
    grid.point_data["height (µm)"] = heights_um.ravel(order="F")
    if not valid.all():
        ids = np.flatnonzero(valid.ravel(order="F"))
        grid = grid.extract_points(ids, adjacent_cells=False)
    plotter = pv.Plotter(off_screen=True, window_size=list(window_size))
    try:
        plotter.set_background("white")
        plotter.add_mesh(
            grid, scalars="height (µm)", cmap=cmap, clim=(lo / UM, hi / UM), smooth_shading=True,
            show_scalar_bar=True, lighting=True,
            scalar_bar_args={"title": "height (µm)", "color": "black", "vertical": True,
                             "position_x": 0.84, "position_y": 0.15, "height": 0.7,
                             "width": 0.05, "title_font_size": max(10, int(window_size[1]) // 40),
                             "label_font_size": max(9, int(window_size[1]) // 48),
                             "unconstrained_font_size": True, "fmt": "%g"},
        )
        _round_bar_labels(plotter.scalar_bar, lo / UM, hi / UM)
        if title is None:
            from surfmet.plots._style import scan_title

            title = scan_title(topo)
        note = f"vertical exaggeration ×{exaggeration:g}; x, y in {unit}"
        if factors != (1, 1):
            note += f"; shown at {nx} × {ny} (block means of {factors[1]} × {factors[0]})"
        plotter.add_text(f"{title}\n{note}", position="upper_left",
                         font_size=max(9, int(window_size[1]) // 55),
                         color="black")
        cx, cy = xs[-1] / 2, ys[-1] / 2
        span = max(xs[-1], ys[-1])
        d = 2.1 * span
        el, az = math.radians(elevation), math.radians(azimuth)
        cam = (cx + d * math.cos(el) * math.sin(az), cy - d * math.cos(el) * math.cos(az),
               d * math.sin(el))
        plotter.camera_position = [cam, (cx, cy, 0.0), (0.0, 0.0, 1.0)]
        # fit the whole surface in view along that direction, leaving room for the bar
        plotter.reset_camera()
        plotter.camera.zoom(1.1)
        # move the picture left, clear of the colour bar on the right
        plotter.camera.SetWindowCenter(0.14, -0.02)
        img = plotter.screenshot(None, return_img=True)
    finally:
        plotter.close()
    img = np.asarray(img)[..., :3].astype(np.uint8)
    if path is not None:
        _write_png(img, Path(path))
    return img


def _round_bar_labels(bar: object, lo: float, hi: float) -> None:
    """Label the colour bar at round heights (:func:`surfmet.plots._style.round_ticks`)
    instead of at equal fractions of its 1-99 % range."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray

    from surfmet.plots._style import round_ticks

    labels = vtkDoubleArray()
    for t in round_ticks(lo, hi):
        labels.InsertNextValue(t)
    bar.SetCustomLabels(labels)
    bar.SetUseCustomLabels(True)


def _write_png(img: np.ndarray, path: Path) -> None:
    import matplotlib.image as mpimg

    from surfmet._atomic import atomic_path

    with atomic_path(path) as tmp:
        mpimg.imsave(tmp, img)
