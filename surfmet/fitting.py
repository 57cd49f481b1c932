"""Least-squares fits of nominal shapes to areal scans: spheres and cylinders.

A ball scanned by a profilometer (the steel balls of Alaci et al. 2022 are 20 mm spheres)
gives a spherical cap; its radius, centre and form deviation come from a sphere fit. The
fit follows the usual two-stage recipe of coordinate metrology (ISO 10360-6 style
"geometric" or orthogonal-distance fitting, Forbes 1989, NPL report DITC 140/89):

1. an **algebraic** start: the linear least-squares solution of
   ``x² + y² + z² + D x + E y + F z + G = 0`` (Kåsa/Delogne form), which needs no
   starting values;
2. a **geometric** refinement that minimises the sum of squared orthogonal distances
   ``d_i = |p_i - c| - R`` with :func:`scipy.optimize.least_squares` (optionally with a
   robust loss).

The standard uncertainty of the parameters comes from the Jacobian at the solution,
``cov = s² (JᵀJ)⁻¹`` with ``s² = Σ d_i² / (n - p)`` (GUM, JCGM 100:2008, least-squares
estimate under independent equal-variance noise). Circle fits of profiles live in the
``profiles`` engine (:func:`profiles.fit_circle`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography, require_measurement

_LOSSES = ("linear", "huber", "soft_l1", "cauchy", "arctan")


@dataclass(frozen=True, eq=False)
class SphereFit:
    """Result of :func:`fit_sphere`.

    Attributes
    ----------
    radius : float
        Fitted radius in metres.
    center : tuple of float
        Centre ``(xc, yc, zc)`` in metres, in the scan's frame (x = i dx, y = j dy).
    radius_uncertainty : float
        Standard uncertainty of the radius (k = 1), metres.
    center_uncertainty : tuple of float
        Standard uncertainties of the centre coordinates, metres.
    rms_residual : float
        Root mean square of the orthogonal residuals, metres.
    pv_form_deviation : float
        Peak-to-valley of all the orthogonal residuals, metres: the peak-to-valley
        deviation from the least-squares sphere, roughness and outliers included (one
        spike sets it).
    form_pv : float
        Form deviation, metres: the peak-to-valley of the quadratic component of the
        residual (the least-squares bivariate polynomial of degree 2 fitted to it), i.e.
        the departure from a sphere (astigmatism, a cap that is not spherical) that
        roughness and outliers do not inflate. This is the one "form deviation" surfmet
        reports.
    residuals : ndarray, shape (ny, nx)
        Orthogonal residual map (positive outside the sphere), NaN where not measured.
    n_points : int
        Number of points used.
    convex : bool
        True if the measured cap bulges towards +z (a ball seen from above).
    loss : str
        Loss function used in the geometric stage.
    """

    radius: float
    center: tuple[float, float, float]
    radius_uncertainty: float
    center_uncertainty: tuple[float, float, float]
    rms_residual: float
    pv_form_deviation: float
    residuals: np.ndarray
    n_points: int
    convex: bool
    loss: str
    form_pv: float = float("nan")
    curvature_resolved: bool = True

    def height(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """Height of the fitted sphere's measured side above ``(x, y)`` (NaN outside)."""
        xc, yc, zc = self.center
        r2 = self.radius**2 - (x - xc) ** 2 - (y - yc) ** 2
        with np.errstate(invalid="ignore"):
            root = np.sqrt(r2)
        return zc + root if self.convex else zc - root


