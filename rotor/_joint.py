"""Fits of the joint law of motion (:mod:`rotor._track`) to all launches of a table.

The pipeline (:func:`fit_table`):

1. a robust fit (soft-L1 loss) of a flexible shared track, from which each launch's reading
   noise (:func:`rotor._noise.estimate_noise`, Student-t) and its misread rows (off by
   more than :data:`~rotor._misreads.MISREAD_THRESHOLD` sigmas and
   :data:`~rotor._misreads.MISREAD_MIN_FRAMES` frames) are read;
2. the track's degree by BIC among shared tracks, weighted by that noise;
3. the group-specific tracks of the same degree, for the shared-track test;
4. the group offset from the shared fit's per-launch offsets: its uncertainty is the larger of
   the between-launch scatter (pooled within groups, so it holds the launch-to-launch spread)
   and the fit's own, with Student's t on ``launches - groups`` degrees of freedom.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares
from scipy.stats import t as student_t

from contact._errors import ContactInputError
from rotor._analysis import prepare_column
from rotor._misreads import MISREAD_MIN_FRAMES, MISREAD_THRESHOLD
from rotor._noise import Noise, estimate_noise, quantisation_sigma
from rotor._track import TrackLayout, track_acceleration, track_times

__all__ = ["DEGREES", "GroupOffset", "JointFit", "TableData", "fit_table", "group_offset",
           "groupwise_fit", "lane_f", "launchwise_fit", "local_accelerations", "prepare_table",
           "shared_track_f"]

DEGREES = (1, 2, 3, 4, 5, 6, 8)
"""Track degrees the BIC chooses among (1: a linear trend of the slope; more: waviness)."""
_FLEX = max(DEGREES)


@dataclass(frozen=True)
class TableData:
    """The launches of a table, padded to a common number of rows.

    ``angles``/``times`` (launches, K): rad from each launch's first mark and s from it;
    ``mask``: real entries; ``names``, ``group_names``; ``group_of_launch``: index into
    ``group_names``; ``span``: the track span (rad) the series is defined on.
    """

    names: tuple[str, ...]
    group_names: tuple[str, ...]
    group_of_launch: np.ndarray
    angles: np.ndarray
    times: np.ndarray
    mask: np.ndarray
    k: np.ndarray
    fps: float
    step: float

    @property
    def span(self) -> float:
        return float(np.max(self.angles) + self.step)


@dataclass(frozen=True)
class JointFit:
    """One fitted joint model: ``shared`` track or group-specific ones, of ``degree``."""

    layout: TrackLayout
    x: np.ndarray
    cov: np.ndarray
    residuals: np.ndarray
    sigma: np.ndarray
    used: np.ndarray
    chi2: float
    n_used: int

    @property
    def shared(self) -> bool:
        return self.layout.n_tracks == 1

    @property
    def bic(self) -> float:
        return self.chi2 + self.layout.n_params * math.log(self.n_used)

    def acceleration(self, launch: int, s: np.ndarray) -> np.ndarray:
        """Model acceleration of one launch at track positions ``s`` (rad), rad/s²."""
        beta, delta, _, _ = self.layout.split(self.x)
        return delta[launch] + track_acceleration(
            s, beta[self.layout.track_of_launch()[launch]], self.layout.span)


@dataclass(frozen=True)
class GroupOffset:
    """``minuend - subtrahend`` of the groups' mean launch offsets, rad/s².

    ``stderr`` holds the launch-to-launch spread; ``ci_low``/``ci_high`` at ``level`` use
    Student's t on ``dof`` degrees of freedom. ``launch_sd``: the pooled within-group standard
    deviation of the launch offsets (rad/s²); ``fit_stderr``: the fit's own standard error.

    See Also
    --------
    group_offset : builds it.

    Examples
    --------
    >>> import numpy as np
    >>> from rotor import fit_table, group_offset, prepare_table, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> data = prepare_table(table3(), groups, 120.0, np.pi / 2)
    >>> shared, groupwise = fit_table(data)
    >>> off = group_offset(data, shared)
    >>> print(off.minuend, off.subtrahend, off.dof, f"t = {off.t_statistic:.1f}")
    as s 4 t = -6.7
    """

    minuend: str
    subtrahend: str
    value: float
    stderr: float
    ci_low: float
    ci_high: float
    level: float
    dof: int
    launch_sd: float
    fit_stderr: float

    @property
    def t_statistic(self) -> float:
        return self.value / self.stderr if self.stderr > 0 else math.inf


def prepare_table(columns: Mapping[str, Sequence[float]], groups: Mapping[str, Sequence[str]],
                  fps: float, step: float, k: Sequence[int] | None = None) -> TableData:
    """Check and pad the launches named by ``groups`` ({group: [columns]}); ``k``: the row
    numbers of the table (default 1, 2, ...; a missing reading is NaN).

    Parameters
    ----------
    columns : Mapping of str to sequence of float
        Frame indices of each launch.
    groups : Mapping of str to sequence of str
        ``{group: its columns}``, at least two columns per group.
    fps, step : float
        Frame rate (1/s) and the angle between marks (rad).
    k : sequence of int, optional
        The row numbers.

    Returns
    -------
    TableData
        The launches' times (s) and angles (rad), padded to a common number of rows.

    Raises
    ------
    ContactInputError
        A group of fewer than two launches, a column the table lacks, a column of fewer
        than 6 readings or whose frame indices do not increase, or a non-positive ``fps`` or
        ``step``.

    See Also
    --------
    fit_table, judge_table

    Examples
    --------
    >>> import numpy as np
    >>> from rotor import prepare_table, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> data = prepare_table(table3(), groups, 120.0, np.pi / 2)
    >>> data.group_names, data.angles.shape, f"{data.angles.max():.2f} rad"
    (('s', 'as'), (6, 25), '37.70 rad')
    """
    names, gidx, rows = [], [], []
    for gi, (gname, cols) in enumerate(groups.items()):
        if len(cols) < 2:
            raise ContactInputError(
                f"group {gname!r} has {len(cols)} launch; the joint model needs at least 2 "
                f"per group to measure the launch-to-launch spread")
        for c in cols:
            if c not in columns:
                raise ContactInputError(f"group {gname!r} names column {c!r}, which the table "
                                        f"lacks (it has {', '.join(columns)})")
            _, kk, t, a = prepare_column(c, columns[c], k, fps, step)
            names.append(c)
            gidx.append(gi)
            rows.append((kk, t, a))
    n_k = max(r[1].size for r in rows)
    shape = (len(rows), n_k)
    angles, times, k = np.zeros(shape), np.zeros(shape), np.zeros(shape, dtype=int)
    mask = np.zeros(shape, dtype=bool)
    for i, (kk, t, a) in enumerate(rows):
        n = t.size
        angles[i, :n], times[i, :n], k[i, :n], mask[i, :n] = a, t, kk, True
        angles[i, n:], times[i, n:], k[i, n:] = a[-1], t[-1], kk[-1]
    return TableData(tuple(names), tuple(groups), np.asarray(gidx), angles, times, mask, k,
                     float(fps), float(step))


def _start(data: TableData, layout: TrackLayout, prev: JointFit | None) -> np.ndarray:
    """Starting parameters: from a previous fit where it has them, else constant
    accelerations from each launch's last mark."""
    n = layout.n_launches
    x = np.zeros(layout.n_params)
    nb = layout.n_tracks * layout.degree
    if prev is not None:
        beta, delta, phi0, t0 = prev.layout.split(prev.x)
        m = min(prev.layout.degree, layout.degree)
        for tr in range(layout.n_tracks):
            x[tr * layout.degree : tr * layout.degree + m] = beta[min(tr, beta.shape[0] - 1), :m]
        x[nb:] = np.concatenate([delta, phi0, t0])
        return x
    last = np.array([np.flatnonzero(r)[-1] for r in data.mask])
    a_end = data.angles[np.arange(n), last] + 0.5 * data.step
    x[nb : nb + n] = 2.0 * a_end / np.maximum(data.times[np.arange(n), last], 1e-3) ** 2
    x[nb + n : nb + 2 * n] = -0.5 * data.step
    x[nb + 2 * n :] = -np.sqrt(2 * 0.5 * data.step / x[nb : nb + n])
    return x


