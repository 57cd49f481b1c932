"""The demo's rotor step: the law-of-motion analysis of the shipped Table 3 and the
paper's parabolas."""

from __future__ import annotations

from typing import Any

import numpy as np

from contact.rotor.paper import FPS, MARK_STEP, PARABOLAS, TABLE3_FILENAME
from surfmet.demo.outputs import data_file
from surfmet.units import quantity


def _parabola(coef: Any) -> dict[str, Any]:
    c2, c1, c0 = (float(c) for c in coef)
    return {"c2": quantity(c2, "rad/s^2"), "c1": quantity(c1, "rad/s"), "c0": quantity(c0, "rad")}


def rotor_step() -> tuple[dict[str, Any], Any]:
    """The law-of-motion analysis of the shipped Table 3, and the paper's parabolas."""
    from contact.rotor.frames import table3_tsv
    from contact.rotor.groups import analyse_table
    from surfmet.frames import read_frames_table

    path = data_file(TABLE3_FILENAME)
    ks, cols = read_frames_table(path)
    an = analyse_table(cols, ks, fps=FPS, step=MARK_STEP, cv="approx")
    fps = an.fps
    tests = []
    for t in an.tests:
        tests.append({
            "name": t.name, "group": t.group, "selected_model": t.selected,
            "effect": t.effect, "misread_rows": [int(k) for k in t.outliers],
            "eps0": quantity(t.eps0, "rad/s^2"), "eps0_stderr": quantity(t.eps0_stderr, "rad/s^2"),
            "rms_paper_model": quantity(t.fits["rest"].rms * fps, "frame"),
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
    # which group's parabola is each of the paper's (to the three decimals it prints)?
    match = {}
    for label, ref in PARABOLAS.items():
        for g in an.groups:
            if np.allclose(np.round(g.paper_parabola, 3), np.round(ref, 3), atol=1e-9):
                match[label] = g.name
    comps = [{"groups": [c.a, c.b], "model": c.model, "quantity": c.quantity,
              "difference": quantity(c.difference, "rad/s^2"),
              "uncertainty": quantity(c.uncertainty, "rad/s^2"),
              "z": quantity(c.z, ""), "p_value": quantity(c.p_value, "")}
             for c in an.comparisons if c.quantity == "eps0"]
    rec = {
        "file": path.name,
        "equals_the_split_of_the_printed_rows": path.read_text(encoding="utf-8") == table3_tsv(),
        "fps": quantity(fps, "1/s"), "step": quantity(an.step, "rad"),
        "quantisation_sigma": quantity(an.noise_floor, "s"),
        "study_model": an.study_model,
        "tests": tests,
        "groups": groups,
        "paper_reported": {k: _parabola(v) for k, v in PARABOLAS.items()},
        "paper_label_match": match,
        "comparisons": comps,
    }
    return rec, an

