"""The demo's findings as text for a terminal, written from ``summary.json`` alone: one
function per section of the story."""

from __future__ import annotations

import math
import textwrap
from pathlib import Path
from typing import Any

from surfmet.demo._outputs import SUMMARY
from surfmet.records._solve import solve_from_record
from surfmet.units import format_length, format_quantity


def _v(q: Any) -> float:
    v = q["value"] if isinstance(q, dict) else q
    return math.nan if v is None else float(v)


def _um(q: Any, digits: int = 3) -> str:
    return f"{_v(q) * 1e6:.{digits}f} µm"


class _Text:
    """Lines of the story, with headings and wrapped paragraphs."""

    def __init__(self) -> None:
        self.lines: list[str] = []

    def add(self, line: str) -> None:
        self.lines.append(line)

    def head(self, text: str) -> None:
        self.lines.extend(["", text, "-" * len(text)])

    def para(self, text: str, indent: str = "") -> None:
        self.lines.extend(textwrap.wrap(text, 92, initial_indent=indent,
                                        subsequent_indent=indent + ("  " if indent else "")))


#: The story's own header: its first line, before the verdict that answers the paper.
TITLE = ("surfmet demo: rolling friction of a steel ball on an aluminium plate "
         "(Alaci et al. 2022)")


def _title(t: _Text, summary: dict[str, Any]) -> None:
    t.add(TITLE)


def _scans(t: _Text, summary: dict[str, Any]) -> None:
    t.head("The scans")
    sc = summary["scans"]
    for name, what in (("plate", "aluminium plate"), ("ball", "steel ball")):
        s = sc[name]
        t.add(f"  {what:16} {s['file']}: {s['nx']} x {s['ny']} points, pitch "
              f"{format_length(_v(s['dx']))}, {format_length(_v(s['size_x']))} x "
              f"{format_length(_v(s['size_y']))}")
    t.para("These are synthetic stand-ins with the statistics of the paper's scans, written "
           "as X3P by surfmet (the original NanoFocus files are not public).", "  ")


def _roughness(t: _Text, summary: dict[str, Any]) -> None:
    r = summary["roughness"]
    t.head(f"1. Roughness (every row; λc = "
           f"{_v(r['plate_rows']['settings']['lc']) * 1e3:g} mm, ISO 4288)")
    t.add(f"  {'':16}{'median of rows':>16}{'paper (Table 2 mean)':>24}")
    for part, key in (("plate", "plate_rows"), ("ball", "ball_rows")):
        paper = r["paper_table2_mean"][part]
        label = part
        for sym, q in r[key]["median"].items():
            ref = f"{_v(paper[sym]) * 1e6:.3f} µm" if sym in paper else "-"
            t.add(f"  {label:6}{sym:10}{_um(q):>16}{ref:>24}")
            label = ""
    a = r["plate_areal"]
    raw, cl = a["as_scanned"], a["cleaned"]
    t.add(f"  plate areal, as scanned: Sa {_um(raw['parameters']['Sa'])}, Sq "
          f"{_um(raw['parameters']['Sq'])}, Sq/Sa = {_v(raw['sq_over_sa']):.2f}")
    t.add(f"  after removing {a['spikes_removed']['count']} spikes: Sa "
          f"{_um(cl['parameters']['Sa'])}, Sq {_um(cl['parameters']['Sq'])}, Sq/Sa = "
          f"{_v(cl['sq_over_sa']):.3f} (Gaussian {_v(cl['gaussian_sq_over_sa']):.3f})")
    t.para("Optical spikes, not roughness, are what pushed the paper's Table 1 Sq/Sa up to "
           "4.3; surfmet flags them and takes them out before any contact analysis.", "  ")


def _ball(t: _Text, summary: dict[str, Any]) -> None:
    b = summary["ball"]
    sp = b["sphere"]
    t.head("2. The ball's radius")
    # the radius, its uncertainty and the residuals as surfmet fit prints them
    t.add(f"  best-fit sphere  R = {format_length(_v(sp['radius']), 8)} ± "
          f"{format_length(_v(sp['radius_uncertainty']), 3)} (k = 1), nominal "
          f"{format_length(_v(b['nominal_radius']))}")
    t.add(f"  R - nominal = {_v(b['radius_minus_nominal']) * 1e6:+.1f} µm = "
          f"{_v(b['radius_minus_nominal_in_uncertainties']):+.0f} uncertainties")
    t.add(f"  sphere residual {format_length(_v(sp['rms_residual']))} rms (roughness, "
          f"outliers, form); form deviation {format_length(_v(sp['form_pv']))} (PV of its "
          "quadratic component)")
    t.add(f"  circle fits: {b['row_circle']['profile']} R = "
          f"{_v(b['row_circle']['radius']) * 1e3:.3f} mm, "
          f"{b['column_circle']['profile']} R = "
          f"{_v(b['column_circle']['radius']) * 1e3:.3f} mm (the cap is not a sphere)")


