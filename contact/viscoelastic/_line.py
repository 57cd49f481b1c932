"""Steady rolling of a cylinder on a viscoelastic half-plane (plane strain), exact BEM.

Influence coefficients. Cell j (centre x_j, width dx) carries a uniform pressure. On a
half-plane of unit compliance its surface displacement at x is (Johnson 1985, *Contact
Mechanics*, eq. 2.25b; datum: zero 1 m from a unit line load, as in :mod:`contact.line`)

    w_j(x) = -(2/pi) [P(y2) - P(y1)],   P(y) = y ln|y| - y,   y1 = x - x_j + dx/2,
                                                               y2 = x - x_j - dx/2.

The contact moves at V towards +x, so a material point at x was at x + xi a time xi/V
before; with the pair's creep series C(t) = C_g + sum dC_m (1 - exp(-t/theta_m)) (see
:mod:`contact.viscoelastic._rheology`) the hereditary integral becomes, with l_m = V theta_m,

    u(x) = C_g w(x) + sum_m dC_m F_m(x),  F_m(x) = (1/l_m) int_0^inf e^{-xi/l_m} w(x+xi) dxi.

Integrating by parts, F_m = w + int_0^inf e^{-xi/l} w'(x + xi) dxi, and with
w_j' = -(2/pi) ln|y1/y2| and int_0^inf e^{-xi/l} ln|y + xi| dxi = l (ln|y| + E(y/l)),
E(s) = e^s E_1(s) (principal value -e^s Ei(-s) for s < 0), every coefficient is closed form:

    F_mj(x) = w_j(x) - (2 l_m / pi) [ln|y1| + E(y1/l_m) - ln|y2| - E(y2/l_m)].

(Wang & Knothe 1993 and CONTACT integrate the same kernel numerically; Kalker 1990,
*Three-dimensional elastic bodies in rolling contact*, app. D.) The matrix is Toeplitz in
i - j but not symmetric: the pressure's wake lies behind it.

Solution. Dense active set with the load as a constraint: on the contact set C solve
A_CC p_C - delta = -h_C, dx sum p = W; drop cells with p < 0, add cells with gap < 0,
until neither occurs (a few iterations; exact for the discretised problem).
"""

from __future__ import annotations

import math

import numpy as np

from contact._errors import ContactInputError, ConvergenceError
from contact._grid import Grid
from contact._record import edge_contact, edge_warning
from contact._validate import positive
from contact.bem._line import active_set_record, solve_active_set
from contact.halfspace.plane_strain import line_column
from contact.viscoelastic._result import RollingResult, edges_1d, frozen
from contact.viscoelastic._rheology import CreepSeries
from contact.viscoelastic._window import cylinder_window


def _logsafe(v: np.ndarray) -> np.ndarray:
    av = np.abs(v)
    return np.where(av > 0, np.log(np.where(av > 0, av, 1.0)), 0.0)


def exp_e1(s: np.ndarray) -> np.ndarray:
    """E(s) = e^s E_1(s) for s > 0 and its principal-value continuation -e^s Ei(-s) for s < 0.

    E(0) is the log-singular limit's regular part and is only ever used together with the
    matching ln|y| term, where their sum is finite; it returns -ln|s| - gamma there.
    """
    from scipy.special import expi

    s = np.asarray(s, dtype=float)
    out = np.empty_like(s)
    big = np.abs(s) > 40.0
    small = ~big & (s != 0)
    ss = s[small]
    out[small] = -np.exp(ss) * expi(-ss)
    sb = s[big]
    inv = 1.0 / sb  # asymptotic e^s E1(s) ~ 1/s - 1/s^2 + 2/s^3 - 6/s^4 + 24/s^5
    out[big] = inv * (1 - inv * (1 - 2 * inv * (1 - 3 * inv * (1 - 4 * inv))))
    out[s == 0] = 0.0
    return out


def _creep_column(d: np.ndarray, dx: float, ell: float) -> np.ndarray:
    """F_j - w_j at offsets d = x - x_j (unit compliance), for one creep length l."""
    y1, y2 = d + dx / 2, d - dx / 2
    # ln|y| + E(y/l) is finite at y = 0: E(s) ~ -ln|s| - gamma, so the sum is ln(l) - gamma.
    def g(y: np.ndarray) -> np.ndarray:
        out = _logsafe(y) + exp_e1(y / ell)
        return np.where(y == 0, math.log(ell) - np.euler_gamma, out)

    return -(2.0 * ell / math.pi) * (g(y1) - g(y2))


