"""The demo's rotor step: the law-of-motion analysis of the shipped Table 3 and the
paper's parabolas."""

from __future__ import annotations

from typing import Any

import numpy as np

from rotor import FPS, MARK_STEP, PARABOLAS, TABLE3_FILENAME
from surfmet.demo.outputs import data_file
from surfmet.units import quantity


def _parabola(coef: Any) -> dict[str, Any]:
    c2, c1, c0 = (float(c) for c in coef)
    return {"c2": quantity(c2, "rad/s^2"), "c1": quantity(c1, "rad/s"), "c0": quantity(c0, "rad")}


#: What ``--quick`` leaves out of the rotor step, and why (the story says it).
QUICK_LEAVES_OUT = ("the per-test law-of-motion models (misread rows, the BIC choice, their "
                    "rms and the group comparisons) and their two figures: the model "
                    "selection over every test is most of the demo's time; run without "
                    "--quick, or 'surfmet rotor paper2022', for them")


def _parabola_groups(cols: dict[str, Any], fps: float, step: float) -> list[dict[str, Any]]:
    """The paper's parabola of each group (:func:`rotor.paper_parabola`,
    the one :func:`rotor.analyse_table` fits), without the model selection."""
    from rotor import group_of, paper_parabola

    groups = []
    for gname in dict.fromkeys(group_of(n) for n in cols):
        names = [n for n in cols if group_of(n) == gname]
        coef, se, prms = paper_parabola([np.asarray(cols[n], float) for n in names], fps, step)
        groups.append({"name": gname, "tests": names, "paper_parabola": _parabola(coef),
                       "paper_parabola_stderr": _parabola(se),
                       "paper_parabola_rms": quantity(prms, "rad")})
    return groups


def _label_match(groups: list[dict[str, Any]]) -> dict[str, str]:
    """Which group's parabola is each of the paper's (to the three decimals it prints)?"""
    match = {}
    for label, ref in PARABOLAS.items():
        for g in groups:
            coef = [g["paper_parabola"][c]["value"] for c in ("c2", "c1", "c0")]
            if np.allclose(np.round(coef, 3), np.round(ref, 3), atol=1e-9):
                match[label] = g["name"]
    return match


def rotor_step(quick: bool = False) -> tuple[dict[str, Any], Any]:
    """The law-of-motion analysis of the shipped Table 3, and the paper's parabolas;
    ``quick``: the parabolas only (:data:`QUICK_LEAVES_OUT`), the analysis None."""
    from rotor import analyse_table, table3_tsv
    from surfmet.frames import read_frames_table
    from surfmet.plots.rotor import PAPER_MODEL, rms_frames

    path = data_file(TABLE3_FILENAME)
    ks, cols = read_frames_table(path)
    head = {
        "file": path.name,
        "equals_the_split_of_the_printed_rows": path.read_text(encoding="utf-8") == table3_tsv(),
        "fps": quantity(FPS, "1/s"), "step": quantity(MARK_STEP, "rad"),
    }
    if quick:
        groups = _parabola_groups(cols, FPS, MARK_STEP)
        return {**head, "groups": groups,
                "paper_reported": {k: _parabola(v) for k, v in PARABOLAS.items()},
                "paper_label_match": _label_match(groups),
                "left_out": QUICK_LEAVES_OUT}, None
    an = analyse_table(cols, ks, fps=FPS, step=MARK_STEP, cv="approx")
    fps = an.fps
    tests = []
    for t in an.tests:
        tests.append({
            "name": t.name, "group": t.group, "selected_model": t.selected,
            "effect": t.effect, "misread_rows": [int(k) for k in t.outliers],
            "eps0": quantity(t.eps0, "rad/s^2"), "eps0_stderr": quantity(t.eps0_stderr, "rad/s^2"),
            # the residual figure's titles print the same function's value
            "rms_paper_model": quantity(rms_frames(t, PAPER_MODEL, fps), "frame"),
            "rms_selected": quantity(t.fit.rms * fps, "frame"),
        })
    groups = []
    for g in an.groups:
        groups.append({
            "name": g.name, "tests": list(g.tests),
            "paper_parabola": _parabola(g.paper_parabola),
            "paper_parabola_stderr": _parabola(g.paper_parabola_stderr),
            "paper_parabola_rms": quantity(g.paper_rms, "rad"),
            "eps0": {m: {"mean": quantity(v[0], "rad/s^2"),
                         "uncertainty": quantity(v[1], "rad/s^2")}
                     for m, v in g.eps.items() if m in ("paper", "rest", "const", an.study_model)},
        })
    comps = [{"groups": [c.a, c.b], "model": c.model, "quantity": c.quantity,
              "difference": quantity(c.difference, "rad/s^2"),
              "uncertainty": quantity(c.uncertainty, "rad/s^2"),
              "z": quantity(c.z, ""), "p_value": quantity(c.p_value, "")}
             for c in an.comparisons if c.quantity == "eps0"]
    rec = {
        **head,
        "quantisation_sigma": quantity(an.noise_floor, "s"),
        "study_model": an.study_model,
        "paper_model": PAPER_MODEL,
        "tests": tests,
        "groups": groups,
        "paper_reported": {k: _parabola(v) for k, v in PARABOLAS.items()},
        "paper_label_match": _label_match(groups),
        "comparisons": comps,
    }
    return rec, an
