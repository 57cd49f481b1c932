"""What the demo computes with: the settings of each step, and Table 2 of the paper.

The paper's rotor facts (the balls' radius, the Hertz check's load and its 0.936 µm and
136 µm, the film's frame rate and marks, the parabolas φ_s and φ_a) have one home,
:mod:`contact.rotor.paper`; the demo uses them from there.
"""

from __future__ import annotations

MATERIALS = "steel,aluminium"
LC = "0.8mm"  # ISO 4288 cut-off for Ra in 0.1-2 µm
PLATE_LEVEL = "plane"  # a least-squares line on each row
BALL_LEVEL = "poly:2"  # a parabola takes the ball's curvature off each row
ROW_PARAMETERS = ("Ra", "Rq", "Rz", "Rt")

#: Table 2 of the paper, means of its three profiles (µm).
PAPER_TABLE2_MEAN_UM = {
    "plate": {"Ra": (1.776 + 1.263 + 2.165) / 3, "Rq": (2.342 + 1.629 + 2.639) / 3,
              "Rz": (11.220 + 9.277 + 13.566) / 3, "Rt": (16.256 + 11.337 + 13.566) / 3},
    "ball": {"Ra": (0.209 + 0.230 + 0.192) / 3, "Rq": (0.330 + 0.329 + 0.290) / 3},
}
