"""The data model: :class:`Topography` (areal scan) and :class:`Profile` (line scan).

Both hold SI values only: heights in metres, NaN where the instrument did not measure.
They are frozen dataclasses whose arrays are made read-only, so a scan cannot be changed
behind the back of code that holds it; derive new ones with :meth:`Topography.replace`.

Metadata conventions (every key optional; readers add anything else the file carries):

``format``             registry name of the reader (``"x3p"``, ``"nms"``...)
``instrument``         instrument or software name as written in the file
``vendor``             manufacturer
``date``               acquisition date, ISO 8601 text where the file allows
``height_unit``        height unit used in the file (``"m"``, ``"um"``, ``""`` if none)
``lateral_unit``       lateral unit used in the file
``lateral_calibrated`` ``False`` where the file states no lateral unit (dx, dy are then
                       the file's numbers taken as metres)
``source``             the path the scan was read from
``height_unit_source`` who stated the height unit: ``"file"``, ``"assumed"`` (the file
                       states none; ``height_unit`` is what was taken) or ``"user"``
``lateral_unit_source`` the same for the pixel size / lateral unit
                       (:class:`Calibration` reads both, with the older flags above)
"""

from __future__ import annotations

import dataclasses
import math
import sys
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError

# re-exported: the readers and users import them from the data model
from surfmet._stated_units import ASSUMED as ASSUMED
from surfmet._stated_units import SOURCE_WORDS as SOURCE_WORDS
from surfmet._stated_units import STATED as STATED
from surfmet._stated_units import UNIT_SOURCES as UNIT_SOURCES
from surfmet._stated_units import USER as USER
from surfmet._stated_units import Calibration as Calibration
from surfmet._stated_units import unit_sources as unit_sources
from surfmet._stated_units import unit_text as unit_text


def _frozen_array(values: Any, ndim: int, name: str) -> np.ndarray:
    # Reuse an array that is already float64 and read-only; copy anything else, so that
    # freezing never makes the caller's own array read-only behind its back.
    if isinstance(values, np.ndarray) and values.dtype == np.float64 and not values.flags.writeable:
        arr = values
    else:
        try:
            arr = np.array(values, dtype=np.float64)
        except (TypeError, ValueError) as exc:
            raise SurfmetInputError(f"{name} must be numeric: {exc}") from None
    if arr.ndim != ndim:
        raise SurfmetInputError(f"{name} must be a {ndim}D array, got shape {arr.shape}")
    arr.setflags(write=False)
    return arr


def _check_step(value: float, name: str) -> float:
    """A pixel size every reader and every caller of the model gets checked: positive,
    finite and a normal float (a subnormal pixel, e.g. 5e-324 m from a damaged header,
    makes slopes and spectra divide by zero)."""
    v = float(value)
    if not (math.isfinite(v) and v > 0):
        raise SurfmetInputError(f"{name} must be a positive finite length in metres, got {value!r}")
    if v < sys.float_info.min:
        raise SurfmetInputError(f"{name} {v:.3g} m is too small to be a pixel size (below "
                                f"{sys.float_info.min:.3g}): a damaged file or a wrong unit")
    return v


