"""Beyond the closed family: the plate-wave models, tried when the family's choice does not
explain a column, and the second look at misread rows that a smooth wave may explain.

The family of :mod:`rotor._family` is closed. When the adequacy check
(:mod:`rotor._adequacy`) rejects the in-family choice, the plate-wave models
(:data:`rotor._family.EXTENSION`: the chosen model's decay with a wave of free period)
are fitted from the residual periodogram's two highest peaks and the selection is made again
under the same rule (BIC with the nested margin; each wave model has its unbalance
counterpart as a parent). Because the wave models are only tried on columns the check
rejects, a clean column is given a wave at most at the check's calibrated false-alarm rate.

Misread rows are kept only where no smooth model explains them: when rows are flagged, a
linearised wave on every row (:func:`rotor._adequacy.smooth_deletion_z`) looks for a
period under which a flagged row is within the misread threshold; if one is found, the wave
model is fitted and the misread search's backward step, under that model, puts back the rows
it predicts. The second look never flags a row the in-family search let stand (a smooth
model explained it).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rotor._adequacy import (
    AdequacyCheck,
    scan_peaks,
    smooth_deletion_z,
    wave_scan,
)
from rotor._family import EXTENSION, MODELS, ModelFit
from rotor._fitting import fit_all_models
from rotor._forward import PARAM_NAMES, crossing_times
from rotor._misreads import MisreadSearch, find_misread_rows
from rotor._selection import select_model

__all__ = ["GRID_STARTS", "RUN_STARTS", "Extended", "extend_family", "start_indices",
           "wave_models_for"]

GRID_STARTS = 6
"""Periods, evenly spaced in frequency over the resolvable range, each wave fit may start
from besides the periodogram's highest peak."""
RUN_STARTS = 2
"""Starting points each wave fit runs to convergence: the periodogram's peak and the grid
period of least cost."""

_WAVE_OF = {"position": ("position+wave",), "speed": ("speed+wave",),
            "position+speed": ("position+wave", "speed+wave")}


@dataclass(frozen=True)
class Extended:
    """The outcome of :func:`extend_family`: the fits (core and any wave models), the
    choice, the misread rows (mask) and the misread search that judged them last (None if
    unchanged); ``tried`` names the wave models fitted."""

    fits: dict[str, ModelFit]
    chosen: str
    outliers: np.ndarray
    search: MisreadSearch | None
    tried: tuple[str, ...]


def wave_models_for(chosen: str, n_used: int) -> list[str]:
    """The wave models to try after ``chosen``: the chosen decay with a wave, or ``wave``
    alone; those the rows can support."""
    names = list(_WAVE_OF.get(MODELS[chosen].decay_form or "", ()))
    names = [m for m in names if n_used > len(MODELS[m].free) + 2] or ["wave"]
    return [m for m in names if n_used > len(MODELS[m].free) + 2]


def start_indices(scan, grid: int = GRID_STARTS) -> tuple[list[int], list[int]]:
    """Scan indices the wave fits may start from: the periodogram's highest peak, and
    ``grid`` periods evenly spaced in frequency over the scan (a fixed grid, so that the
    outcome does not hinge on which of two near-equal peaks the linearised scan puts
    first)."""
    n = scan.periods.size
    if n == 0:
        return [], []
    peak = scan_peaks(scan, 1)
    even = np.linspace(0, n - 1, grid).round().astype(int) if grid else np.zeros(0, int)
    return peak, [int(j) for j in dict.fromkeys(even.tolist()) if int(j) not in peak]


def _wave_starts(times, angles, fit: ModelFit, scan,
                 names: list[str]) -> dict[str, list[dict[str, float]]]:
    """The peak's start and the grid start of least cost (the model's weighted sum of
    squares with the scan's linearised wave at that period): :data:`RUN_STARTS` in all."""
    base = {k: float(fit.params[k]) for k in PARAM_NAMES}
    peak, grid = start_indices(scan)
    used = np.asarray(fit.used, bool)
    phi, t = np.asarray(angles, float)[used], np.asarray(times, float)[used]
    sig = np.asarray(fit.sigma, float)[used]

    def start(j: int) -> dict[str, float]:
        amp, ph = float(scan.amplitude[j]), float(scan.phase[j])
        return {**base, "wave_period": float(scan.periods[j]),
                "wave_c": amp * np.cos(ph), "wave_s": amp * np.sin(ph)}

    def cost(st: dict[str, float]) -> float:
        r = (crossing_times(phi, **st) - t) / sig
        return float(r @ r) if np.all(np.isfinite(r)) else np.inf

    starts = [start(j) for j in peak]
    if grid:
        starts += sorted((start(j) for j in grid), key=cost)[: RUN_STARTS - len(starts)]
    return {m: [{k: v for k, v in s.items() if k in MODELS[m].free} for s in starts]
            for m in names}


