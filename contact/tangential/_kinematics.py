"""Kinematics of rolling and shift: creepages, rigid slip, and the slip of the surfaces.

Sign convention (one for the whole package, that of Kalker 1990 and CONTACT with the
rolling direction chi = 0):

- the contact moves over both bodies in the +x direction at the rolling speed V; the
  material flows through it in -x, entering at the **leading edge** (largest x);
- the creepages are the rigid slip velocity of body 1 relative to body 2 divided by V:
  longitudinal xi (x), lateral eta (y) and spin phi (rad/m). The rigid slip at (x, y) is
  w = (xi - phi y, eta + phi x);
- the tractions (q_x, q_y) act on body 1 (body 2 receives the opposite), so a positive
  creepage xi gives a negative force F_x (friction opposes the slip of body 1).

Steady rolling: the relative slip velocity of the surface particles, divided by V, is
s = w - d(u)/dx with u = u(1) - u(2) the tangential displacement difference. Following
Kalker's steady-state discretisation it is taken upwind, the particle at x_j having come
from x_{j+1}: s_j = w_j + (u_j - u_{j+1})/dx.

Shift (quasi-static, Cattaneo-Mindlin): the slip distance between two instants is
s = w + u - u', w the rigid shift of body 1 relative to body 2 and u' the displacement
difference at the previous instant.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from contact._errors import ContactInputError


@dataclass(frozen=True)
class Creepage:
    """Prescribed creepages of steady rolling (see the module's sign convention).

    Attributes
    ----------
    xi, eta : float
        Longitudinal and lateral creepage (dimensionless).
    phi : float
        Spin creepage (1/m).
    """

    xi: float = 0.0
    eta: float = 0.0
    phi: float = 0.0

    def __post_init__(self) -> None:
        for name in ("xi", "eta", "phi"):
            if not math.isfinite(getattr(self, name)):
                raise ContactInputError(f"creepage {name} must be a finite number")


def rigid_slip(x: np.ndarray, y: np.ndarray, creep: Creepage) -> np.ndarray:
    """w = (xi - phi y, eta + phi x) on the grid, shape (2, ny, nx)."""
    xx, yy = np.meshgrid(np.asarray(x, float), np.asarray(y, float))
    return np.stack([creep.xi - creep.phi * yy, creep.eta + creep.phi * xx])


def rolling_slip(u: np.ndarray, dx: float) -> np.ndarray:
    """The elastic part of the steady-rolling slip, (u_j - u_{j+1})/dx (upwind).

    ``u`` has shape (..., nx); the last column (the leading edge of the grid, which
    carries no traction when the grid holds the contact) takes u_{nx} = u_{nx-1}.
    """
    out = np.empty_like(u)
    out[..., :-1] = (u[..., :-1] - u[..., 1:]) / dx
    out[..., -1] = 0.0
    return out
