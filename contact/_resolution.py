"""Resolution study: the same ball-on-plate contact on the scan coarsened 8x, 4x, 2x and native.

A rough contact's answers depend on the lateral resolution of the roughness it is solved
on. Hertz-scale quantities (the second-moment radius a*, the approach, the profile) are set
by the ball's curvature and the height distribution and converge as the pixel shrinks;
asperity-scale quantities (real area, peak pressure, yielded area) do not converge on a
self-affine surface, because every halving of the pixel adds slopes and curvatures that
were averaged away before.

Coarsening is a block average of the heights (:func:`contact._fields.block_average`): the
mean of each ``k x k`` block of native pixels, an honest low-pass that a coarser
instrument (a larger spot or stylus) would also apply. Every level is solved on the same
physical domain, centred on the same point of the scan (to within half a native pixel),
with the contact grid's pitch equal to the level's pixel, so that no interpolation adds a
second filter.

Per level the study reports a*, the approach, the real area, the perimeter-corrected area,
the yielded fraction, pmax, the combined rms slope (and, from :func:`rolling_study`,
lambda_eff). :func:`contact._convergence.trend` says whether each quantity has converged
(relative change below 2 % over the last halving), its observed order and Richardson
extrapolate when the changes shrink, and its power-law exponent against the pixel when
they do not.

Theory for the trends (small-load regime, Bush, Gibson & Thomas 1975, Wear 35:87;
Persson 2001, J. Chem. Phys. 115:3840; Hyun, Pei, Molinari & Robbins 2004, Phys. Rev. E
70:026117): the real area is A = kappa W / (E* h'_rms) with h'_rms the rms slope. For a
self-affine surface with Hurst exponent H, h'_rms ~ dx^(H-1), so A ~ dx^(1-H): the area
*shrinks* as the pixel shrinks and never converges until the surface's own small-scale
cut-off is resolved; the elastic peak pressure grows like h'_rms. The study measures the
rms slope of each level and gives the predicted area exponent from it.

The perimeter-corrected area is :func:`contact._fields.corrected_area` (Yastrebov, Anciaux &
Molinari 2015, Int. J. Solids Struct. 52:83; also used in their 2017 J. Mech. Phys. Solids
107:469).
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from contact._convergence import Trend, trend
from contact._errors import ContactInputError
from contact._fields import centred_blocks, corrected_area
from contact._material_pair import MaterialPair, modulus
from contact._roughstats import rms_slope
from contact._validate import positive
from contact.setups._composite import CompositeRoughness

#: The coarsening factors of the study, coarsest first.
FACTORS = (8, 4, 2, 1)


# -- the study ------------------------------------------------------------------------------

#: Quantity name -> unit, in the order of the study's table.
QUANTITIES = {
    "a_star": "m", "approach": "m", "area": "m^2", "corrected_area": "m^2",
    "yielded_fraction": "1", "pmax": "Pa", "pmax_elastic": "Pa", "sigma": "m", "rms_slope": "1",
    "profile_deviation": "1",
}

#: Criteria whose failure survives refinement although their quantity keeps moving: the
#: variance of block means never exceeds the variance of the pixels, so sigma (and with it
#: the GJM alpha) can only grow as the pixel shrinks; an alpha already above its limit
#: stays above it on any finer scan.
FAILURE_SURVIVES = {"alpha": "σ can only grow as the pixel shrinks, so this failure "
                             "survives refinement"}

#: hertz-check criterion -> the quantity it rests on (None: independent of the pixel).
CRITERION_QUANTITY = {
    "alpha": "sigma", "profile": "profile_deviation", "radius": "a_star",
    "approach": "approach", "yield": "yielded_fraction", "first_yield": None,
    "peak": "pmax_elastic", "area": "area", "resolution": None,
}


@dataclass(frozen=True, eq=False)
class StudyLevel:
    """One level of the study: the solution on the scan coarsened ``factor`` times.

    Attributes
    ----------
    factor : int
        Block side in native pixels.
    pixel : float
        The level's pixel (m), also the contact grid's pitch.
    grid : int
        Contact cells per side.
    values : dict of str to float
        The quantities of :data:`QUANTITIES` (SI) at this level.
    comparison, result, sweep
        The Hertz comparison and the solution (contact), or the sweep (rolling).
    seconds : float
        Wall time of the level.
    """

    factor: int
    pixel: float
    grid: int
    values: dict[str, float]
    comparison: Any = None
    result: Any = None
    sweep: Any = None
    seconds: float = 0.0


@dataclass(frozen=True, eq=False)
class ResolutionStudy:
    """The levels (coarsest first), the trends and the verdict's filtered criteria."""

    levels: tuple[StudyLevel, ...]
    trends: dict[str, Trend]
    side: float
    notes: tuple[str, ...] = ()
    settings: dict[str, Any] = field(default_factory=dict)

    @property
    def pixels(self) -> tuple[float, ...]:
        return tuple(lv.pixel for lv in self.levels)

    @property
    def converged(self) -> tuple[str, ...]:
        """Names of the quantities that converged."""
        return tuple(k for k, t in self.trends.items() if t.converged)

    @property
    def moving(self) -> tuple[str, ...]:
        """Names of the quantities that keep moving."""
        return tuple(k for k, t in self.trends.items() if not t.converged)

    @property
    def finest(self) -> StudyLevel:
        return self.levels[-1]

    def verdict(self) -> tuple[bool | None, tuple[str, ...], tuple[str, ...]]:
        """Hertz verdict at the finest level from converged quantities only.

        Returns ``(holds, reasons, left_out)``. ``reasons`` are the sentences of the
        criteria whose quantity converged (or does not depend on the pixel); ``left_out``
        names the criteria left out because their quantity keeps moving. ``holds`` is False
        when a decisive criterion among those used fails (that failure survives
        refinement), True when every decisive criterion was usable and passed, and None
        when nothing used fails but a decisive criterion had to be left out (undecided),
        or when the study has no Hertz comparison (rolling).
        """
        comp = self.finest.comparison
        if comp is None:
            return None, (), ()
        used, left, left_decisive = [], [], False
        for c in sorted(comp.criteria, key=lambda c: (c.passed or not c.decisive,
                                                      not c.decisive)):
            q = CRITERION_QUANTITY.get(c.name)
            if q is None or (q in self.trends and self.trends[q].converged):
                used.append(c)
            elif c.decisive and not c.passed and c.name in FAILURE_SURVIVES:
                used.append(dataclasses.replace(
                    c, reason=f"{c.reason} ({FAILURE_SURVIVES[c.name]})"))
            else:
                left_decisive |= c.decisive
                t = self.trends.get(q)
                why = (f"{100 * t.last_change:.3g} %" if t is not None
                       and math.isfinite(t.last_change) else "from 0")
                left.append(f"{c.name} ({q} keeps moving with the pixel: {why} over the "
                            "last halving)")
        if any(c.decisive and not c.passed for c in used):
            holds: bool | None = False
        else:
            holds = None if left_decisive else True
        return holds, tuple(c.reason for c in used), tuple(left)


