"""The reader/writer registry: one entry per file format, detection by magic bytes.

Each format module calls :func:`register_reader` (and optionally :func:`register_writer`) at
import time. :func:`read` picks the format from ``format=``, else from the first registered
magic check that accepts the bytes, else from the file extension, and turns any failure
inside a reader into :class:`~surfmet._errors.SurfmetFormatError`, so that a damaged file can
never surface as an ``IndexError`` from deep inside numpy.
"""

from __future__ import annotations

import os
import struct
import zipfile
import zlib
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from surfmet._errors import SurfmetError, SurfmetFormatError, SurfmetInputError
from surfmet._model import (
    MAX_HEIGHT_SPAN,
    MAX_NUMERIC_SPAN,
    Profile,
    Topography,
    height_span_error,
)
from surfmet.io._reader_options import GENERIC_OPTIONS as GENERIC_OPTIONS
from surfmet.io._reader_options import check_options, take_generic_options
from surfmet.io._sources import Source, source_bytes

Scan = Topography | Profile
Decoder = Callable[..., Scan]
Encoder = Callable[..., bytes]
MagicCheck = Callable[[bytes], bool]


@dataclass(frozen=True)
class FormatSpec:
    """What the registry knows about one format.

    Attributes
    ----------
    name : str
        Registry name (``read(..., format=name)``).
    extensions : tuple of str
        File extensions, lower case, without the dot.
    description : str
        One line for ``surfmet formats``.
    decode, encode : callable or None
        The reader and the writer (None where the format has none).
    magic : callable or None
        ``magic(buf) -> bool``, the content check used by :func:`detect_format`.
    priority : int
        Order of the magic checks (lower first).

    See Also
    --------
    formats : every registered FormatSpec.

    Examples
    --------
    >>> from surfmet.io import formats
    >>> spec = formats()["x3p"]
    >>> spec.extensions, spec.encode is not None
    (('x3p',), True)
    """

    name: str
    extensions: tuple[str, ...]
    description: str
    decode: Decoder | None = None
    encode: Encoder | None = None
    magic: MagicCheck | None = None
    priority: int = 50  # lower = tried first during magic detection


_FORMATS: dict[str, FormatSpec] = {}


def register_reader(
    name: str,
    *,
    extensions: tuple[str, ...] | list[str],
    description: str,
    magic: MagicCheck | None = None,
    priority: int = 50,
) -> Callable[[Decoder], Decoder]:
    """Register ``decode(buf: bytes, name: str, **options) -> Topography | Profile``.

    Parameters
    ----------
    name : str
        Registry name, used by ``read(..., format=name)``.
    extensions : sequence of str
        File extensions without dot, lower case (``"x3p"``).
    description : str
        One line for ``surfmet formats`` and error messages.
    magic : callable, optional
        ``magic(buf) -> bool``: True if the bytes look like this format. Must be cheap and
        must never raise.
    priority : int
        Order of magic checks; strong binary signatures use small numbers, text heuristics
        larger ones.

    Returns
    -------
    callable
        A decorator that registers the decoder and returns it unchanged.

    See Also
    --------
    register_writer, formats

    Examples
    --------
    A reader for a made-up text format of whitespace-separated heights in metres:

    >>> import numpy as np
    >>> from surfmet import Topography
    >>> from surfmet.io import read_bytes
    >>> from surfmet.io import register_reader
    >>> @register_reader("demo-heights", extensions=("dhz",), description="demo heights")
    ... def decode(buf, name, **options):
    ...     z = np.loadtxt(buf.decode().splitlines())
    ...     return Topography(z, dx=1e-6, dy=1e-6, metadata={"format": "demo-heights"})
    >>> read_bytes(b"0 1e-9\\n2e-9 3e-9", format="demo-heights").shape
    (2, 2)
    >>> from surfmet.io._registry import _FORMATS
    >>> del _FORMATS["demo-heights"]  # keep the registry as it was
    """

    def deco(func: Decoder) -> Decoder:
        old = _FORMATS.get(name)
        _FORMATS[name] = FormatSpec(
            name=name,
            extensions=tuple(e.lower().lstrip(".") for e in extensions),
            description=description,
            decode=func,
            encode=old.encode if old else None,
            magic=magic,
            priority=priority,
        )
        return func

    return deco


def register_writer(name: str) -> Callable[[Encoder], Encoder]:
    """Register ``encode(scan, **options) -> bytes`` for an already registered format.

    Parameters
    ----------
    name : str
        Registry name of a format whose reader is registered.

    Returns
    -------
    callable
        A decorator that registers ``encode(scan, **options) -> bytes`` and returns it.

    Raises
    ------
    KeyError
        If no reader of that name is registered yet.

    See Also
    --------
    register_reader, encode

    Examples
    --------
    >>> from surfmet.io import register_writer
    >>> register_writer("no-such-format")(lambda scan: b"")
    Traceback (most recent call last):
    ...
    KeyError: "register the reader of 'no-such-format' before its writer"
    """

    def deco(func: Encoder) -> Encoder:
        if name not in _FORMATS:
            raise KeyError(f"register the reader of {name!r} before its writer")
        spec = _FORMATS[name]
        _FORMATS[name] = FormatSpec(**{**spec.__dict__, "encode": func})
        return func

    return deco


