"""The composite roughness of a ball-on-plate pair, as the contact set-ups take it.

One small frozen value object carries what the set-ups need to put measured roughness
under the ball: the composite height map (the sum of the two surfaces' heights, each
measured outward from its own body, so that it closes the gap, h = r^2/(2R) - z; NaN where
not measured), its pitch, where the ball's apex sits on it (a track position), and whether
its least-squares plane is removed first. How the two scans were paired onto one grid
(resampling, mirroring the ball, filling) is the caller's business (``surfmet.pairing``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from contact._errors import ContactInputError
from contact._validate import frozen, positive


def _two_lengths(value: object, what: str) -> tuple[float, float]:
    """``value`` as two finite floats (m), else :class:`ContactInputError`."""
    try:
        a, b = (float(v) for v in value)  # type: ignore[union-attr]
    except (TypeError, ValueError):
        raise ContactInputError(f"{what} must be two lengths in m, got {value!r}") from None
    if not (math.isfinite(a) and math.isfinite(b)):
        raise ContactInputError(f"{what} must be finite, got {value!r}")
    return a, b


@dataclass(frozen=True, eq=False)
class CompositeRoughness:
    """Composite roughness on a regular grid, ready for a ball-on-plate set-up.

    Parameters
    ----------
    heights : ndarray, shape (ny, nx)
        Composite roughness z (m), NaN where not measured; row i at Y = i dy, column j at
        X = j dx (scan coordinates). Stored as a read-only copy.
    dx : float
        Pitch along x (m).
    dy : float, optional
        Pitch along y (m); default ``dx``.
    centre : (float, float), optional
        Scan coordinates (X, Y) of the ball's apex (m); default the middle of the map.
    level : bool
        Remove the least-squares plane of the whole map before solving. A tilt between
        ball and plate is a rigid-body rotation: it only moves the contact sideways, and a
        height offset only shifts the approach; levelling makes the result independent of
        both.

    Raises
    ------
    ContactInputError
        Not a 2D map of at least 2 x 2 points, nothing measured, a pitch that is not a
        positive length, or a centre that is not two finite lengths.

    Examples
    --------
    >>> import numpy as np
    >>> z = CompositeRoughness(np.zeros((65, 65)), 5e-6)
    >>> z.apex
    (0.00016, 0.00016)
    >>> [round(v * 1e6, 6) for v in z.shifted((100e-6, -20e-6)).apex]   # µm
    [260.0, 140.0]
    """

    heights: np.ndarray
    dx: float
    dy: float | None = None
    centre: tuple[float, float] | None = None
    level: bool = True

    def __post_init__(self) -> None:
        z = np.array(self.heights, dtype=float)
        if z.ndim != 2 or min(z.shape) < 2:
            raise ContactInputError(f"the roughness must be a 2D map, got shape {z.shape}")
        if not np.isfinite(z).any():
            raise ContactInputError("the roughness map is NaN everywhere: nothing measured")
        dx = positive(self.dx, "the roughness pitch dx", "m")
        dy = dx if self.dy is None else positive(self.dy, "the roughness pitch dy", "m")
        centre = None if self.centre is None else _two_lengths(self.centre,
                                                                "the apex position (X, Y)")
        object.__setattr__(self, "heights", frozen(z))
        object.__setattr__(self, "dx", dx)
        object.__setattr__(self, "dy", dy)
        object.__setattr__(self, "centre", centre)
        object.__setattr__(self, "level", bool(self.level))

    @property
    def middle(self) -> tuple[float, float]:
        """Scan coordinates (X, Y) of the middle of the map (m)."""
        ny, nx = self.heights.shape
        return (0.5 * (nx - 1) * self.dx, 0.5 * (ny - 1) * self.dy)

    @property
    def apex(self) -> tuple[float, float]:
        """Where the ball's apex sits (m): ``centre``, or the middle of the map."""
        return self.centre if self.centre is not None else self.middle

    def shifted(self, offset: tuple[float, float] | None) -> CompositeRoughness:
        """The same roughness with the apex at ``offset`` (x, y in m) from the middle of the
        map: a track position. None keeps the apex where it is."""
        if offset is None:
            return self
        ox, oy = _two_lengths(offset, "the track position (x, y)")
        mx, my = self.middle
        return replace(self, centre=(mx + ox, my + oy))
