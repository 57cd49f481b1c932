"""The Greenwood-Tripp rough sphere: Greenwood-Williamson asperities under a Hertz body.

A smooth elastic sphere of radius R is pressed with a load N onto a nominally flat surface
carrying Greenwood-Williamson asperities (summit density η, mean summit radius R_s,
Gaussian summit heights of standard deviation σ_s), all elastic with the composite
modulus E* (Greenwood & Tripp 1967; Johnson 1985, sec. 13.4). At radius r the local
separation between the deformed sphere and the mean summit plane is

    g(r) = -d + r²/(2R) + u(r),

with d the depth of the sphere's apex below the mean summit plane (set by the load) and
u(r) the combined normal displacement of the two half-spaces under the nominal pressure
p(r) (Boussinesq; for axisymmetric loads the ring kernel with complete elliptic
integrals, Johnson 1985, Eq. 3.39 for a uniform disc: the ring operator of
:mod:`contact.halfspace.axisymmetric`). The nominal pressure is the GW
asperity load per unit area at that separation,

    p(r) = η ∫_{g}^{∞} f(z - g) φ(z) dz,   f(w) = (4/3) E* R_s^{1/2} w^{3/2}  (Hertz),

and the pressure integrates to N. This module solves that nonlinear integral equation by
Newton's method on piecewise-constant rings: the displacement of a uniform annulus is
exact (difference of two uniform discs), so the discretisation error is that of the
piecewise-constant pressure only.

Elastic-plastic asperities (``plastic="cap"``, the default when a hardness is given):
an asperity is Hertzian until its mean contact pressure reaches H, at the interference
``w_c = R_s (3πH / 4E*)²``; beyond it the mean pressure stays at H over the area π R_s w
(continuous with the elastic area at w_c), so ``f(w) = π H R_s w``. This is the same
perfectly-plastic rule as the boundary elements' pressure cap p ≤ H (contact.bem). The
alternative ``plastic="ceb"`` is Chang, Etsion & Bogy (1987, J. Tribol. 109:257):
yield when the Hertz peak pressure reaches K·H (K = 0.454 + 0.41 ν), then the area
``π R_s w (2 - w_c/w)`` at the mean pressure K·H.

Approach: a Gaussian summit population has no highest summit, so "first touch" is
defined here as the apex position at which the expected number of summits touching the
undeformed sphere is one, ``2π R η ∫_{d1}^{∞} Q(z/σ_s) dz = 1`` (Q the Gaussian tail);
the approach is the apex travel from there, d - d1 (comparable with the boundary
elements' approach from the first touching point of a finite scan).

Effective radius: a* = sqrt(5/2 <r²>_p), the radius of the Hertz distribution with the
same second moment of pressure (:func:`contact._fields.effective_radius`); a* = a for
Hertz, so a*/a0 is Johnson's Fig. 13.12 ratio measured the same way as the BEM's.

Limits. GT is a statistical model: it holds when many asperities lie under the ball
(correlation lengths well below a0). Its asperities do not interact, so the asperity
layer is too compliant where contact is nearly complete: for a surface of fixed lateral
structure and amplitude ε the layer's compliance falls only like ε^(1/3), and a nearly
smooth scan's GT a* stays several per cent above a0 (about 10 % at α = 0.005 on a
4-10 µm band) while the boundary elements, and Hertz, agree. The solution depends only
on α = σ_s R / a0² and μ = η σ_s √(R R_s) (dimensional analysis of the equation above).

References
----------
Greenwood, J. A. & Tripp, J. H. (1967). The elastic contact of rough spheres. J. Appl.
Mech. 34, 153-159.
Greenwood, J. A. & Williamson, J. B. P. (1966). Proc. R. Soc. A 295, 300.
Johnson, K. L. (1985). Contact Mechanics. Cambridge University Press, sec. 3.4, 13.4.
Chang, W. R., Etsion, I. & Bogy, D. B. (1987). An elastic-plastic model for the contact
of rough surfaces. J. Tribol. 109, 257-263.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from scipy.special import erfc

from contact._errors import ContactInputError, ConvergenceError
from contact._hertz import hertz_sphere
from contact._validate import positive
from contact.halfspace.axisymmetric import RingOperator

if TYPE_CHECKING:  # only the annotation of Asperities.of names it
    from contact.roughcontact._summits import SummitParameters

#: Gauss-Legendre nodes for the summit-height integrals (in t = sqrt(z - g)).
_GL_T, _GL_W = np.polynomial.legendre.leggauss(48)
#: The summit heights are integrated up to this many σ_s.
_ZMAX = 9.0
PLASTIC_MODELS = ("cap", "ceb")


@dataclass(frozen=True)
class Asperities:
    """The summit population of a Greenwood-Tripp solve and its asperity law.

    Attributes
    ----------
    sigma_s, density, summit_radius : float
        Summit-height standard deviation σ_s (m), summit density η (1/m²) and mean summit
        radius R_s (m), e.g. from :func:`contact.roughcontact.summit_parameters`.
    plastic : {"cap", "ceb"}
        Elastic-plastic asperity law when the solve has a hardness.
    poisson : float
        Poisson's ratio of the softer body (only for CEB's K = 0.454 + 0.41 ν).

    Examples
    --------
    >>> from contact.roughcontact._greenwood_tripp import Asperities
    >>> Asperities(sigma_s=1e-7, density=1e10, summit_radius=1e-5).plastic
    'cap'
    """

    sigma_s: float
    density: float
    summit_radius: float
    plastic: str = "cap"
    poisson: float = 0.3

    @classmethod
    def of(cls, summits: SummitParameters, **law: Any) -> Asperities:
        """The population of :func:`contact.roughcontact.summit_parameters`' answer
        (``law``: ``plastic``, ``poisson``)."""
        return cls(sigma_s=summits.sigma_s, density=summits.density,
                   summit_radius=summits.radius, **law)


@dataclass(frozen=True, eq=False)
class GreenwoodTripp:
    """Solution of the Greenwood-Tripp rough-sphere problem (SI units).

    Attributes
    ----------
    r : ndarray
        Ring centres (m).
    edges : ndarray
        Ring edges (m), ``r.size + 1`` values from 0.
    p : ndarray
        Nominal pressure on each ring (Pa).
    load, radius, e_star : float
        N (N), R (m), E* (Pa).
    sigma_s, density, summit_radius : float
        Summit parameters σ_s (m), η (1/m²), R_s (m).
    hardness : float or None
        Pressure cap of the asperities (Pa); None: elastic asperities.
    plastic : str or None
        ``"cap"``, ``"ceb"`` or None.
    depth : float
        Apex depth d below the mean summit plane (m).
    approach : float
        Apex travel from first touch (m), see the module notes.
    a_star : float
        Effective (second-moment) contact radius (m).
    peak : float
        Largest nominal pressure (Pa).
    a0, p0, delta0 : float
        Hertz radius, peak pressure and approach at the same load.
    iterations : int
        Newton iterations.
    """

    r: np.ndarray
    edges: np.ndarray
    p: np.ndarray
    load: float
    radius: float
    e_star: float
    sigma_s: float
    density: float
    summit_radius: float
    hardness: float | None
    plastic: str | None
    depth: float
    approach: float
    a_star: float
    peak: float
    a0: float
    p0: float
    delta0: float
    iterations: int

    @property
    def alpha(self) -> float:
        """Greenwood-Tripp / GJM roughness parameter σ_s R / a0²."""
        return self.sigma_s * self.radius / self.a0**2

    def pressure(self, r: np.ndarray | float) -> np.ndarray:
        """Nominal pressure at radius ``r`` (Pa): linear between ring centres, 0 beyond."""
        rr = np.abs(np.asarray(r, dtype=float))
        return np.interp(rr, self.r, self.p, left=float(self.p[0]), right=0.0)


class _AsperityLaw:
    """Nominal pressure P(g) and dP/dg of a GW population at the separation g."""

    def __init__(self, density: float, radius: float, sigma: float, e_star: float,
                 hardness: float | None, plastic: str | None, poisson: float) -> None:
        self.eta, self.rs, self.sigma, self.e = density, radius, sigma, e_star
        self.h = hardness
        self.kind = plastic if hardness is not None else None
        self.c_el = 4.0 / 3.0 * e_star * math.sqrt(radius)
        if self.kind == "cap":
            self.wc = radius * (3.0 * math.pi * hardness / (4.0 * e_star)) ** 2
            self.pm = hardness
        elif self.kind == "ceb":
            k = 0.454 + 0.41 * poisson
            self.pm = k * hardness
            self.wc = radius * (math.pi * k * hardness / (2.0 * e_star)) ** 2
        else:
            self.wc = math.inf

    def f(self, w: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Load of one asperity at interference w ≥ 0, and its derivative."""
        el = w <= self.wc
        ws = np.sqrt(np.maximum(w, 0.0))
        f = np.where(el, self.c_el * ws**3, 0.0)
        df = np.where(el, 1.5 * self.c_el * ws, 0.0)
        if self.kind == "cap":
            f = np.where(el, f, math.pi * self.h * self.rs * w)
            df = np.where(el, df, math.pi * self.h * self.rs)
        elif self.kind == "ceb":
            f = np.where(el, f, self.pm * math.pi * self.rs * (2.0 * w - self.wc))
            df = np.where(el, df, 2.0 * self.pm * math.pi * self.rs)
        return f, df

    def mean_pressure(self, w: np.ndarray) -> np.ndarray:
        """Mean contact pressure of one asperity at interference w > 0 (Pa)."""
        w = np.asarray(w, dtype=float)
        f, _ = self.f(w)
        if self.kind == "ceb":
            area = np.where(w <= self.wc, math.pi * self.rs * w,
                            math.pi * self.rs * (2.0 * w - self.wc))
        else:
            area = math.pi * self.rs * w
        return f / area

    def __call__(self, g: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """P(g) = η ∫_g^∞ f(z-g) φ(z) dz and dP/dg, by Gauss-Legendre in t = sqrt(z-g)."""
        g = np.asarray(g, dtype=float)
        s = self.sigma
        top = _ZMAX * s
        span = np.maximum(top - g, 0.0)
        # split at the yield interference so that each panel's integrand is smooth
        tc = math.sqrt(self.wc) if math.isfinite(self.wc) else math.inf
        tmax = np.sqrt(span)
        panels = [(np.zeros_like(g), np.minimum(tmax, tc))]
        if math.isfinite(tc):
            panels.append((np.minimum(tmax, tc), tmax))
        P = np.zeros_like(g)
        dP = np.zeros_like(g)
        for lo, hi in panels:
            half = 0.5 * (hi - lo)
            t = (lo + half)[:, None] + half[:, None] * _GL_T[None, :]
            w = t * t
            z = g[:, None] + w
            phi = np.exp(-0.5 * (z / s) ** 2) / (s * math.sqrt(2.0 * math.pi))
            f, df = self.f(w)
            jac = 2.0 * t * half[:, None] * _GL_W[None, :]
            P += np.sum(f * phi * jac, axis=1)
            dP -= np.sum(df * phi * jac, axis=1)
        return self.eta * P, self.eta * dP


def _first_touch_depth(radius: float, density: float, sigma: float) -> float:
    """Apex height d1 (above the mean summit plane) with one expected touching summit."""
    # 2π R η ∫_{d1}^∞ Q(z/σ) dz = 1; the integral is σ [φ(x) - x Q(x)] with x = d1/σ
    target = 1.0 / (2.0 * math.pi * radius * density * sigma)

    def tail(x: float) -> float:
        return math.exp(-0.5 * x * x) / math.sqrt(2 * math.pi) - x * 0.5 * erfc(x / math.sqrt(2))

    lo, hi = -50.0, 40.0
    if tail(lo) < target:  # fewer than one summit in reach even at great depth
        return lo * sigma
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if tail(mid) > target:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi) * sigma


