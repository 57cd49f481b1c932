"""The Hertz-check section of the report (:mod:`surfmet.report`): its inputs, the call to
:func:`surfmet.mechanics.hertz_check.hertz_check`, the radial pressure figure and the HTML."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._report_html import esc, figure_png, figures_html, kv_table, quantity_text
from surfmet.units import format_quantity


@dataclass(frozen=True)
class HertzOptions:
    """Inputs of the Hertz-check section (SI): ball radius (m), load (N), the materials as
    ``"BALL,PLATE"`` (names with optional ``:E=..:nu=..:H=..``), and an optional ball scan
    (a path, or a Topography already read)."""

    radius: float
    load: float
    materials: str
    ball: Any = None


def hertz_check_available() -> bool:
    """True when :mod:`surfmet.mechanics.hertz_check` can be imported."""
    import importlib.util

    return importlib.util.find_spec("surfmet.mechanics.hertz_check") is not None


def run_hertz_check(scan: Any, hz: HertzOptions) -> dict[str, Any]:
    """Call :func:`surfmet.mechanics.hertz_check.hertz_check` on a plate scan;
    its record (:func:`surfmet.records._hertz.hertz_check_record`).

    This is the one place the report touches the Hertz-check module.
    """
    try:
        from surfmet.mechanics.hertz_check import hertz_check
    except ImportError:
        raise SurfmetInputError(
            "the Hertz check is not available in this installation (surfmet.mechanics.hertz_check "
            "is missing); run the report without --radius/--load/--materials"
        ) from None
    import surfmet

    # a path, or the scan the command read with the user's units (--ball-pixel...)
    ball = surfmet.read(hz.ball) if isinstance(hz.ball, (str, Path)) else hz.ball
    from surfmet.records._hertz import hertz_check_record

    res = hertz_check(scan, radius=hz.radius, load=hz.load, materials=hz.materials, ball=ball)
    return hertz_check_record(res)


def _number(v: Any) -> Any:
    """A value of the Hertz-check JSON: ``{"value": v, "unit": u}`` or a bare number."""
    if isinstance(v, dict) and "value" in v:
        return v["value"]
    return v


def hertz_figure(check: dict[str, Any]) -> bytes | None:
    """The radial pressure figure (Hertz vs BEM) of a Hertz-check record, as PNG."""
    from surfmet.plots.contact import radial_pressure

    rp = check.get("radial_profile") or {}
    a0 = _number((check.get("hertz") or {}).get("a"))
    try:
        r, pb, ph = (np.asarray(_number(rp[k]), dtype=float) for k in ("r", "p_bem", "p_hertz"))
    except (KeyError, TypeError, ValueError):
        return None
    if a0 is None or r.size < 2:
        return None
    return figure_png(radial_pressure(r, pb, ph, float(a0)))


# Hertz's quantity and the boundary elements' answer to the same question, side by side,
# as ``surfmet hertz-check`` prints them: (row name, Hertz key or a fixed Hertz value, BEM
# key). Hertz's a is the radius of the loaded disc, so beside it goes the BEM's a* (the
# second-moment radius of the pressure, the same question); the radius of the real contact
# area (asperity spots only) answers another one and gets its own row.
PAIRS = (
    ("peak pressure (p0 / pmax)", "p0", "pmax"),
    ("contact radius (a / a*, second moment of the pressure)", "a", "effective_radius"),
    ("approach (δ / approach)", "delta", "approach"),
    ("area / πa0²", 1.0, "area_fraction"),
    ("yielded area / πa0²", 0.0, "plastic_fraction"),
)
#: BEM quantities without a Hertz counterpart: (row name, BEM key)
BEM_ONLY = (("radius of the real contact area √(A/π)", "contact_radius"),)


def _is_quantity(q: Any) -> bool:
    return isinstance(q, dict) and "value" in q


def _comparison_rows(hertz: dict[str, Any], bem: dict[str, Any]) -> list[str]:
    """Table rows: each Hertz quantity beside the BEM's answer to the same question and
    their relative difference, then the BEM's quantities that Hertz has no counterpart of."""
    rows = []

    def row(name: str, h: Any, b: Any) -> str:
        # h: a record's quantity, or Hertz's own ratio (a float: 1 for the area, 0 yielded)
        hv = h if isinstance(h, float) else h["value"] if _is_quantity(h) else None
        htext = format_quantity(h, "") if isinstance(h, float) else quantity_text(h)
        diff = ""
        if hv and _is_quantity(b) and b["value"] is not None:
            diff = f"{100 * (b['value'] / hv - 1):+.1f} %"
        return (f"<tr><td>{esc(name)}</td><td>{esc(htext)}</td>"
                f"<td>{esc(quantity_text(b))}</td><td>{esc(diff)}</td></tr>")

    for name, hkey, bkey in PAIRS:
        fixed = not isinstance(hkey, str)  # Hertz's value itself, a ratio
        h = hkey if fixed else hertz.get(hkey, "")
        b = bem.get(bkey, "")
        if _is_quantity(b) or (not fixed and _is_quantity(h)):
            rows.append(row(name, h, b))
    for name, bkey in BEM_ONLY:
        if _is_quantity(bem.get(bkey)):
            rows.append(row(name, "—", bem[bkey]))
    return rows


def hertz_html(check: dict[str, Any], fig: bytes | None, hz: HertzOptions | None) -> str:
    holds = check.get("hertz_holds")
    if check.get("judged") is False:  # the scan's pixel does not resolve the contact
        holds = None
    verdict = ('<span class="ok">Hertz holds</span>' if holds else
               '<span class="error">Hertz does not hold</span>' if holds is not None else
               "no verdict: the scan's pixel does not resolve the contact"
               if check.get("judged") is False else "no verdict")
    parts = ["<h3>Hertz check</h3>", f'<p class="verdict">{verdict}'
             f" (α = {esc(quantity_text(check.get('alpha')))})</p>"]
    if hz is not None:
        parts.append(kv_table([("ball radius", format_quantity(float(hz.radius), "m")),
                                ("load", f"{hz.load:.5g} N"), ("materials", hz.materials),
                                ("ball scan", hz.ball or "none (smooth ball)")]))
    grid = check.get("grid")
    if grid:  # the grid and pixel the answer was computed on, as the CLI states them
        parts.append(kv_table([("contact grid", f"{grid['nx']} × {grid['ny']} cells, pixel "
                                 f"{quantity_text(grid['dx'])} ({grid.get('pixel_source', '')})")]))
    reasons = check.get("reasons") or []
    if reasons:
        parts.append("<ul>" + "".join(f"<li>{esc(r)}</li>" for r in reasons) + "</ul>")
    rows = _comparison_rows(check.get("hertz") or {}, check.get("bem") or {})
    if rows:
        parts.append('<table class="hertz"><tr><th>quantity</th><th>Hertz</th>'
                     "<th>boundary elements</th><th>difference</th></tr>"
                     + "".join(rows) + "</table>")
    if fig is not None:
        parts.append(figures_html([("radial pressure: Hertz against boundary elements",
                                     fig)]).replace("<h3>Pictures</h3>", ""))
    return "".join(parts)
