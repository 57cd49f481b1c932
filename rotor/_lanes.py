"""Launch-level lanes: are the groups' tracks more different than the launches' within a
group are?

On a real plate each launch rolls on a lane of its own (a rotor released a few mm aside sees
the plate's wave shifted), so launches differ among themselves and one shared track misfits
them all even when the groups do not differ. The shared-track test
(:func:`rotor._joint.shared_track_f`) reads that as the groups differing. The lane
test compares the groups' tracks with the launches' own: the F statistic
:func:`rotor._joint.lane_f` on ``q_g`` (the track's degree, two groups) and ``q_l``
(``(launches - groups)`` degrees) degrees of freedom, its nominal p under F(q_g, q_l), and
that p's critical value calibrated by simulation with lanes in the null
(``benchmarks/rotor_lane_calibration.py``, the prior
:data:`rotor._tables.LANE_PRIOR`, ``lane_calibration.json``).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from scipy.stats import f as f_dist

from rotor._joint import JointFit, TableData, lane_f, launchwise_fit

__all__ = ["LANE_CALIBRATION_FILE", "LaneTest", "lane_calibration", "lane_p", "lane_test",
           "lane_words"]

LANE_CALIBRATION_FILE = Path(__file__).with_name("lane_calibration.json")


@lru_cache(maxsize=1)
def lane_calibration() -> dict:
    """The lane test's calibration with launch-level lanes in the null
    (``benchmarks/rotor_lane_calibration.py``).

    Returns
    -------
    dict
        The calibration as stored (``lane_calibration.json``, package data): the prior, the
        tables simulated and the lane test's null distribution of nominal p-values.

    See Also
    --------
    LaneTest, judge_table

    Examples
    --------
    >>> from rotor import lane_calibration
    >>> test = lane_calibration()["lane_test"]
    >>> print(test["level"], len(test["null_p_sorted"]), f"{test['critical_p']:.3f}")
    0.02 200 0.014
    """
    return json.loads(LANE_CALIBRATION_FILE.read_text())


def lane_p(p_nominal: float) -> float:
    """The calibrated p of a lane test's nominal p: the share of null tables as extreme."""
    null = lane_calibration()["lane_test"]["null_p_sorted"]
    return (1 + sum(v <= p_nominal for v in null)) / (len(null) + 1)


@dataclass(frozen=True)
class LaneTest:
    """Do the groups' tracks differ more than the launches' within a group do?

    ``f`` (:func:`rotor._joint.lane_f`) on ``q_g``/``q_l`` degrees of freedom, its
    ``p_nominal`` under F(q_g, q_l) against ``p_critical`` (the 2 % quantile of the nominal p
    over null tables simulated with launch-level lanes, ``lane_calibration.json``), its
    calibrated ``p``; ``launch_f``: the launch-specific tracks' drop of chi² per parameter
    over their chi² per degree of freedom (well above 1: the launches differ among
    themselves, each on a lane of its own).

    See Also
    --------
    judge_table : its ``lanes``.
    lane_f, lane_calibration

    Examples
    --------
    In Table 3 the groups' tracks differ more than the launches' do, beyond the calibrated
    2 % point:

    >>> import numpy as np
    >>> from rotor import judge_table, paper_rig, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> verdict = judge_table(table3(), groups, fps=120.0, step=np.pi / 2, rig=paper_rig(),
    ...                       permutation=False)
    >>> lanes = verdict.lanes
    >>> print(f"F = {lanes.f:.2f} on {lanes.q_g} and {lanes.q_l} dof,"
    ...       f" p = {lanes.p_nominal:.4f} < {lanes.p_critical:.3f}")
    F = 5.28 on 4 and 16 dof, p = 0.0066 < 0.014
    """

    f: float
    q_g: int
    q_l: int
    p_nominal: float
    p_critical: float
    p: float
    launch_f: float

    @property
    def groups_differ(self) -> bool:
        return not self.p_nominal >= self.p_critical


def lane_test(shared: JointFit, groupwise: JointFit, data: TableData) -> LaneTest:
    """The lane test of a table's shared and group-specific fits (a launch-specific fit of
    the same degree is made here)."""
    lw = launchwise_fit(data, shared)
    f = lane_f(shared, groupwise, lw)
    q_g = groupwise.layout.n_params - shared.layout.n_params
    q_l = lw.layout.n_params - groupwise.layout.n_params
    dof = lw.n_used - lw.layout.n_params
    launch_f = (max(groupwise.chi2 - lw.chi2, 0.0) / q_l / (lw.chi2 / dof)
                if q_l > 0 and dof > 0 and lw.chi2 > 0 else math.nan)
    p_nom = float(f_dist.sf(f, q_g, q_l)) if math.isfinite(f) else math.nan
    crit = float(lane_calibration()["lane_test"]["critical_p"])
    return LaneTest(f, q_g, q_l, p_nom, crit, lane_p(p_nom if math.isfinite(p_nom) else 0.0),
                    launch_f)


def lane_words(code: str, lanes: LaneTest, f: float) -> str:
    """The lane test's clause, before the verdict's own words when no one track explains
    all launches."""
    cal = lane_calibration()["lane_test"]
    floor = 1.0 / (len(cal["null_p_sorted"]) + 1)
    p = (f"<= {floor:.2g} (the calibration's floor)" if lanes.p <= floor * (1 + 1e-9)
         else f"= {lanes.p:.2g}")
    test = (f"lane F = {lanes.f:.2f} on {lanes.q_g} and {lanes.q_l} dof, nominal p = "
            f"{lanes.p_nominal:.2g} against {lanes.p_critical:.2g}, the "
            f"{float(cal['level']) * 100:g} % point calibrated with launch-level lanes in "
            f"the null; calibrated p {p}")
    if code == "undetermined":
        return (f"{code}: the groups' tracks differ more than the launches' within a group "
                f"do ({test}), and ")
    return (f"{code}: the launches ran on lanes of their own (no one track explains them all, "
            f"F = {f:.1f}), but the groups' tracks differ no more than the launches' within a "
            f"group do ({test}), so the groups are compared by their offsets; ")
