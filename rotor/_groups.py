"""Groups of tests and the whole table: the paper's parabola per group, the initial
accelerations with their uncertainties, leave-one-test-out errors, and the comparison of
groups under one study model."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares

from contact._errors import ContactInputError
from rotor._alignment import ResidualAlignment, residual_alignment
from rotor._analysis import TestReport, analyse_test
from rotor._arrays import readonly
from rotor._family import EXTENSION, MODELS, SELECTABLE
from rotor._forward import PARAM_NAMES, batch_crossing_times, crossing_times
from rotor._misreads import MISREAD_MIN_FRAMES, MISREAD_THRESHOLD
from rotor._noise import quantisation_sigma
from rotor._paper import FPS, MARK_STEP
from rotor._parabola import paper_parabola
from rotor._selection import BIC_MARGIN, select_by_bic
from rotor._starts import from_rest_estimate, inside_bounds, parameter_bounds

__all__ = [
    "GroupComparison",
    "GroupReport",
    "LawOfMotionAnalysis",
    "analyse_table",
    "leave_one_test_out",
    "mean_with_uncertainty",
    "welch_p_value",
]


@dataclass(frozen=True)
class GroupReport:
    """A group of tests (same collar position).

    Attributes
    ----------
    name : str
    tests : tuple of str
    paper_parabola, paper_parabola_stderr : ndarray
        ``[c2, c1, c0]`` (rad/s², rad/s, rad) of the paper's fit through the mean times.
    paper_rms : float
        Its rms angle residual, rad.
    eps : dict
        Per model (and ``"paper"``: ``2 c2``), ``(mean, uncertainty, per-test values)`` of
        the initial acceleration, rad/s². The uncertainty is the larger of the between-test
        standard error of the mean and the fits' pooled standard error.
    params : dict
        The same for ``eta`` (1/s²), ``gamma`` (1/s) and ``amplitude`` (rad/s²) of the study
        model, where it has them.
    loto_rms : dict
        Leave-one-test-out prediction rms (s) per model (:func:`leave_one_test_out`).
    residual_alignment : ResidualAlignment or None
        Whether a leftover wave lines up across the tests at the same track position or
        rotor angle (:func:`rotor._alignment.residual_alignment`).
    """

    name: str
    tests: tuple[str, ...]
    paper_parabola: np.ndarray
    paper_parabola_stderr: np.ndarray
    paper_rms: float
    eps: dict[str, tuple[float, float, tuple[float, ...]]]
    params: dict[str, tuple[float, float, tuple[float, ...]]]
    loto_rms: dict[str, float]
    residual_alignment: ResidualAlignment | None = None


@dataclass(frozen=True)
class GroupComparison:
    """Difference ``b - a`` of two groups' initial accelerations (or of another parameter)
    under one model. ``p_value``: Welch's two-sided t test on the per-test values (NaN for
    ``paper``, one value per group; its ``z`` uses the parabolas' standard errors)."""

    a: str
    b: str
    model: str
    quantity: str
    difference: float
    uncertainty: float
    z: float
    p_value: float
    ratio: float


@dataclass(frozen=True)
class LawOfMotionAnalysis:
    """Everything :func:`analyse_table` finds.

    ``study_model`` is the model with the smallest BIC summed over all tests
    (``total_bic``), used to compare groups like with like.

    Attributes
    ----------
    tests : tuple of TestReport
        Each column's analysis.
    groups : tuple of GroupReport
        Each group's tests and summary.
    comparisons : tuple of GroupComparison
        The groups' differences under each model.
    study_model : str
        The model of the smallest summed BIC.
    total_bic : dict of str to float
        The BIC summed over the tests, per model.
    fps, step : float
        Frame rate (1/s) and the angle between marks (rad).
    noise_floor : float
        The reading-noise floor: the frame quantisation's standard deviation (s).

    See Also
    --------
    analyse_table : builds it.

    Examples
    --------
    The same constant-acceleration run, its frames counted at 118/s in group ``as`` but read
    at 120/s: its acceleration reads ``(120/118)**2`` times larger, 0.06 rad/s² more:

    >>> import numpy as np
    >>> from rotor import analyse_table
    >>> phi = np.arange(12) * np.pi / 2
    >>> t = (-1.0 + np.sqrt(1.0 + 2 * 2.0 * phi)) / 2.0
    >>> result = analyse_table({"s1": np.round(1000 + 120 * t), "as1": np.round(500 + 118 * t)})
    >>> print(result.study_model, [g.name for g in result.groups])
    const ['s', 'as']
    >>> c = result.comparisons[0]
    >>> print(c.a, c.b, c.quantity, f"{c.difference:.2f} rad/s²")
    s as eps0 0.06 rad/s²
    """

    tests: tuple[TestReport, ...]
    groups: tuple[GroupReport, ...]
    comparisons: tuple[GroupComparison, ...]
    study_model: str
    total_bic: dict[str, float]
    fps: float
    step: float
    noise_floor: float

    def test(self, name: str) -> TestReport:
        for t in self.tests:
            if t.name == name:
                return t
        raise KeyError(name)

    def group(self, name: str) -> GroupReport:
        for g in self.groups:
            if g.name == name:
                return g
        raise KeyError(name)


