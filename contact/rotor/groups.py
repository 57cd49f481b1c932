"""Groups of tests and the whole table: the paper's parabola per group, the initial
accelerations with their uncertainties, leave-one-test-out errors, and the comparison of
groups under one study model."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares

from contact.errors import ContactInputError
from contact.rotor.analysis import TestReport, analyse_test
from contact.rotor.arrays import readonly
from contact.rotor.family import MODELS, SELECTABLE
from contact.rotor.forward import crossing_times
from contact.rotor.noise import quantisation_sigma
from contact.rotor.paper import FPS, MARK_STEP
from contact.rotor.parabola import paper_parabola
from contact.rotor.selection import BIC_MARGIN, select_by_bic
from contact.rotor.starts import from_rest_estimate, inside_bounds, parameter_bounds

__all__ = [
    "GroupComparison",
    "GroupReport",
    "LawOfMotionAnalysis",
    "analyse_table",
    "leave_one_test_out",
    "mean_with_uncertainty",
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
    """

    name: str
    tests: tuple[str, ...]
    paper_parabola: np.ndarray
    paper_parabola_stderr: np.ndarray
    paper_rms: float
    eps: dict[str, tuple[float, float, tuple[float, ...]]]
    params: dict[str, tuple[float, float, tuple[float, ...]]]
    loto_rms: dict[str, float]


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
    ``a_c``, ``a_s``) averaged over the group's other tests; only its own start (``t0``,
    ``phi0``), which differs from launch to launch, is fitted to it (weighted by its noise
    model). Misread rows are left out. NaN for fewer than two tests and for ``parabola``.
    """
    if len(reports) < 2 or model == "parabola":
        return math.nan
    phys = ("eps0", "eta", "gamma", "a_c", "a_s")
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

        def fun(x: np.ndarray, t=t, phi=phi, avg=avg, sig=sig) -> np.ndarray:
            return (crossing_times(phi, **avg, t0=x[0], phi0=x[1]) - t) / sig

        r = least_squares(fun, x0, bounds=(lo, hi), x_scale="jac")
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
    threshold: float = 4.0,
    min_frames: float = 1.5,
) -> LawOfMotionAnalysis:
    """Analyse a table of tests (column name -> frame index per row).

    Per test: :func:`analyse_test`. Per group (name without trailing digits): the paper's
    parabola through the mean times, each model's initial acceleration with its uncertainty,
    leave-one-test-out errors. The study model has the smallest BIC summed over all tests
    (with the same nested-margin rule), one model for every test so that groups compare like
    with like. Groups are compared pairwise under ``paper``, ``rest``, ``const`` and the study
    model, and on the study model's decay and unbalance parameters.
    """
    if not columns:
        raise ContactInputError("no test columns to analyse")
    reports = tuple(
        analyse_test(name, columns[name], k, fps=fps, step=step, margin=margin, cv=cv,
                     threshold=threshold, min_frames=min_frames)
        for name in columns
    )
    # short columns leave their richest models out: compare the models every test has
    common = [m for m in SELECTABLE if all(m in r.fits for r in reports)]
    total = {m: float(sum(r.fits[m].bic for r in reports)) for m in common}
    study = select_by_bic(total, margin)

    groups: list[GroupReport] = []
    for gname in dict.fromkeys(r.group for r in reports):
        members = [r for r in reports if r.group == gname]
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
        groups.append(GroupReport(
            name=gname,
            tests=tuple(r.name for r in members),
            paper_parabola=readonly(coef),
            paper_parabola_stderr=readonly(se),
            paper_rms=prms,
            eps=eps,
            params=params,
            loto_rms={m: leave_one_test_out(members, m) for m in common},
        ))

    from scipy import stats

    comps: list[GroupComparison] = []

    def compare(ga, gb, model, quantity, a, b) -> None:
        (ma, ua, va), (mb, ub, vb) = a, b
        diff = mb - ma
        u = math.hypot(ua, ub)
        p = math.nan
        if len(va) > 1 and len(vb) > 1:
            p = float(stats.ttest_ind(vb, va, equal_var=False).pvalue)
        comps.append(GroupComparison(ga.name, gb.name, model, quantity, diff, u,
                                     diff / u if u > 0 else math.nan, p,
                                     mb / ma if ma else math.nan))

    for i in range(len(groups)):
        for j in range(i + 1, len(groups)):
            ga, gb = groups[i], groups[j]
            for m in dict.fromkeys(("paper", "rest", "const", study)):
                compare(ga, gb, m, "eps0", ga.eps[m], gb.eps[m])
            for key in ga.params:
                compare(ga, gb, study, key, ga.params[key], gb.params[key])
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
