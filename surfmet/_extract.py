"""Profile extraction from an areal scan: a row, a column or a straight line.

``spec`` is ``"row:K"`` (heights ``z[K, :]``, step dx), ``"col:K"`` (``z[:, K]``, step dy)
or a segment ``(x0, y0, x1, y1)`` in metres (also as the text ``"x0,y0,x1,y1"``, each with
an optional unit, e.g. ``"0,10um,200um,10um"``). A segment is sampled at step
``min(dx, dy)`` by bilinear interpolation; a sample whose four neighbouring grid points are
not all measured is NaN, so holes are never bridged.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography


def parse_spec(spec: str | Sequence[float]) -> tuple[str, object]:
    """``("row", K)``, ``("col", K)`` or ``("line", (x0, y0, x1, y1))``."""
    if isinstance(spec, str):
        text = spec.strip().lower()
        m = re.fullmatch(r"(row|col|column)\s*[:=]\s*(-?\d+)", text)
        if m:
            return ("row" if m.group(1) == "row" else "col"), int(m.group(2))
        if "," in text:
            from surfmet.units import parse_length

            parts = [p for p in text.removeprefix("line:").split(",")]
            if len(parts) == 4:
                return "line", tuple(parse_length(p) for p in parts)
        raise SurfmetInputError(
            f"cannot read profile spec {spec!r}: use row:K, col:K or x0,y0,x1,y1"
        )
    try:
        vals = tuple(float(v) for v in spec)
    except (TypeError, ValueError):
        raise SurfmetInputError(f"profile spec {spec!r} is not row:K, col:K or 4 numbers") from None
    if len(vals) != 4 or not all(np.isfinite(vals)):
        raise SurfmetInputError(
            f"a line profile needs 4 finite numbers x0, y0, x1, y1, got {spec!r}"
        )
    return "line", vals


def _index(k: int, n: int, what: str) -> int:
    kk = k + n if k < 0 else k
    if not 0 <= kk < n:
        raise SurfmetInputError(f"{what} {k} is outside the scan (0..{n - 1})")
    return kk


def extract_profile(topo: Topography, spec: str | Sequence[float]) -> Profile:
    """Extract a profile from an areal scan.

    Parameters
    ----------
    topo : Topography
    spec : str or 4 floats
        ``"row:K"``, ``"col:K"`` (negative K counts from the end) or ``(x0, y0, x1, y1)``
        in metres.

    Returns
    -------
    Profile
        Metadata gains ``profile`` (the spec) and keeps the scan's metadata.

    Raises
    ------
    SurfmetInputError
        Malformed spec, index or segment outside the scan, a segment shorter than 2 samples.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> row = surfmet.extract_profile(plate, "row:256")
    >>> row.z.size, row.dx, row.metadata["profile"]
    (1024, 5e-06, 'row:256')
    >>> surfmet.extract_profile(plate, "col:-1").metadata["profile"]
    'col:1023'
    >>> diagonal = surfmet.extract_profile(plate, "0,0,1mm,1mm")  # sampled at min(dx, dy)
    >>> diagonal.z.size, diagonal.metadata["profile"]
    (283, 'line:0,0,0.001,0.001')
    """
    if not isinstance(topo, Topography):
        raise SurfmetInputError("profile extraction needs an areal scan (a Topography)")
    kind, arg = parse_spec(spec)
    md = dict(topo.metadata)
    if kind == "row":
        j = _index(int(arg), topo.ny, "row")
        md["profile"] = f"row:{j}"
        md["profile_y"] = j * topo.dy
        return Profile(topo.heights[j, :], topo.dx, metadata=md)
    if kind == "col":
        i = _index(int(arg), topo.nx, "column")
        md["profile"] = f"col:{i}"
        md["profile_x"] = i * topo.dx
        return Profile(topo.heights[:, i], topo.dy, metadata=md)
    x0, y0, x1, y1 = arg  # type: ignore[misc]
    xmax, ymax = (topo.nx - 1) * topo.dx, (topo.ny - 1) * topo.dy
    tol = 1e-9 * max(xmax, ymax, topo.dx)
    for x, y in ((x0, y0), (x1, y1)):
        if not (-tol <= x <= xmax + tol and -tol <= y <= ymax + tol):
            raise SurfmetInputError(
                f"point ({x:.6g} m, {y:.6g} m) lies outside the scan "
                f"[0, {xmax:.6g}] × [0, {ymax:.6g}] m"
            )
    length = float(np.hypot(x1 - x0, y1 - y0))
    step = min(topo.dx, topo.dy)
    n = int(np.floor(length / step + 1e-9)) + 1
    if n < 2:
        raise SurfmetInputError(f"line of {length:.3g} m is shorter than one step ({step:.3g} m)")
    t = np.arange(n) * step / length
    xs = np.clip(x0 + t * (x1 - x0), 0, xmax) / topo.dx
    ys = np.clip(y0 + t * (y1 - y0), 0, ymax) / topo.dy
    i0 = np.minimum(np.floor(xs).astype(np.int64), topo.nx - 2) if topo.nx > 1 else \
        np.zeros(n, dtype=np.int64)
    j0 = np.minimum(np.floor(ys).astype(np.int64), topo.ny - 2) if topo.ny > 1 else \
        np.zeros(n, dtype=np.int64)
    fx = xs - i0
    fy = ys - j0
    z = topo.heights
    i1 = np.minimum(i0 + 1, topo.nx - 1)
    j1 = np.minimum(j0 + 1, topo.ny - 1)
    # NaN in any of the four corners makes the sample NaN (0 × NaN is NaN).
    zi = ((1 - fx) * (1 - fy) * z[j0, i0] + fx * (1 - fy) * z[j0, i1]
          + (1 - fx) * fy * z[j1, i0] + fx * fy * z[j1, i1])
    md["profile"] = f"line:{x0:.9g},{y0:.9g},{x1:.9g},{y1:.9g}"
    return Profile(zi, step, metadata=md)
