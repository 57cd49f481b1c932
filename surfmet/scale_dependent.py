"""Scale-dependent roughness of one surface from several measurements.

What contact.engineering computes for a surface (Sanner et al. 2022, Appl. Surf. Sci. Adv.
7:100190; SurfaceTopography 1.27's ``Container/ScaleDependentStatistics.py``): every
measurement gives its scale-dependent rms slope and curvature, height-difference
autocorrelation, variable-bandwidth rms height and 1D PSD over the scales it resolves
reliably; the surface's value at a scale is the mean over the measurements that contribute
there, each with one equal vote.

Rules (the engine's definitions are in :mod:`profiles._scales`):

* distance grid ``10^(j/N)`` m (``N`` points per decade), whole decades included, from the
  shortest to the longest scale any measurement resolves;
* a measurement contributes to a derivative of order ``n`` at distance ``d`` when
  ``n · max(pixel, cut-off) < d < size`` (the peer's container rule);
* the reliability cut-off comes from the probe: the tip radius that the file states, else
  ``tip_radius=`` (``--tip-radius``), through :func:`profiles._scales.tip_cutoff`; without
  a radius there is no cut-off (stated as such);
* direction (``direction=``, ``--direction``): the derivatives of a map are taken along x
  (the rows; the default, the one SurfaceTopography's tests of maps use), along y (the
  columns: the map is transposed, for every statistic), or along ``both`` axes: as
  SurfaceTopography hands the statistic the x and the y derivative, the two axes'
  variances are added (for the slope, the rms of the gradient |∇h|, as Sdq is; for the
  curvature, of (h_xx, h_yy)) and the ACF and rms height are the mean of the two axes';
  each axis' reliability cut-off is its own, the larger one stated. Profiles are always
  taken along their length;
* PSD (along x; along y with ``direction="y"``; with ``both`` along x, as contact.engineering
  averages a map's rows): averaged as contact.engineering averages it
  (:mod:`surfmet._averaged_psd`): each measurement's 1D PSD on its own DFT wavevectors (periodic
  Hann window, levelled as the container states; maps: mean of the rows; nonuniform profiles:
  their piecewise-linear curve, 5x oversampled), kept below ``2π/cut-off``, bin-averaged in log
  bins of q of its own decades and averaged over the measurements with data in each bin (equal
  votes, abscissas averaged too); ``q`` and ``psd`` are on those bins (10 per decade by
  default), not on the distance grid; variable-bandwidth rms height is interpolated log-log onto
  the distance grid and averaged likewise.

Bad input (one :class:`~surfmet._errors.SurfmetInputError` line each): a tip radius that
leaves no reliable scale in any measurement, and measurements whose reliable bandwidths
leave a gap (no overlap: measurements of different surfaces, or of the same surface with a
hole in scale that the average would hide).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from profiles._scales import (
    Scan,
    height_difference_acf,
    make_scan,
    scale_variance,
    tip_cutoff,
    variable_bandwidth,
)
from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography

#: The axes a map's derivatives may be taken along (module notes).
DIRECTIONS = ("x", "y", "both")
#: What each direction means, in words (text and JSON state it).
DIRECTION_WORDS = {
    "x": "along x (rows); profiles along their length",
    "y": "along y (columns); profiles along their length",
    "both": "along x and y: slope and curvature variances of the two axes added "
            "(rms gradient), ACF, rms height and PSD the mean of the two; profiles along "
            "their length",
}
_EDGE = 1e-9  # relative margin on the grid's bandwidth tests (floating noise at decades)


@dataclass(frozen=True)
class Measurement:
    """One measurement's scale-dependent curves on the common grid (NaN where it does not
    contribute) and how its reliability cut-off was found."""

    file: str
    kind: str
    pixel: float
    size: float
    cutoff: float | None
    cutoff_source: str
    tip_radius: float | None
    variance_slope: np.ndarray = field(repr=False)
    variance_curvature: np.ndarray = field(repr=False)
    acf: np.ndarray = field(repr=False)
    vbm: np.ndarray = field(repr=False)
    psd: np.ndarray = field(repr=False)

    @property
    def reliable_from(self) -> float:
        """Shortest distance the slope may be taken over (m)."""
        return max(self.pixel, self.cutoff or 0.0)


@dataclass(frozen=True)
class ScaleAnalysis:
    """The surface's averaged scale-dependent statistics and each measurement's share."""

    distance: np.ndarray
    rms_slope: np.ndarray
    rms_curvature: np.ndarray
    acf: np.ndarray
    vbm_rms_height: np.ndarray
    q: np.ndarray
    psd: np.ndarray
    measurements: tuple[Measurement, ...]
    per_decade: int
    psd_per_decade: int = 10
    direction: str = "x"

    def contributors(self, quantity: str = "slope") -> np.ndarray:
        """Boolean (measurements x distances): who votes where."""
        key = {"slope": "variance_slope", "curvature": "variance_curvature", "acf": "acf",
               "vbm": "vbm", "psd": "psd"}[quantity]
        return np.array([np.isfinite(getattr(m, key)) for m in self.measurements])

    def psd_band(self) -> tuple[float, float] | None:
        """(q_min, q_max) rad/m over which the averaged PSD is measured."""
        good = np.isfinite(self.psd)
        if not good.any():
            return None
        return float(self.q[good].min()), float(self.q[good].max())


def level_as_stated(m: Profile | Topography) -> Profile | Topography:
    """Apply the measurement's ``metadata["detrend_mode"]`` (a container's ``meta.yml``):
    ``center`` the mean, ``height`` a least-squares line or plane, ``curvature`` a
    least-squares quadratic; nothing for a scan that states none."""
    mode = m.metadata.get("detrend_mode")
    degree = {"center": 0, "height": 1, "curvature": 2}.get(mode or "")
    if degree is None:
        if mode not in (None, "", "none"):
            raise SurfmetInputError(f"detrend_mode {mode!r} (center, height or curvature "
                                    "expected)")
        return m
    if isinstance(m, Profile):
        from profiles._form import remove_form

        return m.replace(z=remove_form(m.z, m.dx, x=m.x, degree=degree).residuals)
    from surfmet.areal._form import remove_form as remove_areal_form

    return remove_areal_form(m, {0: "mean", 1: "plane", 2: "poly:2"}[degree])[0]


def to_scan(m: Profile | Topography) -> Scan:
    """The engine's view of a measurement (SI arrays)."""
    if isinstance(m, Topography):
        return make_scan(m.heights, m.dx, m.dy)
    return make_scan(m.z, m.dx, x=m.x)


