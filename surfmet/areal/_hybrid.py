"""Areal hybrid parameters Sdq and Sdr (ISO 25178-2:2012, 4.4; 2021, Annex D).

Sdq, the root mean square gradient, from forward differences on the grid:
``Sdq² = mean_x[(Δx z / dx)²] + mean_y[(Δy z / dy)²]``, each mean over the differences
whose two end points are measured. Sdr, the developed interfacial area ratio, from the
area of each grid cell taken as the mean of its two triangulations (ISO 25178-2:2021,
Annex D, the "average of both diagonals" rule): with corner triangles spanned by one x
edge ``(dx, 0, Δx z)`` and one y edge ``(0, dy, Δy z)``, the cell area is a quarter of
the sum of the four cross-product norms; Sdr = (Σ cell areas / Σ projected areas - 1),
over cells with four measured corners, in %. For small slopes Sdr ≈ Sdq²/2.
"""

from __future__ import annotations

import math

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.areal._points import fixed_order_dot, heights_of


def gradient_parameters(topo: Topography) -> dict[str, float]:
    """Sdq (forward differences) and Sdr (cell areas, mean of both triangulations), in %."""
    z = heights_of(topo)
    dx, dy = topo.dx, topo.dy
    if z.shape[0] < 2 or z.shape[1] < 2:
        raise SurfmetInputError("Sdq and Sdr need at least 2 × 2 points")
    gx = np.diff(z, axis=1)  # Δx z, shape (ny, nx-1)
    gy = np.diff(z, axis=0)  # Δy z, shape (ny-1, nx)
    full = not np.isnan(z).any()
    if full:
        mx = fixed_order_dot(gx.ravel(), gx.ravel()) / gx.size
        my = fixed_order_dot(gy.ravel(), gy.ravel()) / gy.size
    else:
        vx = gx[~np.isnan(gx)]
        vy = gy[~np.isnan(gy)]
        if vx.size == 0 or vy.size == 0:
            raise SurfmetInputError("no pair of adjacent measured points: Sdq is undefined")
        mx = fixed_order_dot(vx, vx) / vx.size
        my = fixed_order_dot(vy, vy) / vy.size
    sdq = math.sqrt(mx / dx**2 + my / dy**2)

    # Cell areas. |e_x × e_y|² = (dy Δx z)² + (dx Δy z)² + (dx dy)² for a corner triangle.
    ax = gx * dy
    ax *= ax
    ay = gy * dx
    ay *= ay
    c = (dx * dy) ** 2
    bottom, top = ax[:-1], ax[1:]
    left, right = ay[:, :-1], ay[:, 1:]
    s = np.sqrt(bottom + left + c)
    s += np.sqrt(bottom + right + c)
    s += np.sqrt(top + left + c)
    s += np.sqrt(top + right + c)
    if full:
        total = float(s.sum())
        n_cells = s.size
    else:
        ok = ~np.isnan(s)
        n_cells = int(np.count_nonzero(ok))
        if n_cells == 0:
            raise SurfmetInputError("no grid cell with four measured corners: Sdr is undefined")
        total = float(s[ok].sum())
    # Each cell: area = Σ|corner cross| / 4; Sdr = Σ area / (n dx dy) - 1.
    sdr = (0.25 * total / (n_cells * dx * dy) - 1.0) * 100.0
    return {"Sdq": sdq, "Sdr": sdr}
