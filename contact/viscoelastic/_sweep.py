"""Viscoelastic rolling resistance of a ball over a load sweep, and its exponent lambda.

M_r(N) = mu_r N R from :func:`contact.viscoelastic._surface.rolling_sphere` at each load;
lambda is fitted and the local exponent taken as in :mod:`contact._rolling` (the result is a
:class:`contact._rolling.RollingSweep` with ``model="viscoelastic"``).

Rough surfaces. The steady moving-frame problem needs a gap that is steady in the contact
frame. That is exact for roughness on a rigid (or elastic) indenter over a smooth
viscoelastic plate; roughness on the plate itself travels through the contact, so a
steady state does not exist and the roughness is then *frozen* in the contact frame (the
``kinematics="frozen"`` reading of :mod:`contact._rolling`); average several track positions
for a scan. The roughness map is sampled bilinearly on the solver's grid around ``centre``.
On a rough map the pressure's moment about the axis is not zero even without loss (the
asperities in contact lie unevenly ahead of and behind the apex), so the moment of the
elastic solution on the same map (compliance (C_g + C_r)/2) is subtracted: M_r is the part
the material's creep adds.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from typing import Any

import numpy as np

from contact._errors import ContactInputError
from contact._grid import Grid
from contact._sampling import sample_roughness
from contact.viscoelastic._rheology import CreepSeries, pair_creep
from contact.viscoelastic._surface import rolling_sphere
from contact.viscoelastic._window import sphere_window


def roughness_window(roughness: np.ndarray, dx: float, dy: float,
                     centre: tuple[float, float] | None, half: float, n: int) -> np.ndarray:
    """The roughness (m) on an n x n grid of half-width ``half`` centred on ``centre``
    (default the middle of the map), sampled by :func:`contact._sampling.sample_roughness`."""
    z = np.asarray(roughness, dtype=float)
    if z.ndim != 2:
        raise ContactInputError("the roughness must be a 2D map")
    ny, nx = z.shape
    cx, cy = centre if centre is not None else ((nx - 1) * dx / 2, (ny - 1) * dy / 2)
    step = 2 * half / n
    s = -half + step / 2 + np.arange(n) * step
    grid = Grid(x=s, y=s, pitch=(step, step))
    return sample_roughness(z, dx, dy, grid, centre=(cx, cy), average=False)


def viscoelastic_sweep(radius: float, ball: Any, plate: Any, loads: Iterable[float],
                       speed: float, *, roughness: np.ndarray | None = None,
                       roughness_dx: float | None = None, roughness_dy: float | None = None,
                       centre: tuple[float, float] | None = None, n: int = 128,
                       tol: float = 1e-9, confidence: float = 0.95,
                       progress: Callable[[Iterable[Any]], Iterable[Any]] | None = None) -> Any:
    """Viscoelastic rolling resistance of a ball on a plate over a load sweep.

    Parameters
    ----------
    radius : float
        Ball radius R (m).
    ball, plate : None, Material, StandardLinearSolid or PronySeries
        The bodies (None: rigid).
    loads : iterable of float
        Normal loads (N).
    speed : float
        Rolling speed V (m/s).
    roughness, roughness_dx, roughness_dy, centre : optional
        Composite roughness map (m), its pitch (m) and the apex position on it (m).
    n : int
        Grid cells per side; one domain (1.6 relaxed Hertz radii of the largest load).
    tol : float
        Solver tolerance (a metal's resistance is a 1e-4 asymmetry of the pressure).

    Returns
    -------
    contact._rolling.RollingSweep
    """
    from contact._rolling import sweep_loads

    w = sweep_loads(loads)
    creep = pair_creep(ball, plate)
    half = sphere_window(w[-1], radius, creep.relaxed)
    z = None
    if roughness is not None:
        if roughness_dx is None:
            raise ContactInputError("a roughness map needs its pitch roughness_dx (m)")
        z = roughness_window(roughness, roughness_dx, roughness_dy or roughness_dx, centre, half, n)
    elastic = CreepSeries(0.5 * (creep.glassy + creep.relaxed))
    mus = np.zeros(w.size)
    results = []
    seq = progress(range(w.size)) if progress is not None else range(w.size)
    for k in seq:
        res = rolling_sphere(radius, float(w[k]), creep, speed, n=n, half_width=half,
                             roughness=z, tol=tol)
        mus[k] = res.rolling_resistance
        if z is not None:  # the lossless moment of the same rough geometry
            ref = rolling_sphere(radius, float(w[k]), elastic, speed, n=n, half_width=half,
                                 roughness=z, tol=tol)
            mus[k] -= ref.rolling_resistance
        results.append(res)
    settings = {"model": "viscoelastic", "speed": float(speed), "grid": int(n),
                "dx": 2 * half / n, "glassy_compliance": creep.glassy,
                "relaxed_compliance": creep.relaxed, "creep_times": list(creep.times),
                "contact": "sphere", "roughness": "frozen" if z is not None else None}
    return sweep_record("viscoelastic", w, mus * w, radius, settings, results, confidence)


def sweep_record(model: str, loads: np.ndarray, forces: np.ndarray, radius: float,
                 settings: dict, results: Sequence[Any] = (),
                 confidence: float = 0.95) -> Any:
    """A :class:`contact._rolling.RollingSweep` from resisting forces F_r(N) (M_r = F_r R),
    with the power-law fit over the loads that dissipate and the local exponent."""
    from contact._exponent import dissipating_exponents
    from contact._rolling import RollingSweep

    w = np.asarray(loads, dtype=float)
    forces = np.asarray(forces, dtype=float)
    moments = forces * radius
    fit, local = dissipating_exponents(w, moments, confidence)
    notes = [] if fit is not None else \
        ["fewer than 3 loads with a positive moment: no exponent fitted"]
    return RollingSweep(model=model, loads=w, forces=forces, moments=moments, fit=fit,
                        local_lambda=local, radius=float(radius), settings=settings,
                        notes=tuple(notes), results=tuple(results))