def _fit(data: TableData, layout: TrackLayout, sigma: np.ndarray, used: np.ndarray,
         x0: np.ndarray, loss: str = "linear") -> JointFit:
    """Weighted least squares of the crossing times over the ``used`` entries."""
    w = np.where(used, 1.0 / sigma, 0.0)
    nb = layout.n_tracks * layout.degree
    n = layout.n_launches
    lo = np.full(layout.n_params, -np.inf)
    hi = np.full(layout.n_params, np.inf)
    lo[nb + n : nb + 2 * n] = -data.step
    hi[nb + n : nb + 2 * n] = -1e-6
    x0 = np.clip(x0, lo + 1e-9, hi - 1e-12)

    def fun(x: np.ndarray) -> np.ndarray:
        return ((track_times(x, layout, data.angles, data.mask)[0] - data.times) * w).ravel()

    def jac(x: np.ndarray) -> np.ndarray:
        j = track_times(x, layout, data.angles, data.mask, jacobian=True)[1]
        return (j * w[..., None]).reshape(-1, layout.n_params)

    res = least_squares(fun, x0, jac=jac, bounds=(lo, hi), loss=loss, f_scale=3.0,
                        x_scale="jac", max_nfev=100)
    r = track_times(res.x, layout, data.angles, data.mask)[0] - data.times
    jw = jac(res.x)
    try:
        cov = np.linalg.pinv(jw.T @ jw)
    except np.linalg.LinAlgError:
        cov = np.full((layout.n_params, layout.n_params), np.nan)
    chi2 = float(np.sum((r * w) ** 2))
    return JointFit(layout, res.x, cov, np.where(data.mask, r, 0.0), sigma, used, chi2,
                    int(used.sum()))