@dataclass(frozen=True, eq=False)
class Topography:
    """An areal height map.

    Parameters
    ----------
    heights : array_like, shape (ny, nx)
        Heights in metres; row ``j`` is at ``y = j * dy``, column ``i`` at ``x = i * dx``.
        NaN marks points that were not measured.
    dx, dy : float
        Pixel sizes along x (columns) and y (rows), in metres.
    metadata : mapping, optional
        Instrument, date, original units and whatever else the file carries.

    Raises
    ------
    SurfmetInputError
        Heights not a 2D numeric array, no point at all, or a pixel size that is not a
        positive finite length.

    See Also
    --------
    Profile : the line scan.
    surfmet.read : a Topography from a scan file.

    Examples
    --------
    >>> import numpy as np
    >>> from surfmet import Topography
    >>> topo = Topography(np.zeros((4, 6)), dx=1e-6, dy=2e-6, metadata={"instrument": "test"})
    >>> topo.shape, topo.nx, topo.ny
    ((4, 6), 6, 4)
    >>> print(f"{topo.size_x * 1e6:g} µm x {topo.size_y * 1e6:g} µm")
    6 µm x 8 µm
    >>> topo.heights.flags.writeable
    False
    """

    heights: np.ndarray
    dx: float
    dy: float
    metadata: Mapping[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "heights", _frozen_array(self.heights, 2, "heights"))
        object.__setattr__(self, "dx", _check_step(self.dx, "dx"))
        object.__setattr__(self, "dy", _check_step(self.dy, "dy"))
        object.__setattr__(self, "metadata", MappingProxyType(dict(self.metadata)))
        if self.heights.size == 0:
            raise SurfmetInputError("a topography needs at least one point")

    kind = "areal"

    @property
    def ny(self) -> int:
        """Number of rows (points along y)."""
        return int(self.heights.shape[0])

    @property
    def nx(self) -> int:
        """Number of columns (points along x)."""
        return int(self.heights.shape[1])

    @property
    def shape(self) -> tuple[int, int]:
        """``(ny, nx)``."""
        return (self.ny, self.nx)

    @property
    def mask(self) -> np.ndarray:
        """Boolean array, True where the point was *not* measured."""
        return np.isnan(self.heights)

    @property
    def nan_fraction(self) -> float:
        """Fraction of non-measured points."""
        return float(np.count_nonzero(np.isnan(self.heights)) / self.heights.size)

    @property
    def has_nan(self) -> bool:
        """True if any point is non-measured."""
        return bool(np.isnan(self.heights).any())

    @property
    def size_x(self) -> float:
        """Physical width ``nx * dx`` in metres."""
        return self.nx * self.dx

    @property
    def size_y(self) -> float:
        """Physical height ``ny * dy`` in metres."""
        return self.ny * self.dy

    @property
    def x(self) -> np.ndarray:
        """Column positions in metres, starting at 0."""
        return np.arange(self.nx) * self.dx

    @property
    def y(self) -> np.ndarray:
        """Row positions in metres, starting at 0."""
        return np.arange(self.ny) * self.dy

    @property
    def calibration(self) -> Calibration:
        """Which units the file stated and which were assumed (:class:`Calibration`)."""
        return Calibration.of(self.metadata, self.dx, self.dy)

    def replace(self, **changes: Any) -> Topography:
        """A copy with some fields changed (``heights=``, ``dx=``, ``metadata=``...)."""
        return dataclasses.replace(self, **changes)

    def with_metadata(self, **items: Any) -> Topography:
        """A copy whose metadata has ``items`` added or replaced."""
        md = dict(self.metadata)
        md.update(items)
        return dataclasses.replace(self, metadata=md)

    def __repr__(self) -> str:
        return (
            f"Topography(nx={self.nx}, ny={self.ny}, dx={self.dx:.6g} m, dy={self.dy:.6g} m, "
            f"nan_fraction={self.nan_fraction:.4g}, format={self.metadata.get('format')!r})"
        )

    def _repr_html_(self) -> str:
        """A small height map and the grid, pixel and height range (Jupyter)."""
        from surfmet._display import map_html, value_range
        from surfmet.units import format_quantity as q

        return map_html(self.heights, "Topography", [
            ("grid", f"{self.nx} × {self.ny}", "points"),
            ("size", f"{q(self.size_x, 'm')} × {q(self.size_y, 'm')}", ""),
            ("pixel", f"{q(self.dx, 'm')} × {q(self.dy, 'm')}", ""),
            ("height range", value_range(self.heights), "m"),
            ("non-measured", 100 * self.nan_fraction, "%"),
            ("format", self.metadata.get("format") or "-", ""),
        ])


