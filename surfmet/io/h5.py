"""HDF5 height maps (``.h5``), the container of the Contact-Mechanics Challenge's surfaces.

The file (HDF5 file format specification 3.0, read through ``h5py``) holds two-dimensional
numeric data sets at its root, each one channel (the Challenge's files hold one, named
``surface``). As in SurfaceTopography's ``H5Reader``, the first array index is x, so a
data set of shape (640, 480) is a map of nx = 640 by ny = 480 points. HDF5 stores neither
units nor pixel sizes: the map is read with heights taken as metres and a pixel of 1 m,
both marked assumed (:class:`surfmet._model.Calibration`); ``height_unit=`` and ``dx=`` /
``dy=`` of :func:`surfmet.read` state them. The default channel is the first data set in
the file's order.

Before a data set is read, its declared size is checked against the bytes the file holds
for it (raw storage) or against what compression can expand them to, so a damaged header
cannot make numpy allocate what the bytes do not hold.
"""

from __future__ import annotations

import io
from typing import Any

import numpy as np

from surfmet._errors import SurfmetFormatError
from surfmet._model import Topography
from surfmet.io._binary import MAX_DEFLATE_RATIO, MAX_POINTS, format_error
from surfmet.io._calibration import assumed
from surfmet.io._registry import register_reader

FORMAT = "h5"
MAGIC = b"\x89HDF\r\n\x1a\n"
# h5py reports a damaged file through these (RuntimeError: HDF5 library errors).
_H5_ERRORS = (OSError, RuntimeError, ValueError, KeyError, TypeError)


def _is_h5(buf: bytes) -> bool:
    return buf.startswith(MAGIC)


def _maps(f: Any) -> list[tuple[str, Any]]:
    import h5py

    out = []
    for key in f:
        obj = f.get(key)
        if isinstance(obj, h5py.Dataset) and obj.ndim == 2 and obj.dtype.kind in "fiu":
            out.append((key, obj))
    return out


def _load(dset: Any, name: str) -> np.ndarray:
    n = int(np.prod(dset.shape, dtype=np.int64))
    nbytes = n * dset.dtype.itemsize
    if n == 0 or n > MAX_POINTS:
        raise format_error(name, FORMAT, f"data set of absurd shape {dset.shape}")
    stored = dset.id.get_storage_size()
    filtered = dset.compression is not None or bool(dset._filters)
    limit = stored * MAX_DEFLATE_RATIO + 1024 if filtered else stored
    if nbytes > limit:
        raise format_error(name, FORMAT, f"truncated: data set {dset.name!r} declares "
                           f"{nbytes} bytes but the file holds {stored}")
    return np.asarray(dset[...], dtype=np.float64)


@register_reader(FORMAT, extensions=("h5", "hdf5", "hdf"), description="HDF5 height map",
                 magic=_is_h5, priority=10)
def decode(buf: bytes, name: str, channel: int | str | None = None) -> Topography:
    """Read one two-dimensional data set of an HDF5 file.

    Parameters
    ----------
    channel : int or str, optional
        Index among the two-dimensional data sets or a data set name. Default: the first.
    """
    import h5py

    try:
        with h5py.File(io.BytesIO(buf), "r") as f:
            maps = _maps(f)
            if not maps:
                raise format_error(name, FORMAT, "no two-dimensional numeric data set")
            names = [k for k, _ in maps]
            if channel is None:
                index = 0
            elif isinstance(channel, str) and channel in names:
                index = names.index(channel)
            elif isinstance(channel, int) or str(channel).isdigit():
                index = int(channel)
                if not 0 <= index < len(maps):
                    raise format_error(name, FORMAT, f"channel {index} does not exist: the "
                                       f"file holds {len(maps)} data sets {names}")
            else:
                raise format_error(name, FORMAT, f"no data set named {channel!r}; data sets: "
                                   f"{names}")
            z = _load(maps[index][1], name)
            grids = [[int(d.shape[0]), int(d.shape[1])] for _, d in maps]  # nx, ny each
    except SurfmetFormatError:
        raise
    except _H5_ERRORS as exc:
        raise format_error(name, FORMAT, f"unreadable HDF5 file ({type(exc).__name__}: "
                           f"{str(exc)[:200]})") from None
    with np.errstate(invalid="ignore", over="ignore"):
        heights = z.T.copy()
    heights[~np.isfinite(heights)] = np.nan
    # HDF5 stores neither: heights taken as metres, a pixel of 1 m, both said to be assumed
    md: dict[str, Any] = {"channel": names[index], "channels": names,
                          "channel_grids": grids, "height_unit": "m", "lateral_unit": "",
                          "lateral_calibrated": False, **assumed(True, True)}
    return Topography(heights, 1.0, 1.0, md)


__all__ = ["decode"]