def _noise_and_misreads(data: TableData, fit: JointFit) -> tuple[np.ndarray, np.ndarray]:
    """Each launch's reading noise (robust) and the rows it leaves out as misread."""
    sq = quantisation_sigma(data.fps)
    sigma = np.full(data.times.shape, sq)
    used = data.mask.copy()
    for i in range(data.times.shape[0]):
        rows = np.flatnonzero(data.mask[i])
        s = data.angles[i, rows] - fit.layout.split(fit.x)[2][i]
        omega = np.sqrt(2.0 * np.maximum(_u_of(fit, i, s), 1e-12))
        eps0 = float(fit.acceleration(i, np.zeros(1))[0])
        noise: Noise = estimate_noise(fit.residuals[i, rows[1:]], omega[1:], eps0, sq,
                                      robust=True)
        sig = noise.sigma(omega, eps0, origin=0)
        sigma[i, rows] = sig
        bad = (np.abs(fit.residuals[i, rows]) > MISREAD_THRESHOLD * sig) & (
            np.abs(fit.residuals[i, rows]) * data.fps > MISREAD_MIN_FRAMES)
        bad[0] = False  # the first row is the time origin: a misread there is a start offset
        used[i, rows[bad]] = False
    return sigma, used


def _u_of(fit: JointFit, launch: int, s: np.ndarray) -> np.ndarray:
    """``phi'^2 / 2`` of one launch at track positions ``s``, by quadrature of the model."""
    grid = np.linspace(0.0, float(np.max(s)) if s.size else 0.0, 2001)
    acc = fit.acceleration(launch, grid)
    u = np.concatenate([[0.0], np.cumsum(0.5 * (acc[1:] + acc[:-1]) * np.diff(grid))])
    return np.interp(s, grid, u)


