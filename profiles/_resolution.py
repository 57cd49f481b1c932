"""How finely a scan must be sampled to carry a filter or a sampling length: the one rule.

A Gaussian filter of nesting index λ (a profile's λs or λc, an areal S- or L-filter) is
realised on the samples. With λ under a few sampling distances its weights cover one or
two points and the filter passes the data unchanged: a 1 µm L-filter on a 5 µm pixel
leaves an S-L surface of zeros (Sa = Sq = Sz = 0), a 1 µm S-filter the scan itself.

The rule (:data:`MIN_STEPS`): a nesting index must span at least three sampling
distances. Source: ISO 25178-3:2012, Table 1, which pairs every S-filter nesting index
with a maximum sampling distance of about a third of it (2.5 µm with 0.8 µm, 8 µm with
2.5 µm, 25 µm with 8 µm). ISO 3274:1996 (Table 1) asks more of a stylus profile's λs, a
fifth (2.5 µm with 0.5 µm); that is a conformance rule, applied where λs is chosen
automatically (:func:`profiles._analysis.analyze_profile`, ``ls="auto"``), not the floor
below which a filter cannot be carried at all.

A sampling length is numerically a cut-off (ISO 4287:1997, 3.1.9; ISO 21920-2: lr = λc),
so the same floor holds for it: each of the ``n_sampling`` parts over which Rp, Rv, Rz
(and with ISO 4287 every parameter) are taken must span three sampling distances, else
a part holds one point or none and Rz is 0 beside a non-zero Rt, Rq equals Ra.

Both checks return the one-line message (or None), so that each layer raises its own
error type (the engine never imports ``surfmet``).
"""

from __future__ import annotations

from profiles._arrays import length_text

MIN_STEPS = 3
"""Sampling distances a nesting index or a sampling length must span (ISO 25178-3 Table 1)."""

RULE = "ISO 25178-3 Table 1: a nesting index or sampling length spans 3 sampling distances"
"""The rule as stated in messages and documentation."""


def _spans(length: float, step: float) -> bool:
    return length >= MIN_STEPS * step * (1 - 1e-9)


def nesting_index_problem(value: float, step: float, what: str) -> str | None:
    """Why a filter of nesting index ``value`` cannot be carried by sampling ``step``.

    Parameters
    ----------
    value, step : float
        Nesting index (cut-off) and sampling distance, metres (for an areal scan the
        coarser of its two pixel sides).
    what : str
        How the message names the filter (e.g. ``"λc (L-filter nesting index)"``).

    Returns
    -------
    str or None
        The one-line refusal, or None when the sampling carries the filter.
    """
    if _spans(value, step):
        return None
    return (f"{what} = {length_text(value)} spans {value / step:.3g} sampling distances "
            f"({length_text(step)} each): its Gaussian weights cover one or two points, no "
            f"filter. Use at least {length_text(MIN_STEPS * step)} ({RULE}), or a finer scan")


def sampling_length_problem(length: float, n_sampling: int, step: float) -> str | None:
    """Why ``n_sampling`` sampling lengths cannot divide an evaluation length ``length``.

    Returns the one-line refusal, or None when each part spans :data:`MIN_STEPS` steps.
    """
    part = length / n_sampling
    if _spans(part, step):
        return None
    most = max(int(length / (MIN_STEPS * step) * (1 + 1e-9)), 1)
    return (f"{n_sampling} sampling lengths of the {length_text(length)} evaluated would be "
            f"{length_text(part)} each, {part / step:.3g} sampling distances "
            f"({length_text(step)} each): use at most {most} ({RULE})")