def _plan(shape: tuple[int, int], dx: float, dy: float, side: float, factors: Sequence[int],
          max_grid: int) -> tuple[tuple[int, int], int]:
    """Native centre pixel and the native cell count of the common domain."""
    kmax = max(factors)
    if sorted(factors, reverse=True) != list(factors) or factors[-1] != 1:
        raise ContactInputError("the factors must decrease to 1, e.g. (8, 4, 2, 1)")
    cy, cx = (shape[0] - 1) // 2, (shape[1] - 1) // 2
    avail = min(cy, shape[0] - 1 - cy) * dy, min(cx, shape[1] - 1 - cx) * dx
    half = min(avail) - 2 * kmax * max(dx, dy)  # keep whole blocks on both sides
    step = 2 * kmax
    n_want = step * math.ceil(side / (step * dx))
    n_fit = step * math.floor(2 * half / (step * dx)) if half > 0 else 0
    n = min(n_want, n_fit)
    if n < 8 * kmax:
        raise ContactInputError(
            f"the scan ({shape[1]} x {shape[0]} pixels) is too small for a resolution study "
            f"coarsened {kmax}x: it needs at least {8 * kmax + 4 * kmax} pixels per side "
            "around the centre")
    if n > max_grid:
        raise ContactInputError(
            f"the native grid would be {n} x {n} cells (limit {max_grid}); use a smaller "
            "load or crop the scan")
    return (cy, cx), n


def _level_values(res: Any, comp: Any, pmax_elastic: float, level_z: np.ndarray,
                  pixel: float, hardness: float | None) -> dict[str, float]:
    nominal = math.pi * comp.hertz.a**2
    yielded = (res.plastic_area / nominal) if hardness is not None else 0.0
    return {
        "a_star": float(comp.effective_radius), "approach": float(comp.approach),
        "area": float(res.contact_area),
        "corrected_area": corrected_area(res.contact, res.dx, res.dy),
        "yielded_fraction": float(yielded), "pmax": float(res.pmax),
        "pmax_elastic": float(pmax_elastic),
        "sigma": float(np.std(level_z)), "rms_slope": rms_slope(level_z, pixel),
        "profile_deviation": float(comp.profile_deviation),
    }