def fit_table(data: TableData, degree: int | None = None,
              exclude: np.ndarray | None = None) -> tuple[JointFit, JointFit]:
    """The shared-track fit of the BIC's degree (or ``degree``) and the group-specific fit
    of the same degree, with the noise and misread rows of a flexible robust fit;
    ``exclude`` (launches, K; True: leave out) leaves further rows out (another misread
    rule's, to see what the rule changes).

    Parameters
    ----------
    data : TableData
        The launches (:func:`prepare_table`).
    degree : int, optional
        The track's Legendre degree (default: the BIC's choice).
    exclude : numpy.ndarray of bool, optional
        Further rows to leave out (launches, K).

    Returns
    -------
    shared, groupwise : JointFit
        One track for all launches, and one track per group.

    See Also
    --------
    shared_track_f, group_offset, track_acceleration

    Examples
    --------
    >>> import numpy as np
    >>> from rotor import fit_table, prepare_table, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> data = prepare_table(table3(), groups, 120.0, np.pi / 2)
    >>> shared, groupwise = fit_table(data)
    >>> shared.shared, groupwise.shared, shared.layout.degree, shared.n_used
    (True, False, 4, 146)
    >>> bool(groupwise.chi2 < shared.chi2)
    True
    """
    n_groups = len(data.group_names)
    span = data.span
    sq = quantisation_sigma(data.fps)
    flex = TrackLayout(span, _FLEX, data.group_of_launch, 1)
    base = TrackLayout(span, 1, data.group_of_launch, 1)
    first = _fit(data, base, np.full(data.times.shape, sq), data.mask, _start(data, base, None),
                 loss="soft_l1")
    rough = _fit(data, flex, np.full(data.times.shape, sq), data.mask,
                 _start(data, flex, first), loss="soft_l1")
    sigma, used = _noise_and_misreads(data, rough)
    if exclude is not None:
        used = used & ~np.asarray(exclude, dtype=bool)
    fits: list[JointFit] = []
    prev = first
    for m in (DEGREES if degree is None else (degree,)):
        lay = TrackLayout(span, m, data.group_of_launch, 1)
        prev = _fit(data, lay, sigma, used, _start(data, lay, prev))
        fits.append(prev)
    shared = min(fits, key=lambda f: f.bic)
    return shared, groupwise_fit(data, shared, data.group_of_launch, n_groups)


def groupwise_fit(data: TableData, shared: JointFit, group_of_launch: np.ndarray,
                  n_groups: int) -> JointFit:
    """Group-specific tracks of the shared fit's degree for the labels ``group_of_launch``
    (the table's own, or a relabelling for a permutation test), with the shared fit's
    noise and misread rows: the labels are the only thing that changes."""
    lay = TrackLayout(data.span, shared.layout.degree, np.asarray(group_of_launch), n_groups)
    return _fit(data, lay, shared.sigma, shared.used, _start(data, lay, shared))


