"""Circle fitting to a profile: a ball's or roller's real radius from a line scan.

Two stages, as recommended by Chernov (*Circular and Linear Regression*, CRC 2010) and
Al-Sharadqah & Chernov (Electron. J. Stat. 3, 2009):

1. an algebraic fit, which needs no start value: Kåsa (I. Kåsa, IEEE Trans. Instrum.
   Meas. 25, 1976; biased towards small radii on short arcs), Pratt (V. Pratt,
   SIGGRAPH 1987) or Taubin (G. Taubin, IEEE PAMI 13, 1991; the default, nearly unbiased).
   Pratt and Taubin minimise ``|M a|^2`` for ``a = (A, B, C, D)`` of the circle
   ``A (x^2 + z^2) + B x + C z + D = 0`` under a quadratic constraint ``a^T N a = 1``,
   solved as a generalised eigenproblem on centred, scaled data;
2. a geometric fit (orthogonal distances ``r_i = |p_i - c| - R``) by
   :func:`scipy.optimize.least_squares`, optionally with a robust loss so that dust
   particles or stylus spikes do not pull the radius.

Uncertainty: the covariance of the geometric estimate is ``s^2 (J^T J)^-1`` with
``s^2 = sum r^2 / (n - 3)`` for the linear loss; for a robust loss the M-estimator form
(Huber, *Robust Statistics*, 1981, ch. 7)
``[sum psi(r)^2 / (n - 3)] / [mean psi'(r)]^2 (J^T J)^-1``. It treats residuals as
independent: a form deviation correlated along the arc (reported as ``pv_form_deviation``
and visible in ``residuals``) enters only through its variance.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy import linalg, optimize

from profiles._errors import ProfileError

METHODS = ("taubin", "pratt", "kasa")
LOSSES = ("linear", "huber", "soft_l1", "cauchy")

#: A circle (a sphere, a cylinder) must explain the data clearly better than a straight
#: line (a plane): the line's rms residual must exceed the curved shape's by this factor,
#: else the curvature is not resolved by the data (a flat or tilted profile "fits" any
#: huge radius). The one rule of every form fit (``surfmet.fitting`` uses it too).
CURVATURE_RESOLVED_RATIO = 2.0


def curvature_resolved(rms_flat: float, rms_shape: float) -> bool:
    """Whether a curved fit resolves its curvature: :data:`CURVATURE_RESOLVED_RATIO`."""
    return bool(rms_flat > CURVATURE_RESOLVED_RATIO * rms_shape)


def curvature_message(shape: str, flat: str, rms_flat: float, rms_shape: float,
                      radius: float) -> str:
    """The one-line refusal of a fit whose curvature the data do not resolve."""
    return (f"curvature not resolved by the data: a {flat} fits the scan as well as the "
            f"{shape} (rms residual {rms_flat:.3g} m against {rms_shape:.3g} m), so the "
            f"{shape}'s radius ({radius:.3g} m) means nothing; scan more of the curved "
            f"surface or check that this is the {shape} you meant")


FORM_DEGREE = 4
"""Degree of the polynomial whose PV is a circle fit's form deviation (:func:`form_pv`)."""


def form_pv(x: np.ndarray, res: np.ndarray) -> float:
    """Peak-to-valley of the degree-4 least-squares polynomial of residuals ``res`` at
    ``x``: the form deviation, the smooth departure from the circle that roughness and
    outliers do not inflate (the sphere's is the degree-2 component,
    :func:`surfmet.fitting.quadratic_form_pv`: a circle absorbs a profile's degree-2 part
    into its radius, so its first form errors are the cubic and quartic ones)."""
    u = (x - x.mean()) / max(float(np.ptp(x)), 1e-300)
    a = np.vander(u, FORM_DEGREE + 1, increasing=True)
    coef, *_ = np.linalg.lstsq(a, res, rcond=None)
    return float(np.ptp(a @ coef))