def _coarse_maps(z: np.ndarray, dx: float, dy: float, centre: tuple[int, int], n1: int,
                 factors: Sequence[int], progress: Callable[[str], Any] | None, *,
                 level: bool) -> Iterator[tuple[int, CompositeRoughness, int, float]]:
    """Per factor k: the k x k block average of ``z`` around the study's centre pixel as a
    :class:`CompositeRoughness` (apex on the centre block), the level's grid n1 // k and the
    time the level started."""
    for k in factors:
        if progress is not None:
            progress(f"pixel x{k}")
        t0 = time.perf_counter()
        zc, (i, j) = centred_blocks(z, k, centre)
        px, py = dx * k, dy * k
        rough = CompositeRoughness(zc, px, py, centre=(j * px, i * py), level=level)
        yield k, rough, n1 // k, t0


def _levels(roughness: np.ndarray, dx: float, dy: float | None, factors: Sequence[int]
            ) -> tuple[np.ndarray, float, tuple[int, int]]:
    from contact._geometry import remove_plane
    from contact._sampling import fill_nan

    z = np.array(roughness, dtype=float)
    if z.ndim != 2:
        raise ContactInputError(f"the roughness must be a 2D map, got shape {z.shape}")
    if not np.isfinite(z).any():
        raise ContactInputError("the roughness map is NaN everywhere: nothing measured")
    dx = positive(dx, "the roughness pitch dx", "m")
    dy = dx if dy is None else positive(dy, "the roughness pitch dy", "m")
    # level once at native, so that every level sees the same surface
    z, _ = fill_nan(z)
    z, _ = remove_plane(z, dx, dy)
    return z, dy, z.shape


def sphere_study(
    radius: float,
    load: float,
    e_star: float | MaterialPair,
    roughness: np.ndarray,
    dx: float,
    dy: float | None = None,
    *,
    hardness: float | None = None,
    sigma: float | None = None,
    factors: Sequence[int] = FACTORS,
    size: float | None = None,
    max_grid: int = 4096,
    on_edge: str = "enlarge",
    tol: float = 1e-6,
    progress: Callable[[str], Any] | None = None,
) -> ResolutionStudy:
    """Solve a rough ball on a plate at each coarsening factor and fit the trends.

    Parameters
    ----------
    radius, load, e_star : float
        R (m), W (N), E* (Pa).
    roughness : ndarray (ny, nx)
        Composite roughness (m) at its native pitch (NaN filled by the nearest value).
    dx, dy : float
        Native pitch (m).
    hardness : float, optional
        Adds the elastic-plastic solve and the yielded fraction.
    sigma : float, optional
        Rms roughness for the GJM alpha (m); default the native map's rms.
    factors : sequence of int
        Coarsening factors, decreasing to 1 (default 8, 4, 2, 1).
    size : float, optional
        Domain side (m); default :func:`contact._geometry.auto_domain`'s side at the native
        pitch, limited to the scan.
    max_grid : int
        Largest native grid accepted (cells per side).
    on_edge, tol
        Passed to :meth:`contact.setups._ball_on_plate.SphereContact.solve`.
    progress : callable, optional
        Called with a short label before each level.
    """
    from contact._geometry import DomainSpec, auto_domain
    from contact._hertzcheck import compare_with_hertz
    from contact.bem._options import SolveOptions
    from contact.setups._ball_on_plate import SphereContact

    radius = positive(radius, "the ball radius", "m")
    load = positive(load, "the load", "N")
    e_star = positive(modulus(e_star), "E*", "Pa")
    z, dy, shape = _levels(roughness, dx, dy, factors)
    sig = float(np.std(z)) if sigma is None else float(sigma)
    if size is None:
        size = auto_domain(radius, load, e_star, roughness_rms=sig, roughness_dx=dx,
                           hardness=hardness, spec=DomainSpec(grid=16)).size
    centre, n1 = _plan(shape, dx, dy, size, tuple(factors), max_grid)
    notes: list[str] = []
    levels = []
    for k, rough, n, t0 in _coarse_maps(z, dx, dy, centre, n1, factors, progress,
                                        level=False):
        px = rough.dx
        problem = SphereContact(radius, e_star, load, roughness=rough,
                                domain=DomainSpec(grid=n, size=n * px, on_edge=on_edge))
        elastic = problem.solve(load, options=SolveOptions(tol=tol))
        plastic = None
        if hardness is not None:
            # on the elastic domain, warm-started from the elastic solution
            plastic = problem.solve(load, hardness=hardness, initial=elastic, on_edge="warn",
                                    options=SolveOptions(tol=tol))
        comp = compare_with_hertz(elastic, radius=radius, sigma=sig, plastic=plastic,
                                  hardness=hardness, scan_pixel=max(px, rough.dy))
        main = plastic if plastic is not None else elastic
        if problem.domain.n != n:
            notes.append(f"x{k}: the domain was enlarged to {problem.domain.n} cells")
        vals = _level_values(main, comp, elastic.pmax, rough.heights, px, hardness)
        levels.append(StudyLevel(factor=int(k), pixel=px, grid=problem.domain.n, values=vals,
                                 comparison=comp, result=main,
                                 seconds=time.perf_counter() - t0))
    pixels = [lv.pixel for lv in levels]
    trends = {q: trend(q, pixels, [lv.values[q] for lv in levels], unit=u)
              for q, u in QUANTITIES.items()}
    if hardness is None:
        trends.pop("yielded_fraction")
    notes.append(_area_theory(trends))
    return ResolutionStudy(levels=tuple(levels), trends=trends, side=n1 * dx,
                           notes=tuple(notes),
                           settings={"factors": list(factors), "load": load,
                                     "hardness": hardness, "native_pixel": dx})