@dataclass(frozen=True, eq=False)
class CylinderFit:
    """Result of :func:`fit_cylinder`.

    The axis passes through ``point`` with unit direction ``direction``; ``azimuth`` is the
    in-plane angle of the axis from +x (radians), ``elevation`` its tilt out of the plane.
    """

    radius: float
    point: tuple[float, float, float]
    direction: tuple[float, float, float]
    azimuth: float
    elevation: float
    radius_uncertainty: float
    rms_residual: float
    pv_form_deviation: float
    residuals: np.ndarray
    n_points: int
    convex: bool
    axis: str

    def height(self, x: np.ndarray, y: np.ndarray, near: np.ndarray | None = None) -> np.ndarray:
        """Height of the cylinder surface above ``(x, y)``.

        Of the two roots, the one on the measured side (``convex``) is taken, or the one
        nearest ``near`` when given.
        """
        a = np.asarray(self.direction)
        p0 = np.asarray(self.point)
        qx, qy, qz = x - p0[0], y - p0[1], -p0[2]
        qa = qx * a[0] + qy * a[1] + qz * a[2]
        # |q + z e_z|² - ((q + z e_z)·a)² = R², a quadratic in z
        aa = 1.0 - a[2] ** 2
        bb = 2.0 * (qz - qa * a[2])
        cc = qx**2 + qy**2 + qz**2 - qa**2 - self.radius**2
        with np.errstate(invalid="ignore"):
            disc = np.sqrt(bb**2 - 4 * aa * cc)
        z1 = (-bb + disc) / (2 * aa)
        z2 = (-bb - disc) / (2 * aa)
        if near is not None:
            return np.where(np.abs(z1 - near) <= np.abs(z2 - near), z1, z2)
        return z1 if self.convex else z2


def _valid_points(topo: Topography, mask: np.ndarray | None):
    z = require_measurement(topo).heights
    valid = np.isfinite(z)
    if mask is not None:
        m = np.asarray(mask, dtype=bool)
        if m.shape != z.shape:
            raise SurfmetInputError(f"mask has shape {m.shape}, the scan {z.shape}")
        valid &= m
    jj, ii = np.nonzero(valid)
    return valid, ii * topo.dx, jj * topo.dy, z[valid]


def _require_curvature(x: np.ndarray, y: np.ndarray, z: np.ndarray, rms_shape: float,
                       shape: str, radius: float, require: bool = True) -> bool:
    """Whether the curvature is resolved; raises when it is not and ``require``.

    The rule is the profile engine's, one for every form fit
    (:data:`profiles._circle.CURVATURE_RESOLVED_RATIO`: a plane's rms residual must exceed
    the curved shape's twice over)."""
    from profiles._circle import curvature_message, curvature_resolved

    a = np.column_stack([np.ones_like(x), x - x.mean(), y - y.mean()])
    coef, *_ = np.linalg.lstsq(a, z - z.mean(), rcond=None)
    rms_plane = float(np.sqrt(np.mean((z - z.mean() - a @ coef) ** 2)))
    resolved = curvature_resolved(rms_plane, rms_shape)
    if not resolved and require:
        raise SurfmetInputError(curvature_message(shape, "plane", rms_plane, rms_shape, radius))
    return bool(resolved)


def _check_loss(loss: str) -> str:
    if loss not in _LOSSES:
        raise SurfmetInputError(f"unknown loss {loss!r}; use one of {', '.join(_LOSSES)}")
    return loss


