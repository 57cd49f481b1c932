"""What to do with a scan's spikes before a contact is built: the choice and the cleaning
(re-exported by :mod:`surfmet.mechanics.scan_preparation`, where every facade takes them)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from surfmet._errors import SurfmetInputError

if TYPE_CHECKING:
    from surfmet._model import Topography
    from surfmet.mechanics._types import Spikes

#: The spike choices, the default first.
SPIKE_CHOICES = ("remove", "keep")
#: The default: spikes are removed before any contact is built.
SPIKES = SPIKE_CHOICES[0]


def spike_mode(spikes: Spikes) -> str:
    """``"remove"`` or ``"keep"`` from the text or a flag (True: remove, False: keep).

    Parameters
    ----------
    spikes : str or bool
        ``"remove"``, ``"keep"``, True (remove) or False (keep).

    Returns
    -------
    str
        ``"remove"`` or ``"keep"``.

    Raises
    ------
    SurfmetInputError
        Any other value.

    Examples
    --------
    >>> from surfmet.mechanics.scan_preparation import spike_mode
    >>> spike_mode(True), spike_mode("keep")
    ('remove', 'keep')
    """
    if isinstance(spikes, bool):
        return "remove" if spikes else "keep"
    if spikes in SPIKE_CHOICES:
        return str(spikes)
    raise SurfmetInputError(f"spikes must be one of {', '.join(SPIKE_CHOICES)}, got {spikes!r}")


def clean_spikes(scan: Topography, what: str, spikes: Spikes = SPIKES
                 ) -> tuple[Topography, int, str | None]:
    """The scan with its spikes removed (``spikes="remove"``) or as measured (``"keep"``):
    the scan, the number of spikes removed, and a note saying what was done.

    Parameters
    ----------
    scan : Topography
        The scan.
    what : str
        Its role, for the note.
    spikes : {"remove", "keep"} or bool
        What to do.

    Returns
    -------
    (Topography, int, str or None)
        The scan, the number of spikes removed and the note.

    See Also
    --------
    surfmet._spikes : the spike detector.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.scan_preparation import clean_spikes
    >>> scan, n, note = clean_spikes(surfmet.read(path("paper_plate.x3p")), "plate")
    >>> n, note
    (60, '60 spike(s) removed from the plate scan (60 points made non-measured)')
    """
    if spike_mode(spikes) == "keep":
        return scan, 0, f"spikes kept in the {what} scan (--spikes keep)"
    from surfmet._spikes import remove_spikes

    new, report = remove_spikes(scan)
    if not report.count:
        return new, 0, None
    return new, int(report.count), (f"{report.count} spike(s) removed from the {what} scan "
                                    f"({report.n_points} points made non-measured)")
