"""What the demo computes with: the paper's set-up and the settings of each step.

The paper's own numbers that the story quotes (Table 2's means, the Hertz check's 0.936 µm
and 136 µm, the parabolas φ_s and φ_a) are re-typed from Alaci et al. (2022).
"""

from __future__ import annotations

RADIUS = 0.02  # m, nominal radius of the rotor's balls
MATERIALS = "steel,aluminium"
CHECK_LOAD = 10.0  # N, the load of the paper's Hertz check ("the rotor weight")
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
#: The paper's Hertz check at 10 N (Section 3): approach and contact radius (m).
PAPER_HERTZ = {"delta": 0.936e-6, "a": 136e-6}
#: The paper's parabolas (Section 4): phi = c2 t^2 + c1 t + c0 (rad, t in s).
PAPER_PARABOLAS = {"phi_s": (0.821, 1.134, -0.527), "phi_a": (0.951, 1.0254, -0.249)}
