"""What a file holds, as ``surfmet info`` states it: the scan's record and, for a file of
several channels or a container of several measurements, each of them read on its own.

One home for the record, so that ``info --json`` and the report's info section (and any
other entry point that states what a file is) give the same answer.
"""

from __future__ import annotations

import os
from typing import Any

from surfmet._errors import SurfmetError

__all__ = ["channel_choices", "channel_listing", "info_record"]


def channel_choices(scan: Any) -> list[tuple[Any, str]]:
    """(what ``channel=`` takes, a label) for each channel the file holds, or [] for a
    file of one channel."""
    names = scan.metadata.get("channels")
    if not isinstance(names, (list, tuple)) or len(names) < 2:
        return []
    out = []
    for i, entry in enumerate(names):
        if isinstance(entry, dict):  # Gwyddion: numbered channels with a title
            out.append((entry.get("number", i), str(entry.get("title") or "untitled")))
        else:
            out.append((i, str(entry)))
    return out


def channel_listing(path: str | os.PathLike, scan: Any, format: str | None = None,
                    read_options: dict[str, Any] | None = None
                    ) -> list[tuple[Any, str, Any, str | None]]:
    """Every channel (or container measurement) of the file at ``path``, each read on its
    own with ``read_options`` (less ``channel``): (choice, label, scan or None, error)."""
    import surfmet

    opts = {k: v for k, v in (read_options or {}).items() if k != "channel"}
    out = []
    for choice, label in channel_choices(scan):
        try:
            out.append((choice, label, surfmet.read(path, format=format, channel=choice,
                                                    **opts), None))
        except SurfmetError as exc:
            out.append((choice, label, None, str(exc)))
    return out


def info_record(path: str | os.PathLike, scan: Any, format: str | None = None,
                read_options: dict[str, Any] | None = None,
                listing: list[tuple[Any, str, Any, str | None]] | None = None
                ) -> dict[str, Any]:
    """The ``surfmet info --json`` record of ``scan`` (read from ``path``): its
    :func:`surfmet.records.scan_record` and, for several channels or measurements,
    ``channels_read`` (``listing``, when the caller already has it, else read here).

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.file_info import info_record
    >>> path = surfmet.data.path("paper_plate.x3p")
    >>> rec = info_record(path, surfmet.read(path))
    >>> rec["format"], rec["kind"]
    ('x3p', 'areal')
    """
    from surfmet.records._scans import channel_record, scan_record

    rec = scan_record(scan)
    if listing is None:
        listing = channel_listing(path, scan, format, read_options)
    if listing:
        rec["channels_read"] = [
            {"channel": c, "name": label, **({"error": err} if err else channel_record(s))}
            for c, label, s, err in listing]
    return rec