def _line_rms(x: np.ndarray, z: np.ndarray) -> float:
    """rms residual of the least-squares straight line z(x)."""
    a = np.column_stack([np.ones_like(x), x - x.mean()])
    coef, *_ = np.linalg.lstsq(a, z - z.mean(), rcond=None)
    return float(np.sqrt(np.mean((z - z.mean() - a @ coef) ** 2)))


@dataclass(frozen=True, eq=False)
class CircleFit:
    """Best-fit circle through a profile.

    Attributes
    ----------
    radius : float
        Radius in metres.
    center : tuple of float
        Centre ``(xc, zc)`` in metres, in the profile's (x, z) frame.
    rms_residual : float
        Root mean square of the radial residuals (metres).
    pv_form_deviation : float
        Peak-to-valley of all the radial residuals (metres): roughness and any outliers
        included (one spike sets it); the residual PV.
    form_pv : float
        Form deviation (metres): the peak-to-valley of the degree-4 component of the
        residual (:func:`form_pv`).
    curvature_resolved : bool
        Whether a straight line fits clearly worse (:func:`curvature_resolved`).
    radius_uncertainty : float
        Standard uncertainty of the radius from the fit covariance (metres).
    center_uncertainty : tuple of float
        Standard uncertainties of ``xc`` and ``zc`` (metres).
    residuals : ndarray
        Radial residuals ``|p_i - c| - R`` (positive outside the circle), one per point
        used, in the input order.
    n_points : int
        Number of points used (NaN points are left out).
    method : str
        Algebraic start: ``"taubin"``, ``"pratt"`` or ``"kasa"``.
    loss : str
        Loss of the geometric refinement.
    f_scale : float
        Residual scale of the robust loss in metres (NaN for the linear loss).

    See Also
    --------
    fit_circle : makes it.

    Examples
    --------
    >>> import numpy as np
    >>> from profiles import fit_circle
    >>> t = np.linspace(-0.3, 0.3, 61)
    >>> fit = fit_circle(0.01 * np.sin(t), 0.01 * np.cos(t))
    >>> print(f"R = {fit.radius * 1e3:.3f} mm, rms = {fit.rms_residual:.0e} m")
    R = 10.000 mm, rms = ... m
    """

    radius: float
    center: tuple[float, float]
    rms_residual: float
    pv_form_deviation: float
    radius_uncertainty: float
    center_uncertainty: tuple[float, float]
    residuals: np.ndarray
    n_points: int
    method: str
    loss: str
    f_scale: float = math.nan
    form_pv: float = math.nan
    curvature_resolved: bool = True


def _algebraic(u: np.ndarray, v: np.ndarray, method: str) -> tuple[float, float, float]:
    """Circle (uc, vc, R) through centred, unit-scaled points."""
    w = u * u + v * v
    if method == "kasa":
        design = np.column_stack([u, v, np.ones_like(u)])
        (b, c, d), *_ = np.linalg.lstsq(design, -w, rcond=None)
        uc, vc = -b / 2, -c / 2
        r2 = uc * uc + vc * vc - d
        if not r2 > 0:
            raise ProfileError("the points do not define a circle (Kåsa fit failed)")
        return uc, vc, math.sqrt(r2)
    m = np.column_stack([w, u, v, np.ones_like(u)])
    moments = m.T @ m / u.size
    if method == "pratt":
        constraint = np.array(
            [[0, 0, 0, -2], [0, 1, 0, 0], [0, 0, 1, 0], [-2, 0, 0, 0]], dtype=float
        )
    else:  # taubin, data centred so that mean(u) = mean(v) = 0
        wm = float(np.mean(w))
        constraint = np.diag([4 * wm, 1.0, 1.0, 0.0])
        constraint[0, 1] = constraint[1, 0] = 2 * float(np.mean(u))
        constraint[0, 2] = constraint[2, 0] = 2 * float(np.mean(v))
    vals, vecs = linalg.eig(moments, constraint)
    vals = np.real(vals)
    vecs = np.real(vecs)
    ok = np.isfinite(vals) & (vals > -1e-12 * max(1.0, float(np.abs(moments).max())))
    if not np.any(ok):
        raise ProfileError(f"the points do not define a circle ({method} fit failed)")
    best = np.flatnonzero(ok)[np.argmin(vals[ok])]
    a, b, c, d = vecs[:, best]
    if abs(a) < 1e-12 * max(abs(b), abs(c), 1e-300):
        raise ProfileError(
            "the points lie on a straight line: no finite circle fits them "
            "(is the profile levelled, or too short to show curvature?)"
        )
    uc, vc = -b / (2 * a), -c / (2 * a)
    r2 = (b * b + c * c - 4 * a * d) / (4 * a * a)
    if not r2 > 0:
        raise ProfileError(f"the points do not define a circle ({method} fit failed)")
    return float(uc), float(vc), math.sqrt(r2)


