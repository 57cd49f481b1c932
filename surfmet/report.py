"""One self-contained HTML report for one or several scans.

``write_report(paths, "report.html")`` writes a single file that opens anywhere, offline:
the style sheet is inline and every picture is a PNG embedded as a ``data:`` URI; the page
loads nothing and runs no script. All text from files (metadata, names, messages) is
HTML-escaped, so a scan whose metadata says ``<script>`` shows that text and runs nothing.

For each scan the report holds:

* the instrument metadata and the grid (as ``surfmet info`` reports them);
* the parameter table from :func:`surfmet.roughness.roughness`, called on the file with the
  options ``surfmet roughness`` takes (so a profile keeps the conditions its file states),
  each value with its unit
  (lengths in µm, Spd in 1/mm², Spc in 1/µm; the exact SI value is kept in the cell's
  ``data-si`` attribute), and the processing settings used (form removal, S/L filters
  with nesting indices and edge treatment, spikes, window, the full settings as JSON);
* pictures: the 3D view (:func:`surfmet._render.render_3d`), the height map, the
  Abbott–Firestone curve with the Sk construction, the PSD with its Hurst fit exactly as
  ``surfmet spectrum FILE`` gives it (:func:`surfmet.mechanics.spectrum.scan_spectrum`); for
  a profile, the primary / waviness / roughness figure instead of the two maps;
* when a ball radius, a load and the materials are given, the Hertz-check section
  (:mod:`surfmet.mechanics.hertz_check`): verdict, reasons, Hertz against boundary elements and the
  radial pressure profile.

A scan that cannot be read or evaluated (an internal error included) gets a section with
its error; the others go on. :meth:`ScanSection.summary` (``report --json``) carries every
number the page prints, in the records the commands emit: ``info`` (``surfmet info
--json``), ``roughness`` (one record of ``surfmet roughness --json``), ``spectrum``
(``surfmet spectrum --json``) and ``hertz_check`` (``surfmet hertz-check --json``).
"""

from __future__ import annotations

import datetime as _dt
import json
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from surfmet._errors import SurfmetInputError
from surfmet._report_figures import figures_areal, figures_profile, spectrum_section
from surfmet._report_hertz import HertzOptions, hertz_figure, hertz_html, run_hertz_check
from surfmet._report_html import (
    esc,
    figures_html,
    kv_table,
    quantity_text,
)
from surfmet.units import valid_text

if TYPE_CHECKING:
    from surfmet._measurements import Measurement

_CSS = """
body{font-family:system-ui,-apple-system,'Segoe UI',Roboto,sans-serif;margin:2em auto;
max-width:1200px;color:#222;padding:0 1em}
h1{font-size:1.6em;margin-bottom:.2em}h2{border-bottom:2px solid #4a7;padding-bottom:.2em;
margin-top:2em}h3{margin-top:1.4em}
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:.25em .6em;
text-align:left;vertical-align:top}th{background:#eef5ee}td.num{text-align:right;
font-variant-numeric:tabular-nums}
.figs{display:flex;flex-wrap:wrap;gap:1em}.figs figure{margin:0;flex:1 1 480px}
.figs img{max-width:100%;height:auto;border:1px solid #ddd}
figcaption{font-size:.85em;color:#555}.error{color:#a00;font-weight:bold}
.ok{color:#070;font-weight:bold}.meta td:first-child{white-space:nowrap;color:#555}
pre{background:#f6f6f6;padding:.6em;overflow:auto;font-size:.8em;max-height:30em}
.small{font-size:.85em;color:#555}.cols{display:flex;flex-wrap:wrap;gap:2em}
.cols>div:first-child{flex:0 0 auto}.cols>div:last-child{flex:1 1 420px;min-width:0}
"""


def display_value(value: Any, unit: str) -> tuple[str, str]:
    """``(number text, unit text)`` of an SI parameter value for the table."""
    from surfmet.units import split_quantity

    return split_quantity(value, unit, digits=5)


