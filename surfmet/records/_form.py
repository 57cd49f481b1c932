"""The JSON record of a form removal (:class:`surfmet.areal._form.FormFit`): the method, the
residual rms, the polynomial's coefficients or the sphere's or cylinder's shape, each
dimensional value with its unit."""

from __future__ import annotations

from typing import Any

__all__ = ["form_record", "shape_record"]


def shape_record(shape: dict[str, Any]) -> dict[str, Any]:
    """A sphere's or cylinder's shape parameters (SI), each with its unit
    (:data:`surfmet.areal._form.SHAPE_UNITS`), the flags as they are."""
    from surfmet.areal._form import SHAPE_UNITS

    return {k: {"value": v, "unit": SHAPE_UNITS[k]} if k in SHAPE_UNITS else v
            for k, v in shape.items()}


def form_record(fit: Any) -> dict[str, Any]:
    """What form was removed, as JSON (values SI; lengths in metres).

    Examples
    --------
    >>> from surfmet.data import path
    >>> from surfmet.io import read
    >>> from surfmet.areal._form import remove_form
    >>> from surfmet.records._form import form_record
    >>> rec = form_record(remove_form(read(path("paper_ball.x3p")), "sphere")[1])
    >>> rec["method"], rec["shape"]["radius"]["unit"]
    ('sphere', 'm')
    """
    out: dict[str, Any] = {"method": fit.method,
                           "residual_rms": {"value": fit.residual_rms, "unit": "m"},
                           "n_points": fit.n_points}
    if fit.terms:
        out["coefficients"] = dict(zip(fit.terms, fit.coefficients))
    if fit.shape:
        out["shape"] = shape_record(fit.shape)
    return out
