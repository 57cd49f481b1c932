"""contact.engineering surface containers (``.zip``): several measurements of one surface.

The container (written by contact.engineering / TopoBank; read by SurfaceTopography's
``CEReader``) is a zip archive holding the measurements' own data files and ``meta.yml``:

.. code-block:: yaml

    surfaces:
    - topographies:
      - datafile: {original: <member name>}
        data_source: 0          # channel of the data file
        unit: nm                # length unit, when the data file has none
        height_scale: 1.0       # factor applied to the heights read from the file
        detrend_mode: height    # center | height | curvature
        instrument: {parameters: {tip_radius: {value: 40, unit: nm}}}   # optional

Each measurement is decoded by the registry (format detection as for a lone file), then
prepared as SurfaceTopography's ``CEReader`` prepares it, so that the scale-dependent
statistics reproduce SurfaceTopography's asserted values: the heights are multiplied by
``height_scale`` (also when the data file calibrates its own heights, as the peer does),
and their ``detrend_mode`` is kept in the metadata: the analysis applies it
(:func:`surfmet.scale_dependent.level_as_stated`; ``center``: mean, ``height``: least-squares
line or plane, ``curvature``: least-squares quadratic), since loading a file never runs
analysis code. A two-column text profile is uniform when no step differs from
the mean step by more than 1e-6 in the file's unit (the peer's XYZ rule), with the pixel
``(x[-1] - x[0]) / (n - 1)``.

``read_container`` returns every measurement; the registry's decoder returns one
(``measurement=``, default the first), so ``surfmet.read(container)`` works like any file.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from surfmet._errors import SurfmetFormatError
from surfmet._model import STATED, Profile, Topography, unit_sources
from surfmet.io._binary import format_error
from surfmet.io._registry import read_bytes, register_reader
from surfmet.io._sources import Source, source_bytes
from surfmet.io._zip import ZIP_MAGIC, member_names, open_zip, read_member
from surfmet.units import length_factor, quantity

FORMAT = "ce"
_MAX_META = 8 << 20
_MAX_DATA = 1 << 31
_TEXT_FORMATS = ("xyz",)
_XYZ_TOL = 1e-6
_DETREND_MODES = (None, "", "none", "center", "height", "curvature")


def _is_container(buf: bytes) -> bool:
    return buf.startswith(ZIP_MAGIC) and b"meta.yml" in member_names(buf)


def _meta(text: bytes, name: str) -> list[dict[str, Any]]:
    """The measurements' entries of ``meta.yml`` (all surfaces, in order)."""
    import yaml

    class Loader(yaml.SafeLoader):
        pass

    # TopoBank writes sizes as Python tuples; read them as lists, refuse other Python tags.
    Loader.add_constructor("tag:yaml.org,2002:python/tuple",
                           lambda loader, node: loader.construct_sequence(node))
    try:
        meta = yaml.load(text, Loader=Loader)  # a SafeLoader subclass
    except yaml.YAMLError as exc:
        raise format_error(name, FORMAT, f"meta.yml is not readable YAML ({exc})") from None
    if not isinstance(meta, dict) or not isinstance(meta.get("surfaces"), list):
        raise format_error(name, FORMAT, "meta.yml has no 'surfaces' list")
    out: list[dict[str, Any]] = []
    for surface in meta["surfaces"]:
        topos = surface.get("topographies") if isinstance(surface, dict) else None
        if not isinstance(topos, list):
            raise format_error(name, FORMAT, "a surface in meta.yml has no 'topographies' list")
        out.extend(t for t in topos if isinstance(t, dict))
    if not out:
        raise format_error(name, FORMAT, "meta.yml names no measurement")
    return out


def _datafile(entry: dict[str, Any], name: str) -> str:
    files = entry.get("datafile")
    if isinstance(files, dict):
        for key in ("original", "squeezed-netcdf"):
            if isinstance(files.get(key), str):
                return files[key]
    raise format_error(name, FORMAT, f"measurement {entry.get('name')!r} names no data file")


def _uniform_text_profile(scan: Profile, unit_factor: float) -> Profile:
    if scan.x is None or scan.n < 3:
        return scan
    x = scan.x
    step = (x[-1] - x[0]) / (x.size - 1)
    if np.max(np.abs(np.diff(x) - step)) < _XYZ_TOL * unit_factor:
        return Profile(scan.z, step, metadata=dict(scan.metadata))
    return scan


