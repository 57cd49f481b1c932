"""Profile roughness in the facade: evaluation conditions, their reasons, JSON units.

A profile's R-parameters depend on four choices that a user comparing with an instrument
must see: the standard (ISO 21920-2 over the evaluation length, or ISO 4287:1997 per
sampling length), λc, λs and the number of sampling lengths. Each is taken, in this order,
from the user, from the file's own statement of its evaluation conditions (a reader puts
them in ``metadata["evaluation_conditions"]``, e.g. a Mitutoyo SurfTest export), or from the
ISO 4288 rule / the default; :func:`resolve_conditions` records which, and the result's
``settings["conditions"]`` says it.

An exported R-profile (``evaluation_conditions["profile"] == "R"``) has already been
filtered by the instrument: its λc then sets the sampling length only, and no λc filter is
applied again.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from surfmet._errors import SurfmetInputError
from surfmet.units import parse_length

DEFAULT_STANDARD = "iso21920"
"""Standard used for profiles when neither the user nor the file states one."""

STANDARD_NAMES = {"iso21920": "ISO 21920-2:2021", "iso4287": "ISO 4287:1997"}

FROM_USER = "given by the user"
FROM_FILE = "stated in the file (instrument's evaluation conditions)"
FROM_RULE = "ISO 4288 rule"
FROM_DEFAULT = "default"
FROM_DEFAULT_PEAK = FROM_DEFAULT + " (ISO 4287: peak first)"

_UNSET = object()


@dataclass(frozen=True)
class Conditions:
    """Resolved evaluation conditions of a profile, each with the reason it was chosen.

    ``lc`` is ``"auto"`` (ISO 4288 rule), None (no λc filter) or metres; ``prefiltered``
    is True for a file that holds an already λc-filtered R-profile.
    """

    standard: str
    lc: Any
    ls: float | None
    n_sampling: int
    prefiltered: bool
    why: dict[str, str]
    rk_line: str = "secant"
    element_start: str = "peak"


def parse_cutoff(value: Any, what: str) -> Any:
    """User value of a cut-off: the unset marker, None ("none"/"off") or a length (m)."""
    if value is None:
        return _UNSET
    if isinstance(value, str) and value.strip().lower() in ("none", "off", "no"):
        return None
    if isinstance(value, str) and value.strip().lower() == "auto" and what == "lc":
        return "auto"
    v = parse_length(value)
    if not v > 0:
        raise SurfmetInputError(f"{what} must be a positive length, got {value!r}")
    return v


def _standard(value: Any) -> str:
    from profiles._errors import ProfileError
    from profiles._parameters import parse_standard

    try:
        return parse_standard(value)
    except ProfileError as exc:
        raise SurfmetInputError(str(exc)) from None


def resolve_conditions(metadata: dict[str, Any], *, standard: Any, lc: Any, ls: Any,
                       n_sampling: Any, rk_line: Any = None,
                       element_start: Any = None) -> Conditions:
    """User choices first, then the file's stated conditions, then the rule or default."""
    stated = metadata.get("evaluation_conditions") or {}
    why: dict[str, str] = {}
    if standard is not None:
        std, why["standard"] = _standard(standard), FROM_USER
    elif stated.get("standard"):
        std, why["standard"] = _standard(stated["standard"]), FROM_FILE
    else:
        std, why["standard"] = DEFAULT_STANDARD, FROM_DEFAULT
    prefiltered = str(stated.get("profile", "")).strip().upper() == "R"
    lc_user = parse_cutoff(lc, "lc")
    if lc_user is not _UNSET:
        lc_v, why["lc"] = lc_user, FROM_USER
        prefiltered = prefiltered and lc_user is None
    elif stated.get("lc"):
        lc_v, why["lc"] = float(stated["lc"]), FROM_FILE
    else:
        lc_v, why["lc"] = "auto", FROM_RULE
    ls_user = parse_cutoff(ls, "ls")
    if ls_user is not _UNSET:
        ls_v, why["ls"] = ls_user, FROM_USER
    elif stated.get("ls") and not prefiltered:
        ls_v, why["ls"] = float(stated["ls"]), FROM_FILE
    else:
        ls_v = None
        why["ls"] = (FROM_FILE + ": already applied by the instrument" if prefiltered
                     and stated.get("ls") else "default: no λs filter")
    if n_sampling is not None:
        n, why["n_sampling"] = _count(n_sampling), FROM_USER
    elif stated.get("n_sampling"):
        n, why["n_sampling"] = _count(stated["n_sampling"]), FROM_FILE
    else:
        n, why["n_sampling"] = 5, "ISO 4288 default (5)"
    if ls_v is not None and isinstance(lc_v, float) and not ls_v < lc_v:
        raise SurfmetInputError(f"ls ({ls_v:.3g} m) must be shorter than lc ({lc_v:.3g} m)")
    if rk_line is not None:
        line, why["rk_line"] = str(rk_line), FROM_USER
    elif stated.get("rk_line"):
        # the instrument's construction, which goes with the conditions the file states
        line = str(stated["rk_line"])
        why["rk_line"] = (f"the instrument's own Rk construction ({stated['source']}), part "
                          "of the evaluation the file states" if stated.get("source")
                          else FROM_FILE)
    else:
        line, why["rk_line"] = "secant", FROM_DEFAULT
    start, why["element_start"] = _element_start(stated, std, element_start)
    return Conditions(std, lc_v, ls_v, n, prefiltered, why, line, start)


