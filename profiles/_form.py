"""Form removal: least-squares line or polynomial on (x, z), NaN-aware.

ISO 4287 and ISO 21920-2 take the mean line of the primary profile as the
least-squares fit of the nominal form; for a flat part that is a straight line. The fit
uses the measured points only; non-measured points stay NaN in the residuals.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.polynomial import polynomial as P

from profiles._arrays import as_heights, as_positions, as_step, require_valid
from profiles._errors import ProfileError


@dataclass(frozen=True, eq=False)
class FormFit:
    """Result of a form removal.

    Attributes
    ----------
    residuals : ndarray
        ``z - form`` (NaN where ``z`` is NaN).
    form : ndarray
        The fitted form evaluated at every position (also where ``z`` is NaN).
    coefficients : tuple of float
        Polynomial coefficients in ascending powers of ``x`` in metres
        (``form = c0 + c1*x + c2*x**2 ...``); empty for ``level="none"``.
    degree : int
        Polynomial degree (-1 for no levelling).
    method : str
        ``"none"``, ``"mean"``, ``"line"`` or ``"poly:N"``.

    See Also
    --------
    remove_form, level_profile : make it.

    Examples
    --------
    >>> import numpy as np
    >>> from profiles import remove_form
    >>> fit = remove_form(0.5e-6 + 1e-3 * np.arange(10) * 1e-6, 1e-6)
    >>> fit.degree, fit.method
    (1, 'line')
    """

    residuals: np.ndarray
    form: np.ndarray
    coefficients: tuple[float, ...]
    degree: int
    method: str


def parse_level(level: Any) -> tuple[str, int]:
    """Normalise a levelling request to ``(name, degree)``.

    Accepts ``"none"``/``None``, ``"mean"``, ``"line"`` (alias ``"plane"``, what an areal
    command line calls it) and ``"poly:N"`` (also ``"polyN"``) or an int degree.
    """
    if level is None:
        return "none", -1
    if isinstance(level, (int, np.integer)) and not isinstance(level, bool):
        deg = int(level)
    else:
        text = str(level).strip().lower()
        if text in ("none", "raw", "off"):
            return "none", -1
        if text in ("mean", "offset"):
            return "mean", 0
        if text in ("line", "plane", "linear", "tilt"):
            return "line", 1
        body = text[4:].lstrip(":") if text.startswith("poly") else None
        try:
            deg = int(body) if body else -2
        except ValueError:
            deg = -2
        if deg < -1:
            raise ProfileError(
                f"unknown levelling {level!r}: use 'none', 'mean', 'line' or 'poly:N'"
            )
    if deg < 0:
        raise ProfileError(f"polynomial degree must be >= 0, got {deg}")
    if deg > 20:
        raise ProfileError(f"polynomial degree {deg} is too high for form removal (max 20)")
    names = {0: "mean", 1: "line"}
    return names.get(deg, f"poly:{deg}"), deg


def remove_form(z: Any, dx: float = 1.0, *, x: Any = None, degree: int = 1) -> FormFit:
    """Subtract the least-squares polynomial of ``degree`` from a profile.

    Parameters
    ----------
    z : array_like
        Heights in metres, NaN where not measured.
    dx : float
        Step in metres (positions ``i*dx``) when ``x`` is not given.
    x : array_like, optional
        Positions in metres.
    degree : int
        0 = mean, 1 = line, ``N`` = polynomial; -1 = nothing removed.

    Returns
    -------
    FormFit

    Raises
    ------
    ProfileError
        All-NaN profile or fewer measured points than coefficients.

    See Also
    --------
    level_profile : the same, by a levelling name.
    FormFit : the result.

    Examples
    --------
    A tilted line leaves no residual; its coefficients are the offset and the slope:

    >>> import numpy as np
    >>> from profiles import remove_form
    >>> z = 0.5e-6 + 1e-3 * np.arange(10) * 1e-6     # 0.5 µm offset, slope 1e-3
    >>> fit = remove_form(z, 1e-6)
    >>> print([f"{c:.3g}" for c in fit.coefficients], f"{np.abs(fit.residuals).max():.0e}")
    ['5e-07', '0.001'] ...
    """
    z = as_heights(z)
    pos = as_positions(x, z.size) if x is not None else np.arange(z.size) * as_step(dx)
    name = {-1: "none", 0: "mean", 1: "line"}.get(degree, f"poly:{degree}")
    valid = require_valid(z, max(degree + 1, 1), f"levelling by {name}")
    if degree < 0:
        zero = np.zeros_like(z)
        return FormFit(z.copy(), zero, (), -1, "none")
    # Fit in a centred, scaled variable so that high degrees stay well conditioned, then
    # convert to plain powers of x for the record.
    xv = pos[valid]
    centre = 0.5 * (pos[0] + pos[-1])
    half = max(0.5 * (pos[-1] - pos[0]), np.finfo(float).tiny)
    u = (pos - centre) / half
    coef_u = P.polyfit(u[valid], z[valid], degree)
    form = P.polyval(u, coef_u)
    if xv.size and degree >= 0:
        poly = np.polynomial.Polynomial(coef_u, domain=[centre - half, centre + half])
        coefficients = tuple(float(c) for c in poly.convert().coef)
        coefficients += (0.0,) * (degree + 1 - len(coefficients))
    else:  # pragma: no cover - guarded by require_valid
        coefficients = ()
    return FormFit(z - form, form, coefficients, degree, name)


def level_profile(z: Any, dx: float = 1.0, *, x: Any = None, level: Any = "line") -> FormFit:
    """:func:`remove_form` driven by a levelling name (see :func:`parse_level`).

    Parameters
    ----------
    z : array_like
        Heights in metres.
    dx : float
        Step in metres (for uniform profiles).
    x : array_like, optional
        Positions in metres (non-uniform profiles).
    level : str or int
        A levelling name: ``"none"``, ``"mean"``, ``"line"``, ``"poly:N"`` or an int degree.

    Returns
    -------
    FormFit
        Residuals, form and coefficients.

    Raises
    ------
    ProfileError
        An unknown levelling name or too few points for the degree.

    See Also
    --------
    remove_form

    Examples
    --------
    >>> import numpy as np
    >>> from profiles import level_profile
    >>> x = np.arange(11) * 1e-6
    >>> fit = level_profile(1e3 * (x - 5e-6) ** 2, 1e-6, level=2)
    >>> fit.degree, bool(np.abs(fit.residuals).max() < 1e-20)
    (2, True)
    """
    _, degree = parse_level(level)
    return remove_form(z, dx, x=x, degree=degree)


FLAT_RELATIVE = 1e-12
"""What levelling leaves of constant or planar heights is rounding: a scan whose levelled
heights stay under this fraction of its raw heights is flat (float64 rounding of a plane
leaves about 1e-16 of it; the margin covers the least-squares solve)."""


def is_flat(raw: Any, levelled: Any) -> bool:
    """Whether a scan is flat: its levelled heights are rounding of its raw ones.

    The one flatness criterion of surfmet (profiles and areal scans alike; ``spectrum``,
    the contact commands and ``roughness`` ask it). NaN (non-measured) points are ignored;
    all-zero heights are flat.

    Parameters
    ----------
    raw, levelled : array_like
        The heights as measured and after the form removal (any shape, same units).
    """
    raw = np.asarray(raw, dtype=float)
    lev = np.asarray(levelled, dtype=float)
    lev = lev[np.isfinite(lev)]
    raw = raw[np.isfinite(raw)]
    if lev.size == 0 or raw.size == 0:
        return False
    return not float(np.max(np.abs(lev))) > FLAT_RELATIVE * float(np.max(np.abs(raw)))