def group_offset(data: TableData, fit: JointFit, minuend: int = 1, subtrahend: int = 0,
                 level: float = 0.95) -> GroupOffset:
    """Offset of group ``minuend`` over ``subtrahend`` (indices into ``group_names``).

    Parameters
    ----------
    data : TableData
        The launches (:func:`prepare_table`).
    fit : JointFit
        A fit of :func:`fit_table`.
    minuend, subtrahend : int
        The groups (indices into ``data.group_names``).
    level : float
        Confidence level of the interval.

    Returns
    -------
    GroupOffset
        The offset (rad/s²), its standard error and interval.

    Raises
    ------
    ContactInputError
        A group index out of range.

    See Also
    --------
    judge_table : tests it.

    Examples
    --------
    Table 3: the asymmetric rotor accelerates 0.20 rad/s² less than the symmetric one:

    >>> import numpy as np
    >>> from rotor import fit_table, group_offset, prepare_table, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> data = prepare_table(table3(), groups, 120.0, np.pi / 2)
    >>> shared, groupwise = fit_table(data)
    >>> off = group_offset(data, shared)
    >>> print(f"{off.value:.2f} rad/s², 95 % CI {off.ci_low:.2f} to {off.ci_high:.2f}")
    -0.20 rad/s², 95 % CI -0.28 to -0.12
    """
    lay = fit.layout
    _, delta, _, _ = lay.split(fit.x)
    g = data.group_of_launch
    if not (0 <= minuend < len(data.group_names) and 0 <= subtrahend < len(data.group_names)):
        raise ContactInputError("the offset needs two groups")
    a, b = delta[g == minuend], delta[g == subtrahend]
    value = float(a.mean() - b.mean())
    dof = int(g.size - len(data.group_names))
    resid = np.concatenate([delta[g == k] - delta[g == k].mean()
                            for k in range(len(data.group_names))])
    launch_sd = float(math.sqrt(np.sum(resid**2) / dof)) if dof > 0 else math.nan
    spread_se = launch_sd * math.sqrt(1.0 / a.size + 1.0 / b.size)
    nb = lay.n_tracks * lay.degree
    c = np.zeros(lay.n_params)
    c[nb : nb + lay.n_launches] = np.where(g == minuend, 1.0 / a.size, 0.0) - np.where(
        g == subtrahend, 1.0 / b.size, 0.0)
    scale = max(fit.chi2 / max(fit.n_used - lay.n_params, 1), 1.0)
    fit_se = float(math.sqrt(max(c @ fit.cov @ c, 0.0) * scale))
    se = max(spread_se, fit_se) if math.isfinite(spread_se) else fit_se
    q = float(student_t.ppf(0.5 + level / 2, max(dof, 1)))
    return GroupOffset(data.group_names[minuend], data.group_names[subtrahend], value, se,
                       value - q * se, value + q * se, level, dof, launch_sd, fit_se)


def shared_track_f(shared: JointFit, groupwise: JointFit) -> float:
    """The F statistic of one shared track against group-specific ones: the drop of chi²
    per added parameter over the group-specific fit's chi² per degree of freedom (the
    noise scale cancels; its null distribution is calibrated by simulation).

    Parameters
    ----------
    shared, groupwise : JointFit
        The two fits of :func:`fit_table`.

    Returns
    -------
    float
        The F statistic.

    See Also
    --------
    verdict_calibration : its critical value.

    Examples
    --------
    Table 3's F far exceeds the calibrated 2 % point (3.75): no shared track explains both
    groups.

    >>> import numpy as np
    >>> from rotor import fit_table, prepare_table, shared_track_f, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> data = prepare_table(table3(), groups, 120.0, np.pi / 2)
    >>> shared, groupwise = fit_table(data)
    >>> print(f"F = {shared_track_f(shared, groupwise):.1f}")
    F = 17.4
    """
    q = groupwise.layout.n_params - shared.layout.n_params
    dof = groupwise.n_used - groupwise.layout.n_params
    if q <= 0 or dof <= 0 or groupwise.chi2 <= 0:
        return math.nan
    return float(max(shared.chi2 - groupwise.chi2, 0.0) / q / (groupwise.chi2 / dof))


def launchwise_fit(data: TableData, shared: JointFit) -> JointFit:
    """A track of the shared fit's degree for every launch (each on a lane of its own), with
    the shared fit's noise and misread rows.

    Parameters
    ----------
    data : TableData
        The launches (:func:`prepare_table`).
    shared : JointFit
        The shared-track fit of :func:`fit_table`.

    Returns
    -------
    JointFit
        One track per launch.

    See Also
    --------
    lane_f

    Examples
    --------
    >>> import numpy as np
    >>> from rotor import fit_table, launchwise_fit, prepare_table, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> data = prepare_table(table3(), groups, 120.0, np.pi / 2)
    >>> shared, groupwise = fit_table(data)
    >>> launchwise = launchwise_fit(data, shared)
    >>> launchwise.layout.n_tracks, bool(launchwise.chi2 <= groupwise.chi2)
    (6, True)
    """
    n = data.group_of_launch.size
    return groupwise_fit(data, shared, np.arange(n), n)


