"""How a scan becomes a contact's roughness: one preparation, one set of defaults, for every
command and API entry point that builds a contact from a scan (``contact``, ``hertz-check``,
``flat-contact``, ``rolling``, ``sweep``, the report, the demo and the facades in
:mod:`surfmet.mechanics`).

1. Spikes (:data:`SPIKES`, ``"remove"`` by default): optical outliers are not asperities.
   A single 50 µm spike carries newtons in an elastic solution and pushes the peak pressure
   above the composite modulus; :func:`surfmet._spikes.remove_spikes` turns them into
   non-measured points. ``"keep"`` leaves the scan as measured.
2. The plate is levelled, the ball's best-fit sphere removed, both paired on one grid and
   the non-measured points filled with the nearest measured value
   (:func:`surfmet.mechanics.pairing.prepare_pair`).

Every result built this way states what was done (its record is
:func:`surfmet.records._preparation.preparation_record`).
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.mechanics._spike_choice import SPIKE_CHOICES as SPIKE_CHOICES
from surfmet.mechanics._spike_choice import SPIKES as SPIKES
from surfmet.mechanics._spike_choice import clean_spikes as clean_spikes
from surfmet.mechanics._spike_choice import spike_mode as spike_mode

if TYPE_CHECKING:
    from surfmet.mechanics._types import ScanSource, Spikes
    from surfmet.mechanics.pairing import PairedRoughness

#: The largest automatic contact grid, for every entry point (CLI, API, report, sweep):
#: None runs on the scans' own pixel at any size that fits in memory, so that two ways of
#: asking the same question get the same grid.
MAX_GRID: int | None = None

def pixel_source(dx: float, pair: PairedRoughness | None, grid: int | None) -> str:
    """Where a contact grid's pixel came from, for the output.

    Parameters
    ----------
    dx : float
        The grid's pixel (m).
    pair : PairedRoughness or None
        The paired scans.
    grid : int or None
        The user's grid, if any.

    Returns
    -------
    str
        A few words for the output.

    Examples
    --------
    >>> from surfmet.mechanics.scan_preparation import pixel_source
    >>> pixel_source(5e-6, None, 64)
    '--grid 64'
    """
    if grid is not None:
        return f"--grid {grid}"
    if pair is not None and abs(dx - pair.dx) <= 1e-9 * pair.dx:
        return "the scans' own pixel"
    if pair is not None:
        return "finer than the scans' pixel: 16 cells per Hertz radius"
    return "automatic, smooth ball"


def read_areal(obj: ScanSource | None, what: str) -> Topography | None:
    """The scan of the ``what`` (a Topography, or a file read with :func:`surfmet.read`).

    Parameters
    ----------
    obj : Topography, path or None
        The scan or its file.
    what : str
        ``"plate"``, ``"ball"``..., for the messages.

    Returns
    -------
    Topography or None
        The scan (None for None).

    Raises
    ------
    SurfmetFormatError, SurfmetInputError
        An unreadable file, or a profile where an areal scan is needed.

    Examples
    --------
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.scan_preparation import read_areal
    >>> read_areal(path("paper_ball.x3p"), "ball").shape, read_areal(None, "ball")
    ((152, 147), None)
    """
    if obj is None:
        return None
    scan: object = obj
    if isinstance(obj, (str, os.PathLike, Path)):
        import surfmet

        scan = surfmet.read(obj)
    if not isinstance(scan, Topography):
        kind = getattr(scan, "kind", type(scan).__name__)
        whose = "" if what == "scan" else f" of the {what}"
        raise SurfmetInputError(f"a contact needs an areal scan (a height map){whose}, got "
                                f"a {kind}: give a map, not a single profile")
    return scan


@dataclass(frozen=True, eq=False)
class PreparedScans:
    """Scans made ready for the contact engine.

    Attributes
    ----------
    pair : PairedRoughness or None
        Composite roughness on one grid (None: two smooth bodies).
    sigma, sigma_plate, sigma_ball : float
        Combined rms roughness and its parts (m), from the measured points (0 for a
        surface not given).
    notes : tuple of str
    spikes_removed : dict
        Spikes removed per scan (counts).
    residuals : dict
        Each scan's own form residual (plane for the plate, sphere for the ball).
    spikes : str
        ``"remove"`` or ``"keep"``.

    See Also
    --------
    prepare_scans : makes it.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.scan_preparation import prepare_scans
    >>> prep = prepare_scans(surfmet.read(path("paper_plate.x3p")))
    >>> print(f"sigma = {prep.sigma * 1e6:.2f} µm", prep.spikes_removed)
    sigma = 2.28 µm {'plate': 60}
    """

    pair: PairedRoughness | None
    sigma: float
    sigma_plate: float
    sigma_ball: float
    notes: tuple[str, ...]
    spikes_removed: dict[str, int]
    residuals: dict[str, Topography] = field(default_factory=dict)
    spikes: str = SPIKES

    @property
    def filled_fraction(self) -> float | None:
        """The fraction of the paired grid that was not measured (None: no scans)."""
        return None if self.pair is None else self.pair.filled_fraction

    def paired(self) -> PairedRoughness:
        """``pair``, for a computation that needs the scans' roughness.

        Raises
        ------
        SurfmetInputError
            No scan was given (two smooth bodies: ``pair`` is None).
        """
        if self.pair is None:
            raise SurfmetInputError("this needs a scan (a plate or a ball): with two smooth "
                                    "bodies there is no roughness to pair")
        return self.pair


@dataclass(frozen=True, eq=False)
class FlatPreparation:
    """What was done to a single scan for a flat contact or a spectrum.

    Attributes
    ----------
    spikes : str
        ``"remove"`` or ``"keep"``.
    spikes_removed : dict
        Spikes removed (``{"scan": count}``).
    filled_fraction : float
        Fraction of the scan not measured and filled with the nearest measured value.
    notes : tuple of str
    levelling : str or None
        The levelling applied afterwards (:func:`surfmet.mechanics.spectrum.prepare`),
        None before it.

    See Also
    --------
    prepare_flat : makes it.
    surfmet.records._preparation.flat_preparation_record : its record.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.scan_preparation import prepare_flat
    >>> _, done = prepare_flat(surfmet.read(path("paper_plate.x3p")))
    >>> done.spikes, done.spikes_removed, done.levelling
    ('remove', {'scan': 60}, None)
    """

    spikes: str
    spikes_removed: dict[str, int]
    filled_fraction: float
    notes: tuple[str, ...]
    levelling: str | None = None


@dataclass(frozen=True, eq=False)
class ScansUsed:
    """The scans an adhesive run was sampled from, and the roughness on its grid.

    Attributes
    ----------
    prep : PreparedScans
        The prepared scans.
    plate, ball : Topography, path or None
        The scans as given.
    dx : float
        The solver's pixel (m).
    z : ndarray
        The roughness on the solver's grid (m).
    profile : str or None
        For a line contact, which profile of the plate was used.

    See Also
    --------
    surfmet.mechanics.adhesion.rough_grid : makes it.
    surfmet.records._adhesion.scans_record : its record.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.adhesion import rough_grid
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy)
    >>> _, used = rough_grid(patch, None, 32, 3e-4)
    >>> used.plate_name, used.ball_name, used.z.shape
    ('(in memory)', None, (32, 32))
    """

    prep: PreparedScans
    plate: ScanSource | None
    ball: ScanSource | None
    dx: float
    z: np.ndarray
    profile: str | None = None

    @property
    def plate_name(self) -> str | None:
        """The plate's file name, "(in memory)" for a Topography, None when not given."""
        return scan_name(self.plate)

    @property
    def ball_name(self) -> str | None:
        """The ball's file name, "(in memory)" for a Topography, None when not given."""
        return scan_name(self.ball)

    @property
    def roughness_rms(self) -> float:
        """The rms of the roughness on the solver's grid (m)."""
        z = self.z
        return float(math.sqrt(float(((z - z.mean()) ** 2).mean())))

    @property
    def notes(self) -> list[str]:
        """The preparation's notes, and one when the solver's pixel is finer than the
        scans' (the roughness is then interpolated)."""
        pair = self.prep.paired()
        notes = list(self.prep.notes)
        if self.dx < pair.dx * (1 - 1e-9):
            notes.append(f"the solver's pixel ({self.dx * 1e9:.4g} nm) is finer than the "
                         f"scans' ({pair.dx * 1e9:.4g} nm): the roughness is interpolated "
                         "between measured points")
        return notes