def _psi(r: np.ndarray, loss: str, f: float) -> tuple[np.ndarray, np.ndarray]:
    """Influence function psi(r) and its derivative for scipy's robust losses."""
    t = (r / f) ** 2
    if loss == "linear":
        return r, np.ones_like(r)
    if loss == "huber":
        inside = t <= 1
        psi = np.where(inside, r, f * np.sign(r))
        dpsi = np.where(inside, 1.0, 0.0)
    elif loss == "soft_l1":
        psi = r / np.sqrt(1 + t)
        dpsi = (1 + t) ** -1.5
    else:  # cauchy
        psi = r / (1 + t)
        dpsi = (1 - t) / (1 + t) ** 2
    return psi, dpsi


def _standard_uncertainties(r: np.ndarray, jac: np.ndarray, loss: str, f: float
                            ) -> np.ndarray:
    """Standard uncertainties of (uc, vc, R) in the fit's scaled units (module docstring)."""
    dof = r.size - 3
    if dof <= 0:
        return np.full(3, math.nan)
    psi, dpsi = _psi(r, loss, f)
    mean_d = float(np.mean(dpsi))
    s2 = float(np.sum(psi * psi)) / dof / (mean_d * mean_d if mean_d > 0 else math.nan)
    try:
        cov = s2 * np.linalg.inv(jac.T @ jac)
    except np.linalg.LinAlgError:
        return np.full(3, math.inf)
    return np.sqrt(np.clip(np.diag(cov), 0.0, None))


