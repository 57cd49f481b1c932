"""JSON records of what was done to the scans before a contact or a spectrum: spikes,
filled points, notes (:mod:`surfmet.mechanics.scan_preparation`)."""

from __future__ import annotations

from typing import Any

from surfmet.units import quantity

__all__ = ["flat_preparation_record", "preparation_record"]


def preparation_record(prep: Any) -> dict[str, Any]:
    """What was done to a plate and a ball scan, for the output.

    Parameters
    ----------
    prep : surfmet.mechanics.scan_preparation.PreparedScans
        The prepared scans.

    Returns
    -------
    dict
        ``spikes``, ``spikes_removed``, ``filled_fraction`` (a ratio) and ``notes``.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.scan_preparation import prepare_scans
    >>> from surfmet.records._preparation import preparation_record
    >>> preparation_record(prepare_scans(surfmet.read(path("paper_plate.x3p"))))["spikes"]
    'remove'
    """
    return {"spikes": prep.spikes, "spikes_removed": dict(prep.spikes_removed),
            "filled_fraction": quantity(prep.filled_fraction, ""),
            "notes": list(prep.notes)}


def flat_preparation_record(prep: Any) -> dict[str, Any]:
    """What was done to the one scan of a flat contact or a spectrum, for the output.

    Parameters
    ----------
    prep : surfmet.mechanics.scan_preparation.FlatPreparation
        What :func:`~surfmet.mechanics.scan_preparation.prepare_flat` did (and the
        levelling, once levelled).

    Returns
    -------
    dict
        ``spikes``, ``spikes_removed``, ``filled_fraction``, ``notes`` and, once levelled,
        ``levelling``.

    Examples
    --------
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.spectrum import prepared_scan
    >>> from surfmet.records._preparation import flat_preparation_record
    >>> rec = flat_preparation_record(prepared_scan(path("paper_plate.x3p"))[3])
    >>> rec["spikes_removed"], rec["levelling"]
    ({'scan': 60}, 'mean')
    """
    rec: dict[str, Any] = {"spikes": prep.spikes, "spikes_removed": dict(prep.spikes_removed),
                           "filled_fraction": quantity(prep.filled_fraction, ""),
                           "notes": list(prep.notes)}
    if prep.levelling is not None:
        rec["levelling"] = prep.levelling
    return rec
