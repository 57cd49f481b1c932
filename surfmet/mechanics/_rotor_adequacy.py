"""The rotor's adequacy check in words: what the check of the chosen model says about one
launch (:func:`rotor.check_adequacy`), the one text ``surfmet rotor`` prints, its JSON
carries (``adequacy.summary``) and the paper's example shows.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rotor import AdequacyCheck, TestReport

__all__ = ["a_p", "adequacy_sentences", "named_wave_of"]


def adequacy_sentences(t: TestReport) -> list[str]:
    """What the adequacy check says about one test, in words."""
    from rotor import EXTENSION, MIN_ROWS

    a = t.adequacy
    if a is None or not a.judged:
        return [f"not judged: {int(sum(t.used))} rows, fewer than the {MIN_ROWS} the "
                "adequacy calibration starts at"]
    p = (f"p {a.p_value:.3g}" if math.isfinite(a.p_value) else "uncalibrated")
    if math.isfinite(a.p_value) and a.p_value <= a.p_floor:
        p = f"p <= {a.p_floor:.3g}, the calibration's floor"
    stats = f"runs z {a.runs_z:+.2f}, lag-1 {a.lag1:+.2f}, periodogram share {a.wave_share:.2f}"
    w = a.residual
    named = named_wave_of(t)
    lines = []
    if named is not None:
        lines.append(f"a plate wave is named ({t.selected}): period {named.revolutions:.2f} rev "
                     f"({named.track_length * 1e3:.0f} mm of track), amplitude "
                     f"{named.amplitude:.3f} rad/s²; the in-family choice {t.family_choice} did "
                     f"not explain the data (p {a_p(t.family_adequacy)})")
    if a.adequate:
        lines.append(f"adequate: what {t.selected} leaves looks like reading noise ({p}; {stats})")
    else:
        lines.append(f"NOT ADEQUATE: the chosen model {t.selected} does not explain the data "
                     f"({p}; {stats})")
        if w is not None:
            lines.append(f"  what is left: a wave of period {w.revolutions:.2f} rev "
                         f"({w.track_length * 1e3:.0f} mm of track), amplitude "
                         f"{w.amplitude:.3f} rad/s², {100 * w.share:.0f} % of the residual")
    shown = named if named is not None else (w if not a.adequate else None)
    if shown is not None and shown.unbalance_like:
        lines.append("  its period is one revolution within the resolution: a plate wave and "
                     "an unbalance look the same in one launch")
    elif "unbalance" in t.effect:
        lines.append("  (an unbalance has the form of a plate wave of one revolution: one launch "
                     "cannot tell them apart)")
    sm = t.smooth
    if sm is not None:
        lines.append(f"  unexplained smooth deviation: {sm.modes} Legendre mode(s) of the "
                     f"rotation angle beat {sm.model} by {sm.delta_bic:.1f} in BIC; largest "
                     f"{sm.amplitude:.3f} rad/s², {sm.at_angle / (2 * math.pi):.2f} rev after "
                     "the first mark (no effect of the family or plate wave explains it)")
    if t.extension_tried and t.selected not in EXTENSION:
        lines.append(f"  plate-wave models tried ({', '.join(t.extension_tried)}): none won "
                     "by the selection margin")
    return lines


def named_wave_of(t: TestReport) -> Any:
    """The plate wave named in one launch's chosen model, or None."""
    from rotor import named_wave

    span = float(max(t.angles) - min(t.angles))
    return named_wave(t.fit, span)


def a_p(a: AdequacyCheck | None) -> str:
    """An adequacy check's calibrated p in words (``-`` when there is none)."""
    return "-" if a is None or not math.isfinite(a.p_value) else f"{a.p_value:.3g}"