def scan_name(scan: ScanSource | None) -> str | None:
    """A scan's file name, "(in memory)" for a Topography, None when not given.

    Parameters
    ----------
    scan : Topography, path or None
        A scan as given.

    Returns
    -------
    str or None
        Its file (the one it was read from, for a Topography), or "(in memory)".

    Examples
    --------
    >>> from surfmet.mechanics.scan_preparation import scan_name
    >>> scan_name("plate.x3p"), scan_name(None)
    ('plate.x3p', None)
    """
    if scan is None:
        return None
    if isinstance(scan, Topography):  # read by the caller: its file, when it has one
        return scan.metadata.get("source") or "(in memory)"
    return str(scan)


def prepare_scans(plate: ScanSource | None = None, ball: ScanSource | None = None, *,
                  spikes: Spikes = SPIKES) -> PreparedScans:
    """Spikes, levelling, sphere removal and pairing of a plate and a ball scan.

    Parameters
    ----------
    plate, ball : Topography or path, optional
        The scans (either, both or none).
    spikes : {"remove", "keep"} or bool
        Remove spikes (:func:`surfmet._spikes.remove_spikes`) from each scan first (they
        become non-measured points), or keep them. True means "remove".

    Returns
    -------
    PreparedScans
        The paired roughness, the rms roughness of each scan and of the pair, the notes and
        the spikes removed.

    See Also
    --------
    surfmet.mechanics.pairing.prepare_pair : the pairing step.
    prepare_flat : one scan for a flat contact.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.scan_preparation import prepare_scans
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> prep = prepare_scans(plate, surfmet.read(path("paper_ball.x3p")))
    >>> print(f"sigma = {prep.sigma * 1e6:.2f} µm (plate {prep.sigma_plate * 1e6:.2f} µm)")
    sigma = 2.42 µm (plate 2.28 µm)
    >>> print(prep.notes[3])
    ball: best-fit sphere of radius 19.956 mm removed, residual mirrored in x
    """
    from surfmet.areal._form import remove_form
    from surfmet.mechanics.pairing import prepare_pair

    mode = spike_mode(spikes)
    plate = read_areal(plate, "plate")
    ball = read_areal(ball, "ball")
    if plate is None and ball is None:
        return PreparedScans(None, 0.0, 0.0, 0.0, ("no scan: smooth surfaces",), {},
                             spikes=mode)
    notes: list[str] = []
    removed: dict[str, int] = {}
    cleaned: dict[str, Topography | None] = {"plate": plate, "ball": ball}
    from surfmet.roughness import unit_caveats

    for name, scan in (("plate", plate), ("ball", ball)):
        if scan is not None:
            # what the file does not state about its units reaches every result built on it
            notes.extend(f"CAVEAT ({name} scan): {c}" for c in unit_caveats(scan))
            cleaned[name], removed[name], note = clean_spikes(scan, name, mode)
            if note:
                notes.append(note)
    plate, ball = cleaned["plate"], cleaned["ball"]
    pair = prepare_pair(plate, ball)
    notes.extend(pair.notes)
    # each surface's own residual, for its spectrum (summit parameters)
    residuals = {name: remove_form(scan, form)[0]
                 for name, scan, form in (("plate", plate, "plane"), ("ball", ball, "sphere"))
                 if scan is not None}
    s_plate = s_ball = 0.0
    if "plate" in pair.fits:
        s_plate = float(pair.fits["plate"].residual_rms)
    if "ball" in pair.fits:
        s_ball = float(pair.fits["ball"].residual_rms)
    return PreparedScans(pair=pair, sigma=math.hypot(s_plate, s_ball), sigma_plate=s_plate,
                         sigma_ball=s_ball, notes=tuple(notes), spikes_removed=removed,
                         residuals=residuals, spikes=mode)


