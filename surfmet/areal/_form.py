"""F-operators: removal of the nominal form before roughness evaluation (ISO 25178-2, 3.1.4.2).

``remove_form(topo, method)`` returns the residual surface (the S-F surface when no
S-filter is applied) and a :class:`FormFit` that records what was removed:

``"none"``      nothing
``"mean"``      the mean height of the valid points
``"plane"``     least-squares plane over the valid points (heights ``z = a + b x + c y``)
``"poly:N"``    least-squares bivariate polynomial of total degree N
``"sphere"``    geometric least-squares sphere (see :mod:`surfmet.fitting`)
``"cylinder"``  geometric least-squares cylinder, axis in any in-plane direction;
``"cylinder:x"`` / ``"cylinder:y"`` fix the axis along x or y.

Every fit uses the measured points only (NaN stays NaN). Residuals are reported as height
differences ``z - z_form(x, y)``, which is what the later filters and parameters expect.

Polynomials are fitted in a tensor Legendre basis on coordinates scaled to [-1, 1] (well
conditioned up to high degree), through the normal equations. Their moments are separable,
``Σ_valid P_a(x) P_b(y) z = P_b(y)ᵀ Z P_a(x)``, so a plane over a 2048 × 2048 scan costs
a few matrix-vector products instead of a 4-million-row least-squares problem.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography

METHODS = ("none", "mean", "plane", "poly:N", "sphere", "cylinder", "cylinder:x", "cylinder:y")


#: The unit of each shape parameter of a sphere or cylinder fit (:attr:`FormFit.shape`);
#: the other keys (``convex``, ``curvature_resolved``) are flags.
SHAPE_UNITS = {"radius": "m", "radius_uncertainty": "m", "center": "m",
               "pv_form_deviation": "m", "form_pv": "m", "axis_point": "m",
               "axis_direction": "", "azimuth": "°"}


@dataclass(frozen=True, eq=False)
class FormFit:
    """What an F-operator removed.

    Attributes
    ----------
    method : str
        Canonical method name (``"plane"``, ``"poly:3"``, ``"sphere"``...).
    coefficients : tuple of float
        Polynomial methods: coefficients of the monomials in :attr:`terms`, in SI units
        (heights in metres, x and y in metres from the scan origin). Empty otherwise.
    terms : tuple of str
        Monomials matching :attr:`coefficients`, e.g. ``("1", "x", "y")``.
    shape : mapping
        Shape parameters for sphere/cylinder (radius, centre or axis, uncertainties), SI
        values; their units are :data:`SHAPE_UNITS` (keys not there are flags).
    residual_rms : float
        Root mean square of the residual heights (valid points), metres.
    n_points : int
        Number of valid points used by the fit.
    """

    method: str
    coefficients: tuple[float, ...] = ()
    terms: tuple[str, ...] = ()
    shape: dict[str, Any] = field(default_factory=dict)
    residual_rms: float = float("nan")
    n_points: int = 0



def parse_method(method: str) -> tuple[str, int]:
    """Canonical name and polynomial degree of a form method (degree -1 if not a polynomial)."""
    if not isinstance(method, str):
        raise SurfmetInputError(f"form method must be a string, got {method!r}")
    m = method.strip().lower()
    if m in ("none", "raw"):
        return "none", -1
    if m in ("mean", "center", "centre"):
        return "mean", 0
    if m in ("plane", "line", "tilt"):
        return "plane", 1
    if m in ("sphere", "cylinder", "cylinder:x", "cylinder:y", "cylinder:free"):
        return ("cylinder" if m == "cylinder:free" else m), -1
    mm = re.fullmatch(r"poly(?:nomial)?:(\d+)", m)
    if mm:
        deg = int(mm.group(1))
        if deg > 20:
            raise SurfmetInputError(f"polynomial degree {deg} is too high (at most 20)")
        return f"poly:{deg}", deg
    raise SurfmetInputError(
        f"unknown form method {method!r}; use none, mean, plane, poly:N, sphere, "
        "cylinder, cylinder:x or cylinder:y"
    )


def _scaled(n: int) -> tuple[np.ndarray, float, float]:
    """Index grid 0..n-1 mapped onto [-1, 1]: returns (u, centre, half-width) in index units."""
    centre = (n - 1) / 2.0
    half = centre if n > 1 else 1.0
    return (np.arange(n) - centre) / half, centre, half


def _legendre_table(u: np.ndarray, deg: int) -> np.ndarray:
    """Rows P_0(u)...P_deg(u) by Bonnet's recursion."""
    out = np.empty((deg + 1, u.size))
    out[0] = 1.0
    if deg >= 1:
        out[1] = u
    for k in range(1, deg):
        out[k + 1] = ((2 * k + 1) * u * out[k] - k * out[k - 1]) / (k + 1)
    return out


