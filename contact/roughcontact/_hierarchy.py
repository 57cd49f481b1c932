"""Which model holds? Hertz, Greenwood-Tripp and its elastic-plastic variant against the BEM.

Each model's prediction is measured against the boundary-element solution (the reference)
with the metrics of :mod:`contact._fields`:

- ``radius_error``: a*_model / a*_BEM - 1, with a* the second-moment radius
  sqrt(5/2 <r²>_p) (:func:`contact._fields.effective_radius`);
- ``profile_error``: the area-weighted rms, over the BEM's radial bins within 1.5 a0, of
  the azimuthally averaged BEM pressure minus the model's pressure averaged over the same
  cells, in units of the Hertz p0 (for Hertz this is the existing ``profile_deviation``).

The verdict names the simplest model within tolerance, in the order hertz <
greenwood_tripp < greenwood_tripp_plastic < bem: Hertz when :mod:`contact._hertzcheck`'s
verdict holds, otherwise the first extended model whose radius and profile errors are both
within the limits that verdict used (its ``radius`` and ``profile`` criteria, i.e.
:data:`contact._hertzcheck.RADIUS_TOLERANCE` and ``PROFILE_TOLERANCE``), otherwise the BEM
itself.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from contact._fields import PROFILE_EXTENT, profile_deviation, radial_average

if TYPE_CHECKING:
    from contact._hertzcheck import HertzComparison

#: The hierarchy, simplest first.
ORDER = ("hertz", "greenwood_tripp", "greenwood_tripp_plastic", "bem")


@dataclass(frozen=True, eq=False)
class ModelPrediction:
    """One model's prediction and its errors against the BEM.

    ``r``, ``p``: its radial pressure profile (m, Pa); ``radius_error`` and
    ``profile_error`` are 0 for the BEM itself; ``radius_limit`` and ``profile_limit`` are
    the Hertz verdict's limits on them.
    """

    name: str
    a_star: float
    approach: float
    peak: float
    r: np.ndarray
    p: np.ndarray
    radius_error: float
    profile_error: float
    radius_limit: float
    profile_limit: float

    @property
    def within_tolerance(self) -> bool:
        return (abs(self.radius_error) <= self.radius_limit
                and self.profile_error <= self.profile_limit)


@dataclass(frozen=True, eq=False)
class ModelHierarchy:
    """All models, the named one and the reasons (sentences with numbers)."""

    models: dict[str, ModelPrediction]
    verdict: str
    reasons: tuple[str, ...]
    left_out: dict[str, str] = field(default_factory=dict)

    def gain(self, name: str, metric: str = "radius") -> float:
        """Fraction of Hertz's error that model ``name`` removes (1 = all, < 0 = worse)."""
        key = "radius_error" if metric == "radius" else "profile_error"
        e_h = abs(getattr(self.models["hertz"], key))
        e_m = abs(getattr(self.models[name], key))
        return (1.0 - e_m / e_h) if e_h > 0 else 0.0


class _Tabulated:
    """A radial pressure p(r) given on points, as an object with ``pressure(r)``."""

    def __init__(self, pressure: Any) -> None:
        self.pressure = pressure


def _limits(comp: HertzComparison) -> dict[str, float]:
    """The Hertz verdict's limits on the radius and profile errors."""
    return {"radius_limit": comp.criterion("radius").limit,
            "profile_limit": comp.criterion("profile").limit}


def _measure(name: str, comp: HertzComparison, ref: Any, model_pressure: Any, a_star: float,
             approach: float, peak: float, r: np.ndarray, p: np.ndarray) -> ModelPrediction:
    hz = comp.hertz
    prof = comp.profile
    r_max = float(prof.r[-1]) + 0.5 * prof.width
    avg = radial_average(np.asarray(ref.pressure), ref.x, ref.y, width=prof.width,
                         r_max=r_max, hertz=_Tabulated(model_pressure))
    err = profile_deviation(avg, hz.p0, PROFILE_EXTENT * hz.a)
    # a reference loaded on a single cell has a* = 0: no radius to measure against (NaN,
    # never within tolerance)
    a_ref = comp.effective_radius
    radius_error = float(a_star / a_ref - 1.0) if a_ref > 0 else math.nan
    return ModelPrediction(name=name, a_star=float(a_star), approach=float(approach),
                           peak=float(peak), r=np.asarray(r, float), p=np.asarray(p, float),
                           radius_error=radius_error,
                           profile_error=float(err), **_limits(comp))