def mean_with_uncertainty(values: Sequence[float], errors: Sequence[float]) -> tuple[float, float]:
    v = np.asarray(values, float)
    e = np.asarray(errors, float)
    n = v.size
    mean = float(v.mean())
    sem = float(v.std(ddof=1) / math.sqrt(n)) if n > 1 else math.nan
    fit_u = float(math.sqrt(np.nansum(e**2)) / n) if np.any(np.isfinite(e)) else math.nan
    cands = [x for x in (sem, fit_u) if math.isfinite(x)]
    return mean, (max(cands) if cands else math.nan)


def leave_one_test_out(reports: Sequence[TestReport], model: str) -> float:
    """Leave-one-test-out prediction rms (s) of ``model`` within a group.

    Each test is predicted with the physical parameters (``eps0``, ``eta``, ``gamma``,
    ``a_c``, ``a_s`` and the plate wave's) averaged over the group's other tests; only its
    own start (``t0``, ``phi0``), which differs from launch to launch, is fitted to it
    (weighted by its noise model). Misread rows are left out. NaN for fewer than two tests
    and for ``parabola``.
    """
    if len(reports) < 2 or model == "parabola":
        return math.nan
    phys = ("eps0", "eta", "gamma", "a_c", "a_s", "wave_c", "wave_s", "wave_period")
    errs: list[np.ndarray] = []
    for i, rep in enumerate(reports):
        others = [r for j, r in enumerate(reports) if j != i]
        avg = {k: float(np.mean([o.fits[model].params[k] for o in others])) for k in phys}
        own = rep.fits[model]
        used = np.array(own.used)
        t, phi = rep.times[used], rep.angles[used]
        if model == "rest":
            errs.append(crossing_times(phi, **avg, t0=float(t[0]), phi0=float(phi[0])) - t)
            continue
        sig = np.array(own.sigma)[used]
        bd = parameter_bounds(t, phi, rep.step, from_rest_estimate(t, phi))
        lo = [bd["t0"][0], bd["phi0"][0]]
        hi = [bd["t0"][1], bd["phi0"][1]]
        x0 = [inside_bounds(own.params["t0"], lo[0], hi[0]),
              inside_bounds(own.params["phi0"], lo[1], hi[1])]

        base = np.array([{**avg, "t0": 0.0, "phi0": 0.0}.get(k, 0.0) if k != "wave_period"
                         else avg.get(k, 2 * math.pi) for k in PARAM_NAMES])
        cols = [PARAM_NAMES.index("t0"), PARAM_NAMES.index("phi0")]

        def times_at(xs: np.ndarray, phi=phi, base=base, cols=cols) -> np.ndarray:
            rows = np.repeat(base[None, :], xs.shape[0], axis=0)
            rows[:, cols] = xs
            return batch_crossing_times(phi, rows)

        def fun(x: np.ndarray, t=t, sig=sig, times_at=times_at) -> np.ndarray:
            return (times_at(x[None, :])[0] - t) / sig

        def jac(x: np.ndarray, sig=sig, times_at=times_at, hi=hi) -> np.ndarray:
            # forward differences in one batch, stepping inwards at an upper bound
            h = 1e-7 * np.maximum(1.0, np.abs(x))
            h = np.where(x + h > np.asarray(hi), -h, h)
            tt = times_at(np.vstack([x, x + np.diag(h)]))
            return ((tt[1:] - tt[0]) / h[:, None]).T / sig[:, None]

        r = least_squares(fun, x0, jac=jac, bounds=(lo, hi), x_scale="jac")
        errs.append(r.fun * sig)
    allr = np.concatenate(errs)
    return float(np.sqrt(np.mean(allr**2)))