def fit_circle(
    x: Any,
    z: Any,
    *,
    method: str = "taubin",
    loss: str = "linear",
    f_scale: float | None = None,
    require_curvature: bool = True,
) -> CircleFit:
    """Fit a circle to profile points (x, z).

    Parameters
    ----------
    x, z : array_like
        Point coordinates in metres (same length). Points with a NaN coordinate are left
        out.
    method : {"taubin", "pratt", "kasa"}
        Algebraic fit that gives the start value.
    loss : {"linear", "huber", "soft_l1", "cauchy"}
        Loss of the geometric least-squares refinement; anything but ``"linear"`` is
        robust to outliers (spikes, dust).
    f_scale : float, optional
        Residual size (metres) beyond which the robust loss down-weights points. Default:
        2.5 times a robust (MAD) estimate of the residual scale of the linear fit.
    require_curvature : bool
        Refuse points whose curvature the circle does not resolve (a straight line fits
        them about as well, :data:`CURVATURE_RESOLVED_RATIO`; default). False: return the
        fit with ``curvature_resolved=False``.

    Returns
    -------
    CircleFit

    Raises
    ------
    ProfileError
        Fewer than 3 usable points, collinear points, unknown method or loss, or a
        curvature the data do not resolve.

    See Also
    --------
    CircleFit : the result.

    References
    ----------
    .. [1] G. Taubin, "Estimation of planar curves, surfaces and nonplanar space curves
       defined by implicit equations", IEEE Trans. PAMI 13 (1991) 1115-1138.

    Examples
    --------
    Points on an arc of a 10 mm ball, apex at the origin:

    >>> import numpy as np
    >>> from profiles import fit_circle
    >>> t = np.linspace(-0.3, 0.3, 61)
    >>> fit = fit_circle(0.01 * np.sin(t), 0.01 * np.cos(t) - 0.01)
    >>> print(f"R = {fit.radius * 1e3:.4f} mm, centre z = {fit.center[1] * 1e3:.4f} mm")
    R = 10.0000 mm, centre z = -10.0000 mm
    """
    method = str(method).lower()
    loss = str(loss).lower()
    if method not in METHODS:
        raise ProfileError(f"unknown circle method {method!r}: use one of {', '.join(METHODS)}")
    if loss not in LOSSES:
        raise ProfileError(f"unknown loss {loss!r}: use one of {', '.join(LOSSES)}")
    try:
        xa = np.asarray(x, dtype=float).ravel()
        za = np.asarray(z, dtype=float).ravel()
    except (TypeError, ValueError) as exc:
        raise ProfileError(f"x and z must be arrays of numbers: {exc}") from None
    if xa.size != za.size:
        raise ProfileError(f"x has {xa.size} points but z has {za.size}")
    keep = np.isfinite(xa) & np.isfinite(za)
    xa, za = xa[keep], za[keep]
    n = xa.size
    if n < 3:
        raise ProfileError(f"a circle needs at least 3 measured points, got {n}")
    if f_scale is not None and not (math.isfinite(f_scale) and f_scale > 0):
        raise ProfileError(f"f_scale must be a positive length in metres, got {f_scale!r}")

    # centre and scale the data: algebraic fits are then well conditioned
    x0, z0 = float(np.mean(xa)), float(np.mean(za))
    scale = float(np.sqrt(np.mean((xa - x0) ** 2 + (za - z0) ** 2)))
    if not scale > 0:
        raise ProfileError("all points coincide: no circle can be fitted")
    u, v = (xa - x0) / scale, (za - z0) / scale
    uc, vc, rr = _algebraic(u, v, method)

    def resid(p: np.ndarray) -> np.ndarray:
        return np.hypot(u - p[0], v - p[1]) - p[2]

    def jac(p: np.ndarray) -> np.ndarray:
        du, dv = u - p[0], v - p[1]
        dist = np.maximum(np.hypot(du, dv), 1e-300)
        return np.column_stack([-du / dist, -dv / dist, -np.ones_like(u)])

    p0 = np.array([uc, vc, rr])
    opts = {"method": "lm" if n >= 3 else "trf", "xtol": 1e-15, "ftol": 1e-15, "gtol": 1e-15}
    sol = optimize.least_squares(resid, p0, jac=jac, **opts)
    p = sol.x
    fs = math.nan
    if loss != "linear":
        if f_scale is None:
            r_lin = resid(p)
            mad = 1.4826 * float(np.median(np.abs(r_lin - np.median(r_lin))))
            fs_u = 2.5 * mad if mad > 0 else float(np.std(r_lin)) or 1e-12
        else:
            fs_u = f_scale / scale
        sol = optimize.least_squares(
            resid, p, jac=jac, loss=loss, f_scale=fs_u, method="trf",
            xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=2000,
        )
        p = sol.x
        fs = fs_u * scale
    if not np.all(np.isfinite(p)) or p[2] <= 0:
        raise ProfileError("the geometric circle fit did not converge (check the data)")

    r = resid(p)
    sd = _standard_uncertainties(r, jac(p), loss, fs / scale if loss != "linear" else 1.0)
    sd = sd * scale

    res_m = r * scale
    rms = float(np.sqrt(np.mean(res_m * res_m)))
    radius = float(p[2] * scale)
    rms_line = _line_rms(xa, za)
    resolved = curvature_resolved(rms_line, rms)
    if not resolved and require_curvature:
        raise ProfileError(curvature_message("circle", "straight line", rms_line, rms, radius))
    return CircleFit(
        radius=radius,
        center=(float(x0 + p[0] * scale), float(z0 + p[1] * scale)),
        rms_residual=rms,
        pv_form_deviation=float(res_m.max() - res_m.min()),
        radius_uncertainty=float(sd[2]),
        center_uncertainty=(float(sd[0]), float(sd[1])),
        residuals=res_m,
        n_points=int(n),
        method=method,
        loss=loss,
        f_scale=float(fs),
        form_pv=form_pv(xa, res_m),
        curvature_resolved=resolved,
    )