@dataclass
class ScanSection:
    """What the report shows for one scan (kept for the JSON summary and the tests)."""

    file: str
    status: str = "ok"
    error: str | None = None
    kind: str | None = None
    info: dict[str, Any] = field(default_factory=dict)
    parameters: dict[str, Any] = field(default_factory=dict)
    settings: dict[str, Any] = field(default_factory=dict)
    figures: list[tuple[str, bytes]] = field(default_factory=list)
    hertz: dict[str, Any] | None = None
    hertz_figure: bytes | None = None
    hertz_error: str | None = None
    #: the ``surfmet roughness --json`` record of the scan
    roughness: dict[str, Any] | None = None
    #: the ``surfmet spectrum --json`` record (areal scans), or ``{"error": message}``
    spectrum: dict[str, Any] | None = None
    #: the roughness profile's PSD fit the profile page draws (profiles)
    profile_psd: dict[str, Any] | None = None

    def summary(self) -> dict[str, Any]:
        """The ``report --json`` entry of the scan: every number its section prints, in
        the records the commands emit (see the module docstring)."""
        out: dict[str, Any] = {"file": self.file, "status": self.status}
        if self.info:
            out["info"] = self.info
        if self.error:
            out["error"] = self.error
            return out
        out["kind"] = self.kind
        out["figures"] = [name for name, _ in self.figures]
        out["roughness"] = self.roughness
        if self.spectrum is not None:
            out["spectrum"] = self.spectrum
        if self.profile_psd is not None:
            out["profile_psd"] = self.profile_psd
        out["hertz_check"] = self.hertz
        if self.hertz_error:
            out["hertz_error"] = self.hertz_error
        return out


# ---------------------------------------------------------------------------------------
# computing a section


def scan_section(path: str | Path | Measurement, options: dict[str, Any] | None = None, *,
                 include_3d: bool = True, hertz: HertzOptions | None = None,
                 read_options: dict[str, Any] | None = None) -> ScanSection:
    """Compute everything the report shows for one scan; errors end up in the section.

    Parameters
    ----------
    path : str, Path or surfmet._measurements.Measurement
        A scan file, or one measurement of a container (its section is named
        ``CONTAINER:MEMBER``, as the roughness command names its record).
    options : dict, optional
        Keyword arguments of :func:`surfmet.roughness.roughness` (level, ls, lc, window,
        profile, spikes, edge, standard, n_sampling, rk_line, valley_suppression,
        element_start), as ``surfmet roughness`` passes them.
    include_3d : bool
        Render the 3D view (pyvista) for areal scans.
    hertz : HertzOptions, optional
        Add the Hertz-check section.
    """
    import surfmet
    from surfmet._measurements import Measurement, read_measurement

    options = dict(options or {})
    sec = ScanSection(file=str(path))  # a container's measurement: CONTAINER:MEMBER
    try:
        if isinstance(path, Measurement):
            scan = read_measurement(path, **(read_options or {}))
        else:
            scan = surfmet.read(path, **(read_options or {}))  # --height-unit, --pixel...
        _evaluate(sec, scan, options, include_3d, read_options,
                  measurement=isinstance(path, Measurement))
    except Exception as exc:  # a failing scan (a bug too) is reported; the others go on
        sec.status, sec.error = "error", _error_text(exc)
        return sec
    if hertz is not None:
        # its own failure (no convergence, contact at the domain edge...) must not hide
        # the roughness part
        try:
            sec.hertz = run_hertz_check(scan, hertz)
            sec.hertz_figure = hertz_figure(sec.hertz)
        except Exception as exc:  # as above
            sec.hertz_error = _error_text(exc)
    return sec


def _error_text(exc: BaseException) -> str:
    """A scan's error as the page and the JSON state it: the message of a user error, and
    for anything else (a bug) that it is an internal error, as ``surfmet roughness`` rows
    say it."""
    from surfmet._errors import user_error_types

    if isinstance(exc, user_error_types()):
        return str(exc)
    return f"internal error: {type(exc).__name__}: {exc}"


