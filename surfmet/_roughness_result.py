"""What a roughness evaluation returns, and what every result states about itself.

:class:`RoughnessResult` (the parameters with their units and the settings that say how
they were obtained), :func:`unit_caveats` (what the file does not state about its units)
and :func:`consistent_diagnosis` (the spike diagnosis restated with the result's own
numbers): shared by the areal path (:mod:`surfmet.roughness`) and the profile path
(:mod:`surfmet._profile_evaluation`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError


@dataclass(frozen=True, eq=False)
class RoughnessResult:
    """Outcome of :func:`roughness`.

    Attributes
    ----------
    kind : {"areal", "profile"}
    parameters : dict
        ``{symbol: (value, unit)}``; SI lengths, ratios in %, angles in degrees.
    settings : dict
        What was done (form, filters, cut-offs, edge treatment, window, spikes, diagnosis).
    spike_report : SpikeReport or None
        Present when spike removal ran.
    spike_diagnosis : SpikeDiagnosis or None
        Sq/Sa (Rq/Ra) diagnosis of the evaluated surface.
    file : str or None
        Source path when known.
    surface : Topography or None
        The evaluated areal surface (after window, spikes, F-operator and filters) that
        the S-parameters describe, for figures; not part of the JSON.
    analysis : profiles.ProfileAnalysis or None
        The profile engine's analysis behind R-parameters (primary, waviness, roughness),
        for figures; not part of the JSON.
    """

    kind: str
    parameters: dict[str, tuple[float, str]]
    settings: dict[str, Any] = field(default_factory=dict)
    spike_report: Any = None
    spike_diagnosis: Any = None
    file: str | None = None
    surface: Any = field(default=None, repr=False)
    analysis: Any = field(default=None, repr=False)

    def value(self, symbol: str) -> float:
        """The value of one parameter (SI)."""
        try:
            return self.parameters[symbol][0]
        except KeyError:
            raise SurfmetInputError(
                f"{symbol!r} was not computed; have {', '.join(self.parameters)}"
            ) from None

    def __repr__(self) -> str:
        # RoughnessResult(areal, 19 parameters: Sa=1.823 µm, Sq=2.416 µm, Sz=243.4 µm)
        from surfmet.units import format_quantity

        prefix = "S" if self.kind == "areal" else "R"
        shown = [f"{prefix}{s}={format_quantity(*self.parameters[prefix + s])}"
                 for s in ("a", "q", "z") if prefix + s in self.parameters]
        return (f"RoughnessResult({self.kind}, {len(self.parameters)} parameters"
                + (": " + ", ".join(shown) if shown else "") + ")")

    def _repr_html_(self) -> str:
        """Every parameter with its unit (Jupyter)."""
        from surfmet._display import quantity_table

        title = f"Roughness ({self.kind})" + (f": {self.file}" if self.file else "")
        return quantity_table(title, [(name, value, unit)
                                      for name, (value, unit) in self.parameters.items()])


def unit_caveats(scan: Any) -> list[str]:
    """What the file does not state about its units, to carry into every result: each unit
    assumed, or stated by the user (:meth:`surfmet._model.Calibration.caveats`).

    ``scan`` is a Topography or Profile (its pixel is named), or its metadata.
    """
    from surfmet._model import Calibration

    cal = getattr(scan, "calibration", None)
    return (cal if cal is not None else Calibration.of(scan or {})).caveats()


def consistent_diagnosis(diag: Any, values: dict[str, float], prefix: str,
                         spikes_removed: int | None) -> Any:
    """The spike diagnosis restated with the result's own q/a ratio and kurtosis.

    The diagnosis recomputes them about the sample mean; the profile parameters are taken
    about the mean line (ISO), so the two could print different Rku for one result. Here
    the table's values are used, and after a spike removal the advice is not "remove
    spikes" again but what the extreme heights left must be.
    """
    import dataclasses

    from surfmet._spikes import OUTLIER_SIGMAS, REMOVE_ADVICE, SUSPECT_SQ_OVER_SA

    q, a, k = values.get(f"{prefix}q"), values.get(f"{prefix}a"), values.get(f"{prefix}ku")
    if not (q and a and k is not None and np.isfinite(k)):
        return diag
    ratio = q / a
    if spikes_removed is None and (f"{ratio:.3g}", f"{k:.3g}") == (
            f"{diag.sq_over_sa:.3g}", f"{diag.kurtosis:.3g}"):
        return diag  # already says what the table says
    suspected = ratio > SUSPECT_SQ_OVER_SA or diag.n_outliers > 0
    names = f"{prefix}q, {prefix}z, {prefix}sk and {prefix}ku"
    head = (f"{prefix}q/{prefix}a = {ratio:.3g} (Gaussian surface: {diag.gaussian_ratio:.3g}; "
            f"real textures at most ~1.4); {prefix}ku = {k:.3g}; {diag.n_outliers} point(s) "
            f"lie beyond {OUTLIER_SIGMAS:g} robust sigma of the height distribution.")
    if not suspected:
        msg = (f"{prefix}q/{prefix}a = {ratio:.3g} (Gaussian surface: "
               f"{diag.gaussian_ratio:.3g}); no sign of spikes.")
    elif spikes_removed is None:
        msg = (f"{head} A few extreme heights (spikes, outliers, dust) dominate {names}: "
               + REMOVE_ADVICE)
    else:
        msg = (f"{head} This is after removing {spikes_removed} spike(s): the extreme "
               "heights left are not isolated spikes (wide dust, pits, scratches, steps or "
               f"non-measured edges read as heights), which spike removal does not touch; "
               f"inspect the scan before trusting {names}.")
    return dataclasses.replace(diag, sq_over_sa=ratio, kurtosis=float(k),
                               suspected=bool(suspected), message=msg)