def influence_matrix(n: int, dx: float, creep: CreepSeries, speed: float) -> np.ndarray:
    """Dense (n, n) viscoelastic steady-rolling influence matrix (m/Pa).

    ``u = A @ p`` is the combined displacement of the pair (module notes).
    """
    if n < 2 or not (math.isfinite(dx) and dx > 0):
        raise ContactInputError("the line grid needs n >= 2 cells of positive pitch")
    k = np.arange(-(n - 1), n)
    d = k * dx
    col = creep.relaxed * line_column(d, dx)
    for dc, th in zip(creep.amplitudes, creep.times):
        col = col + dc * _creep_column(d, dx, speed * th)
    idx = np.arange(n)[:, None] - np.arange(n)[None, :] + (n - 1)
    return col[idx]


def solve_line(grid: Grid, load: float, creep: CreepSeries, speed: float, *,
               radius: float | None = None, max_iter: int = 200) -> RollingResult:
    """Steady rolling line contact on a viscoelastic half-plane.

    Parameters
    ----------
    grid : Grid
        A line-contact :class:`contact._grid.Grid` (``line=True``, one row, not periodic)
        of at least 4 cells with the undeformed gap h(x) between the bodies (m), e.g.
        x^2/(2R) minus a roughness profile; its centres and pitch place the cells.
    load : float
        Load per unit length W' (N/m).
    creep : CreepSeries
        The pair's combined plane-strain creep compliance (``pair_creep``).
    speed : float
        Rolling speed V (m/s), the contact moving towards +x.
    radius : float, optional
        Cylinder radius R (m), for the rolling-resistance coefficient.

    Returns
    -------
    RollingResult
    """
    if not isinstance(grid, Grid) or grid.h is None or not grid.line or grid.periodic:
        raise ContactInputError("the viscoelastic line needs a free line-contact "
                                "contact._grid.Grid (line=True) with its gap h")
    h = np.asarray(grid.h, dtype=float).reshape(-1)
    if h.size < 4 or not np.all(np.isfinite(h)):
        raise ContactInputError("the line heights must be a finite 1D array of >= 4 cells")
    v = positive(speed, "the rolling speed", "m/s")
    W = positive(load, "the load per unit length", "N/m")
    dx = positive(grid.dx, "the cell pitch", "m")
    n = h.size
    x = np.asarray(grid.x, dtype=float)
    A = influence_matrix(n, dx, creep, v)
    start = h <= np.quantile(h, 0.2)
    found = solve_active_set(A, h, dx, W, start, 1e-12 * max(float(np.ptp(h)), 1e-300),
                             max_iter)
    if found is None:
        raise ConvergenceError(f"viscoelastic line contact: active set not settled after "
                               f"{max_iter} iterations", iterations=max_iter)
    p, delta, it = found
    u = A @ p
    gap = np.where(p > 0, 0.0, np.maximum(h + u - delta, 0.0))
    trailing, leading = edges_1d(x, p)
    record = active_set_record("viscoelastic plane-strain active set", h + u - delta,
                               start, h, it, edge_contact(p))
    edge_warning(record.edge_contact)
    mu = float((p * x).sum() * dx / (W * radius)) if radius else float("nan")
    cells = Grid(x=frozen(x), y=np.zeros(1), line=True, pitch=(dx, 1.0))
    return RollingResult(grid=cells, pressure=frozen(p), displacement=frozen(u),
                         gap=frozen(gap), approach=delta, load=W, radius=radius, speed=v,
                         leading=leading, trailing=trailing, rolling_resistance=mu,
                         solve=record, gap_residual=record.residual)



def rolling_cylinder(radius: float, load: float, creep: CreepSeries, speed: float, *,
                     n: int = 1024, half_length: float | None = None,
                     roughness: np.ndarray | None = None) -> RollingResult:
    """A cylinder of radius R rolling at V under W' per unit length (smooth or rough).

    The grid spans +-``half_length`` (default 1.6 times the relaxed Hertz half-width, which
    bounds the contact at every speed); ``roughness`` (m, length n) is subtracted from the
    gap (material heights up, as a plate's profile).
    """
    R = positive(radius, "the radius", "m")
    W = positive(load, "the load per unit length", "N/m")
    L = half_length if half_length is not None else cylinder_window(W, R, creep.relaxed)
    dx = 2.0 * L / n
    # centres as x0 + j dx, as the grid was always laid here (see surface.rolling_sphere)
    x = -L + dx / 2 + np.arange(n) * dx
    h = x**2 / (2 * R)
    if roughness is not None:
        z = np.asarray(roughness, dtype=float)
        if z.shape != (n,):
            raise ContactInputError(f"the roughness profile must have {n} samples")
        h = h - z
    return solve_line(line_grid(x, dx, h), W, creep, speed, radius=R)


def line_grid(x: np.ndarray, dx: float, h: np.ndarray) -> Grid:
    """A free line-contact grid of centres ``x`` (m), pitch ``dx`` (m) and gap ``h`` (m)."""
    return Grid(x=np.asarray(x, dtype=float), y=np.zeros(1),
                h=np.asarray(h, dtype=float).reshape(1, -1), line=True, pitch=(float(dx), 1.0))
