"""The design's own evidence: exact permutation tests over the launches' group labels.

Under the null hypothesis that the collar's position makes no difference, the group labels
of the launches are exchangeable: every split of the launches into groups of the table's
sizes is as likely to show the statistic as the real one. The exact permutation p-value is
the share of splits whose statistic is at least the real one's, the real split included,
so it can be no smaller than ``1 / n_splits``: with 3 + 3 launches there are
``C(6, 3) / 2 = 10`` distinct splits (a split and its mirror give the same statistics), and
``p >= 0.1`` whatever the data. The model-calibrated p-values (:mod:`rotor._verdict`)
assume the simulation's prior; this one assumes only exchangeability, and so bounds what the
design itself can show.

Two statistics: the shared-track F (:func:`rotor._joint.shared_track_f`; each split
refits the group-specific tracks, :func:`rotor._joint.groupwise_fit`) and the
absolute group offset (the difference of the groups' mean launch offsets under the shared
track, which does not depend on the labels: no refit).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from rotor._joint import JointFit, TableData, groupwise_fit, shared_track_f

__all__ = ["MAX_SPLITS", "PermutationTest", "label_splits", "permutation_test"]

MAX_SPLITS = 252
"""Most splits enumerated exactly (5 + 5 launches); beyond, a fixed-seed random sample."""
_TIE = 1e-9


@dataclass(frozen=True)
class PermutationTest:
    """``f_p``/``offset_p``: the permutation p-values of the shared-track F and of the
    absolute offset; ``f_values``/``offsets``: each split's statistic (the real split
    first); ``n_splits``; ``exact``: every split enumerated (else a sample);
    ``f_rank``: the real F's rank among the splits (1: the largest)."""

    f_p: float
    offset_p: float
    f_values: tuple[float, ...]
    offsets: tuple[float, ...]
    n_splits: int
    exact: bool

    @property
    def smallest_p(self) -> float:
        """The smallest p the design allows: one split in ``n_splits``."""
        return 1.0 / self.n_splits

    @property
    def f_rank(self) -> int:
        return 1 + sum(f > self.f_values[0] * (1 + _TIE) for f in self.f_values[1:])


def label_splits(group_of_launch: np.ndarray, most: int = MAX_SPLITS,
                 seed: int = 0) -> tuple[list[np.ndarray], bool]:
    """The distinct splits of the launches into two groups of the table's sizes, the real
    one first, as label vectors (0/1); and whether all of them are there (else ``most`` of
    them, the real one and a fixed-seed random sample of the others)."""
    g = np.asarray(group_of_launch)
    n, n0 = g.size, int(np.sum(g == 0))
    real = frozenset(np.flatnonzero(g == 0).tolist())

    def key(members: frozenset) -> frozenset:
        # a split and its mirror are one split when the groups have the same size
        other = frozenset(range(n)) - members
        return min(members, other, key=sorted) if n0 == n - n0 else members

    total = math.comb(n, n0) // (2 if n0 == n - n0 else 1)
    seen = {key(real)}
    out = [g.copy()]
    if total <= most:
        combos = (frozenset(c) for c in itertools.combinations(range(n), n0))
    else:
        rng = np.random.default_rng(seed)
        combos = (frozenset(rng.choice(n, n0, replace=False).tolist()) for _ in range(100 * most))
    for c in combos:
        k = key(c)
        if k in seen:
            continue
        seen.add(k)
        lab = np.ones(n, dtype=int)
        lab[sorted(c)] = 0
        out.append(lab)
        if len(out) >= min(total, most):
            break
    return out, len(out) == total


def _offset(delta: np.ndarray, labels: np.ndarray) -> float:
    return float(delta[labels == 1].mean() - delta[labels == 0].mean())


def permutation_test(data: TableData, shared: JointFit, groupwise: JointFit | None = None,
                     most: int = MAX_SPLITS) -> PermutationTest:
    """The permutation p-values of a table's two groups; ``groupwise``: the real split's
    group-specific fit when already made (it is refitted otherwise)."""
    splits, exact = label_splits(data.group_of_launch, most)
    delta = shared.layout.split(shared.x)[1]
    fs, offs = [], []
    for i, lab in enumerate(splits):
        gw = groupwise if (i == 0 and groupwise is not None) else groupwise_fit(
            data, shared, lab, 2)
        fs.append(shared_track_f(shared, gw))
        offs.append(_offset(delta, lab))
    f0, o0 = fs[0], abs(offs[0])
    f_p = sum(f >= f0 * (1 - _TIE) for f in fs) / len(fs) if math.isfinite(f0) else math.nan
    o_p = sum(abs(o) >= o0 * (1 - _TIE) for o in offs) / len(offs)
    return PermutationTest(float(f_p), float(o_p), tuple(fs), tuple(offs), len(fs), exact)