def distance_grid(lower: float, upper: float, per_decade: int) -> np.ndarray:
    """``10^(j/N)`` m from the decade below ``lower`` to the decade above ``upper``."""
    if per_decade < 1:
        raise SurfmetInputError(f"--per-decade must be at least 1, got {per_decade}")
    j0 = math.floor(math.log10(lower)) * per_decade
    j1 = math.ceil(math.log10(upper)) * per_decade
    return 10.0 ** (np.arange(j0, j1 + 1) / per_decade)


def _inside(d: np.ndarray, low: float, high: float) -> np.ndarray:
    return (d > low * (1 + _EDGE)) & (d < high * (1 - _EDGE))


def _cutoff(m: Profile | Topography, scan: Scan, tip_radius: float | None
            ) -> tuple[float | None, str, float | None]:
    stated = (m.metadata.get("tip_radius") or {}).get("value")
    radius, source = (stated, "file") if stated else (tip_radius, "--tip-radius")
    if not radius:
        return None, "no tip radius", None
    return tip_cutoff(scan, float(radius)), f"tip radius from {source}", float(radius)


def measurement_spectrum(m: Profile | Topography, scan: Scan, cutoff: float | None
                     ) -> tuple[np.ndarray, np.ndarray]:
    """The measurement's reliable 1D PSD on its own wavevectors
    (:func:`surfmet._averaged_psd.measurement_psd`, levelled as its container states)."""
    from surfmet._averaged_psd import measurement_psd

    mode = str(m.metadata.get("detrend_mode") or "")
    degree = {"center": 0, "height": 1, "curvature": 2}.get(mode)
    return measurement_psd(scan, cutoff, degree=degree, centre=mode == "")


def _vbm_on_grid(scan: Scan, d: np.ndarray, shortest: float) -> np.ndarray:
    widths, rms = variable_bandwidth(scan)
    order = np.argsort(widths)
    widths, rms = widths[order], rms[order]
    out = np.full(d.size, np.nan)
    sel = (d >= max(widths.min(), shortest)) & (d <= widths.max()) & np.isfinite(d)
    if sel.any() and (rms > 0).all():
        out[sel] = np.exp(np.interp(np.log(d[sel]), np.log(widths), np.log(rms)))
    return out


def along_y(m: Topography) -> Topography:
    """The map transposed (its columns as rows), so that 'along x' reads along y."""
    return m.replace(heights=m.heights.T, dx=m.dy, dy=m.dx)


def _measure(m: Profile | Topography, d: np.ndarray, tip_radius: float | None,
             direction: str = "x") -> Measurement:
    if isinstance(m, Topography) and direction == "y":
        return _measure(along_y(m), d, tip_radius)
    if isinstance(m, Topography) and direction == "both":
        return _both_axes(_measure(m, d, tip_radius), _measure(along_y(m), d, tip_radius))
    scan = to_scan(m)
    pixel, size = scan.bandwidth()
    cut, source, radius = _cutoff(m, scan, tip_radius)
    low = max(pixel, cut or 0.0)
    vs, vc, acf = (np.full(d.size, np.nan) for _ in range(3))
    s1, s2 = _inside(d, low, size), _inside(d, 2 * low, size)
    if s1.any():
        vs[s1] = scale_variance(scan, d[s1], 1)
        acf[s1] = height_difference_acf(scan, d[s1])
    if s2.any():
        vc[s2] = scale_variance(scan, d[s2], 2)
    name = str(m.metadata.get("member") or m.metadata.get("source") or "<scan>")
    kind = "map" if scan.is_map else ("profile" if scan.x is None else "nonuniform profile")
    return Measurement(name, kind, pixel, size, cut, source, radius, vs, vc, acf,
                       _vbm_on_grid(scan, d, low), measurement_spectrum(m, scan, cut))


