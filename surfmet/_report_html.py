"""HTML building blocks of the report (:mod:`surfmet.report`): escaped text, PNG pictures as
``data:`` URIs, key-value tables, quantity text and the figure strip."""

from __future__ import annotations

import base64
import html
import io
from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError


def esc(value: Any) -> str:
    """HTML-escaped text of any value (quotes too, so it is safe in attributes), valid
    Unicode (:func:`surfmet.units.valid_text`: a file name that is not UTF-8)."""
    from surfmet.units import valid_text

    return html.escape(valid_text(str(value)), quote=True)


def png_data_uri(png: bytes) -> str:
    """``data:image/png;base64,...`` for PNG bytes."""
    if not png.startswith(b"\x89PNG\r\n\x1a\n"):
        raise SurfmetInputError("not a PNG image")
    return "data:image/png;base64," + base64.b64encode(png).decode("ascii")


def figure_png(fig: Any, dpi: int = 100) -> bytes:
    """PNG bytes of a matplotlib figure, which is then closed."""
    from surfmet.plots._style import close

    buf = io.BytesIO()
    try:
        fig.savefig(buf, format="png", dpi=dpi)
    finally:
        close(fig)
    return buf.getvalue()


def array_png(img: np.ndarray) -> bytes:
    """PNG bytes of an RGB(A) uint8 image array."""
    import matplotlib.image as mpimg

    buf = io.BytesIO()
    mpimg.imsave(buf, np.asarray(img), format="png")
    return buf.getvalue()


def kv_table(rows: Iterable[tuple[str, Any]], cls: str = "meta") -> str:
    body = "".join(f"<tr><td>{esc(k)}</td><td>{esc(v)}</td></tr>" for k, v in rows)
    return f'<table class="{cls}">{body}</table>'


def quantity_text(q: Any) -> str:
    """Human text of a ``{"value", "unit"}`` quantity
    (:func:`surfmet.units.format_quantity`)."""
    from surfmet.units import format_quantity

    if isinstance(q, dict) and "value" in q:
        v, u = q["value"], q.get("unit", "")
        if v is None:
            return "n/a"
        if isinstance(v, (int, float)) and not isinstance(v, bool):
            return format_quantity(float(v), u)
        return f"{v} {u}".rstrip()
    return str(q)


def figures_html(figs: Sequence[tuple[str, bytes]]) -> str:
    items = "".join(
        f'<figure><img alt="{esc(cap)}" src="{png_data_uri(png)}">'
        f"<figcaption>{esc(cap)}</figcaption></figure>" for cap, png in figs)
    return f'<h3>Pictures</h3><div class="figs">{items}</div>' if figs else ""
