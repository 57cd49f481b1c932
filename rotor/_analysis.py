"""The law-of-motion analysis of one test (one column of frame indices).

The data are like Table 3 of Alaci et al. (2022): for each launch ("test"), the frame index at
which the rotor has turned each further mark step (a quarter turn), filmed at ``fps``. Row
``k`` is at angle ``(k - k_first) step``; times are ``(f_k - f_first)/fps``. The paper assumes
constant angular acceleration from rest at the first mark and fits parabolas ``phi(t)``;
:func:`analyse_test` finds the misread rows (:mod:`rotor._misreads`), fits the whole
family (:mod:`rotor._fitting`), selects one model (:mod:`rotor._selection`)
and states the evidence for it. Leave-one-point-out prediction errors (approximate, from the
leverages, or exact refits) are reported beside, with a runs test and the lag-1
autocorrelation of the residuals to tell systematic misfit from noise.

References
----------
Alaci S., Ciornei F.-C., Romanu I.-C. (2022) Materials 15(7):2518, Eqs. (47)-(49), Table 3.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from contact._errors import ContactInputError
from rotor._adequacy import AdequacyCheck, check_adequacy
from rotor._arrays import readonly
from rotor._extension import extend_family
from rotor._family import MODELS, ModelFit
from rotor._fitting import fit_all_models, loo_exact
from rotor._forward import model_speeds
from rotor._misreads import MISREAD_MIN_FRAMES, MISREAD_THRESHOLD, find_misread_rows
from rotor._noise import Noise
from rotor._paper import FPS, MARK_STEP
from rotor._selection import (
    BIC_MARGIN,
    WEAK_DELTA_BIC,
    WEAK_FALSE_ALARM,
    false_alarm_probability,
    select_model,
    verdict_evidence,
)
from rotor._smooth import SmoothDeviation, fit_smooth_deviation

__all__ = ["TestReport", "analyse_test", "group_of", "prepare_column"]


@dataclass(frozen=True)
class TestReport:
    """The law-of-motion analysis of one test (one column).

    Attributes
    ----------
    name, group : str
    k : ndarray of int
        Row numbers present in the column.
    frames : ndarray
        Frame indices as given.
    times, angles : ndarray
        ``(f - f_first)/fps`` (s) and ``(k - k_first) step`` (rad).
    fits : dict of ModelFit
        Every model, fitted on the rows judged sound.
    selected : str
        The BIC choice (:func:`select_model`).
    effect : str
        ``none``, ``decaying``, ``unbalance`` or ``decaying+unbalance``.
    decay_form : str or None
        ``position``, ``speed`` or ``position+speed`` when the acceleration decays.
    outliers : tuple of int
        Row numbers ``k`` judged misread (left out of the fits).
    eps0, eps0_stderr : float
        Initial angular acceleration of the selected model and its standard error, rad/s².
    z : ndarray
        Each row's leave-one-out error in noise sigmas under the misread search's model.
    omega_first : float
        The selected model's angular speed at the first mark, rad/s (0: starts there).
    delta_bic : float
        BIC of the best model nested in the selected one minus the selected model's (the
        evidence over the next simpler model; NaN for ``rest``, which has none).
    effect_evidence : float
        BIC of the best no-effect model minus that of the best effect model.
    false_alarm : float
        Calibrated probability that a clean column (no effect) reaches ``effect_evidence``
        (:func:`false_alarm_probability`).
    weak_evidence : bool
        An effect is named but on weak evidence: ``false_alarm`` above 1 % or ``delta_bic``
        below 10 ("very strong" starts there on Kass & Raftery's scale).
    adequacy : AdequacyCheck
        Whether the selected model explains the data (:mod:`rotor._adequacy`).
    family_choice, family_adequacy :
        The choice within the core family and its adequacy check (before any plate-wave
        model was tried).
    extension_tried : tuple of str
        The plate-wave models fitted (:mod:`rotor._extension`); empty when the
        family's choice was adequate and no flagged row could be a smooth deviation.
    smooth : SmoothDeviation or None
        The last resort (:mod:`rotor._smooth`): an unexplained smooth deviation of the
        acceleration, selected when the chosen model is inadequate and the smooth term wins
        by the selection margin.

    See Also
    --------
    analyse_test : builds it.

    Examples
    --------
    Column ``s1`` of the paper's Table 3 (the symmetric collar): its acceleration, about
    2.2 rad/s², decays with the angle turned:

    >>> from rotor import analyse_test, table3
    >>> report = analyse_test("s1", table3()["s1"])
    >>> print(report.group, report.selected, report.effect, f"{report.eps0:.1f} rad/s²")
    s position decaying 2.2 rad/s²
    """

    __test__ = False  # not a pytest class

    name: str
    group: str
    k: np.ndarray
    frames: np.ndarray
    times: np.ndarray
    angles: np.ndarray
    fits: dict[str, ModelFit]
    selected: str
    effect: str
    decay_form: str | None
    outliers: tuple[int, ...]
    eps0: float
    eps0_stderr: float
    z: np.ndarray
    omega_first: float
    fps: float
    step: float
    delta_bic: float = math.nan
    effect_evidence: float = math.nan
    false_alarm: float = math.nan
    weak_evidence: bool = False
    adequacy: AdequacyCheck | None = None
    family_choice: str = ""
    family_adequacy: AdequacyCheck | None = None
    extension_tried: tuple[str, ...] = ()
    smooth: SmoothDeviation | None = None

    @property
    def fit(self) -> ModelFit:
        return self.fits[self.selected]

    @property
    def used(self) -> np.ndarray:
        return self.fit.used


def group_of(name: str) -> str:
    """Group of a column: its name without trailing digits (``as2`` -> ``as``).

    Parameters
    ----------
    name : str
        A column (launch) name.

    Returns
    -------
    str
        The name without its trailing digits, or the name itself when it is all digits.

    See Also
    --------
    analyse_table : groups its columns this way.

    Examples
    --------
    >>> from rotor import group_of
    >>> group_of("as2"), group_of("s12"), group_of("7")
    ('as', 's', '7')
    """
    g = re.sub(r"\d+$", "", name)
    return g or name


def speed_at_first_mark(fit: ModelFit, phi_first: float) -> float:
    if fit.model == "parabola":
        return math.nan
    return float(model_speeds(np.array([phi_first]), fit.params)[0])


def prepare_column(name: str, frames: Sequence[float], k: Sequence[int] | None, fps: float,
             step: float):
    if not (math.isfinite(fps) and fps > 0):
        raise ContactInputError(f"fps must be positive, got {fps!r}")
    if not (math.isfinite(step) and step > 0):
        raise ContactInputError(f"the mark step must be positive, got {step!r}")
    f = np.asarray(frames, dtype=float)
    kk = np.arange(1, f.size + 1) if k is None else np.asarray(k)
    if f.ndim != 1 or kk.shape != f.shape:
        raise ContactInputError(f"column {name!r}: frames and row numbers differ in length")
    ok = np.isfinite(f)
    f, kk = f[ok], kk[ok].astype(int)
    if f.size < 6:
        raise ContactInputError(
            f"column {name!r} has {f.size} readings; the law-of-motion analysis needs >= 6"
        )
    if np.any(np.diff(kk) <= 0):
        raise ContactInputError(f"column {name!r}: row numbers must increase")
    times = (f - f[0]) / fps
    angles = (kk - kk[0]) * step
    bad = np.flatnonzero(np.diff(f) <= 0)
    if bad.size:
        raise ContactInputError(
            f"column {name!r}: frame indices must increase down the column, but row "
            f"{kk[bad[0] + 1]} ({f[bad[0] + 1]:g}) is not after row {kk[bad[0]]} "
            f"({f[bad[0]]:g})"
        )
    return f, kk, times, angles


def analyse_test(
    name: str,
    frames: Sequence[float],
    k: Sequence[int] | None = None,
    *,
    fps: float = FPS,
    step: float = MARK_STEP,
    margin: float = BIC_MARGIN,
    cv: str = "approx",
    threshold: float = MISREAD_THRESHOLD,
    min_frames: float = MISREAD_MIN_FRAMES,
    noise: Noise | None = None,
    extend: bool = True,
) -> TestReport:
    """Analyse one column of frame indices: misread rows, every model, the BIC choice, its
    adequacy, and the plate-wave models where the family's choice does not explain the data.

    Parameters
    ----------
    name : str
        Column name (its group is the name without trailing digits).
    frames : sequence
        Frame index at each row; NaN for a missing reading.
    k : sequence of int, optional
        Row numbers (default 1, 2, ...). Row ``k`` is at angle ``(k - k_first) step``.
    fps, step : float
        Frame rate (1/s) and mark step (rad).
    margin : float
        BIC margin a richer model must win by (:func:`select_model`).
    cv : {"approx", "exact"}
        Leave-one-point-out errors from the leverages, or from refits (slower).
    threshold, min_frames : float
        Misread threshold in noise sigmas, and its floor in frames.
    noise : Noise, optional
        Reading noise to weight every fit with (default: each model estimates its own).
    extend : bool
        Try the plate-wave models (:func:`rotor._extension.extend_family`); False
        keeps to the core family (as the calibrations measure it).

    Returns
    -------
    TestReport
        The selected model (``selected``), its initial angular acceleration ``eps0`` with
        ``eps0_stderr`` (rad/s²), the misread rows (``outliers``) and every fit.

    Raises
    ------
    ContactInputError
        Too few readings, frames that do not increase, or an unknown ``cv``.

    See Also
    --------
    analyse_table : every column of a table, by group.

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of Rolling
       Friction Moment on the Normal Force for Elastic Materials", Materials 15 (2022) 2518.
    .. [2] G. Schwarz, "Estimating the dimension of a model", Ann. Statist. 6 (1978)
       461-464 (the BIC).

    Examples
    --------
    Frames of a rotor that starts at 1 rad/s and accelerates at 2 rad/s², a mark every
    quarter turn filmed at 120 frames/s (rounded to whole frames):

    >>> import numpy as np
    >>> from rotor import analyse_test
    >>> phi = np.arange(12) * np.pi / 2
    >>> t = (-1.0 + np.sqrt(1.0 + 2 * 2.0 * phi)) / 2.0
    >>> report = analyse_test("s1", np.round(1000 + 120 * t), extend=False)
    >>> print(report.selected, f"eps0 = {report.eps0:.2f} rad/s²")
    const eps0 = 2.01 rad/s²
    """
    if cv not in ("approx", "exact"):
        raise ContactInputError(f"cv must be 'approx' or 'exact', got {cv!r}")
    f, kk, times, angles = prepare_column(name, frames, k, fps, step)
    search = find_misread_rows(times, angles, fps=fps, step=step, threshold=threshold,
                               min_frames=min_frames)
    outl = np.array(search.outliers)
    # noise=None: every model estimates its own reading noise (from leverage-corrected
    # residuals, see fit_model), so the BIC compares profile likelihoods
    fits = fit_all_models(times, angles, fps=fps, step=step, used=~outl, noise=noise)
    chosen = select_model(fits, margin)
    # judge the rows again under the chosen model; refit once if the verdict moves
    if chosen != search.reference:
        again = find_misread_rows(times, angles, fps=fps, step=step, threshold=threshold,
                                  min_frames=min_frames, reference=chosen, initial=outl,
                                  start=fits[chosen])
        if not np.array_equal(again.outliers, outl):
            outl = np.array(again.outliers)
            fits = fit_all_models(times, angles, fps=fps, step=step, used=~outl, noise=noise)
            chosen = select_model(fits, margin)
        search = again
    family_choice = chosen
    checked = fits[chosen]
    first = check_adequacy(times, angles, checked, step=step)
    tried: tuple[str, ...] = ()
    if extend:
        ext = extend_family(times, angles, fits, chosen, outl, first, fps=fps, step=step,
                            margin=margin, threshold=threshold, min_frames=min_frames,
                            noise=noise)
        fits, chosen, outl, tried = ext.fits, ext.chosen, ext.outliers, ext.tried
        search = ext.search or search
    if cv == "exact":
        fits = {m: (fit if m == "parabola" else replace(
            fit, loo_rms=loo_exact(times, angles, fit, fps=fps, step=step), loo_kind="exact"))
            for m, fit in fits.items()}
    sel = fits[chosen]
    delta, evidence = verdict_evidence(fits, chosen)
    pfa = false_alarm_probability(evidence)
    final = first if sel is checked else check_adequacy(times, angles, sel, step=step)
    smooth = None
    if extend and final.judged and not final.adequate:
        smooth = fit_smooth_deviation(angles, sel, margin=margin)
    weak = MODELS[chosen].effect != "none" and (
        pfa > WEAK_FALSE_ALARM or not delta >= WEAK_DELTA_BIC)
    return TestReport(
        name=name,
        group=group_of(name),
        k=readonly(kk),
        frames=readonly(f),
        times=readonly(times),
        angles=readonly(angles),
        fits=fits,
        selected=chosen,
        effect=MODELS[chosen].effect,
        decay_form=MODELS[chosen].decay_form,
        outliers=tuple(int(v) for v in kk[outl]),
        eps0=sel.eps0,
        eps0_stderr=sel.eps0_stderr,
        z=search.z,
        omega_first=speed_at_first_mark(sel, float(angles[0])),
        fps=float(fps),
        step=float(step),
        delta_bic=delta,
        effect_evidence=evidence,
        false_alarm=pfa,
        weak_evidence=bool(weak),
        adequacy=final,
        family_choice=family_choice,
        family_adequacy=first,
        extension_tried=tried,
        smooth=smooth,
    )
