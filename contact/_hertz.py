"""Hertz theory: a smooth sphere or cylinder pressed on a flat elastic half-space.

The two bodies enter only through the composite modulus E* (see
:func:`contact._materials.composite_modulus`); the ball of radius R stands for the relative
curvature of the pair. Formulas from K. L. Johnson, *Contact Mechanics*, Cambridge
University Press (1985), ch. 4 (Hertz theory of elastic contact; sphere sec. 4.2, cylinder
sec. 4.3) and ch. 3 (surface displacement under the Hertz pressure). With P = 1/E* they
are the forms Alaci et al. (2022) print: delta = (9 P^2 N^2 / (16 R))^(1/3), a = (3/4 N R P)^(1/3).

Sign convention: displacements are positive *into* the bodies (the combined normal
displacement of the two surfaces), so that at the contact centre u(0) = delta.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass

import numpy as np

from contact._errors import ContactInputError
from contact._validate import positive


@dataclass(frozen=True)
class HertzSphere:
    """Hertz solution of a sphere of radius R pressed with load W on a flat.

    Attributes
    ----------
    radius, load, e_star : float
        R (m), W (N), E* (Pa).
    a : float
        Contact radius (m), a = (3 W R / (4 E*))^(1/3).
    delta : float
        Approach of distant points (m), delta = a^2 / R.
    p0 : float
        Maximum pressure (Pa), p0 = 3 W / (2 pi a^2).

    See Also
    --------
    hertz_sphere, hertz_sphere_from_approach : make it.

    References
    ----------
    .. [1] H. Hertz, "Über die Berührung fester elastischer Körper", J. reine angew. Math.
       92 (1882) 156-171.
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sec. 4.2.

    Examples
    --------
    >>> from contact import hertz_sphere
    >>> h = hertz_sphere(0.02, 10.0, 58.6e9)
    >>> print(f"a = {h.a * 1e6:.0f} µm, delta = {h.delta * 1e6:.3f} µm, p0 = {h.p0 / 1e6:.0f} MPa")
    a = 137 µm, delta = 0.936 µm, p0 = 255 MPa
    """

    radius: float
    load: float
    e_star: float
    a: float
    delta: float
    p0: float

    @property
    def mean_pressure(self) -> float:
        """Mean contact pressure W / (pi a^2) = 2 p0 / 3, in Pa."""
        return self.load / (math.pi * self.a**2)

    @property
    def stiffness(self) -> float:
        """Normal contact stiffness dW/d(delta) = 2 E* a, in N/m."""
        return 2.0 * self.e_star * self.a

    def pressure(self, r: np.ndarray | float) -> np.ndarray:
        """p(r) = p0 sqrt(1 - r^2/a^2) inside the contact, 0 outside (Pa)."""
        r = np.asarray(r, dtype=float)
        s = 1.0 - (r / self.a) ** 2
        return self.p0 * np.sqrt(np.clip(s, 0.0, None))

    def displacement(self, r: np.ndarray | float) -> np.ndarray:
        """Combined normal surface displacement u(r) of both bodies (m) (Johnson ch. 3).

        Inside, u = pi p0 (2a^2 - r^2) / (4 a E*) = delta - r^2/(2R); outside,
        u = p0 [(2a^2 - r^2) asin(a/r) + r a sqrt(1 - a^2/r^2)] / (2 a E*).
        """
        r = np.abs(np.asarray(r, dtype=float))
        a = self.a
        inside = math.pi * self.p0 * (2 * a**2 - r**2) / (4 * a * self.e_star)
        with np.errstate(divide="ignore", invalid="ignore"):
            ro = np.maximum(r, a)
            outside = (
                self.p0
                / (2 * a * self.e_star)
                * ((2 * a**2 - ro**2) * np.arcsin(a / ro) + ro * a * np.sqrt(1 - (a / ro) ** 2))
            )
        return np.where(r <= a, inside, outside)

    def gap(self, r: np.ndarray | float) -> np.ndarray:
        """Deformed gap r^2/(2R) - delta + u(r): zero inside the contact, positive outside."""
        r = np.asarray(r, dtype=float)
        return np.maximum(r**2 / (2 * self.radius) - self.delta + self.displacement(r), 0.0)


def hertz_sphere(radius: float, load: float, e_star: float) -> HertzSphere:
    """Hertz contact of a sphere on a flat (or two spheres with 1/R = 1/R1 + 1/R2).

    Parameters
    ----------
    radius : float
        Sphere radius R in metres.
    load : float
        Normal load W in newtons.
    e_star : float
        Composite modulus E* in Pa.

    Returns
    -------
    HertzSphere
        Contact radius, approach and peak pressure.

    Raises
    ------
    ContactInputError
        A radius, load or modulus that is not positive and finite.

    See Also
    --------
    hertz_sphere_from_approach : the same for a given approach.
    contact.solve_sphere : the numerical (BEM) solution, rough or smooth.

    References
    ----------
    .. [1] H. Hertz, "Über die Berührung fester elastischer Körper", J. reine angew. Math.
       92 (1882) 156-171.
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), eqs.
       (4.22)-(4.23).

    Examples
    --------
    The check of Alaci et al. (2022): a 20 mm steel ball on aluminium at 10 N.

    >>> from contact._materials import material, composite_modulus
    >>> h = hertz_sphere(0.02, 10.0, composite_modulus(material("steel"), material("al")))
    >>> round(h.delta * 1e6, 3), round(h.a * 1e6)
    (0.936, 137)
    """
    R = positive(radius, "radius", "m")
    W = positive(load, "load", "N")
    E = positive(e_star, "E*", "Pa")
    a = (3.0 * W * R / (4.0 * E)) ** (1.0 / 3.0)
    delta = a**2 / R if a > 0 else 0.0
    p0 = 3.0 * W / (2.0 * math.pi * a**2) if a**2 > 0 else math.inf
    _representable(R, W, E, a=a, delta=delta, p0=p0)
    return HertzSphere(radius=R, load=W, e_star=E, a=a, delta=delta, p0=p0)


def _representable(radius: float, load: float, e_star: float, **values: float) -> None:
    """Refuse inputs whose Hertz solution underflows or overflows a float (each input
    representable, e.g. a 1e-200 N load on a 1e-200 m ball): the engine's own error,
    not a division by zero or an infinite pressure."""
    bad = [k for k, v in values.items() if not (math.isfinite(v) and v >= sys.float_info.min)]
    if bad:
        raise ContactInputError(
            f"the Hertz solution of R = {radius:.3g} m, W = {load:.3g} N, E* = {e_star:.3g} "
            f"Pa is out of range ({', '.join(bad)} under- or overflow): not a physical "
            "contact")


def hertz_sphere_from_approach(radius: float, delta: float, e_star: float) -> HertzSphere:
    """The Hertz solution for a prescribed approach delta: W = (4/3) E* R^(1/2) delta^(3/2).

    Parameters
    ----------
    radius : float
        Sphere radius R in metres.
    delta : float
        Approach of distant points in metres.
    e_star : float
        Composite modulus E* in Pa.

    Returns
    -------
    HertzSphere
        The load that gives that approach, with a and p0.

    Raises
    ------
    ContactInputError
        A radius, approach or modulus that is not positive and finite.

    See Also
    --------
    hertz_sphere

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), eq. (4.23).

    Examples
    --------
    The inverse of :func:`hertz_sphere`:

    >>> from contact import hertz_sphere, hertz_sphere_from_approach
    >>> h = hertz_sphere(0.02, 10.0, 58.6e9)
    >>> print(f"{hertz_sphere_from_approach(0.02, h.delta, 58.6e9).load:.6f} N")
    10.000000 N
    """
    R = positive(radius, "radius", "m")
    d = positive(delta, "approach", "m")
    E = positive(e_star, "E*", "Pa")
    load = 4.0 / 3.0 * E * math.sqrt(R) * d**1.5
    return hertz_sphere(R, load, E)


@dataclass(frozen=True)
class HertzCylinder:
    """Hertz solution of a cylinder of radius R pressed on a flat with load W' per length.

    Attributes
    ----------
    radius, load_per_length, e_star : float
        R (m), W' (N/m), E* (Pa).
    a : float
        Contact half-width (m), a = sqrt(4 W' R / (pi E*)).
    p0 : float
        Maximum pressure (Pa), p0 = 2 W' / (pi a) = sqrt(W' E* / (pi R)).

    See Also
    --------
    hertz_cylinder : makes it.

    Notes
    -----
    A line contact has no finite approach on a half-space: the displacement of a 2D
    half-space grows like log(distance), so delta depends on the datum where it is measured
    (Johnson 1985, sec. 4.3). This class therefore gives the surface displacement
    relative to the contact centre, :meth:`relative_displacement`, not a delta.

    Examples
    --------
    >>> from contact import hertz_cylinder
    >>> h = hertz_cylinder(0.01, 1e4, 58.6e9)
    >>> print(f"a = {h.a * 1e6:.1f} µm, p0 = {h.p0 / 1e6:.1f} MPa")
    a = 46.6 µm, p0 = 136.6 MPa
    """

    radius: float
    load_per_length: float
    e_star: float
    a: float
    p0: float

    def pressure(self, x: np.ndarray | float) -> np.ndarray:
        """p(x) = p0 sqrt(1 - x^2/a^2) inside the strip, 0 outside (Pa)."""
        x = np.asarray(x, dtype=float)
        return self.p0 * np.sqrt(np.clip(1.0 - (x / self.a) ** 2, 0.0, None))

    def relative_displacement(self, x: np.ndarray | float) -> np.ndarray:
        """u(0) - u(x), the drop of the combined surface displacement from the centre (m).

        Inside it equals x^2/(2R) (the contact closes the gap); outside it follows from
        integrating the surface slope under the elliptical pressure (Johnson ch. 2),
        du/dx = -(2/(pi E*)) int p(s)/(x - s) ds = -(x - sqrt(x^2 - a^2))/R::

            u(0) - u(x) = [x^2 - x sqrt(x^2 - a^2) + a^2 acosh(|x|/a)] / (2R)
        """
        x = np.abs(np.asarray(x, dtype=float))
        a, R = self.a, self.radius
        xo = np.maximum(x, a)
        outside = (xo**2 - xo * np.sqrt(xo**2 - a**2) + a**2 * np.arccosh(xo / a)) / (2 * R)
        return np.where(x <= a, x**2 / (2 * R), outside)


def hertz_cylinder(radius: float, load_per_length: float, e_star: float) -> HertzCylinder:
    """Hertz line contact of a cylinder (axis along y) on a flat.

    Parameters
    ----------
    radius : float
        Cylinder radius R in metres.
    load_per_length : float
        Normal load per unit length W' in N/m.
    e_star : float
        Composite modulus E* in Pa.

    Returns
    -------
    HertzCylinder
        Contact half-width and peak pressure.

    Raises
    ------
    ContactInputError
        A radius, load or modulus that is not positive and finite.

    See Also
    --------
    contact.solve_cylinder : the numerical (BEM) line contact.

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sec. 4.3.

    Examples
    --------
    A 10 mm roller at 10 kN/m on E* = 58.6 GPa; ``p0 = sqrt(W' E* / (π R))``:

    >>> import math
    >>> from contact import hertz_cylinder
    >>> h = hertz_cylinder(0.01, 1e4, 58.6e9)
    >>> print(f"a = {h.a * 1e6:.1f} µm, p0 = {h.p0 / 1e6:.1f} MPa")
    a = 46.6 µm, p0 = 136.6 MPa
    >>> print(f"{math.sqrt(1e4 * 58.6e9 / (math.pi * 0.01)) / 1e6:.1f} MPa")
    136.6 MPa
    """
    R = positive(radius, "radius", "m")
    W = positive(load_per_length, "load per length", "N/m")
    E = positive(e_star, "E*", "Pa")
    a = math.sqrt(4.0 * W * R / (math.pi * E))
    p0 = 2.0 * W / (math.pi * a) if a > 0 else math.inf
    _representable(R, W, E, a=a, p0=p0)
    return HertzCylinder(radius=R, load_per_length=W, e_star=E, a=a, p0=p0)
