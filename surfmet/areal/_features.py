"""Areal feature parameters Spd and Spc (ISO 25178-2:2012, 4.5; segmentation ISO 25178-3).

Spd (density of significant peaks) and Spc (their mean curvature) from a watershed
segmentation of the surface into hills (scikit-image) with Wolf pruning at 5 % of Sz
(ISO 25178-3 default): a hill survives when its peak rises at least 5 % Sz above the
highest saddle leading to a higher peak, which is the h-dynamics criterion (Grimaud
1992; Wolf 1991) computed by :func:`skimage.morphology.h_maxima`. Hills whose watershed
region touches the scan border or a non-measured area are incomplete and are not
counted by default (``exclude_edge=True``, as MountainsMap does). Spc = mean of
``-(∂²z/∂x² + ∂²z/∂y²)/2`` at the peaks (central second differences), in 1/m.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from surfmet._model import Topography
from surfmet.areal._points import centred, heights_of

WOLF_PRUNING = 0.05
"""ISO 25178-3 default Wolf pruning height, as a fraction of Sz."""


@dataclass(frozen=True, eq=False)
class Hills:
    """Wolf-pruned hill segmentation: labels (0 = none), significant peak positions."""

    labels: np.ndarray
    peaks: np.ndarray  # (n, 2) int rows, cols of the counted peaks
    edge_peaks: np.ndarray  # peaks of hills that touch the border or a hole
    threshold: float  # pruning height, metres


def significant_hills(topo: Topography, pruning: float = WOLF_PRUNING,
                      exclude_edge: bool = True) -> Hills:
    """Watershed segmentation into hills with Wolf pruning at ``pruning`` × Sz."""
    from scipy import ndimage
    from skimage.morphology import h_maxima
    from skimage.segmentation import watershed

    z = heights_of(topo)
    d, valid, full = centred(z)
    sz = float(np.nanmax(d) - np.nanmin(d))
    h = pruning * sz
    if not sz > 0:
        empty = np.zeros((0, 2), dtype=int)
        return Hills(np.zeros(z.shape, dtype=np.int32), empty, empty, h)
    low = float(np.nanmin(d))
    filled = d if full else np.where(valid, d, low - sz)
    # h_maxima keeps the maxima whose dynamic is >= h: those are the hills Wolf pruning
    # leaves. Its float comparison can drop a hill whose dynamic equals h to the last bit;
    # shrinking h by a relative 1e-9 keeps the ">= h" semantics robust.
    markers_bin = h_maxima(filled, h * (1 - 1e-9)) if h > 0 else None
    markers, n = ndimage.label(markers_bin, structure=np.ones((3, 3)))
    labels = watershed(-filled, markers, mask=valid, connectivity=2)
    if n == 0:
        empty = np.zeros((0, 2), dtype=int)
        return Hills(labels, empty, empty, h)
    # One peak pixel per hill: the highest point of its marker.
    idx = np.arange(1, n + 1)
    pos = ndimage.maximum_position(filled, markers, idx)
    peaks = np.array(pos, dtype=int).reshape(-1, 2)
    touching = np.zeros(n + 1, dtype=bool)
    if exclude_edge:
        border = np.zeros(z.shape, dtype=bool)
        border[0, :] = border[-1, :] = border[:, 0] = border[:, -1] = True
        if not full:
            border |= ndimage.binary_dilation(~valid, structure=np.ones((3, 3)))
        touching[np.unique(labels[border & valid])] = True
    keep = ~touching[idx]
    return Hills(labels, peaks[keep], peaks[~keep], h)


def feature_parameters(topo: Topography, pruning: float = WOLF_PRUNING,
                       exclude_edge: bool = True) -> dict[str, float]:
    """Spd (1/m²) and Spc (1/m) of the significant hills."""
    z = heights_of(topo)
    hills = significant_hills(topo, pruning, exclude_edge)
    n_valid = int(np.count_nonzero(~np.isnan(z)))
    area = n_valid * topo.dx * topo.dy
    spd = hills.peaks.shape[0] / area
    curv = []
    ny, nx = z.shape
    for j, i in hills.peaks:
        if 0 < j < ny - 1 and 0 < i < nx - 1:
            zxx = (z[j, i + 1] - 2 * z[j, i] + z[j, i - 1]) / topo.dx**2
            zyy = (z[j + 1, i] - 2 * z[j, i] + z[j - 1, i]) / topo.dy**2
            k = -0.5 * (zxx + zyy)
            if np.isfinite(k):
                curv.append(k)
    spc = float(np.mean(curv)) if curv else float("nan")
    return {"Spd": float(spd), "Spc": spc}