def _fit_waves(times, angles, fits, chosen, outl, scan, *, fps, step, noise):
    names = wave_models_for(chosen, int(np.count_nonzero(~outl)))
    if not names:
        return {}, ()
    waves = fit_all_models(times, angles, fps=fps, step=step, used=~outl, noise=noise,
                           models=names, starts=_wave_starts(times, angles, fits[chosen], scan,
                                                              names),
                           fitted=fits, max_starts=dict.fromkeys(names, RUN_STARTS))
    return waves, tuple(names)


def _smooth_candidates(angles, fit: ModelFit, outl: np.ndarray, step: float,
                       threshold: float, thr_abs: float):
    """The all-row scan of ``fit`` and whether its best wave explains any flagged row."""
    rows = np.ones(outl.shape, bool)
    scan = wave_scan(None, angles, fit, step=step, rows=rows)
    j = scan.best
    if j < 0:
        return scan, False
    z = smooth_deletion_z(angles, fit, float(scan.periods[j]))
    sig = np.asarray(fit.sigma, float)
    explained = (np.abs(z) <= threshold) | (np.abs(z * sig) <= thr_abs)
    return scan, bool(np.any(explained & outl))


def extend_family(times, angles, fits: dict[str, ModelFit], chosen: str, outl: np.ndarray,
                  first: AdequacyCheck, *, fps: float, step: float, margin: float,
                  threshold: float, min_frames: float, noise=None) -> Extended:
    """Try the plate-wave models where the in-family choice is inadequate or a flagged row
    may be a smooth deviation (module docstring)."""
    outl = np.asarray(outl, bool)
    kw = dict(fps=fps, step=step, noise=noise)
    search = None
    tried: tuple[str, ...] = ()
    if outl.any():
        scan, smooth = _smooth_candidates(angles, fits[chosen], outl, step, threshold,
                                          min_frames / fps)
        if smooth:
            waves, tried = _fit_waves(times, angles, fits, chosen, outl, scan, **kw)
            if waves:
                ref = min(waves, key=lambda m: waves[m].bic)
                search = find_misread_rows(times, angles, fps=fps, step=step,
                                           threshold=threshold, min_frames=min_frames,
                                           reference=ref, initial=outl, start=waves[ref])
                # a second look only puts rows back: a row the in-family search let stand
                # is explained by a smooth model already
                kept = np.asarray(search.outliers) & outl
                if not np.array_equal(kept, outl):
                    outl = kept
                    fits = fit_all_models(times, angles, fps=fps, step=step, used=~outl,
                                          noise=noise)
                    chosen = select_model(fits, margin)
                    waves, tried = _fit_waves(times, angles, fits, chosen, outl,
                                              wave_scan(times, angles, fits[chosen],
                                                        step=step), **kw)
                fits = {**fits, **waves}
                return Extended(fits, select_model(fits, margin), outl, search, tried)
    if first.adequate:
        return Extended(fits, chosen, outl, None, tried)
    waves, tried = _fit_waves(times, angles, fits, chosen, outl, first.scan, **kw)
    fits = {**fits, **waves}
    new = select_model(fits, margin)
    if new != chosen and outl.any() and new in EXTENSION:
        # judge the flagged rows again under the wave model
        search = find_misread_rows(times, angles, fps=fps, step=step, threshold=threshold,
                                   min_frames=min_frames, reference=new, initial=outl,
                                   start=fits[new])
        kept = np.asarray(search.outliers) & outl
        if not np.array_equal(kept, outl):
            outl = kept
            core = fit_all_models(times, angles, fps=fps, step=step, used=~outl, noise=noise)
            waves, tried = _fit_waves(times, angles, core, select_model(core, margin), outl,
                                      wave_scan(times, angles, core[select_model(core, margin)],
                                                step=step), **kw)
            fits = {**core, **waves}
            new = select_model(fits, margin)
    return Extended(fits, new, outl, search, tried)
