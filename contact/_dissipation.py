"""The dissipation model of a rolling-resistance sweep, as one small frozen value.

:func:`contact._rolling.sphere_sweep` and :func:`contact._rolling.cylinder_sweep` turn
contact solutions into rolling resistance under a dissipation model (the notes of
:mod:`contact._rolling`): elastic hysteresis (a lost fraction ``alpha_h`` of the work of
loading, on the body with displacement share ``share``, the material derivative taken as
``kinematics`` says) or first-pass plastic flow at the flow pressure ``hardness`` (its
band of width ``band`` around x = 0, the depth scale widened by ``roughness_rms``), and
fits the load exponent with a ``confidence`` interval. :class:`Dissipation` carries those
settings, checked once, so that a sweep takes one argument for them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from contact._errors import ContactInputError
from contact._validate import positive

#: The material derivative of the hysteresis model (see :func:`contact._rolling.hysteresis_work`).
KINEMATICS = ("rolling", "frozen")
#: The dissipation models of a sweep.
MODELS = ("hysteresis", "plastic")


def check_fraction(value: float, what: str) -> float:
    """``value`` as a float in (0, 1], else one :class:`ContactInputError` line."""
    v = float(value)
    if not (math.isfinite(v) and 0 < v <= 1):
        raise ContactInputError(f"{what} must lie in (0, 1], got {value!r}")
    return v


@dataclass(frozen=True)
class Dissipation:
    """How a rolling-resistance sweep turns contact solutions into dissipated work.

    Attributes
    ----------
    model : {"hysteresis", "plastic"}
        Dissipation model (:mod:`contact._rolling`). "plastic" needs ``hardness``.
    hardness : float, optional
        Flow pressure of the softer body (Pa).
    alpha_h : float
        Hysteresis loss fraction (hysteresis model); M_r is proportional to it.
    share : float
        Displacement share of the lossy body (hysteresis model; 1 = both bodies).
    kinematics : {"rolling", "frozen"}
        See :func:`contact._rolling.hysteresis_work`.
    band : float
        See :func:`contact._rolling.plastic_work`.
    roughness_rms : float, optional
        Rms roughness for the plastic band width (m; default: from the sweep's roughness).
    confidence : float
        Level of the confidence interval of the fitted load exponent.

    Raises
    ------
    ContactInputError
        An unknown model or kinematics, "plastic" without a hardness, a non-positive
        ``alpha_h`` or a share outside (0, 1].

    Examples
    --------
    >>> Dissipation(alpha_h=0.02).model
    'hysteresis'
    """

    model: str = "hysteresis"
    hardness: float | None = None
    alpha_h: float = 1.0
    share: float = 1.0
    kinematics: str = "rolling"
    band: float = 0.05
    roughness_rms: float | None = None
    confidence: float = 0.95

    def __post_init__(self) -> None:
        if self.model not in MODELS:
            raise ContactInputError(f"model must be one of {MODELS}, got {self.model!r}")
        if self.model == "plastic" and self.hardness is None:
            raise ContactInputError("the plastic model needs the hardness of the softer body")
        positive(self.alpha_h, "alpha_h")
        if self.kinematics not in KINEMATICS:
            raise ContactInputError(
                f"kinematics must be one of {KINEMATICS}, got {self.kinematics!r}")
        check_fraction(self.share, "the displacement share")


def dissipation_of(dissipation: Dissipation | None) -> Dissipation:
    """``dissipation``, or the default hysteresis model where None."""
    if dissipation is None:
        return Dissipation()
    if not isinstance(dissipation, Dissipation):
        raise ContactInputError(
            f"dissipation must be a contact.Dissipation, got {type(dissipation).__name__}")
    return dissipation