def _measurement(zf: Any, entry: dict[str, Any], index: int, name: str
                 ) -> Profile | Topography:
    member = _datafile(entry, name)
    if member not in zf.namelist():
        raise format_error(name, FORMAT, f"meta.yml names {member!r}, which the archive "
                           "does not hold")
    data = read_member(zf, member, name, FORMAT, _MAX_DATA, what="measurement")
    label = f"{name}:{member}"
    unit = entry.get("unit")
    options: dict[str, Any] = {}
    scan = read_bytes(data, name=label)
    fmt = scan.metadata.get("format")
    if fmt in _TEXT_FORMATS and isinstance(unit, str):
        # Coordinate text carries no unit: meta.yml gives it.
        options["unit"] = unit
        scan = read_bytes(data, format=fmt, name=label, **options)
        # stated by the container's meta.yml, not by the user
        scan = scan.with_metadata(**unit_sources(STATED, STATED))
    if "data_source" in entry and fmt not in _TEXT_FORMATS and int(entry["data_source"]):
        scan = read_bytes(data, format=fmt, name=label, channel=int(entry["data_source"]))
    if isinstance(scan, Profile) and fmt in _TEXT_FORMATS:
        scan = _uniform_text_profile(scan, length_factor(unit) if isinstance(unit, str) else 1)
    if entry.get("detrend_mode") not in _DETREND_MODES:
        raise format_error(name, FORMAT, f"detrend_mode {entry.get('detrend_mode')!r} of "
                           f"{member!r} (center, height or curvature expected)")
    scale = float(entry.get("height_scale", 1.0) or 1.0)
    if scale != 1.0:
        if isinstance(scan, Profile):
            scan = scan.replace(z=scan.z * scale)
        else:
            scan = scan.replace(heights=scan.heights * scale)
    md: dict[str, Any] = {**scan.metadata, "format": FORMAT, "measurement_format": fmt,
                          "container": name, "member": member,
                          "measurement": index, "name": entry.get("name", member),
                          "detrend_mode": entry.get("detrend_mode"), "height_scale": scale}
    tip = ((entry.get("instrument") or {}).get("parameters") or {}).get("tip_radius")
    if isinstance(tip, dict) and "value" in tip and "unit" in tip:
        md["tip_radius"] = quantity(float(tip["value"]) * length_factor(str(tip["unit"])), "m")
    return scan.replace(metadata=md)


def decode_all(buf: bytes, name: str) -> list[Profile | Topography]:
    """Every measurement of a container held in memory, prepared as described above."""
    zf = open_zip(buf, name, FORMAT)
    entries = _meta(read_member(zf, "meta.yml", name, FORMAT, _MAX_META, what="meta.yml"),
                    name)
    return [_measurement(zf, e, i, name) for i, e in enumerate(entries)]


@register_reader(FORMAT, extensions=("zip",),
                 description="contact.engineering container (zip with meta.yml)",
                 magic=_is_container, priority=12)
def decode(buf: bytes, name: str, measurement: int | None = None,
           channel: int | str | None = None) -> Profile | Topography:
    """Read one measurement of a container (default the first).

    ``channel`` (``--channel``) is the same choice as ``measurement``: an index, or a
    measurement's name as ``meta.yml`` gives it. ``metadata["channels"]`` names them all.
    """
    scans = decode_all(buf, name)
    names = [str(s.metadata.get("name")) for s in scans]
    choice = channel if measurement is None else measurement
    if choice is None:
        index = 0
    elif isinstance(choice, str) and choice in names:
        index = names.index(choice)
    elif isinstance(choice, int) or str(choice).isdigit():
        index = int(choice)
    else:
        raise format_error(name, FORMAT, f"no measurement named {choice!r}; the container "
                           f"holds {names}")
    if not 0 <= index < len(scans):
        raise format_error(name, FORMAT, f"measurement {index} does not exist: the "
                           f"container holds {len(scans)} {names}")
    return scans[index].with_metadata(channel=names[index], channels=names)


def read_container(source: Source) -> list[Profile | Topography]:
    """Every measurement of a contact.engineering container.

    Parameters
    ----------
    source : path-like, bytes or binary file-like object
        The container file, its bytes or a binary stream (as :func:`surfmet.io.read`).

    Raises
    ------
    SurfmetFormatError
        Not a readable container, a data file that ``meta.yml`` names is missing, or a
        measurement that cannot be read (the message names the member).
    """
    buf, name, source_name = source_bytes(source)
    if not _is_container(buf):
        raise SurfmetFormatError(f"{name}: not a contact.engineering container (a zip holding "
                                 "meta.yml)")
    scans = decode_all(buf, name)
    return [s.with_metadata(source=source_name) if source_name else s for s in scans]


__all__ = ["decode", "decode_all", "read_container"]