def _evaluate(sec: ScanSection, scan: Any, options: dict[str, Any], include_3d: bool,
              read_options: dict[str, Any] | None = None, measurement: bool = False) -> None:
    """Fill ``sec`` from the functions the commands call: ``scan_record`` (info),
    :func:`surfmet.roughness.roughness` with the roughness command's options, and the
    spectrum command's :func:`surfmet.mechanics.spectrum.scan_spectrum`."""
    from surfmet.file_info import info_record
    from surfmet.roughness import roughness

    # a measurement's info is its own (the container's listing is the container's)
    sec.info = _jsonable(info_record(sec.file, scan, read_options=read_options,
                                     listing=[] if measurement else None))
    res = roughness(scan, **options)
    from surfmet.records._roughness import parameters_record, roughness_record

    sec.roughness = {"file": sec.file, "status": "ok", **roughness_record(res)}
    sec.kind = res.kind  # "profile" also for a row of an areal scan
    sec.parameters = parameters_record(res, plain=True)
    sec.settings = res.settings
    name = valid_text(Path(sec.file).name)
    if res.kind == "areal":
        sec.figures = figures_areal(res.surface, res.parameters, include_3d)
        sec.spectrum, fig = spectrum_section(scan, sec.file)
        if fig is not None:
            sec.figures.append(fig)
    else:
        sec.figures, sec.profile_psd = figures_profile(res.analysis, name)


# ---------------------------------------------------------------------------------------
# HTML


def _info_html(info: dict[str, Any]) -> str:
    rows = [("format", info.get("format")), ("kind", info.get("kind")),
            ("grid", f"{info.get('nx')} × {info.get('ny')}" if info.get("kind") == "areal"
             else f"{info.get('nx')} points")]
    rows.append(("pixel size", f"{quantity_text(info.get('dx'))} × {quantity_text(info.get('dy'))}"
                 if info.get("kind") == "areal" else quantity_text(info.get("dx"))))
    if info.get("kind") == "areal":
        rows.append(("scan size", f"{quantity_text(info.get('size_x'))} × "
                                  f"{quantity_text(info.get('size_y'))}"))
    else:
        rows.append(("length", quantity_text(info.get("length"))))
    rows.append(("non-measured", f"{100 * float(info.get('nan_fraction') or 0):.3f} %"))
    rows.extend(("CAVEAT", c) for c in (info.get("units") or {}).get("caveats", []))
    for k, v in (info.get("metadata") or {}).items():
        text = _meta_text(_jsonable(v))
        if len(text) > 400:
            text = text[:397] + "..."
        rows.append((k, text))
    return "<h3>Instrument and grid</h3>" + kv_table(rows)


def _meta_text(v: Any) -> str:
    """Readable text of a metadata value: quantities with their unit, mappings as
    ``key: value; ...``, numbers with 6 significant digits."""
    if isinstance(v, dict):
        if "value" in v and "unit" in v and len(v) == 2:
            return quantity_text(v)
        def inner(x: Any) -> str:
            t = _meta_text(x)
            nested = isinstance(x, dict) and not ("value" in x and "unit" in x)
            return "{" + t + "}" if nested else t

        return "; ".join(f"{k}: {inner(x)}" for k, x in v.items())
    if isinstance(v, list):
        return "[" + ", ".join(_meta_text(x) for x in v) + "]"
    if isinstance(v, float):
        return f"{v:.6g}"
    return "" if v is None else str(v)


def _length_text(v: Any) -> str:
    """A length of the settings (SI m) as text, as :func:`quantity_text` writes one."""
    from surfmet.units import format_quantity

    if isinstance(v, (int, float)) and not isinstance(v, bool):
        return format_quantity(float(v), "m")
    return f"{v} m"


def _jsonable(v: Any) -> Any:
    from surfmet.units import jsonable

    return jsonable(v)


def _params_html(params: dict[str, Any]) -> str:
    head = "<tr><th>parameter</th><th>value</th><th>unit</th></tr>"
    rows = []
    for sym, q in params.items():
        value, unit = q["value"], q["unit"]
        text, shown = display_value(value, unit)
        si = "" if value is None else repr(float(value))
        rows.append(f'<tr data-symbol="{esc(sym)}"><td>{esc(sym)}</td>'
                    f'<td class="num" data-si="{esc(si)}" data-si-unit="{esc(unit)}">'
                    f"{esc(text)}</td><td>{esc(shown)}</td></tr>")
    return ('<h3>Parameters</h3><table class="params">' + head + "".join(rows) + "</table>")