def formats() -> dict[str, FormatSpec]:
    """All registered formats, by name.

    Returns
    -------
    dict of str to FormatSpec
        Every format surfmet reads, with its extensions and description.

    See Also
    --------
    FormatSpec, read

    Examples
    --------
    >>> from surfmet.io import formats
    >>> table = formats()
    >>> "x3p" in table and "plu" in table
    True
    >>> sorted(name for name, spec in table.items() if spec.encode)
    ['npy', 'npz', 'x3p']
    """
    _load_all()
    return dict(_FORMATS)


def _load_all() -> None:
    from surfmet.io import load_format_modules  # each listed module registers on import
    load_format_modules()


def detect_format(buf: bytes, filename: str | os.PathLike[str] = "") -> str:
    """Name of the format of ``buf``: magic bytes first, then the file extension.

    Parameters
    ----------
    buf : bytes
        The file's content (its first bytes suffice for most formats).
    filename : path-like, optional
        The file's name, whose extension is the fall-back.

    Returns
    -------
    str
        The registry name.

    Raises
    ------
    SurfmetFormatError
        If neither the content nor the extension identifies a registered format.

    See Also
    --------
    read, formats

    Examples
    --------
    >>> from surfmet.io import detect_format
    >>> from surfmet.data import path
    >>> detect_format(path("paper_plate.x3p").read_bytes())
    'x3p'
    >>> detect_format(b"", "scan.unknown-extension")
    Traceback (most recent call last):
    ...
    surfmet._errors.SurfmetFormatError: ...
    """
    _load_all()
    for spec in sorted(_FORMATS.values(), key=lambda s: s.priority):
        if spec.magic is None or spec.decode is None:
            continue
        try:
            if spec.magic(buf):
                return spec.name
        except Exception:
            continue
    suffixes = [s.lower().lstrip(".") for s in Path(str(filename)).suffixes]
    for ext in reversed(suffixes):
        for spec in _FORMATS.values():
            if ext in spec.extensions and spec.decode is not None:
                return spec.name
    names = ", ".join(sorted(_FORMATS))
    raise SurfmetFormatError(
        f"{filename or '<bytes>'}: unknown file format (no known signature, extension "
        f"{''.join(Path(str(filename)).suffixes) or 'none'}); pass format= one of: {names}"
    )


# Exceptions that a damaged file can provoke inside a decoder. Anything else is a bug in
# surfmet and must surface as such.
_DAMAGE = (
    ValueError,
    IndexError,
    KeyError,
    struct.error,
    zipfile.BadZipFile,
    zlib.error,
    EOFError,
    UnicodeError,
    OverflowError,
    MemoryError,
    TypeError,
    AttributeError,
    LookupError,
    ArithmeticError,
    RecursionError,
    NotImplementedError,  # e.g. a zip member with an unknown compression method
    OSError,
)


def read_bytes(
    buf: bytes, format: str | None = None, name: str = "<bytes>", **options: Any
) -> Scan:
    """Decode a scan held in memory. See :func:`read`.

    Parameters
    ----------
    buf : bytes-like
        The file's content.
    format : str, optional
        Registry name; by default detected from the bytes, then from ``name``'s extension.
    name : str
        A name for messages (and the extension fall-back).
    **options
        As for :func:`read`.

    Returns
    -------
    Topography or Profile
        Heights in metres, NaN where not measured, ``metadata["format"]`` set.

    Raises
    ------
    SurfmetFormatError
        Empty, unknown, truncated or inconsistent content.
    SurfmetInputError
        ``buf`` is not a bytes-like object.

    See Also
    --------
    read : the same from a file.

    Examples
    --------
    >>> from surfmet.io import read_bytes
    >>> from surfmet.data import path
    >>> scan = read_bytes(path("paper_ball.x3p").read_bytes(), name="ball.x3p")
    >>> scan.shape, scan.metadata["format"]
    ((152, 147), 'x3p')
    """
    _load_all()
    if not isinstance(buf, (bytes, bytearray, memoryview)):
        raise SurfmetInputError("read_bytes needs a bytes object")
    buf = bytes(buf)
    if len(buf) == 0:
        raise SurfmetFormatError(f"{name}: the file is empty")
    fmt = format or detect_format(buf, name)
    spec = _FORMATS.get(fmt)
    if spec is None or spec.decode is None:
        raise SurfmetFormatError(f"{name}: no reader for format {fmt!r}; known: {sorted(_FORMATS)}")
    stated = take_generic_options(spec.name, spec.decode, options, name)
    check_options(spec.name, spec.decode, options)
    from surfmet.io._calibration import UnitContradiction

    try:
        scan = spec.decode(buf, name, **options)
    except (SurfmetFormatError, UnitContradiction):
        raise
    except SurfmetError as exc:
        raise SurfmetFormatError(f"{name}: inconsistent {fmt} file: {exc}") from exc
    except MemoryError as exc:
        # the decoders refuse sizes the bytes cannot hold before allocating, so this is a
        # valid file larger than the memory left, not damage
        raise SurfmetFormatError(
            f"{name}: not enough memory to decode this {fmt} file ({exc or 'MemoryError'}); "
            "free memory or crop the scan") from exc
    except _DAMAGE as exc:
        raise SurfmetFormatError(
            f"{name}: corrupted or truncated {fmt} file ({type(exc).__name__}: {exc})"
        ) from exc
    if isinstance(scan, (Topography, Profile)) and stated:
        from surfmet.io._calibration import state_units

        scan = state_units(scan, name, **stated)
    return _validated(scan, fmt, name)


