"""Scan-level rolling resistance: the effective exponent lambda of M_r = s_r N^lambda for a
ball rolling on a scanned plate (and a scanned ball).

The scans are prepared as for every contact
(:func:`surfmet.mechanics.scan_preparation.prepare_scans`:
spikes removed, plate levelled, ball sphere removed, both paired on one grid) and the load
sweep runs in the contact engine (:func:`contact._rolling.sphere_sweep`; the models, the
choice of displacement and the exponent fit are documented in :mod:`contact._rolling`).

Its record (:func:`surfmet.records._rolling.rolling_record`) holds ``lambda_eff``,
``lambda_ci`` [lo, hi], ``loads``, ``moments``, ``local_lambda``, ``model`` and the
``settings`` used; every value is ``{"value": v, "unit": "..."}``.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet.mechanics.scan_preparation import MAX_GRID, SPIKES

if TYPE_CHECKING:
    from distributed import Client

    from contact._exponent import ExponentFit
    from contact._materials import Material
    from contact._rolling import RollingSweep
    from surfmet.mechanics._types import Loads, Materials, PathLike, ScanSource, Spikes
    from surfmet.mechanics.scan_preparation import PreparedScans

LOSSY = ("both", "plate", "ball")


@dataclass(frozen=True, eq=False)
class RollingReport:
    """Outcome of :func:`rolling_resistance`.

    Attributes
    ----------
    sweep : contact._rolling.RollingSweep
    radius : float
    ball_material, plate_material : contact._materials.Material
    scans : surfmet.mechanics.scan_preparation.PreparedScans
    notes : tuple of str

    See Also
    --------
    rolling_resistance : makes it.

    Examples
    --------
    >>> from surfmet.mechanics.rolling_resistance import rolling_resistance
    >>> report = rolling_resistance(radius=0.02, loads="1N:10N:3", grid=64)
    >>> print(report.sweep.loads, f"lambda = {report.lambda_eff:.3f}")
    [ 1.          3.16227766 10.        ] lambda = 1.334
    """

    sweep: RollingSweep
    radius: float
    ball_material: Material
    plate_material: Material
    scans: PreparedScans
    notes: tuple[str, ...]
    grid: int | None = None

    @property
    def lambda_eff(self) -> float:
        return self.sweep.lambda_eff

    @property
    def lambda_ci(self) -> tuple[float, float]:
        return self.sweep.lambda_ci

    def figure(self, path: PathLike | None = None) -> Any:
        """M_r(N) and the local exponent (:func:`surfmet.plots.hertz.rolling_figure`)."""
        from surfmet.plots.hertz import rolling_figure

        return rolling_figure(self.sweep, path)


def _load_list(loads: Loads | str) -> np.ndarray:
    from surfmet.units import parse_force
    from surfmet.value_lists import parse_values

    if isinstance(loads, str):  # the grammar of surfmet.value_lists, ascending
        loads = sorted(set(parse_values(loads, parse_force, "loads")))
    arr = np.asarray(list(loads) if not isinstance(loads, np.ndarray) else loads, dtype=float)
    if arr.ndim != 1 or arr.size < 2:
        raise SurfmetInputError("give at least two loads (or a range F1:F2[:N])")
    return arr


def rolling_resistance(
    plate: ScanSource | None = None,
    ball: ScanSource | None = None,
    *,
    radius: float,
    materials: Materials = "steel,aluminium",
    loads: Loads | str = "1N:100N:9",
    model: str = "hysteresis",
    hardness: float | None = None,
    alpha_h: float = 1.0,
    lossy: str = "both",
    kinematics: str = "rolling",
    spikes: Spikes = SPIKES,
    grid: int | None = None,
    max_grid: int | None = MAX_GRID,
    centre: tuple[float, float] | None = None,
    offset: tuple[float, float] | None = None,
    progress: Callable[[Iterable[Any]], Iterable[Any]] | None = None,
    mu: float = 0.3,
    traction_ratio: float = 0.0,
) -> RollingReport:
    """Rolling-resistance moments over a load sweep and the fitted exponent lambda.

    Parameters
    ----------
    plate, ball : Topography or path, optional
        The scans; without them the smooth (Hertz) case is computed.
    radius : float
        Ball radius R (m).
    materials : str or (Material, Material)
        ``"BALL,PLATE"``.
    loads : str or sequence of float
        ``"F1:F2[:N]"`` (N log-spaced loads, default 9) or the loads (N).
    model : {"hysteresis", "plastic"}
        Dissipation model (see :mod:`contact._rolling`).
    hardness : float, optional
        Flow pressure of the softer body (Pa; plastic model); default the materials'.
    alpha_h : float
        Hysteresis loss fraction.
    lossy : {"both", "plate", "ball"}
        The body whose hysteresis dissipates: its share of the displacement is used
        ("both": the combined displacement, both bodies losing alpha_h).
    kinematics : {"rolling", "frozen"}
        See :func:`contact._rolling.hysteresis_work`.
    spikes : {"remove", "keep"} or bool
        Remove spikes from the scans first (the default) or keep them.
    grid, max_grid : int, optional
        Contact grid settings; ``max_grid=None`` runs on the scans' own pixel at any size
        that fits in memory (native resolution).
    centre : (float, float), optional
        Apex position on the paired roughness map (m); default its middle.
    offset : (float, float), optional
        Apex position relative to the middle of the paired map (m), a track position
        (instead of ``centre``).
    progress : callable, optional
        Wraps the iterable of loads (a progress bar).
    mu, traction_ratio : float
        Microslip model (:mod:`contact.tangential._microslip`): friction coefficient and
        ``|F_x|/N`` opposing the rolling (0: free rolling).

    Returns
    -------
    RollingReport
        The sweep (loads, forces, moments), the fitted exponent ``lambda_eff`` with its
        interval ``lambda_ci``, the notes, and ``figure()`` (its record:
        :func:`surfmet.records._rolling.rolling_record`).

    Raises
    ------
    SurfmetInputError, ContactError
        Bad loads or materials, scans that cannot be paired, a solver failure.

    See Also
    --------
    contact.sphere_sweep : the engine's sweep, on arrays.
    rolling_tracks : several track positions.

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sec. 9.
    .. [2] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of Rolling
       Friction Moment on the Normal Force for Elastic Materials", Materials 15 (2022) 2518.

    Examples
    --------
    Elastic hysteresis of the paper's smooth steel ball on aluminium: the moment grows as
    the load to the power 4/3 (Johnson 1985):

    >>> from surfmet.mechanics.rolling_resistance import rolling_resistance
    >>> report = rolling_resistance(radius=0.02, loads="1N:10N:3", grid=64)
    >>> low, high = report.lambda_ci
    >>> print(f"lambda = {report.lambda_eff:.3f}, 95 % CI {low:.3f}..{high:.3f}")
    lambda = 1.334, 95 % CI 1.331..1.338
    """
    from contact._rolling import MODELS, sphere_sweep
    from contact.setups import CompositeRoughness
    from surfmet.mechanics.material_spec import material_pair, parse_materials
    from surfmet.mechanics.scan_preparation import prepare_scans
    from surfmet.units import parse_length

    radius = parse_length(radius) if isinstance(radius, str) else float(radius)
    if not (math.isfinite(radius) and radius > 0):
        raise SurfmetInputError(f"the ball radius must be a positive length, got {radius!r}")
    if model not in (*MODELS, "microslip"):
        raise SurfmetInputError(f"model must be one of {(*MODELS, 'microslip')}, got {model!r}")
    if lossy not in LOSSY:
        raise SurfmetInputError(f"lossy must be one of {LOSSY}, got {lossy!r}")
    mats = material_pair(materials)
    ball_m, plate_m = parse_materials(mats)
    if model == "plastic":
        # the one home of the default hardness (contact._material_pair.resolve_pair): the
        # user's, else the softer body's table value
        hardness = mats.with_hardness(hardness).hardness
        if hardness is None:
            raise SurfmetInputError("the plastic model needs a hardness: give --hardness or "
                                    "a material with H=...")
    share = 1.0
    if lossy != "both":
        shares = mats.shares
        share = shares[0] if lossy == "ball" else shares[1]
    w = _load_list(loads)
    prep = prepare_scans(plate, ball, spikes=spikes)
    pair = prep.pair
    if offset is not None:
        from surfmet.mechanics.pairing import apex_centre

        centre = apex_centre(pair, offset)
    if model == "microslip":
        from contact.tangential._microslip import microslip_sweep

        sweep = microslip_sweep(
            radius, ball_m, plate_m, w, mu, traction_ratio=traction_ratio,
            roughness=None if pair is None else (pair.roughness, pair.dx, pair.dy),
            grid=grid or 32, progress=progress)
    else:
        from contact import Dissipation, DomainSpec

        sweep = sphere_sweep(
            radius, mats, w,
            dissipation=Dissipation(model=model, hardness=hardness, alpha_h=alpha_h,
                                    share=share, kinematics=kinematics,
                                    roughness_rms=prep.sigma),
            roughness=None if pair is None else CompositeRoughness(
                pair.roughness, pair.dx, pair.dy, centre=centre),
            domain=DomainSpec(grid=grid, max_grid=max_grid), progress=progress,
        )
    notes = [*(n for n in prep.notes if pair is not None), *sweep.notes]
    return RollingReport(sweep=sweep, radius=radius, ball_material=ball_m,
                         plate_material=plate_m, scans=prep, notes=tuple(notes), grid=grid)


@dataclass(frozen=True)
class TrackJob:
    """One track position of :func:`rolling_tracks`: the arguments of
    :func:`rolling_resistance` (scans as paths, so that the job pickles small).

    Attributes
    ----------
    plate, ball : Topography, path or None
        The scans.
    offset : (float, float) or None
        The track position (m from the middle of the paired map).
    options : tuple of (str, value)
        The other keyword arguments of :func:`rolling_resistance`.

    See Also
    --------
    track_moments : runs it.

    Examples
    --------
    >>> from surfmet.mechanics.rolling_resistance import TrackJob, track_moments
    >>> job = TrackJob(None, None, None, (("radius", 0.02), ("loads", "1N:10N:3"), ("grid", 64)))
    >>> print(f"lambda = {track_moments(job)['lambda']:.3f}")
    lambda = 1.334
    """

    plate: ScanSource | None
    ball: ScanSource | None
    offset: tuple[float, float] | None
    options: tuple[tuple[str, Any], ...]


def track_moments(job: TrackJob) -> dict[str, Any]:
    """Moments of one track position (a top-level function, for worker processes).

    Parameters
    ----------
    job : TrackJob
        The scans, the track position and the options.

    Returns
    -------
    dict
        ``offset``, ``loads``, ``moments``, ``lambda``, ``grid``, ``dx``, ``notes`` and
        ``error`` (None, or the one line of a failed position).

    See Also
    --------
    rolling_tracks

    Examples
    --------
    >>> from surfmet.mechanics.rolling_resistance import TrackJob, track_moments
    >>> job = TrackJob(None, None, None, (("radius", 0.02), ("loads", "1N:10N:3"), ("grid", 64)))
    >>> sorted(track_moments(job))
    ['dx', 'error', 'grid', 'lambda', 'loads', 'moments', 'notes', 'offset']
    """
    rep = rolling_resistance(job.plate, job.ball, offset=job.offset, **dict(job.options))
    s = rep.sweep
    return {"offset": job.offset, "loads": np.asarray(s.loads), "moments": np.asarray(s.moments),
            "lambda": float(s.lambda_eff) if s.fit is not None else math.nan,
            "grid": s.settings.get("grid"), "dx": s.settings.get("dx"),
            "notes": tuple(rep.notes), "error": None}


def _track_error(job: TrackJob, message: str) -> dict[str, Any]:
    return {"offset": job.offset, "error": message}


@dataclass(frozen=True, eq=False)
class TrackReport:
    """Rolling resistance over several track positions (:func:`rolling_tracks`).

    Attributes
    ----------
    tracks : tuple of dict
        Per position: ``offset`` (m), ``loads`` (N), ``moments`` (N m), ``lambda``, or
        ``error`` for a position that failed.
    loads : ndarray
        The loads (N).
    mean_moments : ndarray
        Mean moment over the positions that succeeded (N m), summed in position order.
    fit : contact._exponent.ExponentFit or None
        Power law fitted to the mean moments (None with fewer than 3 dissipating loads).

    See Also
    --------
    rolling_tracks : makes it.

    Examples
    --------
    >>> from surfmet.mechanics.rolling_resistance import rolling_tracks
    >>> report = rolling_tracks(positions=[None, None], workers=1, radius=0.02,
    ...                         loads="1N:10N:3", grid=64)
    >>> len(report.tracks), f"{report.fit.exponent:.3f}"
    (2, '1.334')
    """

    tracks: tuple[dict[str, Any], ...]
    loads: np.ndarray
    mean_moments: np.ndarray
    fit: ExponentFit | None

    @property
    def lambda_eff(self) -> float:
        return float(self.fit.exponent) if self.fit is not None else math.nan



def rolling_tracks(plate: ScanSource | None = None, ball: ScanSource | None = None, *,
                   positions: Sequence[tuple[float, float] | None],
                   workers: int | None = None, scheduler: str | Client | None = None,
                   progress: bool | None = None, **options: Any) -> TrackReport:
    """:func:`rolling_resistance` at several track positions, in parallel, and the exponent
    of the mean moment.

    Each position's warm-started load sweep is one item of :func:`surfmet._batch.batch_map`
    (local processes by default, a Dask cluster with ``scheduler``), so the moments are
    bitwise those of the serial run (``workers=1``). A position that fails keeps its error
    in ``tracks`` and is left out of the mean.

    Returns
    -------
    TrackReport
        Every position's moments (``tracks``), the mean moments and their exponent fit.

    Raises
    ------
    SurfmetInputError
        No position, or every position failed (the first error is named).

    See Also
    --------
    rolling_resistance : one position.
    surfmet._batch.batch_map : the parallel map.

    Examples
    --------
    Two positions of a smooth pair give the same moments, so their mean has the Hertz
    exponent 4/3:

    >>> from surfmet.mechanics.rolling_resistance import rolling_tracks
    >>> report = rolling_tracks(positions=[None, None], workers=1, radius=0.02,
    ...                         loads="1N:10N:3", grid=64)
    >>> print(len(report.tracks), f"lambda = {report.fit.exponent:.3f}")
    2 lambda = 1.334
    """
    from contact._exponent import fit_exponent
    from surfmet._batch import batch_map

    if not positions:
        raise SurfmetInputError("give at least one track position")
    jobs = [TrackJob(plate=plate, ball=ball, offset=None if pos is None else
                     (float(pos[0]), float(pos[1])),
                     options=tuple(sorted(options.items()))) for pos in positions]
    tracks = batch_map(track_moments, jobs, workers=workers, scheduler=scheduler,
                       on_error=_track_error, progress=progress, desc="track positions")
    good = [t for t in tracks if not t.get("error")]
    if not good:
        raise SurfmetInputError(f"every track position failed: {tracks[0]['error']}")
    loads = good[0]["loads"]
    total = np.zeros_like(loads)
    for t in good:  # a fixed order: the same sum whatever the engine
        total = total + t["moments"]
    mean = total / len(good)
    dissipating = mean > 0
    fit = (fit_exponent(loads[dissipating], mean[dissipating])
           if np.count_nonzero(dissipating) >= 3 else None)
    return TrackReport(tracks=tuple(tracks), loads=loads, mean_moments=mean, fit=fit)
