"""A flat scan's roughness: what is said, what is kept, what is left out.

Whether a scan is flat is one question with one answer,
:func:`profiles._form.is_flat` (what levelling leaves of a constant or planar scan is
rounding, under :data:`profiles._form.FLAT_RELATIVE` of its heights), asked by
``roughness`` here and by ``spectrum`` and the contact commands
(:func:`surfmet.mechanics.spectrum.prepare`), so that no command calls a scan flat that
another evaluates.

A flat scan has zero amplitude: its height and slope parameters are 0 (not the 1e-15 nm
of rounding left by the levelling), stated as such. Its shape parameters (skewness,
kurtosis, autocorrelation lengths, texture direction, peak densities, material-ratio
parameters, profile elements) are ratios of those zeros or need a height distribution:
they are undefined and left out, and a note says so.
"""

from __future__ import annotations

from typing import Any

AREAL_KEPT = ("Sa", "Sq", "Sp", "Sv", "Sz", "Sdq", "Sdr")
"""Areal parameters a flat scan keeps, each 0."""

PROFILE_KEPT = ("a", "q", "p", "v", "z", "t", "dq")
"""Profile parameters a flat profile keeps (after the R/P/W letter), each 0."""


def flat_parameters(parameters: dict[str, tuple[float, str]], kind: str
                    ) -> tuple[dict[str, tuple[float, str]], str]:
    """The parameters of a flat scan and the note that says why: (parameters, note).

    ``parameters`` are the computed ``{symbol: (value, unit)}``; the amplitude ones are
    set to 0 and the shape ones dropped.
    """
    if kind == "areal":
        kept = {k: (0.0, u) for k, (_, u) in parameters.items() if k in AREAL_KEPT}
    else:
        kept = {k: (0.0, u) for k, (_, u) in parameters.items() if k[1:] in PROFILE_KEPT}
    left = [k for k in parameters if k not in kept]
    note = ("the scan is flat (constant heights or a plane, to the file's rounding): its "
            "amplitude parameters are 0 and its shape parameters are undefined, left out"
            + (f" ({', '.join(left)})" if left else ""))
    return kept, note


def flat_diagnosis(diag: Any) -> Any:
    """The spike diagnosis of a flat scan: nothing to diagnose (its ratios are rounding)."""
    import dataclasses
    import math

    return dataclasses.replace(diag, sq_over_sa=math.nan, kurtosis=math.nan, n_outliers=0,
                               suspected=False,
                               message="the scan is flat: there are no heights to diagnose")