def _hertz(t: _Text, summary: dict[str, Any]) -> None:
    h = summary["hertz_check"]
    d = h["details"]
    t.head(f"3. Does Hertz hold? ({_v(d['load']):g} N, R = {_v(d['radius']) * 1e3:g} mm, "
           f"{d['materials']['ball']} on {d['materials']['plate']})")
    t.add(f"  Hertz: δ0 = {_um(h['hertz']['delta'])} (paper {_um(h['paper']['delta'])}), "
          f"a0 = {_um(h['hertz']['a'], 1)} (paper {_um(h['paper']['a'], 1)}), p0 = "
          f"{format_quantity(_v(h['hertz']['p0']), 'Pa', 3)}")
    verdict = ("Hertz cannot be judged (the scan's pixel does not resolve the contact)"
               if h.get("judged") is False else
               "Hertz holds" if h["hertz_holds"] else "Hertz does NOT hold")
    t.add(f"  verdict: {verdict} (α = {_v(h['alpha']):.3g}, σ = {_um(h['sigma'])})")
    for reason in h["reasons"]:
        t.para(f"- {reason}", "    ")


def _contact(t: _Text, summary: dict[str, Any]) -> None:
    c = summary["contact"]
    rl = c["rotor_loads"]
    t.head(f"4. Contact at the rotor's load ({_v(c['load']):.2f} N per ball)")
    t.add(f"  rotor loads per ball: symmetric {_v(rl['symmetric']):.2f} N; asymmetric "
          f"{_v(rl['asymmetric_ball1']):.2f} N and {_v(rl['asymmetric_ball2']):.2f} N")
    t.add(f"  grid {c['grid']['nx']} x {c['grid']['ny']}, pitch "
          f"{format_length(_v(c['grid']['dx']))}")
    t.add(f"  solve: {solve_from_record(c['solve']).text()}")
    t.add(f"  95 % of the load within {_um(c['radius_95'], 0)} of the centre (Hertz a0 "
          f"{_um(c['hertz']['a'], 0)})")
    t.add(f"  approach {_um(c['approach'])} (Hertz {_um(c['hertz']['delta'])})")
    a_hz = math.pi * _v(c["hertz"]["a"]) ** 2
    t.add(f"  {c['n_clusters']} contact spots, real area {_v(c['contact_area']) / a_hz:.3g}"
          f" × π a0², of which {_v(c['plastic_area']) / a_hz:.3g} × π a0² at the "
          f"hardness {format_quantity(_v(c['hardness']), 'Pa', 3)}")  # as the Hertz check
    t.add(f"  regime: {c['regime']}")


def _rolling(t: _Text, summary: dict[str, Any]) -> None:
    ro = summary["rolling"]
    st = ro["settings"]
    lo, hi = ro["lambda_ci"]["value"]
    alpha = _v(st["alpha_h"])
    radius = _v(st["radius"])
    t.head("5. Rolling resistance M_r = s_r N^λ (hysteresis model, one track position)")
    t.add(f"  λ_eff = {_v(ro['lambda_eff']):.3f}, "
          f"{100 * _v(st['confidence']):.0f} % CI [{lo:.3f}, {hi:.3f}]   "
          "(smooth Hertz contact: 4/3)")
    t.para(f"Assumed: α_h = {alpha:g}, the fraction of the work done on the material that "
           f"is lost{' (all of it: an upper bound)' if alpha == 1 else ''}. M_r and "
           "μ_r = M_r/(N R) scale with α_h, λ does not: a measured μ_r divided by the one "
           "below is the α_h of the pair.", "  ")
    t.add(f"  {'load (N)':>10}{'M_r (N m)':>13}{'μ_r':>11}{'local λ':>10}"
          f"   (at α_h = {alpha:g})")
    for w, m, lam in zip(ro["loads"]["value"], ro["moments"]["value"],
                         ro["local_lambda"]["value"]):
        lam_s = f"{lam:10.3f}" if lam is not None else f"{'-':>10}"
        t.add(f"  {w:10.3g}{m:13.4g}{m / (w * radius):11.3g}{lam_s}")
    regime = summary.get("contact", {}).get("regime", "")
    if regime.startswith("plastic"):
        t.para(f"The hysteresis sweep solves the contact elastically, while section 4 finds "
               f"it {regime}: the work of plastic flow is not in these moments "
               "('surfmet rolling --model plastic' counts it).", "  ")
    prepared = set(st.get("scan_preparation", {}).get("notes", []))
    for note in st.get("notes", []):
        if note not in prepared:
            t.para(f"note: {note}", "  ")