def _settings_rows(s: dict[str, Any]) -> list[tuple[str, str]]:
    rows: list[tuple[str, str]] = []
    if s.get("kind") == "areal":
        rows.append(("surface", s.get("surface", "")))
        form = s.get("form") or {}
        rows.append(("F-operator (form removed)",
                     f"{s.get('level')} (residual rms {quantity_text(form.get('residual_rms'))})"))
        for name in ("ls", "lc"):
            rows.append((f"{'S' if name == 'ls' else 'L'}-filter nesting index {name}",
                         quantity_text(s[name]) if s.get(name) else "none"))
        for f in s.get("filters") or []:
            rows.append((f"{f.get('kind')}-filter",
                         f"Gaussian ISO 16610-61, λ = {quantity_text(f.get('nesting_index'))}, "
                         f"edge treatment {f.get('edge')}"))
        rows.append(("measured points used", str(s.get("n_valid_points"))))
    else:
        rows.append(("parameters of", str(s.get("parameters_of", ""))))
        rows.append(("levelling", str(s.get("level"))))
        lc = s.get("lc")
        rows.append(("λc (L-filter cut-off)", "none" if lc is None else
                     f"{_length_text(lc)} ({s.get('lc_mode')})"))
        ls = s.get("ls")
        rows.append(("λs (S-filter cut-off)", "none" if ls is None else
                     _length_text(ls)))
        if s.get("filter"):
            rows.append(("filter", str(s["filter"])))
        for key in ("lc_note", "ls_note"):
            if s.get(key):
                rows.append(("note", str(s[key])))
        if s.get("evaluation_length") is not None:
            rows.append(("evaluation length",
                         f"{_length_text(s['evaluation_length'])} "
                         f"({s.get('n_sampling')} sampling lengths)"))
    win = s.get("window")
    rows.append(("window", "whole scan" if not win else json.dumps(_jsonable(win))))
    sp = s.get("spikes") or {}
    rows.append(("spikes", f"removed: {sp.get('count', 0)} spike(s)" if sp.get("removed")
                 else "not removed"))
    diag = s.get("spike_diagnosis") or {}
    if diag.get("message"):
        rows.append(("spike diagnosis", diag["message"]))
    for note in s.get("notes") or []:
        rows.append(("note", str(note)))
    return rows


def _settings_html(s: dict[str, Any]) -> str:
    full = json.dumps(_jsonable(s), indent=1, ensure_ascii=False)
    return ("<h3>Processing (settings used)</h3>" + kv_table(_settings_rows(s))
            + "<details><summary>all settings (JSON, SI units)</summary><pre>"
            + esc(full) + "</pre></details>")


def _section_html(k: int, sec: ScanSection, hz: HertzOptions | None) -> str:
    name = Path(sec.file).name
    out = [f'<section class="scan" id="scan-{k}"><h2>{esc(name)}</h2>'
           f'<p class="small">{esc(sec.file)}</p>']
    if sec.status != "ok":
        out.append(f'<p class="error">could not be evaluated: {esc(sec.error)}</p></section>')
        return "".join(out)
    out.append(_info_html(sec.info))
    out.append('<div class="cols"><div>' + _params_html(sec.parameters) + "</div><div>"
               + _settings_html(sec.settings) + "</div></div>")
    out.append(figures_html(sec.figures))
    if sec.spectrum is not None and "error" in sec.spectrum:
        out.append(f'<p class="small">no PSD: surfmet spectrum refuses the scan: '
                   f"{esc(sec.spectrum['error'])}</p>")
    if sec.hertz is not None:
        out.append(hertz_html(sec.hertz, sec.hertz_figure, hz))
    elif sec.hertz_error:
        out.append(f'<h3>Hertz check</h3><p class="error">failed: {esc(sec.hertz_error)}</p>')
    out.append("</section>")
    return "".join(out)