def lane_f(shared: JointFit, groupwise: JointFit, launchwise: JointFit) -> float:
    """Do the groups' tracks differ more than the launches' within a group do? The drop of
    chi² from one shared track to group-specific ones per added parameter, over the drop from
    group-specific tracks to launch-specific ones per added parameter: launches differing
    among themselves (lanes) raise both alike, so they are not read as groups differing
    (its null distribution calibrated by simulation with lanes in the null).

    Parameters
    ----------
    shared, groupwise, launchwise : JointFit
        The fits of :func:`fit_table` and :func:`launchwise_fit`.

    Returns
    -------
    float
        The lane F statistic.

    See Also
    --------
    lane_calibration : its null distribution.

    Examples
    --------
    >>> import numpy as np
    >>> from rotor import fit_table, lane_f, launchwise_fit, prepare_table, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> data = prepare_table(table3(), groups, 120.0, np.pi / 2)
    >>> shared, groupwise = fit_table(data)
    >>> print(f"lane F = {lane_f(shared, groupwise, launchwise_fit(data, shared)):.2f}")
    lane F = 5.28
    """
    q_g = groupwise.layout.n_params - shared.layout.n_params
    q_l = launchwise.layout.n_params - groupwise.layout.n_params
    within = max(groupwise.chi2 - launchwise.chi2, 0.0)
    if q_g <= 0 or q_l <= 0 or within <= 0:
        return math.nan
    return float(max(shared.chi2 - groupwise.chi2, 0.0) / q_g / (within / q_l))


def local_accelerations(data: TableData, fit: JointFit, gap: int = 2
                        ) -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """Per launch, the acceleration read off the frames alone: the second divided difference
    of the angle over rows ``k - gap, k, k + gap`` (used rows), at track position ``s``
    (rad since the fitted release), with its standard error from the rows' reading noise.
    Returns ``(s, eps, stderr)`` per launch.

    Parameters
    ----------
    data : TableData
        The launches (:func:`prepare_table`).
    fit : JointFit
        A fit of :func:`fit_table` (its release points, noise and misread rows).
    gap : int
        Rows between the three of each divided difference.

    Returns
    -------
    list of tuple of numpy.ndarray
        ``(s, eps, stderr)`` per launch: track position (rad), acceleration and its standard
        error (rad/s²).

    See Also
    --------
    track_acceleration : the model's acceleration along the track.

    Examples
    --------
    >>> import numpy as np
    >>> from rotor import fit_table, local_accelerations, prepare_table, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> data = prepare_table(table3(), groups, 120.0, np.pi / 2)
    >>> shared, groupwise = fit_table(data)
    >>> s, eps, stderr = local_accelerations(data, shared)[0]
    >>> print(data.names[0], f"{np.mean(eps):.1f} rad/s²")
    s1 1.6 rad/s²
    """
    _, _, phi0, _ = fit.layout.split(fit.x)
    out = []
    for i in range(data.times.shape[0]):
        rows = np.flatnonzero(fit.used[i])
        t, a, sg = data.times[i, rows], data.angles[i, rows], fit.sigma[i, rows]
        if rows.size < 2 * gap + 1:
            out.append((np.zeros(0), np.zeros(0), np.zeros(0)))
            continue
        lo, mid, hi = np.arange(rows.size - 2 * gap), np.arange(gap, rows.size - gap), \
            np.arange(2 * gap, rows.size)
        h1, h2 = t[mid] - t[lo], t[hi] - t[mid]
        v1, v2 = (a[mid] - a[lo]) / h1, (a[hi] - a[mid]) / h2
        eps = 2.0 * (v2 - v1) / (h1 + h2)
        # linear error propagation: d eps / d t of each of the three rows
        d_lo = 2.0 * (-v1 / h1 + (v2 - v1) / (h1 + h2)) / (h1 + h2)
        d_hi = 2.0 * (-v2 / h2 - (v2 - v1) / (h1 + h2)) / (h1 + h2)
        d_mid = -(d_lo + d_hi)
        se = np.sqrt((d_lo * sg[lo]) ** 2 + (d_mid * sg[mid]) ** 2 + (d_hi * sg[hi]) ** 2)
        out.append((a[mid] - phi0[i], eps, se))
    return out