def _validated(scan: Any, fmt: str, name: str) -> Scan:
    if not isinstance(scan, (Topography, Profile)):
        raise SurfmetFormatError(f"{name}: the {fmt} reader returned no scan")
    values = scan.heights if isinstance(scan, Topography) else scan.z
    if values.size == 0:
        raise SurfmetFormatError(f"{name}: the file holds zero points")
    finite = np.isfinite(values)
    if not finite.any():
        raise SurfmetFormatError(f"{name}: every point of the scan is non-measured (all NaN)")
    if np.isinf(values).any():
        raise SurfmetFormatError(f"{name}: the scan holds infinite heights")
    md = dict(scan.metadata)
    # flagged, not refused: the file still reads (and writes back exactly), every analysis
    # refuses it (surfmet._model.require_measurement). Heights in no stated unit are
    # numbers, not metres: only the numeric limit applies to them.
    uncalibrated = md.get("units_missing") or md.get("height_unit") == ""
    span = height_span_error(values, MAX_NUMERIC_SPAN if uncalibrated else MAX_HEIGHT_SPAN)
    if span is not None:
        md["height_range"] = (f"{name}: {span}: the file is damaged (one flipped exponent bit "
                              "turns 2 µm into 1e302 m) or its height unit is wrong (for a "
                              "file that states none, give it: height_unit=)")
    md.setdefault("format", fmt)
    return scan.replace(metadata=md)


def read(source: Source, format: str | None = None, **options: Any) -> Scan:
    """Read a scan from a file, from its bytes or from a binary stream.

    Parameters
    ----------
    source : path-like, bytes or binary file-like object
        The file; or its content (``bytes``, ``bytearray``, ``memoryview``); or an object
        with a ``read()`` that returns bytes (an open file, ``io.BytesIO``, an upload), read
        from its current position to its end. The format is detected from the bytes' magic
        signature; failing that, from the extension of the file's or the stream's
        ``name``. Bytes and nameless streams have no extension: give ``format=`` for the
        formats without a signature (text matrices and columns, see :func:`formats`).
    format : str, optional
        Registry name; overrides detection (see :func:`formats`).
    **options
        Passed to the format's reader (for example ``channel=`` for multi-channel files;
        refused by a single-channel format). Every format takes ``height_unit=`` (the unit
        of the file's height numbers) and ``dx=`` / ``dy=`` (the pixel, m) for a file that
        does not state them: the scan then records them as stated by the user
        (:class:`surfmet._model.Calibration`); a file that states a different one refuses
        them (:mod:`surfmet.io._calibration`).

    Returns
    -------
    Topography or Profile
        Heights in metres, NaN where not measured, ``metadata["format"]`` set;
        ``metadata["source"]`` is the path (or the stream's name) the scan was read from.

    Raises
    ------
    SurfmetFormatError
        Unknown format, unreadable, truncated, corrupted or inconsistent file, zero points
        or all points non-measured. The message names the file (``<bytes>``, or the
        stream's name or ``<stream>``) and the problem.
    SurfmetInputError
        A source that is none of the above (a text-mode stream, a number...).

    See Also
    --------
    read_bytes : the same from bytes in memory.
    formats : the formats known.
    surfmet.read : the same, at the package's top level.

    References
    ----------
    .. [1] ISO 25178-72:2017, Geometrical product specifications (GPS) -- Surface texture:
       Areal -- Part 72: XML file format x3p.

    Examples
    --------
    >>> from surfmet.io import read
    >>> from surfmet.data import path
    >>> plate = read(path("paper_plate.x3p"))
    >>> plate.shape, plate.metadata["format"]
    ((512, 1024), 'x3p')
    >>> print(f"Sq = {plate.heights.std() * 1e6:.3f} µm")
    Sq = ... µm
    """
    buf, name, source_name = source_bytes(source)
    scan = read_bytes(buf, format=format, name=name, **options)
    return scan.with_metadata(source=source_name) if source_name else scan