def _overview(sections: Sequence[ScanSection]) -> str:
    head = "<tr><th>scan</th><th>kind</th><th>Sa / Ra</th><th>Sq / Rq</th><th>status</th></tr>"
    rows = []
    for k, s in enumerate(sections):
        a = s.parameters.get("Sa") or s.parameters.get("Ra") or {}
        q = s.parameters.get("Sq") or s.parameters.get("Rq") or {}
        ta = " ".join(display_value(a.get("value"), a.get("unit", "m"))) if a else ""
        tq = " ".join(display_value(q.get("value"), q.get("unit", "m"))) if q else ""
        status = "ok" if s.status == "ok" else f"error: {s.error}"
        rows.append(f'<tr><td><a href="#scan-{k}">{esc(Path(s.file).name)}</a></td>'
                    f"<td>{esc(s.kind or '')}</td><td class=\"num\">{esc(ta)}</td>"
                    f'<td class="num">{esc(tq)}</td><td>{esc(status)}</td></tr>')
    return '<table class="overview">' + head + "".join(rows) + "</table>"


def render_html(sections: Sequence[ScanSection], *, title: str = "surfmet report",
                options: dict[str, Any] | None = None, hertz: HertzOptions | None = None,
                rotor: Any = None) -> str:
    """The report page for computed sections (see :func:`scan_section`); ``rotor``: a rotor
    verdict (:mod:`rotor._verdict`) to put first."""
    from surfmet import __version__

    now = _dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    # the options given, not the defaults surfmet roughness fills in
    opts = {k: v for k, v in (options or {}).items()
            if v not in (None, False) and (k, v) != ("edge", "discard")}
    parts = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
             '<meta name="viewport" content="width=device-width, initial-scale=1">',
             f"<title>{esc(title)}</title><style>{_CSS}</style></head><body>",
             f"<h1>{esc(title)}</h1>",
             f'<p class="small">surfmet {esc(__version__)}, {esc(now)}; options: '
             f"{esc(json.dumps(_jsonable(opts), ensure_ascii=False) if opts else 'defaults')}"
             "</p>"]
    if rotor is not None:
        from surfmet._report_rotor import rotor_html

        parts.append(rotor_html(rotor))
    parts.append(_overview(sections))
    parts.extend(_section_html(k, s, hertz) for k, s in enumerate(sections))
    parts.append("</body></html>")
    return "\n".join(parts)


def write_report(
    paths: Iterable[str | Path],
    out: str | Path,
    options: dict[str, Any] | None = None,
    *,
    title: str = "surfmet report",
    include_3d: bool = True,
    hertz: HertzOptions | None = None,
    progress: bool | None = None,
    rotor: Any = None,
    read_options: dict[str, Any] | None = None,
) -> list[ScanSection]:
    """Evaluate each scan and write the self-contained HTML report to ``out``.

    Parameters
    ----------
    paths : iterable of path
        Scan files; a container's measurements each get a section.
    out : path
        The HTML file to write.
    options : dict, optional
        :func:`surfmet.roughness.roughness` keyword arguments.
    title : str
    include_3d : bool
        Render the 3D views (the slowest part; off-screen pyvista).
    hertz : HertzOptions, optional
        Add the Hertz-check section to each scan.
    rotor : RotorVerdict, optional
        The rotor verdict, first on the page.
    progress : bool, optional
        Progress bar on stderr (default: when stderr is a terminal).

    Returns
    -------
    list of ScanSection
        One per scan, in order (``status`` "ok" or "error").
    """
    from surfmet._batch import progress_bar
    from surfmet._measurements import expand_measurements

    # a container's measurements each get a section, as each gets a roughness record
    paths = expand_measurements(paths)
    if not paths:
        raise SurfmetInputError("the report needs at least one scan file")
    from surfmet._atomic import check_writable, write_text

    out = Path(out)
    check_writable(out, "report")
    sections = []
    with progress_bar(len(paths), "report", progress) as bar:
        for p in paths:
            sections.append(scan_section(p, options, include_3d=include_3d, hertz=hertz,
                                         read_options=read_options))
            bar.update(1)
    write_text(out, render_html(sections, title=title, options=options, hertz=hertz,
                                rotor=rotor))
    return sections