def analyse_table(
    columns: Mapping[str, Sequence[float]],
    k: Sequence[int] | None = None,
    *,
    fps: float = FPS,
    step: float = MARK_STEP,
    margin: float = BIC_MARGIN,
    cv: str = "approx",
    threshold: float = MISREAD_THRESHOLD,
    min_frames: float = MISREAD_MIN_FRAMES,
    progress: Callable[[str, int, int], None] | None = None,
) -> LawOfMotionAnalysis:
    """Analyse a table of tests (column name -> frame index per row).

    Per test: :func:`analyse_test`. Per group (name without trailing digits): the paper's
    parabola through the mean times, each model's initial acceleration with its uncertainty,
    leave-one-test-out errors. The study model has the smallest BIC summed over all tests
    (with the same nested-margin rule) among the core family's models (the plate-wave
    models are fitted only where a test needs them), one model for every test so that groups
    compare like with like. Groups are compared pairwise under ``paper``, ``rest``,
    ``const`` and the study model, and on the study model's decay and unbalance
    parameters. ``progress(name, i, n)`` is called before each test is analysed.

    Parameters
    ----------
    columns : mapping of str to sequence of float
        Column name -> frame index per row (NaN for a missing reading).
    k : sequence of int, optional
        Row numbers (default 1, 2, ...).
    fps, step, margin, cv, threshold, min_frames
        As for :func:`rotor._analysis.analyse_test`.
    progress : callable, optional
        ``progress(name, i, n)``, called before each test.

    Returns
    -------
    LawOfMotionAnalysis
        The per-test reports (``tests``), the per-group reports (``groups``), the study
        model and the pairwise group comparisons.

    Raises
    ------
    ContactInputError
        An empty table or a column that :func:`analyse_test` refuses.

    See Also
    --------
    rotor.analyse_test : one column.
    surfmet.mechanics.rotor_verdict.table_verdict : the verdict on a table file.

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of Rolling
       Friction Moment on the Normal Force for Elastic Materials", Materials 15 (2022) 2518,
       Table 3.

    Examples
    --------
    Two groups (``s`` and ``as``, the names without their digits) of constant-acceleration
    runs:

    >>> import numpy as np
    >>> from rotor import analyse_table
    >>> phi = np.arange(12) * np.pi / 2
    >>> t = (-1.0 + np.sqrt(1.0 + 2 * 2.0 * phi)) / 2.0
    >>> table = {"s1": np.round(1000 + 120 * t), "as1": np.round(500 + 118 * t)}
    >>> result = analyse_table(table)
    >>> result.study_model, [g.name for g in result.groups]
    ('const', ['s', 'as'])
    """
    if not columns:
        raise ContactInputError("no test columns to analyse")
    reports = []
    for i, name in enumerate(columns):
        if progress is not None:
            progress(name, i, len(columns))
        reports.append(analyse_test(name, columns[name], k, fps=fps, step=step, margin=margin,
                                    cv=cv, threshold=threshold, min_frames=min_frames))
    reports = tuple(reports)
    # short columns leave their richest models out: compare the models every test has; the
    # plate-wave models are fitted only where the family fails, so they are not candidates
    common = [m for m in SELECTABLE if m not in EXTENSION and all(m in r.fits for r in reports)]
    total = {m: float(sum(r.fits[m].bic for r in reports)) for m in common}
    study = select_by_bic(total, margin)

    groups = [_group_report(gname, [r for r in reports if r.group == gname], columns, fps,
                            step, study, common)
              for gname in dict.fromkeys(r.group for r in reports)]
    comps = _compare_groups(groups, study)
    return LawOfMotionAnalysis(
        tests=reports,
        groups=tuple(groups),
        comparisons=tuple(comps),
        study_model=study,
        total_bic=total,
        fps=float(fps),
        step=float(step),
        noise_floor=quantisation_sigma(fps),
    )


