"""The JSON record of the demo's rotor step (:mod:`surfmet.demo._lawofmotion`): the
paper's parabolas of each group, and, in a full run, the law-of-motion models of every
test, their groups and comparisons; every value with its unit."""

from __future__ import annotations

from typing import Any

from surfmet.units import quantity

__all__ = ["analysis_record", "head_record", "paper_group_record", "parabola_record"]


def parabola_record(coef: Any) -> dict[str, Any]:
    """A parabola ``c2 t^2 + c1 t + c0`` of the rotor's angle (rad, s)."""
    c2, c1, c0 = (float(c) for c in coef)
    return {"c2": quantity(c2, "rad/s^2"), "c1": quantity(c1, "rad/s"), "c0": quantity(c0, "rad")}


def head_record(file: str, equals_split: bool, fps: float, step: float) -> dict[str, Any]:
    """The frame table read: its file, whether it is the split of the printed rows, the
    frame rate (1/s) and the angle between marks (rad)."""
    return {"file": file, "equals_the_split_of_the_printed_rows": equals_split,
            "fps": quantity(fps, "1/s"), "step": quantity(step, "rad")}


def paper_group_record(name: str, tests: list[str], coef: Any, stderr: Any,
                       rms: float) -> dict[str, Any]:
    """A group's paper parabola, its standard errors and rms (rad)."""
    return {"name": name, "tests": tests, "paper_parabola": parabola_record(coef),
            "paper_parabola_stderr": parabola_record(stderr),
            "paper_parabola_rms": quantity(rms, "rad")}


def analysis_record(an: Any, rms_paper: list[float], paper_model: str) -> dict[str, Any]:
    """The law-of-motion analysis of the table (:func:`rotor.analyse_table`):
    each test (``rms_paper``: the paper model's rms of each, frames), each group and the
    comparisons of eps0; the paper's model named ``paper_model``."""
    fps = an.fps
    tests = []
    for t, rms in zip(an.tests, rms_paper):
        tests.append({
            "name": t.name, "group": t.group, "selected_model": t.selected,
            "effect": t.effect, "misread_rows": [int(k) for k in t.outliers],
            "eps0": quantity(t.eps0, "rad/s^2"), "eps0_stderr": quantity(t.eps0_stderr, "rad/s^2"),
            # the residual figure's titles print the same function's value
            "rms_paper_model": quantity(rms, "frame"),
            "rms_selected": quantity(t.fit.rms * fps, "frame"),
        })
    groups = []
    for g in an.groups:
        groups.append({
            "name": g.name, "tests": list(g.tests),
            "paper_parabola": parabola_record(g.paper_parabola),
            "paper_parabola_stderr": parabola_record(g.paper_parabola_stderr),
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
    return {"quantisation_sigma": quantity(an.noise_floor, "s"),
            "study_model": an.study_model, "paper_model": paper_model,
            "tests": tests, "groups": groups, "comparisons": comps}
