"""The rotor verdict's section of the report (:mod:`surfmet.report`), first on the page when
``surfmet report --rotor TABLE`` is given: the same verdict as ``surfmet rotor TABLE``."""

from __future__ import annotations

from typing import Any

from surfmet._report_html import esc, figure_png, figures_html, kv_table


def rotor_html(v: Any) -> str:
    """HTML of a :class:`rotor.RotorVerdict`."""
    from surfmet.plots.rotor_verdict import draw_verdict
    from surfmet.records._rotor_verdict import verdict_record

    rec = verdict_record(v)
    o = rec["group_offset"]
    rows = [("verdict", rec["code"]),
            (f"group offset {o['minuend']} - {o['subtrahend']}",
             f"{o['value']:+.4f} rad/s² ({o['level']:.0%} CI {o['ci_low']:+.4f} … "
             f"{o['ci_high']:+.4f})"),
            ("shared track", f"{'adequate' if v.shared_track_adequate else 'rejected'} "
                             f"(F = {v.f_statistic:.2f}, {rec['shared_track']['p_text']})")]
    lam = rec["lambda_needed"]
    if lam is not None and lam["value"] is not None:
        rows.append(("lambda needed", f"{lam['value']:.3g} [{lam['ci_low']:.3g}, "
                                      f"{lam['ci_high']:.3g}] "
                                      f"({rec['lambda_assumptions']['slope_basis']}; "
                                      f"conditional on the slope)"))
    if rec.get("label_swap"):
        rows.append(("labels", rec["label_swap"]))
    parts = ["<h2>The paper's question: is M<sub>r</sub> linear in N?</h2>",
             f'<p class="verdict">{esc(v.sentence)}</p>', kv_table(rows)]
    if rec["confounds"]:
        head = ("<tr><th>confound</th><th>equivalent acceleration</th><th>can make the "
                "offset</th><th>assumption</th></tr>")
        body = "".join(
            f"<tr><td>{esc(c['name'])}</td><td class=\"num\">"
            f"{c['equivalent_acceleration']['value']:.3g} rad/s²</td>"
            f"<td>{'yes' if c['can_explain'] else 'no'}</td><td>{esc(c['assumption'])}</td></tr>"
            for c in rec["confounds"])
        parts.append(f'<table class="overview">{head}{body}</table>')
    fig = draw_verdict(v)
    parts.append(figures_html([("rotor verdict", figure_png(fig))]))
    return "\n".join(parts)
