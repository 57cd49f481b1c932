"""The inverse problem of the rotor study: ``lambda`` and ``s_r`` from two accelerations.

A symmetric and an asymmetric rotor (same mass and inertia, different load split between
the balls) rolling on the same slope give two accelerations; Eqs. (47)-(48) of Alaci,
Ciornei & Romanu (2022) then tie the rolling-friction law ``M_r = s_r N**lambda`` to the
assumed equivalent slope ``S = sin(alpha) sin(beta)`` (:data:`IDENTIFIABILITY`).

References
----------
Alaci S., Ciornei F.-C., Romanu I.-C. (2022) Materials 15(7):2518, Eqs. (47)-(48).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from contact._errors import ContactInputError
from rotor._mechanics import G_STANDARD, MassProperties, mass_properties, normal_reactions

__all__ = ["IDENTIFIABILITY", "RollingLawInference", "infer_rolling_law"]

IDENTIFIABILITY = (
    "Two measured accelerations (symmetric and asymmetric collar) give two equations in "
    "three unknowns: the equivalent slope S = sin(alpha) sin(beta), s_r and lambda. The paper "
    "prints neither alpha nor beta, so S is unknown and only a one-parameter family (lambda(S), "
    "s_r(S)) is identified. Without S: (i) lambda = 1 predicts equal accelerations for any S "
    "(Eq. 49), so a significant difference contradicts lambda = 1 only if both rotors ran on the "
    "same S and nothing else differed; (ii) the sign of the difference gives the side of 1 "
    "(asymmetric slower <=> lambda > 1 on the physical branch); (iii) the rolling torque cannot "
    "exceed the driving torque, so S >= (J + M R^2) eps / (M g R), and an upper bound on S (the "
    "paper says below 1 degree) gives a lower bound on |lambda - 1|. s_r can never be separated "
    "from S: at fixed lambda it moves one-for-one with the assumed slope."
)


@dataclass(frozen=True)
class RollingLawInference:
    """``lambda`` and ``s_r`` implied by two accelerations, for each assumed slope.

    Arrays are indexed like ``slope``. ``lam``/``s_r`` are the solutions for the nominal
    accelerations; ``*_low``/``*_high`` the 16th/84th percentiles under the accelerations'
    uncertainties (Monte Carlo); NaN where no solution exists (``feasible`` is False: the
    slope is too small to overcome the resistance, or the measured ratio of torques is out of
    reach of any ``lambda`` on the physical branch ``lambda >= lambda_min``).
    ``lever_arm`` is ``s_r N_s**(lam - 1)``, m: the linear-law coefficient that the fitted law
    gives at the symmetric rotor's ball load ``N_s``.

    Attributes
    ----------
    slope : numpy.ndarray
        The assumed equivalent slopes ``S = sin(alpha) sin(beta)``.
    lam, lam_low, lam_high : numpy.ndarray
        ``lambda`` and its 16th/84th percentiles.
    s_r, s_r_low, s_r_high : numpy.ndarray
        ``s_r`` (``N**(1 - lambda) m``) and its percentiles.
    lever_arm : numpy.ndarray
        ``s_r N_s**(lam - 1)`` (m).
    torque_sym, torque_asym, torque_ratio : numpy.ndarray
        The two rotors' total rolling torques (N m) and their ratio.
    feasible : numpy.ndarray of bool
        Where a solution exists.
    min_slope : float
        The smallest slope at which neither torque is negative.
    lambda_branch_min : float
        The lower end of the physical branch of ``lambda``.
    note : str
        What two accelerations can and cannot identify (:data:`IDENTIFIABILITY`).

    See Also
    --------
    infer_rolling_law : builds it.

    Examples
    --------
    >>> from rotor import infer_rolling_law
    >>> result = infer_rolling_law(5.4443, 5.4419, [0.01, 0.01745])
    >>> result.feasible.tolist(), round(float(result.lam[1]), 2)
    ([False, True], 1.3)
    """

    slope: np.ndarray
    lam: np.ndarray
    lam_low: np.ndarray
    lam_high: np.ndarray
    s_r: np.ndarray
    s_r_low: np.ndarray
    s_r_high: np.ndarray
    lever_arm: np.ndarray
    torque_sym: np.ndarray
    torque_asym: np.ndarray
    torque_ratio: np.ndarray
    feasible: np.ndarray
    min_slope: float
    lambda_branch_min: float
    note: str = field(default=IDENTIFIABILITY)


def _quantiles(sorted_values: np.ndarray) -> tuple[float, float]:
    """16th and 84th percentiles of sorted samples (which may hold +inf)."""
    n = len(sorted_values)
    return (float(sorted_values[int(0.16 * (n - 1))]), float(sorted_values[int(0.84 * (n - 1))]))


def _ratio(lam: np.ndarray, na: tuple[float, float], ns: tuple[float, float]) -> np.ndarray:
    return (na[0] ** lam + na[1] ** lam) / (ns[0] ** lam + ns[1] ** lam)


def infer_rolling_law(
    eps_sym: float,
    eps_asym: float,
    slope: float | np.ndarray,
    *,
    u_sym: float = 0.0,
    u_asym: float = 0.0,
    props_sym: MassProperties | None = None,
    props_asym: MassProperties | None = None,
    g: float = G_STANDARD,
    n_samples: int = 4000,
    seed: int = 0,
    lam_max: float = 60.0,
) -> RollingLawInference:
    """Solve Eqs. (47)-(48) for ``lambda`` and ``s_r`` given both rotors' accelerations.

    Parameters
    ----------
    eps_sym, eps_asym : float
        Angular accelerations (rad/s^2) of the symmetric and asymmetric rotors, measured on the
        same equivalent slope.
    slope : float or array
        Assumed equivalent slope(s) ``S = sin(alpha) sin(beta)`` (small ``alpha``: cos = 1 and
        no lateral load shift, which changes the loads by ``R/d tan(alpha)`` < 0.5 % below 1°).
    u_sym, u_asym : float
        Standard uncertainties of the accelerations, propagated by Monte Carlo.
    props_sym, props_asym : MassProperties
        Default: the paper's rotor with the collar centred and against a ball.
    g : float
        Gravity (m/s²).
    n_samples, seed : int
        Size and seed of the Monte Carlo sample.
    lam_max : float
        Upper end of the search for ``lambda``.

    Returns
    -------
    RollingLawInference
        ``lambda``, ``s_r`` and their uncertainty bands for each slope.

    Raises
    ------
    ContactInputError
        A non-finite acceleration, a negative uncertainty, or a slope outside [-1, 1].

    See Also
    --------
    angular_acceleration : the forward model this inverts.
    solve_lambda : the exponent from an offset between two groups on a shared track.

    Notes
    -----
    The total rolling torques are ``M_x = M g R S - (J + M R^2) eps_x``. Their ratio
    ``Q = M_a/M_s = (N_a1**lam + N_a2**lam)/(N_s1**lam + N_s2**lam)`` is 1 at ``lam = 0`` and
    ``lam = 1`` and has a single minimum between; the physical branch is the one through 1
    (and the Hertzian 4/3), ``lam >= lam_min``. See :data:`IDENTIFIABILITY`.

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of Rolling
       Friction Moment on the Normal Force for Elastic Materials", Materials 15 (2022) 2518,
       Eqs. (47)-(48).

    Examples
    --------
    Accelerations made by the forward model with ``lambda = 1.3`` and ``s_r = 2e-5`` on a
    1° slope give back that law; on a slope too small to drive the rotors there is none:

    >>> import math
    >>> from rotor import angular_acceleration, infer_rolling_law, mass_properties
    >>> a = math.radians(1.0)
    >>> eps_sym = angular_acceleration(2e-5, 1.3, a, math.pi / 2, mass_properties())
    >>> eps_asym = angular_acceleration(2e-5, 1.3, a, math.pi / 2,
    ...                                 mass_properties(collar_offset="end"))
    >>> print(f"{eps_sym:.4f} {eps_asym:.4f} rad/s²")
    5.4443 5.4419 rad/s²
    >>> result = infer_rolling_law(eps_sym, eps_asym, [0.01, math.sin(a)])
    >>> result.feasible.tolist()
    [False, True]
    >>> print(f"lambda = {result.lam[1]:.3f}, s_r = {result.s_r[1]:.2e}")
    lambda = 1.300, s_r = 2.00e-05
    """
    ps = mass_properties(collar_offset="symmetric") if props_sym is None else props_sym
    pa = mass_properties(collar_offset="end") if props_asym is None else props_asym
    for name, val in (("eps_sym", eps_sym), ("eps_asym", eps_asym)):
        if not math.isfinite(val):
            raise ContactInputError(f"{name} must be finite")
    if u_sym < 0 or u_asym < 0:
        raise ContactInputError("uncertainties must be >= 0")
    slopes = np.atleast_1d(np.asarray(slope, dtype=float))
    if np.any(~np.isfinite(slopes)) or np.any(np.abs(slopes) > 1):
        raise ContactInputError("slopes must be finite values of sin(alpha) sin(beta) in [-1, 1]")
    ns = normal_reactions(ps, 0.0, math.pi / 2, g)
    na = normal_reactions(pa, 0.0, math.pi / 2, g)

    # the minimum of Q(lambda) separates the two branches
    grid = np.linspace(0.0, 1.0, 2001)
    lam_min = float(grid[np.argmin(_ratio(grid, na, ns))])
    q_min = float(_ratio(np.array(lam_min), na, ns))
    q_max = float(_ratio(np.array(lam_max), na, ns))

    def solve(q: np.ndarray, clip: bool = False) -> np.ndarray:
        # vectorised bisection on the increasing branch [lam_min, lam_max]
        lo = np.full(q.shape, lam_min)
        hi = np.full(q.shape, lam_max)
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            up = _ratio(mid, na, ns) < q
            lo = np.where(up, mid, lo)
            hi = np.where(up, hi, mid)
        lam = 0.5 * (lo + hi)
        if clip:
            # for the uncertainty band: a ratio below the branch's minimum is best explained
            # by lam_min, one above reach by "lambda beyond lam_max"
            return np.where(q < q_min, lam_min, np.where(q > q_max, np.inf, lam))
        return np.where((q >= q_min) & (q <= q_max), lam, np.nan)

    mgr_s = ps.mass * g * ps.ball_radius
    mgr_a = pa.mass * g * pa.ball_radius
    rng = np.random.default_rng(seed)
    es = eps_sym + u_sym * rng.standard_normal(n_samples)
    ea = eps_asym + u_asym * rng.standard_normal(n_samples)

    out = {k: np.full(slopes.shape, np.nan) for k in (
        "lam", "lam_low", "lam_high", "s_r", "s_r_low", "s_r_high", "lever", "ms", "ma", "q")}
    for i, s in enumerate(slopes):
        m_s = mgr_s * s - ps.rolling_inertia * eps_sym
        m_a = mgr_a * s - pa.rolling_inertia * eps_asym
        out["ms"][i], out["ma"][i] = m_s, m_a
        if m_s <= 0 or m_a <= 0:
            continue
        q = m_a / m_s
        out["q"][i] = q
        lam = float(solve(np.array([q]))[0])
        out["lam"][i] = lam
        if math.isfinite(lam):
            out["s_r"][i] = m_s / (ns[0] ** lam + ns[1] ** lam)
            out["lever"][i] = out["s_r"][i] * ns[0] ** (lam - 1)
        ms_mc = mgr_s * s - ps.rolling_inertia * es
        ma_mc = mgr_a * s - pa.rolling_inertia * ea
        ok = (ms_mc > 0) & (ma_mc > 0)
        if ok.mean() <= 0.5:
            continue
        lam_mc = np.sort(solve(ma_mc[ok] / ms_mc[ok], clip=True))
        finite = np.isfinite(lam_mc)
        sr_mc = np.sort(
            ms_mc[ok][finite] / (ns[0] ** lam_mc[finite] + ns[1] ** lam_mc[finite])
        ) if finite.any() else np.array([np.nan])
        out["lam_low"][i], out["lam_high"][i] = _quantiles(lam_mc)
        out["s_r_low"][i], out["s_r_high"][i] = _quantiles(sr_mc)
    min_slope = max(ps.rolling_inertia * eps_sym / mgr_s, pa.rolling_inertia * eps_asym / mgr_a)
    return RollingLawInference(
        slope=slopes,
        lam=out["lam"],
        lam_low=out["lam_low"],
        lam_high=out["lam_high"],
        s_r=out["s_r"],
        s_r_low=out["s_r_low"],
        s_r_high=out["s_r_high"],
        lever_arm=out["lever"],
        torque_sym=out["ms"],
        torque_asym=out["ma"],
        torque_ratio=out["q"],
        feasible=np.isfinite(out["lam"]),
        min_slope=float(min_slope),
        lambda_branch_min=lam_min,
    )