def _area_theory(trends: dict[str, Trend]) -> str:
    """The area exponent that A ~ 1/h'_rms predicts from the measured rms-slope trend."""
    s = trends["rms_slope"].exponent
    a = trends["area"].exponent
    if not (math.isfinite(s) and math.isfinite(a)):
        return "area theory: not comparable (a zero value)"
    return (f"rms slope ~ pixel^{s:.2f} over the last halving, so A ~ 1/h'_rms predicts "
            f"area ~ pixel^{-s:.2f}; measured pixel^{a:.2f}")


def rolling_study(
    radius: float,
    e_star: float | MaterialPair,
    loads: Sequence[float],
    roughness: np.ndarray,
    dx: float,
    dy: float | None = None,
    *,
    factors: Sequence[int] = FACTORS,
    max_grid: int = 4096,
    progress: Callable[[str], Any] | None = None,
    **sweep_kwargs: Any,
) -> ResolutionStudy:
    """lambda_eff of :func:`contact._rolling.sphere_sweep` at each coarsening factor.

    The domain is sized for the largest load at the native pitch and kept for every
    level; ``sweep_kwargs`` go to :func:`~contact._rolling.sphere_sweep` (``dissipation``:
    model, hardness, alpha_h, share, kinematics...; ``options``); the roughness rms of
    the plastic band is the native map's unless the dissipation gives one.
    """
    from contact._dissipation import dissipation_of
    from contact._geometry import DomainSpec, auto_domain
    from contact._rolling import sphere_sweep

    e_star = positive(modulus(e_star), "E*", "Pa")
    loads = np.sort(np.asarray(loads, dtype=float))
    if loads.size < 3 or not np.all(loads > 0):
        raise ContactInputError("a rolling study needs at least 3 positive loads")
    z, dy, shape = _levels(roughness, dx, dy, factors)
    notes: list[str] = []
    sig = float(np.std(z))
    diss = dissipation_of(sweep_kwargs.pop("dissipation", None))
    if diss.roughness_rms is None:
        diss = dataclasses.replace(diss, roughness_rms=sig)
    size = auto_domain(radius, float(loads[-1]), e_star, roughness_rms=sig, roughness_dx=dx,
                       hardness=diss.hardness, spec=DomainSpec(grid=16)).size
    centre, n1 = _plan(shape, dx, dy, size, tuple(factors), max_grid)
    levels = []
    for k, rough, n, t0 in _coarse_maps(z, dx, dy, centre, n1, factors, progress,
                                        level=True):
        px = rough.dx
        sw = sphere_sweep(radius, e_star, loads, dissipation=diss, roughness=rough,
                          domain=DomainSpec(grid=n, size=n * px), **sweep_kwargs)
        lo, hi = sw.lambda_ci
        if sw.fit is None:
            notes.append(f"x{k}: no lambda_eff (" + "; ".join(sw.notes) + ")")
        vals = {"lambda_eff": float(sw.lambda_eff), "lambda_lo": float(lo),
                "lambda_hi": float(hi), "rms_slope": rms_slope(rough.heights, px)}
        levels.append(StudyLevel(factor=int(k), pixel=px, grid=n, values=vals, sweep=sw,
                                 seconds=time.perf_counter() - t0))
    pixels = [lv.pixel for lv in levels]
    trends = {q: trend(q, pixels, [lv.values[q] for lv in levels], unit="1")
              for q in ("lambda_eff", "rms_slope")}
    return ResolutionStudy(levels=tuple(levels), trends=trends, side=n1 * dx,
                           notes=tuple(notes),
                           settings={"factors": list(factors), "loads": loads.tolist()})