def _poly_terms(deg: int) -> list[tuple[int, int]]:
    return [(i, t - i) for t in range(deg + 1) for i in range(t, -1, -1)]


def fit_polynomial(topo: Topography, deg: int) -> tuple[np.ndarray, FormFit]:
    """Least-squares bivariate polynomial of total degree ``deg`` over the valid points.

    Returns the trend evaluated on the full grid and a :class:`FormFit` with the monomial
    coefficients in SI units.
    """
    z = topo.heights
    valid = np.isfinite(z)
    n_valid = int(np.count_nonzero(valid))
    terms = _poly_terms(deg)
    if n_valid < len(terms):
        raise SurfmetInputError(
            f"a degree-{deg} form fit needs at least {len(terms)} valid points, the scan has "
            f"{n_valid}"
        )
    ny, nx = z.shape
    u, cx, hx = _scaled(nx)
    v, cy, hy = _scaled(ny)
    px = _legendre_table(u, deg)
    py = _legendre_table(v, deg)
    full = n_valid == z.size
    zz = z if full else np.where(valid, z, 0.0)
    w = None if full else valid.astype(np.float64)
    # Right-hand side: Σ P_a(x) P_b(y) z over valid points. einsum, not BLAS: its fixed
    # summation order makes the fit bitwise identical whatever the BLAS thread count (a
    # serial run and single-threaded Dask workers must agree to the last bit).
    zx = np.einsum("ji,ai->ja", zz, px)  # (ny, deg+1): Σ_i z[j, i] P_a(x_i)
    rhs = np.array([np.einsum("j,j->", py[b], zx[:, a]) for a, b in terms])
    # Gram matrix: Σ P_a P_c (x) P_b P_d (y) over valid points.
    t = len(terms)
    gram = np.empty((t, t))
    for p, (a, b) in enumerate(terms):
        for q in range(p, t):
            c, d = terms[q]
            fx = px[a] * px[c]
            fy = py[b] * py[d]
            val = (fy.sum() * fx.sum() if full
                   else np.einsum("j,j->", fy, np.einsum("ji,i->j", w, fx)))
            gram[p, q] = gram[q, p] = val
    coef, *_ = np.linalg.lstsq(gram, rhs, rcond=None)
    trend = np.zeros((ny, nx))
    for k, (a, b) in enumerate(terms):
        if coef[k] != 0.0:
            trend += coef[k] * np.outer(py[b], px[a])
    mono = _legendre_to_monomials(coef, terms, deg, topo.dx, topo.dy, cx, hx, cy, hy)
    names = tuple(_term_name(i, j) for i, j in terms)
    fit = FormFit(method="mean" if deg == 0 else ("plane" if deg == 1 else f"poly:{deg}"),
                  coefficients=tuple(float(mono[(i, j)]) for i, j in terms), terms=names,
                  n_points=n_valid)
    return trend, fit


def _term_name(i: int, j: int) -> str:
    parts = []
    if i:
        parts.append("x" if i == 1 else f"x^{i}")
    if j:
        parts.append("y" if j == 1 else f"y^{j}")
    return "*".join(parts) or "1"


def _legendre_to_monomials(coef, terms, deg, dx, dy, cx, hx, cy, hy) -> dict:
    """Convert Legendre coefficients on scaled indices to monomials in metres."""
    from numpy.polynomial import legendre as leg
    from numpy.polynomial import polynomial as poly

    # x_index = x / dx; u = (x/dx - cx)/hx = x * (1/(dx hx)) - cx/hx
    ax = np.array([-cx / hx, 1.0 / (dx * hx)])
    ay = np.array([-cy / hy, 1.0 / (dy * hy)])
    out = {(i, j): 0.0 for i, j in terms}
    for k, (a, b) in enumerate(terms):
        if coef[k] == 0:
            continue
        pa = leg.leg2poly(np.eye(deg + 1)[a])  # monomial coefficients in u
        pb = leg.leg2poly(np.eye(deg + 1)[b])
        qx = np.zeros(1)
        for n, c in enumerate(pa):
            qx = poly.polyadd(qx, c * poly.polypow(ax, n))
        qy = np.zeros(1)
        for n, c in enumerate(pb):
            qy = poly.polyadd(qy, c * poly.polypow(ay, n))
        for i, ci in enumerate(qx):
            for j, cj in enumerate(qy):
                if (i, j) in out:
                    out[(i, j)] += coef[k] * ci * cj
    return out


