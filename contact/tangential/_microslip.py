"""Micro-slip rolling resistance: the frictional dissipation of steady rolling over a
load sweep, and its load exponent lambda.

Two elastic bodies with different elastic constants strain differently under the same
pressure, so their surfaces slip over part of the contact as they roll, even with no
tangential force (Bentall & Johnson 1967, Int. J. Mech. Sci. 9:389; Johnson 1985,
*Contact Mechanics*, sec. 8.2); a tangential force (a driving or braking torque, the
rotor's acceleration) adds creep. Friction dissipates, per metre rolled,

    F_r = -iint q . s dA        (s the slip velocity over the rolling speed),

which is the frictional power per unit rolling speed of :mod:`contact.tangential`; as a
rolling-resistance moment M_r = F_r R, comparable with the hysteresis and plastic models
of :mod:`contact._rolling`. For a smooth pair each load is solved on its own grid scaled
with its Hertz radius (so all loads have the same relative resolution), with the normal-tangential
coupling of dissimilar bodies iterated. With roughness, all loads share one grid sized
for the largest load, so that every load sees the same sampling of the asperities.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Sequence
from typing import Any

import numpy as np

from contact._errors import ContactInputError
from contact._exponent import fit_exponent, local_exponent
from contact._grid import sphere_grid
from contact._hertz import hertz_sphere
from contact._materials import Material
from contact._rolling import RollingSweep
from contact._sampling import sample_roughness
from contact.halfspace.constants import pair_constants
from contact.tangential._kinematics import Creepage
from contact.tangential._results import edge_note
from contact.tangential._steady import check_friction, steady_rolling


def microslip_dissipation(radius: float, ball: Material, plate: Material, load: float,
                          mu: float, *, traction_ratio: float = 0.0,
                          roughness: tuple[np.ndarray, float, float] | None = None,
                          grid: int = 32, half_width: float | None = None) -> Any:
    """One steady-rolling solve of a ball on a plate at ``load`` (N).

    ``traction_ratio`` = |F_x|/N, the tangential force on the ball opposing its rolling
    (a ball accelerated by a slope, braked at the contact); 0 is free rolling.
    ``half_width`` fixes the grid (default: 1.25 Hertz radii, 1.5 with roughness).
    Returns the :class:`~contact.tangential._results.TangentialResult`.
    """
    if not (math.isfinite(traction_ratio) and 0 <= traction_ratio < mu):
        raise ContactInputError(
            f"traction ratio must lie in [0, mu) = [0, {mu}), got {traction_ratio}")
    constants = pair_constants(ball, plate)
    a = hertz_sphere(radius, load, constants.e_star).a
    half = half_width or (1.5 if roughness is not None else 1.25) * a
    z = None
    if roughness is not None:
        z = sample_roughness(roughness[0], roughness[1], roughness[2],
                             sphere_grid(radius, half, grid), average=False)
        z = z - z.max()
    g = sphere_grid(radius, half, grid, roughness=z)
    return steady_rolling(g, constants, load, mu, Creepage(), fx=-traction_ratio * load)


def microslip_sweep(
    radius: float,
    ball: Material,
    plate: Material,
    loads: Iterable[float],
    mu: float,
    *,
    traction_ratio: float = 0.0,
    roughness: tuple[np.ndarray, float, float] | None = None,
    grid: int = 32,
    confidence: float = 0.95,
    progress: Callable[[Iterable[Any]], Iterable[Any]] | None = None,
) -> RollingSweep:
    """Micro-slip rolling resistance over a load sweep (see the module notes).

    Parameters
    ----------
    radius : float
        Ball radius R (m).
    ball, plate : Material
        Body 1 (the ball) and body 2 (the plate).
    loads : iterable of float
        Normal loads (N).
    mu : float
        Coefficient of friction.
    traction_ratio : float
        |F_x|/N opposing the rolling (0: free rolling).
    roughness : (ndarray, dx, dy), optional
        Composite roughness map centred on the contact and its pitch (m).
    grid : int
        Elements per side of each load's grid.
    confidence : float
        Level of the exponent's confidence interval.
    progress : callable, optional
        Wraps the iterable of loads.
    """
    mu = check_friction(mu)
    w = np.sort(np.asarray(list(loads), dtype=float))
    if w.size < 1 or not (np.isfinite(w).all() and (w > 0).all()):
        raise ContactInputError("loads must be positive and finite (N)")
    forces = np.zeros(w.size)
    creep = np.zeros(w.size)
    slip_fraction = np.zeros(w.size)
    edge = np.zeros(w.size)
    results = []
    half = None
    if roughness is not None:
        # asperities 3 sigma high still touch out to a^2 + 6 R sigma (as surfmet's domains)
        a = hertz_sphere(radius, float(w[-1]), pair_constants(ball, plate).e_star).a
        sigma = float(np.std(roughness[0]))
        half = 1.25 * math.sqrt(a * a + 6.0 * radius * sigma)
    sequence = progress(range(w.size)) if progress is not None else range(w.size)
    for k in sequence:
        r = microslip_dissipation(radius, ball, plate, float(w[k]), mu,
                                  traction_ratio=traction_ratio, roughness=roughness,
                                  grid=grid, half_width=half)
        forces[k] = r.frictional_power  # never negative: only slip elements dissipate
        creep[k] = r.creepage.xi
        slip_fraction[k] = r.slip_area / max(r.contact_area, 1e-300)
        edge[k] = r.edge_dissipation_share
        results.append(r)
    c = pair_constants(ball, plate)
    settings = {"model": "microslip", "e_star": c.e_star, "grid": grid,
                "dx": results[-1].grid.dx, "hardness": None, "contact": "sphere",
                "microslip": {"mu": mu, "traction_ratio": traction_ratio,
                              "kalker_K": c.K, "dundurs_beta": c.beta,
                              "creepages": creep.tolist(),
                              "slip_fractions": slip_fraction.tolist(),
                              "edge_dissipation_shares": edge.tolist()}}
    note = edge_note(float(edge.max()))
    return _sweep(w, forces, radius, settings, results, confidence,
                  () if note is None else (f"at {w[int(edge.argmax())]:.4g} N: {note}",))


def _sweep(loads: np.ndarray, forces: np.ndarray, radius: float, settings: dict,
           results: Sequence[Any], confidence: float, notes: Sequence[str] = ()) -> RollingSweep:
    moments = forces * radius
    pos = moments > 0
    notes = list(notes)
    fit = fit_exponent(loads[pos], moments[pos], confidence) if pos.sum() >= 3 else None
    if fit is None:
        notes.append(f"only {int(pos.sum())} of {loads.size} loads dissipate: no exponent "
                     "fitted (3 needed)")
    local = np.full(loads.size, math.nan)
    if pos.sum() >= 2:
        local[pos] = local_exponent(loads[pos], moments[pos])
    return RollingSweep(model="microslip", loads=loads, forces=forces, moments=moments,
                        fit=fit, local_lambda=local, radius=float(radius), settings=settings,
                        notes=tuple(notes), results=tuple(results))
