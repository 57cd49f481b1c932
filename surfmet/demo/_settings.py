"""What the demo computes with: the settings of each step, and the means of Table 2.

The paper's rotor facts (the balls' radius, the Hertz check's load and its 0.936 µm and
136 µm, the film's frame rate and marks, the parabolas φ_s and φ_a, Table 2) have one home,
:mod:`rotor._paper`; the demo uses them from there.
"""

from __future__ import annotations

from rotor import TABLE2

MATERIALS = "steel,aluminium"
LC = "0.8mm"  # ISO 4288 cut-off for Ra in 0.1-2 µm
PLATE_LEVEL = "plane"  # a least-squares line on each row
BALL_LEVEL = "poly:2"  # a parabola takes the ball's curvature off each row
ROW_PARAMETERS = ("Ra", "Rq", "Rz", "Rt")

#: Table 2 of the paper (:data:`rotor.TABLE2`), means of its three profiles, m:
#: the plate's four row parameters, and the ball's Ra and Rq (the two the demo compares).
PAPER_TABLE2_MEAN = {
    surface: {p: sum(row[p] for row in TABLE2[surface]) / len(TABLE2[surface]) for p in params}
    for surface, params in (("plate", ROW_PARAMETERS), ("ball", ("Ra", "Rq")))
}
