"""The JSON record of one row of ``surfmet sweep`` (:mod:`surfmet.sweep`): every value
with a unit as ``{"value", "unit"}``, the others plain."""

from __future__ import annotations

from typing import Any

__all__ = ["sweep_row_record"]


def sweep_row_record(row: dict[str, tuple[Any, str]]) -> dict[str, Any]:
    """A row (``name -> (value, unit)``, unit ``""`` for plain values) as JSON.

    Examples
    --------
    >>> from surfmet.records._sweep import sweep_row_record
    >>> sweep_row_record({"load": (1.0, "N"), "status": ("ok", "")})
    {'load': {'value': 1.0, 'unit': 'N'}, 'status': 'ok'}
    """
    return {name: ({"value": v, "unit": u} if u else v) for name, (v, u) in row.items()}
