"""Linear viscoelastic rheology: the standard linear solid, Prony series, creep series.

Conventions (those of CONTACT's user guide, Vollebregt, sec. "Viscoelastic materials").
A standard linear solid (SLS) has a glassy (instantaneous) Young's modulus E_g, a relaxed
(rubbery, long-time) modulus E_r < E_g and a *creep* time tau_c. Its creep compliance is

    J(t) = 1/E_g + (1/E_r - 1/E_g) (1 - exp(-t / tau_c)),

and its relaxation modulus E(t) = E_r + (E_g - E_r) exp(-t / tau_sigma) has the stress-
relaxation time

    tau_sigma = tau_c E_r / E_g            (shorter than the creep time).

Proof: in Laplace form s E(s) = E_r + (E_g - E_r) s / (s + 1/tau_sigma) and
s J(s) = 1 / (s E(s)); the pole of J(s) lies where s E(s) = 0, at
s = -E_r / (E_g tau_sigma) = -1/tau_c. (CONTACT's inputs: GG = G_g, FG = E_g/E_r - 1,
TC = tau_c; its user guide, table "Relations of the viscoelastic input quantities".)
``tests/test_viscoelastic_rheology.py`` checks it by solving the Volterra identity
int_0^t E(t - s) dJ(s) = 1 numerically.

A Prony series in relaxation form, E(t) = E_inf + sum_k E_k exp(-t/tau_k) (the form
rheometers fit), is turned into the creep series the rolling solver needs by the same
Laplace argument: the retardation times are the roots of s E(s) = 0, which interlace the
relaxation times, and the creep amplitudes are the residues there.

Poisson's ratio is taken constant in time (as CONTACT does), so a half-space's surface
compliance is (1 - nu^2) J(t), and the pair's combined compliance is the sum of the two
bodies' (Johnson 1985, *Contact Mechanics*, sec. 6.5 and 8.4):

    C(t) = C_g + sum_m dC_m (1 - exp(-t / theta_m))            (1/Pa).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from contact._errors import ContactInputError
from contact._materials import Material
from contact._validate import positive


@dataclass(frozen=True)
class CreepSeries:
    """Combined surface creep compliance C(t) = C_g + sum dC_m (1 - exp(-t/theta_m)).

    Attributes
    ----------
    glassy : float
        C_g = C(0), in 1/Pa (0 for a rigid pair is not allowed: one body must deform).
    amplitudes : tuple of float
        dC_m >= 0, in 1/Pa.
    times : tuple of float
        Retardation (creep) times theta_m > 0, in s.
    """

    glassy: float
    amplitudes: tuple[float, ...] = ()
    times: tuple[float, ...] = ()

    def __post_init__(self) -> None:
        positive(self.glassy, "the glassy compliance", "1/Pa")
        if len(self.amplitudes) != len(self.times):
            raise ContactInputError("a creep series needs one time per amplitude")
        for dc, t in zip(self.amplitudes, self.times):
            if not (math.isfinite(dc) and dc >= 0):
                raise ContactInputError(f"creep amplitudes must be >= 0 in 1/Pa, got {dc!r}")
            positive(t, "a creep time tau", "s")

    @property
    def relaxed(self) -> float:
        """C(inf) = C_g + sum dC_m, the long-time compliance (1/Pa)."""
        return self.glassy + float(sum(self.amplitudes))

    def compliance(self, t: np.ndarray | float) -> np.ndarray:
        """C(t) in 1/Pa for times t >= 0 (s)."""
        t = np.asarray(t, dtype=float)
        out = np.full(t.shape, self.glassy)
        for dc, th in zip(self.amplitudes, self.times):
            out = out + dc * (1.0 - np.exp(-t / th))
        return out

    def storage_loss(self, omega: np.ndarray | float) -> tuple[np.ndarray, np.ndarray]:
        """(C', C'') of the complex compliance C(omega) = C' - i C'' (1/Pa)."""
        w = np.asarray(omega, dtype=float)
        c1 = np.full(w.shape, self.glassy)
        c2 = np.zeros(w.shape)
        for dc, th in zip(self.amplitudes, self.times):
            wt = w * th
            c1 = c1 + dc / (1.0 + wt**2)
            c2 = c2 + dc * wt / (1.0 + wt**2)
        return c1, c2

    def plus(self, other: CreepSeries) -> CreepSeries:
        """The series of two bodies in series (their compliances add)."""
        return CreepSeries(self.glassy + other.glassy, self.amplitudes + other.amplitudes,
                           self.times + other.times)

    def scaled(self, factor: float) -> CreepSeries:
        """Every compliance times ``factor`` (e.g. 1 - nu^2 for a half-space surface)."""
        f = positive(factor, "the compliance factor", "-")
        return CreepSeries(self.glassy * f, tuple(a * f for a in self.amplitudes), self.times)

    def relaxed_only(self) -> CreepSeries:
        """The elastic limit tau -> 0 (fully relaxed before any change)."""
        return CreepSeries(self.relaxed)


@dataclass(frozen=True)
class StandardLinearSolid:
    """Standard linear solid in CONTACT's convention (see the module notes).

    Attributes
    ----------
    E_g, E_r : float
        Glassy and relaxed Young's moduli (Pa), E_r <= E_g.
    tau_c : float
        Creep time (s).
    nu : float
        Poisson's ratio (constant in time).
    """

    E_g: float
    E_r: float
    tau_c: float
    nu: float = 0.3

    def __post_init__(self) -> None:
        eg = positive(self.E_g, "the glassy modulus Eg", "Pa")
        er = positive(self.E_r, "the relaxed modulus Er", "Pa")
        if er > eg:
            raise ContactInputError(
                f"the relaxed modulus Er = {er:g} Pa exceeds the glassy modulus Eg = {eg:g} Pa "
                "(a standard linear solid softens with time: Er <= Eg)")
        positive(self.tau_c, "the creep time tau", "s")
        if not (math.isfinite(self.nu) and -1.0 < self.nu <= 0.5):
            raise ContactInputError(f"Poisson's ratio must lie in (-1, 0.5], got {self.nu}")

    @property
    def tau_sigma(self) -> float:
        """Stress-relaxation time tau_sigma = tau_c E_r / E_g (s)."""
        return self.tau_c * self.E_r / self.E_g

    def relaxation_modulus(self, t: np.ndarray | float) -> np.ndarray:
        """E(t) = E_r + (E_g - E_r) exp(-t / tau_sigma) (Pa)."""
        t = np.asarray(t, dtype=float)
        return self.E_r + (self.E_g - self.E_r) * np.exp(-t / self.tau_sigma)

    def creep(self) -> CreepSeries:
        """The body's surface creep series (1 - nu^2) J(t)."""
        f = 1.0 - self.nu**2
        return CreepSeries(f / self.E_g, (f * (1.0 / self.E_r - 1.0 / self.E_g),), (self.tau_c,))


@dataclass(frozen=True)
class PronySeries:
    """Relaxation modulus E(t) = E_inf + sum_k E_k exp(-t / tau_k) (Pa, s).

    Attributes
    ----------
    E_inf : float
        Relaxed modulus (Pa).
    moduli, times : tuple of float
        E_k >= 0 (Pa) and relaxation times tau_k > 0 (s).
    nu : float
        Poisson's ratio (constant in time).
    """

    E_inf: float
    moduli: tuple[float, ...]
    times: tuple[float, ...]
    nu: float = 0.3

    def __post_init__(self) -> None:
        positive(self.E_inf, "the relaxed modulus E_inf", "Pa")
        if len(self.moduli) != len(self.times) or not self.moduli:
            raise ContactInputError("a Prony series needs one relaxation time per modulus")
        for e, t in zip(self.moduli, self.times):
            positive(e, "a Prony modulus E_k", "Pa")
            positive(t, "a relaxation time tau", "s")
        if len(set(self.times)) != len(self.times):
            raise ContactInputError("the Prony relaxation times must be distinct")

    @property
    def E_g(self) -> float:
        """Glassy modulus E(0) = E_inf + sum E_k (Pa)."""
        return self.E_inf + float(sum(self.moduli))

    def relaxation_modulus(self, t: np.ndarray | float) -> np.ndarray:
        """E(t) in Pa."""
        t = np.asarray(t, dtype=float)
        out = np.full(t.shape, self.E_inf)
        for e, tau in zip(self.moduli, self.times):
            out = out + e * np.exp(-t / tau)
        return out

    def creep(self) -> CreepSeries:
        """The body's surface creep series (1 - nu^2) J(t), by the Laplace inversion."""
        return _prony_to_creep(self).scaled(1.0 - self.nu**2)


def _prony_to_creep(pr: PronySeries) -> CreepSeries:
    """J(t) of a Prony relaxation modulus: roots of s E(s) = 0 and their residues."""
    from scipy.optimize import brentq

    rates = np.sort(1.0 / np.asarray(pr.times, dtype=float))
    e_of_rate = dict(zip(1.0 / np.asarray(pr.times), pr.moduli))
    ek = np.array([e_of_rate[r] for r in rates])

    def se(s: float) -> float:  # s E(s) on the negative real axis
        return pr.E_inf + float(np.sum(ek * s / (s + rates)))

    def dse(s: float) -> float:
        return float(np.sum(ek * rates / (s + rates) ** 2))

    roots = []
    # s E(s) rises from E_inf at s = 0 to -inf... its zeros lie one in each interval
    # (-rate_k, -rate_{k-1}) and one in (-rate_0, 0), interlacing the poles.
    bounds = np.concatenate(([0.0], -rates))
    for hi, lo in itertools.pairwise(bounds):
        span = hi - lo
        a, b = lo + 1e-12 * span, hi - 1e-12 * span
        roots.append(brentq(se, a, b, xtol=1e-14 * span, rtol=1e-15, maxiter=400))
    # J(s) = 1/(s sE(s)); J(t) = 1/E_g + sum_m dJ_m (1 - exp(s_m t)) with s_m < 0,
    # dJ_m = -1/(s_m dse(s_m)) (residue of 1/(s sE(s)) at s_m, sign for the (1 - e) form).
    amps = tuple(float(-1.0 / (s * dse(s))) for s in roots)
    times = tuple(float(-1.0 / s) for s in roots)
    return CreepSeries(1.0 / pr.E_g, amps, times)


def pair_creep(body1: object, body2: object) -> CreepSeries:
    """Combined creep series of two bodies, each rigid (None), elastic or viscoelastic.

    Parameters
    ----------
    body1, body2 : None, contact._materials.Material, StandardLinearSolid or PronySeries
        None is a rigid body; a Material is elastic with (1 - nu^2)/E.
    """
    parts = []
    for body in (body1, body2):
        if body is None:
            continue
        if isinstance(body, Material):
            parts.append(CreepSeries(body.surface_compliance))
        elif isinstance(body, (StandardLinearSolid, PronySeries)):
            parts.append(body.creep())
        else:
            raise ContactInputError(f"unsupported body description {body!r}")
    if not parts:
        raise ContactInputError("at least one body must deform (both were rigid)")
    out = parts[0]
    for p in parts[1:]:
        out = out.plus(p)
    return out