@dataclass(frozen=True, eq=False)
class Profile:
    """A line scan.

    Parameters
    ----------
    z : array_like, shape (n,)
        Heights in metres, NaN where not measured.
    dx : float
        Sampling step in metres. For a non-uniform profile, the mean step.
    x : array_like, shape (n,), optional
        Positions in metres, strictly increasing, for non-uniformly sampled profiles
        (e.g. a Dektak export). ``None`` means uniform: ``x = i * dx``.
    metadata : mapping, optional
        As for :class:`Topography`.

    Raises
    ------
    SurfmetInputError
        Heights not a 1D numeric array, no point, a bad step, or positions that do not
        increase.

    See Also
    --------
    Topography : the areal scan.
    profiles.analyze_profile : ISO 21920-2 parameters of a profile's heights.

    Examples
    --------
    >>> import numpy as np
    >>> from surfmet import Profile
    >>> prof = Profile(np.sin(np.linspace(0, 2 * np.pi, 101)) * 1e-6, dx=1e-5)
    >>> prof.n, prof.is_uniform, f"{prof.length * 1e3:.1f} mm"
    (101, True, '1.0 mm')
    """

    z: np.ndarray
    dx: float
    x: np.ndarray | None = None
    metadata: Mapping[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "z", _frozen_array(self.z, 1, "z"))
        object.__setattr__(self, "dx", _check_step(self.dx, "dx"))
        if self.x is not None:
            x = _frozen_array(self.x, 1, "x")
            if x.shape != self.z.shape:
                raise SurfmetInputError(f"x has {x.size} points but z has {self.z.size}")
            if not np.all(np.isfinite(x)) or (x.size > 1 and not np.all(np.diff(x) > 0)):
                raise SurfmetInputError("profile positions x must be finite and increasing")
            object.__setattr__(self, "x", x)
        object.__setattr__(self, "metadata", MappingProxyType(dict(self.metadata)))
        if self.z.size == 0:
            raise SurfmetInputError("a profile needs at least one point")

    kind = "profile"

    @property
    def n(self) -> int:
        """Number of points."""
        return int(self.z.size)

    @property
    def nx(self) -> int:
        """Number of points (same as :attr:`n`, for symmetry with Topography)."""
        return self.n

    @property
    def ny(self) -> int:
        """Always 1."""
        return 1

    @property
    def is_uniform(self) -> bool:
        """True if the profile is sampled at a constant step."""
        return self.x is None

    @property
    def positions(self) -> np.ndarray:
        """Point positions in metres (``x`` or ``i * dx``)."""
        if self.x is not None:
            return self.x
        return np.arange(self.n) * self.dx

    @property
    def length(self) -> float:
        """Evaluation length: ``n * dx`` for uniform profiles, the x extent otherwise."""
        if self.x is not None:
            return float(self.x[-1] - self.x[0])
        return self.n * self.dx

    @property
    def mask(self) -> np.ndarray:
        """Boolean array, True where not measured."""
        return np.isnan(self.z)

    @property
    def nan_fraction(self) -> float:
        """Fraction of non-measured points."""
        return float(np.count_nonzero(np.isnan(self.z)) / self.z.size)

    @property
    def calibration(self) -> Calibration:
        """Which units the file stated and which were assumed (:class:`Calibration`)."""
        return Calibration.of(self.metadata, self.dx)

    def replace(self, **changes: Any) -> Profile:
        """A copy with some fields changed."""
        return dataclasses.replace(self, **changes)

    def with_metadata(self, **items: Any) -> Profile:
        """A copy whose metadata has ``items`` added or replaced."""
        md = dict(self.metadata)
        md.update(items)
        return dataclasses.replace(self, metadata=md)

    def __repr__(self) -> str:
        kind = "uniform" if self.is_uniform else "non-uniform"
        return (
            f"Profile(n={self.n}, dx={self.dx:.6g} m, {kind}, "
            f"nan_fraction={self.nan_fraction:.4g}, format={self.metadata.get('format')!r})"
        )

    def _repr_html_(self) -> str:
        """A line of the profile and its length, spacing and height range (Jupyter)."""
        from surfmet._display import line_html, value_range

        return line_html(self.positions, self.z, "Profile", [
            ("points", self.n, ""),
            ("length", self.length, "m"),
            ("spacing", self.dx, "m"),
            ("spacing is", "uniform" if self.is_uniform else "non-uniform", ""),
            ("height range", value_range(self.z), "m"),
            ("non-measured", 100 * self.nan_fraction, "%"),
            ("format", self.metadata.get("format") or "-", ""),
        ])


Scan = Topography | Profile


#: The largest peak-to-valley height span (m) of anything measured as a surface: stylus
#: and optical profilers span at most tens of millimetres, road profiles metres; 1 km is far
#: above all of them. A wider span in a calibrated file is damage (one flipped exponent bit
#: turns 2 µm into 1e302 m) or a wrong height unit, never a surface.
MAX_HEIGHT_SPAN = 1e3
#: The largest span any height statistic can be computed on, calibrated or not: Sku sums
#: fourth powers, which overflow beyond about 1e77.
MAX_NUMERIC_SPAN = 1e60


def height_span_error(values: np.ndarray, limit: float = MAX_HEIGHT_SPAN) -> str | None:
    """Why ``values`` (m, NaN for non-measured) cannot be measured heights: a peak-to-valley
    span beyond ``limit`` (:data:`MAX_HEIGHT_SPAN` for calibrated heights,
    :data:`MAX_NUMERIC_SPAN` for any), as a sentence; None when they can."""
    v = np.asarray(values, dtype=float)
    finite = v[np.isfinite(v)] if not np.isfinite(v).all() else v.ravel()
    if finite.size == 0:
        return None
    span = float(finite.max()) - float(finite.min())  # Python floats: overflow gives inf
    if span <= limit:
        return None
    what = ("any surface's" if limit == MAX_HEIGHT_SPAN
            else "what statistics can be computed on")
    return (f"the heights span {span:.3g} m peak to valley, beyond {what} range "
            f"({limit:g} m)")


def require_measurement(scan: Topography | Profile) -> Topography | Profile:
    """``scan`` if its heights can be analysed, else one clear error: the reader's flag
    (``metadata["height_range"]``: heights beyond any surface's range, a damaged file) or
    a span no statistic survives (:data:`MAX_NUMERIC_SPAN`)."""
    flag = scan.metadata.get("height_range")
    if flag:
        raise SurfmetInputError(str(flag))
    values = scan.heights if isinstance(scan, Topography) else scan.z
    problem = height_span_error(values, MAX_NUMERIC_SPAN)
    if problem:
        raise SurfmetInputError(f"{problem}: not a surface measurement (damaged data or a "
                                "wrong height unit)")
    return scan
