"""The demo's rotor step: the law-of-motion analysis of the shipped Table 3 and the
paper's parabolas."""

from __future__ import annotations

from typing import Any

import numpy as np

from rotor import FPS, MARK_STEP, PARABOLAS, TABLE3_FILENAME
from surfmet.demo._outputs import data_file
from surfmet.records._demo_rotor import (
    analysis_record,
    head_record,
    paper_group_record,
    parabola_record,
)

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
        groups.append(paper_group_record(gname, names, coef, se, prms))
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
    from surfmet._frames import read_frames_table
    from surfmet.plots.rotor import PAPER_MODEL, rms_frames

    path = data_file(TABLE3_FILENAME)
    ks, cols = read_frames_table(path)
    head = head_record(path.name, path.read_text(encoding="utf-8") == table3_tsv(),
                       FPS, MARK_STEP)
    paper = {k: parabola_record(v) for k, v in PARABOLAS.items()}
    if quick:
        groups = _parabola_groups(cols, FPS, MARK_STEP)
        return {**head, "groups": groups, "paper_reported": paper,
                "paper_label_match": _label_match(groups),
                "left_out": QUICK_LEAVES_OUT}, None
    an = analyse_table(cols, ks, fps=FPS, step=MARK_STEP, cv="approx")
    body = analysis_record(an, [rms_frames(t, PAPER_MODEL, an.fps) for t in an.tests],
                           PAPER_MODEL)
    rec = {
        **head,
        "quantisation_sigma": body["quantisation_sigma"],
        "study_model": body["study_model"],
        "paper_model": body["paper_model"],
        "tests": body["tests"],
        "groups": body["groups"],
        "paper_reported": paper,
        "paper_label_match": _label_match(body["groups"]),
        "comparisons": body["comparisons"],
    }
    return rec, an
