"""The four "differences" between the groups, reconciled: one table of each number, the model
it belongs to, whether that model fits the data, and which one the verdict uses; and the two
misread rules (the joint model's and the per-test analysis') side by side.

The numbers (minuend - subtrahend, rad/s²) come from two analyses of the same table:

* the per-test analysis (:func:`rotor._groups.analyse_table`): the paper's parabola
  through each group's mean times (``2 c2``, Fig. 21), a constant acceleration from a release
  per test (``const``), and the study model at the release (the acceleration of a model
  whose acceleration changes along the track, read at its start);
* the joint model (:mod:`rotor._joint`): a constant offset between the groups on one
  shared track, what the paper's constant-offset reading of Eqs. 47-48 predicts.

A model "fits" when the data do not reject it: for a per-test model, when in every test the
chosen model is it or one it contains, or beats it by no more than the selection margin, and
it passes the adequacy test where it is the choice (the paper's parabola, a constant
acceleration with free start terms, is judged as ``const``); for the joint offset, when the
shared-track test does not reject its shared track. Where the study model is ``const`` its
row is the ``const`` row.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from rotor._family import is_nested
from rotor._joint import fit_table, group_offset, shared_track_f
from rotor._selection import BIC_MARGIN

__all__ = ["Difference", "MisreadRules", "differences_table", "misread_rules"]


@dataclass(frozen=True)
class Difference:
    """One of the differences: ``value`` (rad/s²) with ``stderr`` (and ``ci_low``/``ci_high``
    where the model gives an interval; NaN otherwise), ``model`` (its key), ``label`` (what
    it is), ``where`` (where along the track it holds), ``fits`` and ``fit_evidence`` (why),
    ``used_by_verdict`` and ``role``.

    See Also
    --------
    differences_table : builds the four of a table.

    Examples
    --------
    The joint model's row on a simulated table (two launches per group, 12 rows each, the
    symmetric group faster by 0.3 rad/s²): the difference the verdict uses, within about
    one standard error of the truth:

    >>> import dataclasses
    >>> import numpy as np
    >>> from rotor import (analyse_table, draw_scenario, judge_table, paper_rig,
    ...                    simulate_table)
    >>> rng = np.random.default_rng(1)
    >>> scn = dataclasses.replace(draw_scenario(rng, offset=0.3), n_marks=12, launches=2)
    >>> table = simulate_table(scn, rng)
    >>> verdict = judge_table(table, {"s": ["s1", "s2"], "as": ["as1", "as2"]}, fps=120.0,
    ...                       step=np.pi / 2, rig=paper_rig(), permutation=False)
    >>> analysis = analyse_table(table)
    >>> from rotor import differences_table
    >>> d = next(d for d in differences_table(verdict, analysis) if d.model == "joint")
    >>> d.used_by_verdict, d.fits, abs(d.value + 0.3) < 2 * d.stderr
    (True, True, True)
    """

    label: str
    model: str
    value: float
    stderr: float
    ci_low: float
    ci_high: float
    where: str
    fits: bool
    fit_evidence: str
    used_by_verdict: bool
    role: str


def _comparison(analysis: Any, model: str, minuend: str, subtrahend: str
                ) -> tuple[float, float] | None:
    for c in analysis.comparisons:
        if c.model == model and c.quantity == "eps0":
            if (c.b, c.a) == (minuend, subtrahend):
                return c.difference, c.uncertainty
            if (c.a, c.b) == (minuend, subtrahend):
                return -c.difference, c.uncertainty
    return None


def _per_test_fit(analysis: Any, model: str) -> tuple[bool, str]:
    """Whether a per-test model fits every test: the test's chosen model is it or nested in
    it (a simpler one it contains), or beats it by no more than the selection margin; and
    where it is the choice, it passes the adequacy test. The paper's parabola is a constant
    acceleration with free start terms: judged as ``const``."""
    fit_model = "const" if model == "paper" else model
    beaten, inadequate = [], []
    for t in analysis.tests:
        if fit_model not in t.fits:
            continue
        if t.selected == fit_model or is_nested(t.selected, fit_model):
            if t.selected == fit_model and t.adequacy is not None and not t.adequacy.adequate:
                inadequate.append(t.name)
            continue
        d = t.fits[fit_model].bic - t.fit.bic
        if not math.isfinite(d) or d > BIC_MARGIN:
            beaten.append(f"{t.name} {d:.0f} ({t.selected})")
    n = len(analysis.tests)
    why = []
    if beaten:
        why.append(f"rejected in {len(beaten)} of {n} tests by the BIC (dBIC to the test's "
                   f"chosen model: {', '.join(beaten)}; margin {BIC_MARGIN:g})")
    if inadequate:
        why.append(f"the chosen {fit_model} fails the adequacy test in {len(inadequate)} of "
                   f"{n} tests ({', '.join(inadequate)})")
    if why:
        return False, "no: " + "; ".join(why)
    return True, f"yes: it or a model it contains is chosen, and adequate, in all {n} tests"


def differences_table(verdict: Any, analysis: Any) -> tuple[Difference, ...]:
    """The four differences of a table: ``verdict`` (:class:`rotor.RotorVerdict`) and
    ``analysis`` (:class:`rotor.LawOfMotionAnalysis`) of the same table.

    Parameters
    ----------
    verdict : RotorVerdict
        The verdict of :func:`judge_table` on the table.
    analysis : LawOfMotionAnalysis
        The per-test analysis of :func:`analyse_table` on the same table.

    Returns
    -------
    tuple of Difference
        The paper's parabola, the per-test constant acceleration, the joint model's offset
        (the verdict's) and, where it differs, the study model's; each with whether its model
        fits the data.

    See Also
    --------
    misread_rules

    Examples
    --------
    A simulated table (two launches per group, 12 rows each, the symmetric group faster by
    0.3 rad/s²), judged and analysed test by test:

    >>> import dataclasses
    >>> import numpy as np
    >>> from rotor import (analyse_table, draw_scenario, judge_table, paper_rig,
    ...                    simulate_table)
    >>> rng = np.random.default_rng(1)
    >>> scn = dataclasses.replace(draw_scenario(rng, offset=0.3), n_marks=12, launches=2)
    >>> table = simulate_table(scn, rng)
    >>> verdict = judge_table(table, {"s": ["s1", "s2"], "as": ["as1", "as2"]}, fps=120.0,
    ...                       step=np.pi / 2, rig=paper_rig(), permutation=False)
    >>> analysis = analyse_table(table)
    >>> from rotor import differences_table
    >>> for d in differences_table(verdict, analysis):
    ...     print(d.model, f"{d.value:.1f} rad/s²", d.fits, d.used_by_verdict)
    paper -0.3 rad/s² True False
    const -0.3 rad/s² True False
    joint -0.3 rad/s² True True
    """
    o = verdict.offset
    a, b = o.minuend, o.subtrahend
    nan = math.nan
    rows = []
    for model, label, where in (
            ("paper", "2 c2 of the paper's parabola through each group's mean times (Fig. 21)",
             "a constant acceleration over the whole track"),
            ("const", "constant acceleration from a release, per test, mean per group",
             "a constant acceleration over the whole track")):
        got = _comparison(analysis, model, a, b)
        if got is None:
            continue
        fits, why = _per_test_fit(analysis, model)
        rows.append(Difference(label, model, got[0], got[1], nan, nan, where, fits, why, False,
                               "reported; not used: its model does not fit the data"
                               if not fits else "reported"))
    shared_why = (f"{'yes' if verdict.shared_track_adequate else 'no'}: shared-track test F = "
                  f"{verdict.f_statistic:.3g} (critical {verdict.f_critical:.3g})")
    if verdict.permutation is not None:
        shared_why += f", the design's permutation p = {verdict.permutation.f_p:.2g}"
    rows.append(Difference(
        "constant offset between the groups on one shared track (joint model)", "joint",
        o.value, o.stderr, o.ci_low, o.ci_high, "the same at every track position",
        verdict.shared_track_adequate, shared_why, True,
        "used: the verdict tests its shared track; it names the offset only when the track is "
        "shared" + ("" if verdict.shared_track_adequate else " (here it is not, so the offset "
                    "is reported, not laid to rolling friction)")))
    study = analysis.study_model
    got = None if study == "const" else _comparison(analysis, study, a, b)
    if got is not None:
        fits, why = _per_test_fit(analysis, study)
        rows.append(Difference(
            f"study model ({study}) at the release, per test, mean per group", study, got[0],
            got[1], nan, nan, "at the release only (the acceleration changes along the track)",
            fits, why, False, "reported; not used: a value at one end of the track, where the "
                              "groups' tracks differ"))
    return tuple(rows)


@dataclass(frozen=True)
class MisreadRules:
    """The two misread rules on one table: ``joint`` and ``per_test`` ((column, k) pairs),
    ``only_per_test`` with each row's residual under the joint shared track in frames and
    in its launch's noise sigmas; and the joint model refitted with the per-test rule's rows
    also left out (``offset``, ``f_statistic``).

    See Also
    --------
    misread_rules : builds it for a table.

    Examples
    --------
    On a simulated table (two launches per group, 12 rows each): every row the joint rule
    leaves out, the per-test rule leaves out too, and the refit without both keeps the
    simulated offset of -0.3 rad/s² inside its interval:

    >>> import dataclasses
    >>> import numpy as np
    >>> from rotor import (analyse_table, draw_scenario, judge_table, paper_rig,
    ...                    simulate_table)
    >>> rng = np.random.default_rng(1)
    >>> scn = dataclasses.replace(draw_scenario(rng, offset=0.3), n_marks=12, launches=2)
    >>> table = simulate_table(scn, rng)
    >>> verdict = judge_table(table, {"s": ["s1", "s2"], "as": ["as1", "as2"]}, fps=120.0,
    ...                       step=np.pi / 2, rig=paper_rig(), permutation=False)
    >>> analysis = analyse_table(table)
    >>> from rotor import misread_rules
    >>> rules = misread_rules(verdict, analysis)
    >>> set(rules.joint) <= set(rules.per_test), rules.offset_ci[0] < -0.3 < rules.offset_ci[1]
    (True, True)
    """

    joint: tuple[tuple[str, int], ...]
    per_test: tuple[tuple[str, int], ...]
    only_per_test: tuple[tuple[str, int, float, float], ...]
    only_joint: tuple[tuple[str, int], ...]
    offset: float
    offset_ci: tuple[float, float]
    f_statistic: float


def misread_rules(verdict: Any, analysis: Any) -> MisreadRules:
    """Compare the joint model's misread rows with the per-test analysis' and refit the joint
    model without the union of both (one refit of the table).

    Parameters
    ----------
    verdict : RotorVerdict
        The verdict of :func:`judge_table` on the table.
    analysis : LawOfMotionAnalysis
        The per-test analysis of :func:`analyse_table` on the same table.

    Returns
    -------
    MisreadRules
        The rows each rule leaves out, those only one leaves out, and the offset refitted
        without all of them.

    See Also
    --------
    differences_table

    Examples
    --------
    A simulated table (two launches per group, 12 rows each, the symmetric group faster by
    0.3 rad/s²), judged and analysed test by test:

    >>> import dataclasses
    >>> import numpy as np
    >>> from rotor import (analyse_table, draw_scenario, judge_table, paper_rig,
    ...                    simulate_table)
    >>> rng = np.random.default_rng(1)
    >>> scn = dataclasses.replace(draw_scenario(rng, offset=0.3), n_marks=12, launches=2)
    >>> table = simulate_table(scn, rng)
    >>> verdict = judge_table(table, {"s": ["s1", "s2"], "as": ["as1", "as2"]}, fps=120.0,
    ...                       step=np.pi / 2, rig=paper_rig(), permutation=False)
    >>> analysis = analyse_table(table)
    >>> from rotor import misread_rules
    >>> rules = misread_rules(verdict, analysis)
    >>> rules.joint, rules.per_test
    ((('as1', 11),), (('as1', 11), ('as2', 12)))
    >>> print(f"offset without both: {rules.offset:.1f} rad/s²")
    offset without both: -0.3 rad/s²
    """
    data, fit = verdict.data, verdict.shared
    joint = tuple(verdict.misread_rows)
    per = tuple((t.name, int(k)) for t in analysis.tests if t.name in data.names
                for k in t.outliers)
    exclude = np.zeros(data.mask.shape, dtype=bool)
    only = []
    for name, k in per:
        i = data.names.index(name)
        j = np.flatnonzero(data.mask[i] & (data.k[i] == k))
        if j.size == 0:
            continue
        exclude[i, j[0]] = True
        if (name, k) not in joint:
            r = float(fit.residuals[i, j[0]])
            only.append((name, k, r * data.fps, r / float(fit.sigma[i, j[0]])))
    shared, groupwise = fit_table(data, exclude=exclude)
    off = group_offset(data, shared, minuend=1, subtrahend=0)
    return MisreadRules(joint, per, tuple(only), tuple(x for x in joint if x not in per),
                        off.value, (off.ci_low, off.ci_high), shared_track_f(shared, groupwise))