def welch_p_value(a: Sequence[float], b: Sequence[float]) -> float:
    """Two-sided p-value of Welch's t test of equal means (unequal variances), with the
    Welch-Satterthwaite degrees of freedom (Welch 1947, Biometrika 34:28-35); scipy's
    ``special.stdtr`` gives the t distribution (``scipy.stats`` costs a second to import)."""
    from scipy.special import stdtr

    x, y = np.asarray(a, float), np.asarray(b, float)
    va, vb = x.var(ddof=1) / x.size, y.var(ddof=1) / y.size
    se2 = va + vb
    if not se2 > 0:
        return math.nan
    t = (x.mean() - y.mean()) / math.sqrt(se2)
    df = se2**2 / (va**2 / (x.size - 1) + vb**2 / (y.size - 1))
    return float(2.0 * stdtr(df, -abs(t)))


def _group_report(gname: str, members: list[TestReport], columns, fps: float, step: float,
                  study: str, common: list[str]) -> GroupReport:
    cols = [np.asarray(columns[r.name], float) for r in members]
    if len({c.size for c in cols}) == 1:
        coef, se, prms = paper_parabola(cols, fps, step)
    else:
        coef, se, prms = np.full(3, np.nan), np.full(3, np.nan), math.nan
    eps: dict[str, tuple[float, float, tuple[float, ...]]] = {
        "paper": (float(2 * coef[0]), float(2 * se[0]), (float(2 * coef[0]),))
    }
    for m in MODELS:
        if not all(m in r.fits for r in members):
            continue
        vals = [r.fits[m].eps0 for r in members]
        mu, u = mean_with_uncertainty(vals, [r.fits[m].eps0_stderr for r in members])
        eps[m] = (mu, u, tuple(float(v) for v in vals))
    params: dict[str, tuple[float, float, tuple[float, ...]]] = {}
    free = MODELS[study].free
    for key, needs in (("eta", "eta"), ("gamma", "gamma"), ("amplitude", "a_c")):
        if needs in free:
            vals = [r.fits[study].params[key] for r in members]
            errs = [r.fits[study].stderr.get(key, math.nan) for r in members]
            mu, u = mean_with_uncertainty(vals, errs)
            params[key] = (mu, u, tuple(float(v) for v in vals))
    return GroupReport(
        name=gname,
        tests=tuple(r.name for r in members),
        paper_parabola=readonly(coef),
        paper_parabola_stderr=readonly(se),
        paper_rms=prms,
        eps=eps,
        params=params,
        loto_rms={m: leave_one_test_out(members, m) for m in common},
        residual_alignment=residual_alignment(members),
    )


def _compare_groups(groups: list[GroupReport], study: str) -> list[GroupComparison]:
    """Pairwise comparisons under ``paper``, ``rest``, ``const`` and the study model, and
    on the study model's decay and unbalance parameters. Welch's t test needs two values per
    group: the paper's parabola (one per group) has no p-value."""
    comps: list[GroupComparison] = []

    def compare(ga, gb, model, quantity, a, b) -> None:
        (ma, ua, va), (mb, ub, vb) = a, b
        diff = mb - ma
        u = math.hypot(ua, ub)
        p = math.nan
        if len(va) > 1 and len(vb) > 1:
            p = welch_p_value(vb, va)
        comps.append(GroupComparison(ga.name, gb.name, model, quantity, diff, u,
                                     diff / u if u > 0 else math.nan, p,
                                     mb / ma if ma else math.nan))

    for i in range(len(groups)):
        for j in range(i + 1, len(groups)):
            ga, gb = groups[i], groups[j]
            for m in dict.fromkeys(("paper", "rest", "const", study)):
                if m in ga.eps and m in gb.eps:  # short columns may leave a model out
                    compare(ga, gb, m, "eps0", ga.eps[m], gb.eps[m])
            for key in ga.params:
                compare(ga, gb, study, key, ga.params[key], gb.params[key])
    return comps