def _rotor_parabolas(t: _Text, rt: dict[str, Any]) -> None:
    t.add(f"  {rt['file']}: equals the split of the paper's printed rows: "
          f"{rt['equals_the_split_of_the_printed_rows']}")
    for g in rt["groups"]:
        p = g["paper_parabola"]
        t.add(f"  columns {g['name']:>2} ({', '.join(g['tests'])}): φ = "
              f"{_v(p['c2']):.3f} t² {_v(p['c1']):+.3f} t {_v(p['c0']):+.3f} rad")
    inv = {v: k for k, v in rt["paper_label_match"].items()}
    for label, ref in rt["paper_reported"].items():
        grp = rt["paper_label_match"].get(label)
        where = f"reproduced by columns '{grp}'" if grp else "not reproduced by any group"
        t.add(f"  paper's {label} = {_v(ref['c2']):g} t² {_v(ref['c1']):+g} t "
              f"{_v(ref['c0']):+g}: {where}")
    if inv.get("as") == "phi_s" and inv.get("s") == "phi_a":
        t.para("The paper's labels are swapped: its 'symmetric' parabola fits Table 3's "
               "asymmetric columns and vice versa.", "  ")


def _rotor(t: _Text, summary: dict[str, Any]) -> None:
    rt = summary["rotor"]
    t.head("6. The rotor's law of motion (Table 3, 120 frames/s, marks every 90°)")
    _rotor_parabolas(t, rt)
    if "tests" not in rt:  # --quick
        t.para(f"Left out by --quick: {rt.get('left_out', 'the per-test models')}.", "  ")
        return
    t.add(f"  model chosen by the summed BIC: {rt['study_model']}")
    paper = "rms " + rt.get("paper_model", "rest")  # the residual figure's name for it
    t.add(f"  {'test':6}{'chosen model':24}{'misread k':>10}{paper:>10}"
          f"{'rms chosen':>12}  (frames)")
    for test in rt["tests"]:
        mis = ",".join(str(k) for k in test["misread_rows"]) or "-"
        t.add(f"  {test['name']:6}{test['selected_model']:24}{mis:>10}"
              f"{_v(test['rms_paper_model']):10.2f}{_v(test['rms_selected']):12.2f}")
    for cmp in rt["comparisons"]:
        if cmp["model"] in ("paper", rt["study_model"]):
            a_, b_ = cmp["groups"]
            t.add(f"  eps0({b_}) - eps0({a_}) under {cmp['model']}: "
                  f"{_v(cmp['difference']):+.3f} ± {_v(cmp['uncertainty']):.3f} rad/s² "
                  f"(z {_v(cmp['z']):+.1f})")
    rest = [_v(test["rms_paper_model"]) for test in rt["tests"]]
    chosen = [_v(test["rms_selected"]) for test in rt["tests"]]
    q_frames = _v(rt["quantisation_sigma"]) * _v(rt["fps"])
    t.para(f"The paper's model (constant acceleration from rest at the first mark) misses the "
           f"frame indices by {min(rest):.1f}-{max(rest):.1f} frames rms, the chosen models by "
           f"{min(chosen):.2f}-{max(chosen):.2f}, against a reading quantisation of "
           f"{q_frames:.2f} frame. 'surfmet rotor paper2022' prints the full analysis.", "  ")


def _verdict(t: _Text, summary: dict[str, Any]) -> None:
    """The paper's question first: the rotor verdict (surfmet rotor paper2022 says the same)."""
    v = summary.get("verdict")
    if v is None:
        return
    t.head("The paper's question: is M_r linear in N? (the rotor verdict)")
    t.para(v["sentence"], "  ")
    if v.get("label_swap"):
        t.para(f"Labels: {v['label_swap']}.", "  ")
    o = v["group_offset"]
    t.add(f"  group offset {o['minuend']} - {o['subtrahend']}: {o['value']:+.4f} rad/s², "
          f"{o['level']:.0%} CI [{o['ci_low']:+.4f}, {o['ci_high']:+.4f}]")
    lam = v.get("lambda_needed")
    if lam and lam["value"] is not None:
        la = v["lambda_assumptions"]
        t.add(f"  lambda the offset would need at {math.degrees(_v(la['slope'])):.2g}° "
              f"({la['slope_basis']}): {lam['value']:.3g}; lambda = 4/3 gives at most "
              f"{_v(la['largest_offset_lambda_4_3']):+.4f} rad/s² there")
    t.add("  'surfmet rotor paper2022' prints the joint model, the confounds and the tests.")


def _files(t: _Text, summary: dict[str, Any]) -> None:
    t.head("Files")
    out = summary.get("out_dir", ".")
    for name in summary.get("figures", {}).values():
        t.add(f"  {Path(out) / name}")
    t.add(f"  {Path(out) / SUMMARY}")
    total = summary.get("total_time")
    if total:
        t.add(f"  (total {_v(total):.0f} s)")


def story(summary: dict[str, Any]) -> str:
    """The demo's findings as text for a terminal (from the summary alone)."""
    t = _Text()
    for section in (_title, _verdict, _scans, _roughness, _ball, _hertz, _contact, _rolling, _rotor,
                    _files):
        section(t, summary)
    return "\n".join(t.lines)