def remove_form(topo: Topography, method: str = "plane") -> tuple[Topography, FormFit]:
    """Apply an F-operator: subtract the least-squares nominal form.

    Parameters
    ----------
    topo : Topography
        Areal scan (NaN = not measured).
    method : str
        ``"none"``, ``"mean"``, ``"plane"``, ``"poly:N"``, ``"sphere"``, ``"cylinder"``,
        ``"cylinder:x"`` or ``"cylinder:y"``.

    Returns
    -------
    residual : Topography
        Heights minus the fitted form (NaN kept), metadata ``form`` set to the method.
    fit : FormFit

    Raises
    ------
    SurfmetInputError
        Unknown method, an all-NaN scan, or too few points for the fit.
    """
    name, deg = parse_method(method)
    z = topo.heights
    valid = np.isfinite(z)
    if not valid.any():
        raise SurfmetInputError("the scan has no measured point: nothing to level")
    if name == "none":
        res = z
        fit = FormFit(method="none", n_points=int(valid.sum()))
    elif deg >= 0:
        trend, fit = fit_polynomial(topo, deg)
        res = z - trend
    elif name == "sphere":
        from surfmet.fitting import fit_sphere

        sf = fit_sphere(topo, require_curvature=False)
        jj, ii = np.indices(z.shape)
        res = z - sf.height(ii * topo.dx, jj * topo.dy)
        fit = FormFit(method="sphere", shape={
            "radius": sf.radius, "radius_uncertainty": sf.radius_uncertainty,
            "center": list(sf.center), "convex": sf.convex,
            "pv_form_deviation": sf.pv_form_deviation, "form_pv": sf.form_pv,
            "curvature_resolved": sf.curvature_resolved,
        }, n_points=sf.n_points)
    else:
        from surfmet.fitting import fit_cylinder

        cf = fit_cylinder(topo, axis=name.partition(":")[2] or "free", require_curvature=False)
        jj, ii = np.indices(z.shape)
        res = z - cf.height(ii * topo.dx, jj * topo.dy, near=z)
        fit = FormFit(method=name, shape={
            "radius": cf.radius, "radius_uncertainty": cf.radius_uncertainty,
            "axis_point": list(cf.point), "axis_direction": list(cf.direction),
            "azimuth": float(np.degrees(cf.azimuth)), "convex": cf.convex,
        }, n_points=cf.n_points)
    res = np.where(valid, res, np.nan)
    rv = res[valid]
    rms = float(np.sqrt(np.mean(rv * rv))) if name != "none" else float(np.std(rv))
    fit = FormFit(method=fit.method, coefficients=fit.coefficients, terms=fit.terms,
                  shape=fit.shape, residual_rms=rms, n_points=fit.n_points)
    return topo.replace(heights=res).with_metadata(form=fit.method), fit


#: A curved form dominates a levelled scan when a second-order surface removes more than
#: three quarters of what the plane left (its Sq falls below half): the parameters would
#: then describe the shape (a ball's cap, a cylinder's flank), not the texture. A textured
#: flat plate keeps more than 80 % of its Sq under a second-order surface.
DOMINANT_FORM_SQ_RATIO = 0.5


def dominant_form(topo: Topography, fit: FormFit) -> str | None:
    """A caveat when a curved form dominates what a ``none``, ``mean`` or ``plane``
    F-operator (``fit``) left of ``topo``; None otherwise (or for any other F-operator).

    The test: the rms residual of a least-squares second-order polynomial against that of
    ``fit`` (:data:`DOMINANT_FORM_SQ_RATIO`), as a Gwyddion or MountainsMap user would
    check by eye on the levelled map before reading its parameters.
    """
    from surfmet.units import format_length

    if fit.method not in ("none", "mean", "plane") or not fit.residual_rms > 0:
        return None
    _, quad = remove_form(topo, "poly:2")
    ratio = quad.residual_rms / fit.residual_rms
    if ratio >= DOMINANT_FORM_SQ_RATIO:
        return None
    return (f"a curved form dominates this scan: a second-order surface leaves "
            f"{100 * ratio:.2g} % of the Sq the {fit.method} F-operator left "
            f"({format_length(quad.residual_rms)} of {format_length(fit.residual_rms)}), so "
            "these parameters "
            "describe the form, not the texture; remove it first (--level sphere for a "
            "ball, cylinder for a cylinder, poly:2 otherwise)")