def _normalised(x: np.ndarray, y: np.ndarray, z: np.ndarray
                ) -> tuple[np.ndarray, float, tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """The points centred on their mean and divided by their largest span: (origin, scale,
    (px, py, pz)).

    Fits work on these so that the unknowns are O(1): metres of a 20 mm ball with
    nanometre residuals would otherwise strain the solver's tolerances.
    """
    origin = np.array([x.mean(), y.mean(), z.mean()])
    scale = float(max(np.ptp(x), np.ptp(y), np.ptp(z), 1e-300))
    return origin, scale, ((x - origin[0]) / scale, (y - origin[1]) / scale,
                           (z - origin[2]) / scale)


def _covariance(jac: np.ndarray, res: np.ndarray, n_par: int) -> np.ndarray:
    dof = max(res.size - n_par, 1)
    s2 = float(res @ res) / dof
    jtj = jac.T @ jac
    try:
        return s2 * np.linalg.inv(jtj)
    except np.linalg.LinAlgError:
        return np.full((n_par, n_par), np.nan)


def algebraic_sphere(x: np.ndarray, y: np.ndarray, z: np.ndarray) -> tuple[np.ndarray, float]:
    """Linear (Kåsa) sphere fit: centre and radius minimising the algebraic distance.

    Coordinates should be centred and scaled by the caller for conditioning.
    """
    a = np.column_stack([x, y, z, np.ones_like(x)])
    rhs = x * x + y * y + z * z
    sol, *_ = np.linalg.lstsq(a, rhs, rcond=None)
    c = sol[:3] / 2.0
    r2 = sol[3] + c @ c
    if not (np.isfinite(r2) and r2 > 0):
        raise SurfmetInputError("the points do not define a sphere (degenerate algebraic fit)")
    return c, float(np.sqrt(r2))


def fit_sphere_points(
    x: np.ndarray,
    y: np.ndarray,
    z: np.ndarray,
    *,
    loss: str = "linear",
    f_scale: float | None = None,
) -> tuple[np.ndarray, float, np.ndarray, np.ndarray]:
    """Geometric sphere fit of scattered points.

    Returns
    -------
    center : ndarray (3,)
    radius : float
    cov : ndarray (4, 4)
        Covariance of ``(xc, yc, zc, R)``.
    residuals : ndarray
        Orthogonal distances ``|p - c| - R``.
    """
    from scipy.optimize import least_squares

    _check_loss(loss)
    x, y, z = (np.asarray(v, dtype=np.float64) for v in (x, y, z))
    if x.size < 5:
        raise SurfmetInputError(f"a sphere fit needs at least 5 valid points, got {x.size}")
    origin, scale, (px, py, pz) = _normalised(x, y, z)
    c0, r0 = algebraic_sphere(px, py, pz)

    def resid(p: np.ndarray) -> np.ndarray:
        return np.sqrt((px - p[0]) ** 2 + (py - p[1]) ** 2 + (pz - p[2]) ** 2) - p[3]

    def jac(p: np.ndarray) -> np.ndarray:
        d = np.sqrt((px - p[0]) ** 2 + (py - p[1]) ** 2 + (pz - p[2]) ** 2)
        d = np.where(d == 0, 1e-300, d)
        return np.column_stack([-(px - p[0]) / d, -(py - p[1]) / d, -(pz - p[2]) / d,
                                -np.ones_like(d)])

    p0 = np.array([*c0, r0])
    kwargs = {}
    if loss != "linear":
        r_start = resid(p0)
        fs = f_scale / scale if f_scale else 1.4826 * float(np.median(np.abs(r_start))) or 1e-12
        kwargs = {"loss": loss, "f_scale": fs}
    sol = least_squares(resid, p0, jac=jac, method="trf" if loss != "linear" else "lm",
                        xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=200, **kwargs)
    p = sol.x
    res = resid(p)
    cov = _covariance(jac(p), res, 4) * scale**2
    center = p[:3] * scale + origin
    return center, float(p[3] * scale), cov, res * scale


def fit_sphere(
    topo: Topography,
    *,
    loss: str = "linear",
    f_scale: float | None = None,
    mask: np.ndarray | None = None,
    require_curvature: bool = True,
) -> SphereFit:
    """Fit a sphere to an areal scan of a spherical cap (a ball, a lens).

    Parameters
    ----------
    topo : Topography
        Scan of the cap; NaN points are ignored.
    loss : {"linear", "huber", "soft_l1", "cauchy", "arctan"}
        Loss of the geometric stage; robust losses down-weight outliers (spikes, dust).
    f_scale : float, optional
        Residual scale (metres) where a robust loss starts to bend; default
        1.4826 × median |residual| of the algebraic start.
    mask : bool array, optional
        True where points may be used (in addition to the measured points).
    require_curvature : bool
        Refuse a scan whose curvature the fit does not resolve (default). False: return
        the fit with ``curvature_resolved=False`` (form removal, where any near-plane
        fit removes what it should).

    Returns
    -------
    SphereFit
        Radius, centre, standard uncertainties (k = 1, from the Jacobian), rms and PV of
        the orthogonal residuals and the residual map.

    Raises
    ------
    SurfmetInputError
        Fewer than 5 valid points, points that define no sphere, or a scan whose
        curvature the fit does not resolve (a plane fits it as well: flat or tilted data,
        or a cap far flatter than its noise).
    """
    valid, x, y, z = _valid_points(topo, mask)
    center, radius, cov, res = fit_sphere_points(x, y, z, loss=loss, f_scale=f_scale)
    resolved = _require_curvature(x, y, z, float(np.sqrt(np.mean(res**2))), "sphere",
                                  radius, require_curvature)
    resmap = np.full(topo.shape, np.nan)
    resmap[valid] = res
    unc = np.sqrt(np.clip(np.diag(cov), 0, None))
    return SphereFit(
        radius=radius,
        center=(float(center[0]), float(center[1]), float(center[2])),
        radius_uncertainty=float(unc[3]),
        center_uncertainty=(float(unc[0]), float(unc[1]), float(unc[2])),
        rms_residual=float(np.sqrt(np.mean(res**2))),
        pv_form_deviation=float(np.ptp(res)),
        residuals=resmap,
        n_points=int(res.size),
        convex=bool(np.mean(z) > center[2]),
        loss=loss,
        form_pv=quadratic_form_pv(x, y, res),
        curvature_resolved=resolved,
    )


def quadratic_form_pv(x: np.ndarray, y: np.ndarray, res: np.ndarray) -> float:
    """Peak-to-valley of the degree-2 least-squares polynomial fitted to residuals ``res``
    at ``(x, y)``: the form deviation (see :class:`SphereFit`)."""
    u = (x - x.mean()) / max(float(np.ptp(x)), 1e-300)
    v = (y - y.mean()) / max(float(np.ptp(y)), 1e-300)
    a = np.column_stack([np.ones_like(u), u, v, u * u, u * v, v * v])
    coef, *_ = np.linalg.lstsq(a, res, rcond=None)
    return float(np.ptp(a @ coef))


def _direction(azimuth: float, elevation: float) -> np.ndarray:
    ce = np.cos(elevation)
    return np.array([np.cos(azimuth) * ce, np.sin(azimuth) * ce, np.sin(elevation)])


def fit_cylinder(
    topo: Topography,
    *,
    axis: str = "free",
    mask: np.ndarray | None = None,
    require_curvature: bool = True,
) -> CylinderFit:
    """Geometric least-squares cylinder fit of an areal scan (a roller, a wire, a shaft).

    Parameters
    ----------
    topo : Topography
        The scan; NaN points are ignored.
    axis : {"free", "x", "y"}
        ``"x"``/``"y"``: the axis lies along that direction (its tilt out of the plane is
        still fitted); ``"free"``: its in-plane direction is fitted too.
    require_curvature : bool
        Refuse a scan whose curvature the fit does not resolve (see :func:`fit_sphere`).

    Notes
    -----
    The start comes from a quadratic fit: the eigenvector of its Hessian with the larger
    curvature is perpendicular to the axis and 1/|curvature| estimates the radius.
    The geometric stage minimises orthogonal distances to the axis line minus R, with the
    axis parametrised by azimuth, elevation and a foot point in the plane perpendicular
    to it (5 unknowns; 4 when the azimuth is fixed).
    """
    from scipy.optimize import least_squares

    if axis not in ("free", "x", "y"):
        raise SurfmetInputError(f"cylinder axis must be 'free', 'x' or 'y', got {axis!r}")
    valid, x, y, z = _valid_points(topo, mask)
    if x.size < 6:
        raise SurfmetInputError(f"a cylinder fit needs at least 6 valid points, got {x.size}")
    origin, scale, (px, py, pz) = _normalised(x, y, z)

    # Quadratic start: z ≈ c0 + c1 x + c2 y + c3 x² + c4 xy + c5 y².
    a = np.column_stack([np.ones_like(px), px, py, px * px, px * py, py * py])
    c, *_ = np.linalg.lstsq(a, pz, rcond=None)
    hess = np.array([[2 * c[3], c[4]], [c[4], 2 * c[5]]])
    w, v = np.linalg.eigh(hess)
    k = int(np.argmax(np.abs(w)))
    curv = w[k]
    if not abs(curv) > 0:
        raise SurfmetInputError("the scan has no curvature: no cylinder can be fitted")
    perp = v[:, k]
    if axis == "free":
        az0 = float(np.arctan2(perp[0], -perp[1]))  # axis ⟂ to the curvature direction
    else:
        az0 = 0.0 if axis == "x" else np.pi / 2
    r0 = 1.0 / abs(curv)
    convex = curv < 0
    # Foot point: at the apex of the quadratic along the perpendicular, R below/above it.
    n1 = np.array([-np.sin(az0), np.cos(az0), 0.0])
    u_apex = 0.0
    denom = perp @ hess @ perp
    grad0 = np.array([c[1], c[2]])
    if denom != 0:
        u_apex = float(-(grad0 @ perp) / denom) * float(np.sign(perp @ n1[:2]) or 1.0)
    z_apex = c[0]
    w0 = z_apex - r0 if convex else z_apex + r0

    fixed_az = axis != "free"

    def unpack(p: np.ndarray):
        if fixed_az:
            az, el, u, wz, r = az0, p[0], p[1], p[2], p[3]
        else:
            az, el, u, wz, r = p
        d = _direction(az, el)
        e1 = np.array([-np.sin(az), np.cos(az), 0.0])
        e2 = np.cross(d, e1)
        foot = u * e1 + wz * e2
        return d, foot, r

    def resid(p: np.ndarray) -> np.ndarray:
        d, foot, r = unpack(p)
        qx, qy, qz = px - foot[0], py - foot[1], pz - foot[2]
        along = qx * d[0] + qy * d[1] + qz * d[2]
        dist2 = qx * qx + qy * qy + qz * qz - along * along
        return np.sqrt(np.clip(dist2, 0, None)) - r

    p0 = [0.0, u_apex, w0, r0] if fixed_az else [az0, 0.0, u_apex, w0, r0]
    sol = least_squares(resid, np.array(p0), method="lm", xtol=1e-15, ftol=1e-15,
                        gtol=1e-15, max_nfev=2000)
    p = sol.x
    res = resid(p)
    cov = _covariance(sol.jac, res, p.size)
    d, foot, r = unpack(p)
    if r < 0:  # the same cylinder, parametrised with a negative radius
        r = -r
    _require_curvature(x, y, z, float(np.sqrt(np.mean(res**2)) * scale), "cylinder",
                       float(r * scale), require_curvature)
    az, el = (az0, p[0]) if fixed_az else (p[0], p[1])
    resmap = np.full(topo.shape, np.nan)
    resmap[valid] = res * scale
    return CylinderFit(
        radius=float(r * scale),
        point=tuple(float(v) for v in foot * scale + origin),
        direction=tuple(float(v) for v in d),
        azimuth=float(np.mod(az, np.pi)),
        elevation=float(el),
        radius_uncertainty=float(np.sqrt(max(cov[-1, -1], 0.0)) * scale),
        rms_residual=float(np.sqrt(np.mean(res**2)) * scale),
        pv_form_deviation=float(np.ptp(res) * scale),
        residuals=resmap,
        n_points=int(res.size),
        convex=bool(convex),
        axis=axis,
    )
