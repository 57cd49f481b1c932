"""Automatic cut-off choice per ISO 4288:1996 (roughness inspection procedure, Tables 1-3).

The procedure, for a profile whose cut-off is not specified on the drawing:

1. decide whether the profile is periodic (ISO 4288 asks the operator; here the
   autocorrelation is used unless ``periodic`` is given, and the decision is recorded);
2. non-periodic: estimate Ra (Table 1) or Rz (Table 2); periodic: estimate RSm (Table 3);
   look up the cut-off for the estimate;
3. measure the parameter with that cut-off; if the value falls in another row of the
   table, change the cut-off accordingly and measure again, until value and cut-off agree;
4. non-periodic only: if the next shorter cut-off has not been tried, measure
   with it too; if that value is also consistent with the shorter cut-off, use it.

The evaluation length that goes with the chosen cut-off is five cut-offs (ISO 4288 default)
and the short-wave cut-off λs is the one ISO 3274 pairs with λc.
Values outside the tables (e.g. Ra < 0.006 µm) are mapped to the nearest row and noted.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from profiles._arrays import as_heights, as_step, length_text, require_valid
from profiles._errors import ProfileError, ProfileTooShortError
from profiles._filters import gaussian_mean_line
from profiles._parameters import profile_parameters
from profiles._resolution import MIN_STEPS

#: Standard cut-offs λc in metres (ISO 4288 Tables 1-3).
CUTOFFS = (0.08e-3, 0.25e-3, 0.8e-3, 2.5e-3, 8e-3)
#: ISO 3274:1996: λs paired with each λc.
LS_FOR_LC = {0.08e-3: 2.5e-6, 0.25e-3: 2.5e-6, 0.8e-3: 2.5e-6, 2.5e-3: 8e-6, 8e-3: 25e-6}

# Upper bounds (inclusive) of each row, same order as CUTOFFS; and each table's lower bound.
_TABLES = {
    # Table 1, non-periodic: Ra in (0.006, 0.02], (0.02, 0.1], (0.1, 2], (2, 10], (10, 80] µm
    "Ra": ((0.02e-6, 0.1e-6, 2e-6, 10e-6, 80e-6), 0.006e-6),
    # Table 2, non-periodic: Rz in (0.025, 0.1], (0.1, 0.5], (0.5, 10], (10, 50], (50, 200] µm
    "Rz": ((0.1e-6, 0.5e-6, 10e-6, 50e-6, 200e-6), 0.025e-6),
    # Table 3, periodic (and non-periodic RSm): RSm in (0.013, 0.04], ... (1.3, 4] mm
    "Rsm": ((0.04e-3, 0.13e-3, 0.4e-3, 1.3e-3, 4e-3), 0.013e-3),
}
_START = 2  # 0.8 mm: the usual first setting


@dataclass(frozen=True)
class CutoffChoice:
    """Outcome of :func:`iso4288_cutoff`.

    Attributes
    ----------
    lc : float
        Chosen cut-off λc in metres (= sampling length).
    ls : float
        Short-wave cut-off paired with it by ISO 3274, metres.
    evaluation_length : float
        Five sampling lengths, metres (ISO 4288 default).
    parameter : str
        ``"Ra"``, ``"Rz"`` or ``"Rsm"``: the parameter the tables were entered with.
    value : float
        That parameter measured with the chosen cut-off (SI).
    periodic : bool
        Whether the profile was treated as periodic.
    periodicity : float
        Height of the first autocorrelation peak after its first zero (NaN if not
        computed); profiles with a peak >= 0.5 are called periodic.
    history : tuple of (lc, value) pairs
        Every cut-off tried and the value measured with it, in order.
    note : str
        Anything a user should know (value outside the tables, oscillation...).

    See Also
    --------
    iso4288_cutoff : makes it.

    Examples
    --------
    >>> import surfmet, profiles
    >>> from surfmet.data import path
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> choice = profiles.iso4288_cutoff(plate.heights[256], plate.dx)
    >>> choice.lc, choice.ls, choice.parameter
    (0.0008, 2.5e-06, 'Ra')
    """

    lc: float
    ls: float
    evaluation_length: float
    parameter: str
    value: float
    periodic: bool
    periodicity: float
    history: tuple[tuple[float, float], ...]
    note: str = ""

    def __float__(self) -> float:
        return self.lc

    def as_dict(self) -> dict[str, Any]:
        """Plain-JSON view (SI lengths)."""
        return {
            "lc": self.lc,
            "ls": self.ls,
            "evaluation_length": self.evaluation_length,
            "parameter": self.parameter,
            "value": self.value,
            "periodic": self.periodic,
            "periodicity": self.periodicity,
            "history": [list(h) for h in self.history],
            "note": self.note,
        }


def table_cutoff(parameter: str, value: float) -> tuple[int, str]:
    """Row of ISO 4288 Table 1/2/3 for ``value``: (index into CUTOFFS, note)."""
    uppers, lower = _TABLES[parameter]
    if not math.isfinite(value):
        raise ProfileError(f"cannot choose a cut-off: {parameter} is not defined for this profile")
    for k, upper in enumerate(uppers):
        if value <= upper:
            note = ""
            if k == 0 and value <= lower:
                note = (
                    f"{parameter} = {value:.4g} m is below ISO 4288's table "
                    f"({lower:.4g} m); its first row is used"
                )
            return k, note
    return len(uppers) - 1, (
        f"{parameter} = {value:.4g} m is above ISO 4288's table; its last row is used"
    )


def autocorrelation_peak(z: np.ndarray) -> float:
    """Height of the first maximum of the normalised autocorrelation after its first zero.

    Near 1 for a periodic profile, small for a random one; NaN-aware (non-measured points
    are left out of every lag's average).
    """
    valid = np.isfinite(z)
    n = z.size
    if np.count_nonzero(valid) < 8:
        return math.nan
    zc = np.where(valid, z - np.nanmean(z), 0.0)
    v = valid.astype(float)
    m = 1 << math.ceil(math.log2(2 * n))
    fz = np.fft.rfft(zc, m)
    fv = np.fft.rfft(v, m)
    num = np.fft.irfft(fz * np.conj(fz), m)[:n]
    cnt = np.rint(np.fft.irfft(fv * np.conj(fv), m)[:n])
    with np.errstate(invalid="ignore", divide="ignore"):
        acf = (num / np.maximum(cnt, 1)) / (num[0] / max(cnt[0], 1))
    half = n // 2
    acf = acf[:half]
    below = np.flatnonzero(acf <= 0)
    if below.size == 0:
        return 0.0
    rest = acf[below[0] :]
    return float(np.max(rest)) if rest.size else 0.0


def _shortest_usable(n: int, dx: float) -> int:
    """Index into :data:`CUTOFFS` of the shortest cut-off this sampling can use.

    A cut-off must span :data:`profiles._resolution.MIN_STEPS` sampling steps to be
    realised as a Gaussian filter, and the profile must hold at least one of it (one
    sampling length): with less, ISO 4288's tables cannot be entered at all.

    Raises
    ------
    ProfileTooShortError
        The profile is shorter than that cut-off.
    ProfileError
        The step is too coarse for every standard cut-off.
    """
    feasible = [i for i, c in enumerate(CUTOFFS) if c >= MIN_STEPS * dx * (1 - 1e-9)]
    if not feasible:
        raise ProfileError(
            f"sampling step {length_text(dx)} is too coarse for any ISO 4288 cut-off "
            f"(the largest, 8 mm, needs a step of at most {length_text(8e-3 / MIN_STEPS)})"
        )
    k_min = feasible[0]
    length = n * dx
    if length < CUTOFFS[k_min] * (1 - 1e-9) - dx:
        lc = CUTOFFS[k_min]
        raise ProfileTooShortError(
            f"the profile is {length_text(length)} long, shorter than the shortest ISO 4288 "
            f"cut-off its sampling allows (λc = {length_text(lc)}, whose evaluation length "
            f"is {length_text(5 * lc)}): ISO 4288 cannot choose a cut-off for it"
        )
    return k_min


def _measure(z: np.ndarray, dx: float, lc: float, parameter: str) -> float:
    mean_line = gaussian_mean_line(z, dx, lc, end_treatment="moment")
    r = z - mean_line
    length = z.size * dx
    if length >= lc:
        p = profile_parameters(r, dx, sampling_length=lc, n_sampling=None)
    else:  # shorter than one cut-off: the whole profile is the only sampling length
        p = profile_parameters(r, dx, n_sampling=1)
    return {"Ra": p.Ra, "Rz": p.Rz, "Rsm": p.Rsm}[parameter]


def _periodic_without_rsm(z: np.ndarray, dx: float, score: float) -> CutoffChoice | None:
    """The non-periodic choice for a profile that looks periodic but has no RSm element.

    Such a profile (e.g. a single long wave) cannot enter Table 3; None when it has one.
    """
    if math.isfinite(_measure(z, dx, CUTOFFS[_START], "Rsm")):
        return None
    choice = iso4288_cutoff(z, dx, periodic=False, parameter="Ra")
    notes = ("looks periodic but has no RSm element: Ra table used", choice.note)
    return dataclasses.replace(
        choice, periodicity=score, note="; ".join(n for n in notes if n)
    )


def iso4288_cutoff(
    z: Any,
    dx: float,
    *,
    periodic: bool | None = None,
    parameter: str = "auto",
    max_iterations: int = 10,
) -> CutoffChoice:
    """Choose the roughness cut-off λc by the ISO 4288:1996 procedure.

    Parameters
    ----------
    z : array_like
        Uniformly sampled profile heights in metres with the form removed (levelled);
        NaN where not measured.
    dx : float
        Sampling step in metres.
    periodic : bool, optional
        Treat the profile as periodic (RSm, Table 3) or not (Ra/Rz, Tables 1-2).
        ``None``: decided from the autocorrelation (first peak after the first zero
        >= 0.5 means periodic).
    parameter : {"auto", "Ra", "Rz", "Rsm"}
        Table to enter; ``"auto"`` = Rsm for periodic profiles, Ra otherwise.
    max_iterations : int
        Safety bound on the measure/re-choose loop.

    Returns
    -------
    CutoffChoice
        ``float(choice)`` is λc. The profile need not be long enough for the evaluation
        length: compare ``choice.evaluation_length`` with the profile length.

    Raises
    ------
    ProfileError
        All-NaN or too few points, or the parameter is undefined (e.g. no RSm element).

    See Also
    --------
    analyze_profile : uses it for ``lc="auto"``.

    References
    ----------
    .. [1] ISO 4288:1996, Geometrical product specifications (GPS) -- Surface texture:
       Profile method -- Rules and procedures for the assessment of surface texture.

    Examples
    --------
    >>> import surfmet, profiles
    >>> from surfmet.data import path
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> choice = profiles.iso4288_cutoff(plate.heights[256], plate.dx)
    >>> print(f"lc = {choice.lc * 1e3} mm ({choice.parameter} = {choice.value * 1e6:.2f} µm)")
    lc = 0.8 mm (Ra = 1.70 µm)
    """
    z = as_heights(z)
    dx = as_step(dx)
    require_valid(z, 8, "choosing a cut-off (ISO 4288)")
    k_min = _shortest_usable(z.size, dx)
    score = autocorrelation_peak(z)
    if periodic is None:
        periodic = bool(score >= 0.5)
    key = {"auto": "Rsm" if periodic else "Ra", "ra": "Ra", "rz": "Rz", "rsm": "Rsm"}.get(
        str(parameter).strip().lower()
    )
    if key is None:
        raise ProfileError(f"unknown ISO 4288 parameter {parameter!r}: use Ra, Rz or Rsm")

    if key == "Rsm" and str(parameter).strip().lower() == "auto":
        fallback = _periodic_without_rsm(z, dx, score)
        if fallback is not None:
            return fallback

    length = z.size * dx
    k = max(_START, k_min)
    while k > k_min and CUTOFFS[k] > length:
        k -= 1
    measured: dict[int, float] = {}
    history: list[tuple[float, float]] = []
    notes: list[str] = []

    def measure(i: int) -> float:
        if i not in measured:
            measured[i] = _measure(z, dx, CUTOFFS[i], key)
            history.append((CUTOFFS[i], measured[i]))
        return measured[i]

    seen: list[int] = []
    for _ in range(max_iterations):
        k_new, note = table_cutoff(key, measure(k))
        if k_new < k_min:
            notes.append(
                f"ISO 4288 asks for λc = {CUTOFFS[k_new] * 1e3:.4g} mm but the sampling step "
                f"({dx * 1e6:.4g} µm) is too coarse to realise it; the shortest realisable "
                f"cut-off is used instead (not ISO 4288 conformant)"
            )
            k_new = k_min
        if k_new == k:
            if note:
                notes.append(note)
            break
        if k_new in seen:
            # the value flips between two rows: ISO gives no rule; keep the longer cut-off
            k = max(k, k_new)
            notes.append("value alternates between two table rows; the longer cut-off kept")
            break
        seen.append(k)
        k = k_new
    else:
        notes.append(f"no agreement after {max_iterations} iterations; last cut-off kept")

    # ISO 4288 procedure, last step: try the next shorter cut-off if it was not measured before
    if not periodic and k > k_min and (k - 1) not in measured:
        k_short, _ = table_cutoff(key, measure(k - 1))
        if k_short == k - 1:
            k -= 1
            notes.append("next shorter cut-off also consistent with the table: it is used")
    lc = CUTOFFS[k]
    return CutoffChoice(
        lc=lc,
        ls=LS_FOR_LC[lc],
        evaluation_length=5 * lc,
        parameter=key,
        value=measured[k],
        periodic=bool(periodic),
        periodicity=score,
        history=tuple(history),
        note="; ".join(dict.fromkeys(notes)),  # each note once, in order
    )
