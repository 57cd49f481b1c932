"""Model selection by BIC with a nested margin, and its calibration by simulation.

BIC is ``-2 ln L + (p + 2) ln n``; a model nested in the minimum-BIC one wins unless the
richer is better by more than ``margin`` (default 6, "strong" evidence in Kass & Raftery's
scale). The selection is calibrated by simulation over the declared range (frame rate
30-1000 fps, mark step 15-360 deg, 10-60 rows, eps0 0.5-5 rad/s², start anywhere in the
step, 0-2 misread rows): ``benchmarks/rotor_calibration.py`` measures the false-effect rate
(``docs/rotor_calibration.md``) and writes the false-alarm probability against the evidence
(``effect_calibration.json``, package data) that qualifies each verdict.

References
----------
Schwarz G. (1978) Estimating the dimension of a model. Ann. Stat. 6:461-464.
Kass R.E., Raftery A.E. (1995) Bayes factors. J. Am. Stat. Assoc. 90:773-795.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from contact._errors import ContactInputError
from rotor._family import MODELS, SELECTABLE, ModelFit, ancestors, is_nested

__all__ = [
    "BIC_MARGIN",
    "WEAK_DELTA_BIC",
    "WEAK_FALSE_ALARM",
    "false_alarm_floor",
    "false_alarm_probability",
    "select_by_bic",
    "select_model",
    "verdict_evidence",
]

BIC_MARGIN = 6.0
"""BIC margin a richer model must win by over a model nested in it."""


def select_model(fits: Mapping[str, ModelFit], margin: float = BIC_MARGIN) -> str:
    """The BIC choice among :data:`SELECTABLE`; a model nested in it wins instead unless the
    richer one is better by more than ``margin``."""
    bics = {m: fits[m].bic for m in SELECTABLE if m in fits and math.isfinite(fits[m].bic)}
    if not bics:
        raise ContactInputError("no model could be fitted")
    return select_by_bic(bics, margin)


def select_by_bic(bics: Mapping[str, float], margin: float) -> str:
    best = min(bics, key=bics.get)
    changed = True
    while changed:
        changed = False
        for m in sorted(bics, key=lambda k: (len(MODELS[k].free), bics[k])):
            if is_nested(m, best) and bics[m] < bics[best] + margin:
                best, changed = m, True
                break
    return best


_CALIBRATION: dict | None = None
WEAK_FALSE_ALARM = 0.01
WEAK_DELTA_BIC = 10.0


def false_alarm_probability(delta_bic: float) -> float:
    """Calibrated probability that a column without any effect shows ``delta_bic`` or more
    evidence for one (BIC of the best no-effect model minus that of the best effect model).

    From ``rotor/effect_calibration.json``, written by ``benchmarks/rotor_calibration.py``
    (simulated clean columns over the declared range of frame rate, mark step, rows,
    eps0, start angle and misread rows); the value at the largest tabulated ``delta_bic``
    not above the argument (conservative between grid points), 1 below the table.
    """
    global _CALIBRATION
    if _CALIBRATION is None:
        import json
        from pathlib import Path

        _CALIBRATION = json.loads(
            (Path(__file__).resolve().parent / "effect_calibration.json").read_text())
    if not math.isfinite(delta_bic):
        return math.nan
    d = np.asarray(_CALIBRATION["delta_bic"], float)
    pfa = np.asarray(_CALIBRATION["false_alarm"], float)
    i = int(np.searchsorted(d, delta_bic, side="right")) - 1
    return 1.0 if i < 0 else float(pfa[i])


def false_alarm_floor() -> float:
    """The smallest false-alarm probability the calibration can state (its resolution:
    ``1/(n + 1)`` for ``n`` simulated clean columns).

    Returns
    -------
    float
        The smallest tabulated false-alarm probability.

    See Also
    --------
    TestReport : its ``false_alarm`` is calibrated against this table.

    Examples
    --------
    The calibration simulated 360 clean columns:

    >>> from rotor import false_alarm_floor
    >>> print(f"{false_alarm_floor():.5f} = 1/{1 / false_alarm_floor():.0f}")
    0.00277 = 1/361
    """
    false_alarm_probability(0.0)  # loads the table
    return float(min(_CALIBRATION["false_alarm"]))


def verdict_evidence(fits: Mapping[str, ModelFit], selected: str) -> tuple[float, float]:
    """``(delta_bic, effect_evidence)`` of a verdict (see :class:`TestReport`)."""
    simpler = [fits[m].bic for m in ancestors([selected]) - {selected}
               if m in fits and m in SELECTABLE and math.isfinite(fits[m].bic)]
    delta = min(simpler) - fits[selected].bic if simpler else math.nan
    none = [fits[m].bic for m in SELECTABLE if m in fits and MODELS[m].effect == "none"]
    eff = [fits[m].bic for m in SELECTABLE if m in fits and MODELS[m].effect != "none"]
    evidence = min(none) - min(eff) if none and eff else math.nan
    return float(delta), float(evidence)
