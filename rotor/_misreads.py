"""Misread rows: frame numbers mistyped or misjudged, found by a robust forward-backward search.

Misread rows are found by a forward-backward search on externally studentised deletion
residuals under a flexible model, with a Student-t noise estimate that a few gross errors do
not inflate (:func:`find_misread_rows`), then judged again under the chosen model. The first
row is never flagged: a misread first row is a start offset, which the models fit anyway.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rotor._arrays import readonly
from rotor._family import MODELS, ModelFit, ancestors
from rotor._fitting import fit_all_models, fit_model, leverages_at
from rotor._forward import model_speeds
from rotor._noise import Noise, estimate_noise, quantisation_sigma
from rotor._paper import FPS, MARK_STEP

__all__ = ["MISREAD_MIN_FRAMES", "MISREAD_THRESHOLD", "MisreadSearch", "find_misread_rows",
           "robust_noise"]

#: A row is flagged misread when its prediction error exceeds this many noise sigmas...
MISREAD_THRESHOLD = 4.0
#: ...and this many frames (a frame or two off cannot be told from reading scatter).
MISREAD_MIN_FRAMES = 1.5


@dataclass(frozen=True)
class MisreadSearch:
    """Outcome of :func:`find_misread_rows`.

    ``outliers``: rows judged misread. ``z``: each row's leave-one-out error in units of its
    noise sigma (prediction error for the rows left out). ``deletion_residuals``: the same
    errors in seconds. ``noise``: the reading noise of the clean rows.
    """

    outliers: np.ndarray
    z: np.ndarray
    deletion_residuals: np.ndarray
    noise: Noise
    reference: str


def robust_noise(fit: ModelFit, phi: np.ndarray, fps: float) -> Noise:
    """Reading noise from a fit's leverage-corrected residuals (each ``r/sqrt(1 - h)`` has the
    noise variance), Student-t likelihood: a misread row still in the fit does not inflate it,
    and removing one of the few slow rows that inform ``sigma_a`` does not swing it."""
    first = int(np.argmin(phi))
    ui = np.flatnonzero(np.asarray(fit.used))
    ui = ui[ui != first]
    lev = np.asarray(fit.leverage)[ui]
    r = np.asarray(fit.residuals)[ui] / np.sqrt(np.maximum(1 - lev, 1e-6))
    return estimate_noise(r, model_speeds(phi[ui], fit.params), fit.params["eps0"],
                           quantisation_sigma(fps), fit.noise, robust=True)


def find_misread_rows(
    times: np.ndarray,
    angles: np.ndarray,
    *,
    fps: float = FPS,
    step: float = MARK_STEP,
    threshold: float = MISREAD_THRESHOLD,
    min_frames: float = MISREAD_MIN_FRAMES,
    reference: str = "position+unbalance",
    initial: np.ndarray | None = None,
    max_fraction: float = 0.2,
    n_candidates: int = 4,
    start: ModelFit | None = None,
) -> MisreadSearch:
    """Find rows whose frame number was misread or mistyped.

    A forward-backward search on externally studentised deletion residuals under
    ``reference``, a flexible model (so that a smooth trend is not taken for misreads):

    1. Fit the rows not yet flagged; rank them by their leverage-corrected residual in
       noise sigmas, and refit without each of the ``n_candidates`` worst (exact deletion,
       so that a model bent towards a misread row does not mask it).
    2. The candidate whose prediction error is largest in units of the noise sigma of the
       fit without it is flagged if that exceeds ``threshold`` and ``min_frames`` frames (a
       frame or two off cannot be told from reading scatter); then repeat.
    3. Backward: a flagged row whose prediction error under the final fit is within the
       threshold is put back.

    At most ``max_fraction`` of the rows are flagged. ``initial`` starts from a given verdict,
    ``start`` from a fit of ``reference`` already made on the rows not in ``initial``.
    The first row is never flagged: a misread first row is a start offset, which the models
    fit anyway.
    """
    t = np.asarray(times, float)
    phi = np.asarray(angles, float)
    n = t.size
    max_out = max(int(max_fraction * n), 1)
    flagged = np.zeros(n, bool) if initial is None else np.asarray(initial, bool).copy()
    flagged[int(np.argmin(phi))] = False
    # a short column cannot spare rows for a flexible reference: fall back to a simpler
    # one, and never flag so many rows that the reference has too few left to be fitted
    for simpler in ("position", "const"):
        if n - max_out > len(MODELS[reference].free) + 2:
            break
        if reference != simpler and simpler in ancestors([reference]):
            reference = simpler
    max_out = max(min(max_out, n - len(MODELS[reference].free) - 3), 0)
    search = _Search(t, phi, fps, step, reference, threshold, min_frames / fps)
    if start is not None and start.model == reference and np.array_equal(start.used, ~flagged):
        fit = start
    else:
        fit = fit_all_models(t, phi, fps=fps, step=step, used=~flagged,
                             models=[reference])[reference]
    for _ in range(2 * max_out + 2):
        # backward: put back flagged rows the current fit predicts well
        nz = robust_noise(fit, phi, fps)
        back = search.put_back(fit, flagged, nz)
        if back is not None:
            fit = back
            continue
        if flagged.sum() >= max_out:
            break
        # forward: exact deletion of the worst candidates
        worse = search.flag_worst(fit, flagged, nz, n_candidates)
        if worse is None:
            break
        fit = worse
    z, dele, nz = search.final_verdicts(fit, flagged)
    return MisreadSearch(readonly(flagged), readonly(z), readonly(dele), nz, reference)


class _Search:
    """The state of one misread search: the column, the reference model, the thresholds."""

    def __init__(self, t: np.ndarray, phi: np.ndarray, fps: float, step: float,
                 reference: str, threshold: float, thr_abs: float) -> None:
        self.t, self.phi, self.fps, self.step = t, phi, fps, step
        self.reference, self.free = reference, MODELS[reference].free
        self.threshold, self.thr_abs = threshold, thr_abs
        self.first = int(np.argmin(phi))

    def refit(self, used: np.ndarray, base: ModelFit) -> ModelFit:
        return fit_model(self.t, self.phi, self.reference, fps=self.fps, step=self.step,
                         used=used, inits=[{k: base.params[k] for k in self.free}],
                         noise_start=base.noise, irls=1)

    def row_sigma(self, f: ModelFit, nz: Noise, i: int) -> float:
        return float(nz.sigma(model_speeds(self.phi[i : i + 1], f.params), f.params["eps0"])[0])

    def verdict(self, f: ModelFit, i: int, lev: float, nz: Noise) -> tuple[float, float]:
        """Row ``i``'s prediction error under ``f`` (a fit without it) in noise sigmas, and
        in seconds."""
        # externally studentised: the prediction error of a row a fit without it makes has
        # variance sigma_i^2 / (1 - h_ii), h_ii the row's leverage in the fit with it
        d = float(f.residuals[i])
        return d * math.sqrt(max(1.0 - lev, 1e-6)) / self.row_sigma(f, nz, i), d

    def leverage_in(self, f: ModelFit, i: int) -> float:
        h = float(np.asarray(f.leverage)[i])
        if math.isfinite(h):
            return h
        # row i outside f: its leverage in a fit that includes it, at f's parameters
        back = f.used.copy()
        back[i] = True
        return float(leverages_at(self.t, self.phi, f, back, self.fps)[i])

    def put_back(self, fit: ModelFit, flagged: np.ndarray, nz: Noise) -> ModelFit | None:
        """Unflag (in place) the first flagged row ``fit`` predicts well; the refit, or None."""
        for i in np.flatnonzero(flagged):
            z, d = self.verdict(fit, i, self.leverage_in(fit, i), nz)
            if abs(z) <= self.threshold or abs(d) <= self.thr_abs:
                flagged[i] = False
                return self.refit(~flagged, fit)
        return None

    def flag_worst(self, fit: ModelFit, flagged: np.ndarray, nz: Noise,
                   n_candidates: int) -> ModelFit | None:
        """Refit without each of the worst candidates; flag (in place) the one with the
        largest prediction error if it passes both thresholds. The refit, or None."""
        phi = self.phi
        used_idx = np.flatnonzero(~flagged)
        approx = np.zeros(phi.size)
        lev_u = np.asarray(fit.leverage)[used_idx]
        sig_u = nz.sigma(model_speeds(phi[used_idx], fit.params), fit.params["eps0"])
        approx[used_idx] = (np.abs(np.asarray(fit.press)) * np.sqrt(np.maximum(1 - lev_u, 1e-6))
                            / sig_u)
        approx[self.first] = 0.0
        cands = [int(i) for i in np.argsort(-approx)[:n_candidates] if approx[i] > 0]
        best, best_z, best_fit = -1, 0.0, None
        for i in cands:
            used = ~flagged
            used[i] = False
            f = self.refit(used, fit)
            z, d = self.verdict(f, i, float(np.asarray(fit.leverage)[i]),
                                robust_noise(f, phi, self.fps))
            if abs(d) > self.thr_abs and abs(z) > abs(best_z):
                best, best_z, best_fit = i, z, f
        if best >= 0 and abs(best_z) > self.threshold:
            flagged[best] = True
            return best_fit
        return None

    def final_verdicts(self, fit: ModelFit,
                       flagged: np.ndarray) -> tuple[np.ndarray, np.ndarray, Noise]:
        """Per-row verdicts: prediction errors for flagged rows, leverage-corrected residuals
        for the others, in noise sigmas (``z``) and in seconds; and the noise."""
        dele = np.array(fit.residuals, dtype=float)
        dele[np.asarray(fit.used)] = np.asarray(fit.press)
        dele[self.first] = 0.0
        nz = robust_noise(fit, self.phi, self.fps)
        z = np.zeros(self.phi.size)
        for i in range(self.phi.size):
            if i == self.first:
                continue
            if flagged[i]:
                z[i] = self.verdict(fit, i, self.leverage_in(fit, i), nz)[0]
            else:
                h = float(np.asarray(fit.leverage)[i])
                z[i] = dele[i] * math.sqrt(max(1.0 - h, 1e-6)) / self.row_sigma(fit, nz, i)
        return z, dele, nz