def greenwood_tripp(
    load: float,
    radius: float,
    e_star: float,
    *,
    asperities: Asperities,
    hardness: float | None = None,
    rings: int = 240,
    tol: float = 1e-10,
    max_iter: int = 200,
) -> GreenwoodTripp:
    """Solve the Greenwood-Tripp rough sphere (see the module notes).

    Parameters
    ----------
    load, radius, e_star : float
        Normal load N (N), sphere radius R (m), composite modulus E* (Pa).
    asperities : Asperities
        The summit population (σ_s, η, R_s) and the elastic-plastic asperity law
        (:class:`Asperities`; :meth:`Asperities.of` a summit analysis).
    hardness : float, optional
        Caps the asperity mean pressure (Pa); None: elastic asperities.
    rings : int
        Number of pressure rings.
    tol : float
        Newton tolerance on the pressure residual, relative to the Hertz p0.

    Returns
    -------
    GreenwoodTripp

    Raises
    ------
    ContactInputError
        Non-positive inputs, an unknown plastic law.
    ConvergenceError
        Newton's method did not converge.
    """
    sigma_s, density = asperities.sigma_s, asperities.density
    summit_radius, plastic = asperities.summit_radius, asperities.plastic
    for name, v, unit in (("load", load, "N"), ("radius", radius, "m"),
                          ("e_star", e_star, "Pa"), ("sigma_s", sigma_s, "m"),
                          ("density", density, "1/m^2"), ("summit_radius", summit_radius, "m")):
        positive(v, name, unit)
    if hardness is not None:
        positive(hardness, "the hardness", "Pa")
    if plastic not in PLASTIC_MODELS:
        raise ContactInputError(f"plastic must be one of {PLASTIC_MODELS}, got {plastic!r}")
    if rings < 16:
        raise ContactInputError("use at least 16 rings")
    hz = hertz_sphere(radius, load, e_star)
    law = _AsperityLaw(density, summit_radius, sigma_s, e_star, hardness, plastic,
                       asperities.poisson)
    # the domain: where the undeformed sphere stays within reach of the summits at the
    # Hertz approach plus the summit spread, enlarged until the edge carries no pressure
    r_max = max(2.0 * hz.a, math.sqrt(2.0 * radius * (hz.delta + 6.0 * sigma_s)))
    from threadpoolctl import threadpool_limits

    for _ in range(8):
        # a 240² dense solve is sub-millisecond on one thread; a threaded BLAS on a busy
        # machine makes it a hundred times slower
        with threadpool_limits(limits=1, user_api="blas"):
            sol = _solve(law, hz, radius, e_star, load, r_max, rings, tol, max_iter)
        p = sol[0]
        if p[-1] <= 1e-6 * p.max() and p[-rings // 10:].max() <= 1e-3 * p.max():
            break
        r_max *= 1.5
    else:
        raise ConvergenceError("the Greenwood-Tripp pressure does not decay within "
                               f"{r_max:.3g} m", residual=float(p[-1] / p.max()), iterations=0)
    p, depth, edges, r, its = sol
    area = math.pi * np.diff(edges**2)
    m2 = float(np.sum(p * math.pi * np.diff(edges**4) / 2.0) / np.sum(p * area))
    d1 = _first_touch_depth(radius, density, sigma_s)
    return GreenwoodTripp(
        r=r, edges=edges, p=p, load=float(load), radius=float(radius), e_star=float(e_star),
        sigma_s=float(sigma_s), density=float(density), summit_radius=float(summit_radius),
        hardness=hardness, plastic=law.kind, depth=float(depth),
        approach=float(d1 + depth), a_star=math.sqrt(2.5 * m2), peak=float(p.max()),
        a0=hz.a, p0=hz.p0, delta0=hz.delta, iterations=its,
    )


def _solve(law: _AsperityLaw, hz, radius: float, e_star: float, load: float, r_max: float,
           n: int, tol: float, max_iter: int):
    edges = np.linspace(0.0, r_max, n + 1)
    # the axisymmetric half-space operator (E* = 1) of contact.halfspace, at ring centres
    rings = RingOperator(edges)
    r = rings.r
    area = math.pi * np.diff(edges**2)
    K = rings.matrix / e_star
    shape = r * r / (2.0 * radius)
    p0 = hz.p0
    # start: the Hertz pressure (the σ → 0 limit) and the depth that balances the load
    # when the separations are those of the Hertz displacement
    x = np.append(hz.pressure(r) / p0, 0.0)
    u = K @ (x[:-1] * p0)
    lo, hi = -hz.delta - 20 * law.sigma, hz.delta + 20 * law.sigma
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if float(np.sum(law(shape + u - mid)[0] * area)) > load:
            hi = mid
        else:
            lo = mid
    x[-1] = 0.5 * (lo + hi) / hz.delta

    def residual(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        p = x[:-1] * p0
        g = shape + K @ p - x[-1] * hz.delta
        P, dP = law(g)
        res = np.append(x[:-1] - P / p0, (np.sum(p * area) - load) / load)
        return res, dP

    res, dP = residual(x)
    norm = float(np.linalg.norm(res, np.inf))
    its = 0
    for its in range(1, max_iter + 1):
        if norm < tol:
            break
        J = np.zeros((n + 1, n + 1))
        J[:n, :n] = np.eye(n) - dP[:, None] * K
        J[:n, n] = dP * hz.delta / p0
        J[n, :n] = area * p0 / load
        try:
            step = np.linalg.solve(J, -res)
        except np.linalg.LinAlgError:
            # no ring's summits respond to the separation (dP = 0 everywhere): the
            # population cannot carry the load, the model has no solution here
            raise ConvergenceError(
                "Greenwood-Tripp has no solution: no summit of the population responds at "
                f"this load (sigma_s = {law.sigma:.3g} m against the Hertz approach "
                f"{hz.delta:.3g} m)", residual=norm, iterations=its) from None
        lam = 1.0
        while True:
            trial = x + lam * step
            trial[:-1] = np.maximum(trial[:-1], 0.0)
            r_new, dP_new = residual(trial)
            n_new = float(np.linalg.norm(r_new, np.inf))
            if n_new < norm or lam < 1e-4:
                break
            lam *= 0.5
        x, res, dP, norm = trial, r_new, dP_new, n_new
    else:
        raise ConvergenceError(f"Greenwood-Tripp Newton stopped at residual {norm:.3g}",
                               residual=norm, iterations=max_iter)
    return x[:-1] * p0, x[-1] * hz.delta, edges, r, its


def asperity_mean_pressure(sol: GreenwoodTripp, interference: np.ndarray,
                           poisson: float = 0.3) -> np.ndarray:
    """Mean contact pressure of one asperity of ``sol``'s population at ``interference`` (Pa).

    With a hardness, this is what the elastic-plastic law caps (H for ``"cap"``, K·H for
    CEB); without one, Hertz's (4/3π) E* sqrt(w/R_s).
    """
    law = _AsperityLaw(sol.density, sol.summit_radius, sol.sigma_s, sol.e_star,
                       sol.hardness, sol.plastic or "cap", poisson)
    return law.mean_pressure(np.asarray(interference, dtype=float))
