"""Loss data of contact materials (a source per value) and a standard linear solid fitted to it.

The loss factor eta = tan(delta) = E''/E' (= Q^-1, the internal friction; the specific
damping capacity is psi = 2 pi eta) of structural metals at room temperature and small
strain amplitude is of order 1e-4 to 1e-3 and nearly independent of frequency over the
acoustic range: there is no single relaxation, rather a broad background plus thermoelastic
(Zener) and dislocation (Granato-Luecke) peaks. A standard linear solid has one Debye peak,

    tan(delta)_max = (E_g - E_r) / (2 sqrt(E_g E_r))   at   omega = 1/sqrt(tau_c tau_sigma),

so :func:`sls_from_loss` places that peak at the contact's own loading frequency V/a. That
is the *largest* rolling resistance the loss factor can give (a conservative upper bound
for a metal whose eta is spread over many decades); the moduli's geometric mean is the
handbook modulus. For polymers the data are real relaxation spectra and the SLS is a
one-term fit.

Sources
-------
- [Ashby] M. F. Ashby (2011), *Materials Selection in Mechanical Design*, 4th ed.,
  Butterworth-Heinemann, ch. 4, the loss coefficient-modulus chart (fig. 4.9): steels and
  aluminium alloys eta ~ 1e-4 to 1e-3; polymers 1e-2 to 1e-1; elastomers to 1.
- [Lazan] B. J. Lazan (1968), *Damping of Materials and Members in Structural Mechanics*,
  Pergamon: specific damping capacity of steels and aluminium alloys at low stress
  amplitude, psi ~ 0.1 % to 1 % (eta = psi / 2 pi ~ 2e-4 to 2e-3).
- [Zener] C. Zener (1948), *Elasticity and Anelasticity of Metals*, Univ. of Chicago
  Press: thermoelastic damping of metals, peak Q^-1 of order 1e-3 (aluminium) and 1e-4
  (steel) at the thermal-diffusion frequency of the strain gradient.
- [Ferry] J. D. Ferry (1980), *Viscoelastic Properties of Polymers*, 3rd ed., Wiley: glassy
  PMMA below its beta transition, tan(delta) ~ 0.05-0.1 at room temperature, 1 Hz.
- [Wang-Knothe] G. Wang & K. Knothe (1993), J. Appl. Mech. 60:310, via CONTACT's
  visc_cylindr example: PA6, E_g = 3200 MPa, E_r = 1600 MPa, nu = 0.4.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from contact._errors import ContactInputError
from contact.viscoelastic._rheology import StandardLinearSolid


@dataclass(frozen=True)
class LossData:
    """Room-temperature loss factor of a material.

    Attributes
    ----------
    name : str
        Material name (as in :data:`contact._materials.MATERIALS`).
    low, typical, high : float
        Loss factor eta band and a typical value.
    source : str
        Where the numbers come from.

    Examples
    --------
    >>> from contact.viscoelastic import LossData, loss_data
    >>> isinstance(loss_data("aluminium"), LossData)
    True
    """

    name: str
    low: float
    typical: float
    high: float
    source: str


LOSS: dict[str, LossData] = {
    d.name: d
    for d in (
        LossData("steel", 1e-4, 3e-4, 1e-3,
                 "Ashby (2011) fig. 4.9; Lazan (1968); Zener (1948): hardened bearing steel "
                 "near the low end"),
        LossData("mild_steel", 2e-4, 5e-4, 2e-3, "Ashby (2011) fig. 4.9; Lazan (1968)"),
        LossData("aluminium", 1e-4, 5e-4, 1e-3,
                 "Ashby (2011) fig. 4.9; Lazan (1968); Zener (1948) thermoelastic peak ~1e-3"),
        LossData("pmma", 0.05, 0.07, 0.1, "Ferry (1980): glassy PMMA, 1 Hz, 20 C"),
    )
}


def loss_data(name: str) -> LossData:
    """The loss band of a material (table name or alias of :mod:`contact._materials`).

    Parameters
    ----------
    name : str
        A material of the loss table (``"steel"``, ``"mild_steel"``, ``"aluminium"``,
        ``"pmma"``) or an alias of it (``"Al 6061-T6"``...); case and separators ignored.

    Returns
    -------
    LossData
        The loss-factor band (low, typical, high; dimensionless) and its source.

    Raises
    ------
    ContactInputError
        No loss data for that material.

    Examples
    --------
    >>> from contact.viscoelastic import loss_data
    >>> steel = loss_data("steel")
    >>> steel.low, steel.typical, steel.high
    (0.0001, 0.0003, 0.001)
    >>> loss_data("PMMA").typical
    0.07
    """
    from contact._materials import ALIASES

    key = name.strip().lower().replace("-", "_").replace(" ", "_")
    key = ALIASES.get(key, key)
    if key not in LOSS:
        raise ContactInputError(f"no loss data for {name!r}; known: {', '.join(sorted(LOSS))}")
    return LOSS[key]


def sls_from_loss(E: float, nu: float, loss_factor: float, peak_time: float) -> StandardLinearSolid:
    """The SLS with tan(delta)_max = ``loss_factor`` at omega = 1/``peak_time``.

    E_g / E_r = r with (r - 1)/(2 sqrt r) = eta, i.e. sqrt r = eta + sqrt(1 + eta^2);
    E_g = E sqrt r, E_r = E / sqrt r (geometric mean E); sqrt(tau_c tau_sigma) =
    ``peak_time`` with tau_sigma = tau_c E_r/E_g gives tau_c = peak_time sqrt r.
    """
    eta = float(loss_factor)
    if not (math.isfinite(eta) and eta > 0):
        raise ContactInputError(f"the loss factor must be positive, got {loss_factor!r}")
    if not (math.isfinite(peak_time) and peak_time > 0):
        raise ContactInputError(f"the loss peak time must be positive in s, got {peak_time!r}")
    sr = eta + math.sqrt(1.0 + eta * eta)
    return StandardLinearSolid(E_g=E * sr, E_r=E / sr, tau_c=peak_time * sr, nu=nu)