def model_hierarchy(comp: HertzComparison, reference: Any, extended: dict[str, Any],
                    left_out: dict[str, str] | None = None) -> ModelHierarchy:
    """Measure Hertz and the extended models against the BEM solution and name the simplest.

    Parameters
    ----------
    comp : HertzComparison
        :func:`contact._hertzcheck.compare_with_hertz`'s outcome on ``reference``.
    reference : ContactResult
        The BEM solution compared with (elastic-plastic when a hardness was given).
    extended : dict
        ``{"greenwood_tripp": GreenwoodTripp, "greenwood_tripp_plastic": ...}`` (either may
        be absent).
    left_out : dict, optional
        ``{name: reason}`` of the models that could not be evaluated; each is named in
        the reasons with why.
    """
    hz = comp.hertz
    prof = comp.profile
    models: dict[str, ModelPrediction] = {}
    rh = np.linspace(0.0, hz.a, 61)
    models["hertz"] = _measure("hertz", comp, reference, hz.pressure, hz.a, hz.delta, hz.p0,
                               rh, hz.pressure(rh))
    for name in ORDER[1:3]:
        sol = extended.get(name)
        if sol is not None:
            models[name] = _measure(name, comp, reference, sol.pressure, sol.a_star,
                                    sol.approach, sol.peak, sol.r, sol.p)
    models["bem"] = ModelPrediction(
        name="bem", a_star=comp.effective_radius, approach=comp.approach, peak=comp.pmax,
        r=prof.r, p=prof.p, radius_error=0.0, profile_error=0.0, **_limits(comp))
    if comp.hertz_holds:
        verdict = "hertz"
    else:
        verdict = next((n for n in ORDER[1:3] if n in models and models[n].within_tolerance),
                       "bem")
    reasons = []
    h = models["hertz"]
    lim = _limits(comp)
    for name, m in models.items():
        if name == "bem":
            continue
        ok = m.within_tolerance
        text = (f"{name}: a* = {m.a_star * 1e6:.4g} µm against the BEM's "
                f"{comp.effective_radius * 1e6:.4g} µm ({100 * m.radius_error:+.3g} %), "
                f"profile off the BEM by {100 * m.profile_error:.3g} % of p0 "
                f"({'within' if ok else 'beyond'} {100 * lim['radius_limit']:g} % / "
                f"{100 * lim['profile_limit']:g} %)")
        if name != "hertz" and (h.radius_error or h.profile_error):
            hyp = models[name]
            g_r = 1 - abs(hyp.radius_error) / abs(h.radius_error) if h.radius_error else 0.0
            g_p = 1 - hyp.profile_error / h.profile_error if h.profile_error else 0.0
            text += (f"; removes {100 * g_r:.3g} % of Hertz's radius error and "
                     f"{100 * g_p:.3g} % of its profile error")
        reasons.append(text)
    left_out = dict(left_out or {})
    reasons += [f"{name}: not evaluated ({why})" for name, why in left_out.items()]
    head = _headline(comp, models, verdict)
    return ModelHierarchy(models=models, verdict=verdict, reasons=(head, *reasons),
                          left_out=left_out)


def _headline(comp: HertzComparison, models: dict[str, ModelPrediction], verdict: str
              ) -> str:
    """Why this model was named, in agreement with the Hertz verdict's own criteria."""
    failed = [c for c in comp.criteria if c.decisive and not c.passed]
    if not comp.judged:
        res = comp.criterion("resolution")
        return (f"the scans do not resolve the contact ({res.value:.2g} pixels per Hertz "
                f"radius, at least {res.limit:g}): no model can be judged against the "
                "boundary elements, which see the scan interpolated between its points")
    if verdict == "hertz":
        return "Hertz holds (α, profile, radius, approach and yield within their limits)"
    fails = "; ".join(c.name for c in failed)
    if verdict != "bem":
        return f"{verdict} is the simplest model within tolerance (Hertz fails: {fails})"
    if models["hertz"].within_tolerance:
        return (f"hertz is within tolerance of the boundary elements on a* and profile but "
                f"fails the verdict's other criteria ({fails}), and no extended model is "
                "within tolerance: the boundary elements describe this contact")
    return ("no model of the hierarchy is within tolerance: only the boundary elements "
            "describe this contact")


def gains(h: ModelHierarchy, name: str) -> tuple[float, float]:
    """(radius gain, profile gain) of model ``name`` over Hertz; NaN when absent."""
    if name not in h.models:
        return math.nan, math.nan
    return h.gain(name, "radius"), h.gain(name, "profile")