def _element_start(stated: dict[str, Any], std: str, user: Any) -> tuple[str, str]:
    """The profile-element pairing (RSm, Rc) and why: the user's, else the file's while its
    standard is in force, else peak first.

    A file's pairing (a Mitutoyo SurfTest's ``first-crossing``) describes how its
    instrument evaluates each sampling length under the standard it states. Under another
    standard (``iso21920``: one stretch, the evaluation length) it would pair every element
    from the evaluation length's first crossing, a reading the instrument was never seen to
    make (docs/parameters.md), so it is not carried over; the user may still ask for it.
    """
    from profiles._elements import ELEMENT_STARTS

    if user is not None:
        if user not in ELEMENT_STARTS:
            raise SurfmetInputError(f"element_start must be one of {', '.join(ELEMENT_STARTS)}"
                                    f", got {user!r}")
        if user == "first-crossing" and std == "iso21920":
            # one stretch: only the evaluation length's start decides the pairing
            return str(user), (FROM_USER + "; iso21920 has one stretch: elements paired "
                               "from the evaluation length's first mean-line crossing")
        return str(user), FROM_USER
    value = stated.get("element_start")
    if not value:
        return "peak", FROM_DEFAULT_PEAK
    source = f" ({stated['source']})" if stated.get("source") else ""
    own = stated.get("standard")
    if own and _standard(own) != std:
        return "peak", (f"{FROM_DEFAULT_PEAK}: the file's {value} pairing{source} belongs to "
                        f"the {STANDARD_NAMES[_standard(own)]} evaluation it states, not "
                        f"carried over to {STANDARD_NAMES[std]}")
    # like the Rk construction: how the instrument pairs its profile elements
    return str(value), (f"the instrument's own profile-element pairing{source}, part of the "
                        "evaluation the file states" if source else FROM_FILE)


def _count(value: Any) -> int:
    try:
        n = int(value)
    except (TypeError, ValueError):
        raise SurfmetInputError(f"the number of sampling lengths must be an integer, "
                                f"got {value!r}") from None
    if n < 1:
        raise SurfmetInputError(f"the number of sampling lengths must be at least 1, got {n}")
    return n


def engine_cutoffs(cond: Conditions) -> tuple[Any, Any]:
    """(lc, ls) to hand to :func:`profiles.analyze_profile` for these conditions."""
    if cond.prefiltered:
        return None, cond.ls
    return cond.lc, cond.ls


RCM_RATIOS = (10, 50, 90)
"""Material ratios (%) at which the profile output states Rcm (any other: the API)."""


def stratified_parameters(rough: Any, rk_line: str
                          ) -> tuple[dict[str, tuple[float, str]], list[str]]:
    """Material-ratio parameters of the evaluated roughness profile, with units.

    ISO 13565-2 and -3 (ratios in %; the areas A1, A2 in m: a height times a material
    ratio taken as a fraction, a printout's µm·% times 1e-8) and ISO 21920-2 Rcm(p) at
    :data:`RCM_RATIOS` (the level of material ratio p below the highest point, zero or
    negative, keyed ``"Rcm(p%)"``). A profile on which they are undefined (flat, too few
    points) gets a note instead of the values.
    """
    import profiles
    from profiles._errors import ProfileError

    out: dict[str, tuple[float, str]] = {}
    notes: list[str] = []
    try:
        for p in RCM_RATIOS:
            out[f"Rcm({p}%)"] = (float(profiles.material_ratio_height(rough, p / 100)), "m")
        rk = profiles.rk_parameters(rough, construction=rk_line)
        out.update({"Rk": (rk.Rk, "m"), "Rpk": (rk.Rpk, "m"), "Rvk": (rk.Rvk, "m"),
                    "Mr1": (100 * rk.Mr1, "%"), "Mr2": (100 * rk.Mr2, "%"),
                    "A1": (rk.A1, "m"), "A2": (rk.A2, "m")})
        pq = profiles.probability_parameters(rough)
        out.update({"Rpq": (pq.Rpq, "m"), "Rvq": (pq.Rvq, "m"), "Rmq": (100 * pq.Rmq, "%")})
    except ProfileError as exc:
        if "unknown Rk construction" in str(exc):
            raise SurfmetInputError(str(exc)) from None
        notes.append(f"ISO 13565 parameters not computed: {exc}")
    return out, notes


def feature_values(rough: Any, dx: float, rz: float
                   ) -> tuple[dict[str, tuple[float, str]], list[str]]:
    """ISO 21920-2 feature parameters (Wolf pruning at 5 % of ``rz``), with units."""
    import numpy as np

    from profiles._errors import ProfileError
    from profiles._features import feature_parameters

    rough = np.asarray(rough, dtype=float)
    if not np.isfinite(rough).all():
        return {}, ["feature parameters not computed: the evaluated profile has "
                    "non-measured points (the segmentation needs a continuous profile)"]
    try:
        fp = feature_parameters(rough, dx, rz=rz)
    except ProfileError as exc:
        return {}, [f"feature parameters not computed: {exc}"]
    return {k: (v, fp.UNITS[k]) for k, v in fp.as_dict().items()}, []