def _both_axes(mx: Measurement, my: Measurement) -> Measurement:
    """One map's statistics along both axes from those along x and along y (module
    notes): variances added, the ACF and rms height averaged, the PSD that along x;
    the larger cut-off stated."""
    cuts = [c for c in (mx.cutoff, my.cutoff) if c is not None]
    cut = max(cuts) if cuts else None
    source = my.cutoff_source if cut is not None and cut == my.cutoff else mx.cutoff_source
    return Measurement(mx.file, mx.kind, mx.pixel, mx.size, cut, source, mx.tip_radius,
                       mx.variance_slope + my.variance_slope,
                       mx.variance_curvature + my.variance_curvature,
                       0.5 * (mx.acf + my.acf), 0.5 * (mx.vbm + my.vbm),
                       mx.psd)  # the PSD along x: contact.engineering's average of rows


def _check_overlap(ms: list[Measurement]) -> None:
    live = [m for m in ms if m.reliable_from < m.size]
    if not live:
        worst = ms[0]
        raise SurfmetInputError(
            f"the tip radius leaves no reliable scale: {worst.file}'s cut-off "
            f"{worst.cutoff:.4g} m is not below its size {worst.size:.4g} m"
            if worst.cutoff is not None else f"{worst.file}: no reliable scale")
    spans = sorted((m.reliable_from, m.size, m.file) for m in live)
    reach = spans[0][1]
    for lo, hi, name in spans[1:]:
        if lo >= reach:
            raise SurfmetInputError(
                f"no overlapping bandwidth: {name} resolves {lo:.4g}–{hi:.4g} m but the "
                f"measurements below it reach only {reach:.4g} m (different surfaces?)")
        reach = max(reach, hi)


def _mean(values: list[np.ndarray]) -> np.ndarray:
    stack = np.array(values)
    count = np.isfinite(stack).sum(axis=0)
    total = np.nansum(stack, axis=0)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(count > 0, total / np.maximum(count, 1), np.nan)


def analyze_scales(scans: list[Profile | Topography], *, tip_radius: float | None = None,
                   per_decade: int = 5, psd_per_decade: int | None = None,
                   direction: str = "x") -> ScaleAnalysis:
    """Scale-dependent statistics of one surface measured by ``scans``.

    Parameters
    ----------
    scans : list of Profile or Topography
        The measurements; each is first levelled as its metadata's ``detrend_mode`` says
        (containers state it per measurement; plain files state none and are used as read:
        the statistics do not depend on a tilt).
    tip_radius : float, optional
        Probe radius (m) for the measurements whose file states none.
    per_decade : int
        Points per decade of the distance grid.
    psd_per_decade : int, optional
        Bins per decade of q of the averaged PSD, independent of the distance grid
        (default :data:`surfmet._averaged_psd.PSD_PER_DECADE`, contact.engineering's).
    direction : {"x", "y", "both"}
        The axis (or axes) a map's derivatives are taken along (module notes); profiles
        are taken along their length whatever it is.

    Raises
    ------
    SurfmetInputError
        No scan, a tip radius masking everything, a gap between bandwidths, or an
        unknown direction.
    """
    if direction not in DIRECTIONS:
        raise SurfmetInputError(f"unknown direction {direction!r}: use x, y or both")
    if not scans:
        raise SurfmetInputError("no measurement to analyse")
    if tip_radius is not None and not (math.isfinite(tip_radius) and tip_radius > 0):
        raise SurfmetInputError(f"--tip-radius must be a positive length, got {tip_radius!r}")
    scans = [level_as_stated(s) for s in scans]
    bands = [to_scan(s).bandwidth() for s in scans]
    d = distance_grid(min(b[0] for b in bands), max(b[1] for b in bands), per_decade)
    ms = [_measure(s, d, tip_radius, direction) for s in scans]
    _check_overlap(ms)
    from surfmet._averaged_psd import PSD_PER_DECADE, average_psd

    if psd_per_decade is not None and psd_per_decade < 1:
        raise SurfmetInputError(f"PSD bins per decade must be at least 1, got {psd_per_decade}")
    spec = average_psd([m.psd for m in ms], psd_per_decade or PSD_PER_DECADE)
    ms = [replace(m, psd=c) for m, c in zip(ms, spec.per_measurement)]
    vs = _mean([m.variance_slope for m in ms])
    vc = _mean([m.variance_curvature for m in ms])
    return ScaleAnalysis(d, np.sqrt(vs), np.sqrt(vc), _mean([m.acf for m in ms]),
                         _mean([m.vbm for m in ms]), spec.q, spec.C, tuple(ms), per_decade,
                         spec.per_decade, direction)