def prepare_flat(topo: ScanSource, *,
                 spikes: Spikes = SPIKES) -> tuple[Topography, FlatPreparation]:
    """A single scan made ready for a flat contact: spikes as :func:`prepare_scans` does
    them, then every non-measured point filled with its nearest measured value.

    Returns the scan and what was done to it.

    Parameters
    ----------
    topo : Topography or path
        The scan.
    spikes : {"remove", "keep"} or bool
        Spike handling.

    Raises
    ------
    SurfmetFormatError, SurfmetInputError
        An unreadable file or an unusable scan.

    See Also
    --------
    prepare_scans

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.scan_preparation import prepare_flat
    >>> scan, record = prepare_flat(surfmet.read(path("paper_plate.x3p")))
    >>> bool(scan.has_nan), record.spikes_removed
    (False, {'scan': 60})
    """
    from surfmet.mechanics.pairing import fill_nearest

    mode = spike_mode(spikes)
    scan = read_areal(topo, "scan")
    if scan is None:
        raise SurfmetInputError("give a scan (a height map or its file)")
    if not np.isfinite(scan.heights).any():
        raise SurfmetInputError("the scan has no measured point")
    scan, count, note = clean_spikes(scan, "areal", mode)
    notes = [note] if note else []
    z, filled = fill_nearest(np.asarray(scan.heights, dtype=float))
    frac = float(filled.mean())
    if frac > 0:
        notes.append(f"{100 * frac:.3g} % of the scan not measured; filled with the nearest "
                     "measured value")
        scan = scan.replace(heights=z)
    return scan, FlatPreparation(spikes=mode, spikes_removed={"scan": count},
                                 filled_fraction=frac, notes=tuple(notes))
