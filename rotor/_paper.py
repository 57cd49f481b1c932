"""The facts of Alaci, Ciornei & Romanu (2022) that the rotor study uses, in one place.

Everything here is a number printed in the paper (or the paper's Table 3 as printed); the
code that computes with them lives beside (:mod:`rotor._mechanics` builds the rotor
from the dimensions, :mod:`rotor._frames` splits the printed rows). SI units.

References
----------
Alaci S., Ciornei F.-C., Romanu I.-C. (2022) Validation of nonlinear dependence of rolling
friction moment on the normal force for elastic materials. Materials 15(7):2518,
doi:10.3390/ma15072518. Section 2.2.2 (the rotor), Section 3 (the Hertz check), Section 4
and Table 3 (the filmed launches).
"""

from __future__ import annotations

import math

__all__ = [
    "BALL_DENSITY",
    "BALL_RADIUS",
    "CENTRE_DISTANCE",
    "COLLAR_DENSITY",
    "COLLAR_INNER_RADIUS",
    "COLLAR_LENGTH",
    "COLLAR_OUTER_RADIUS",
    "FPS",
    "HERTZ_CHECK",
    "HERTZ_CHECK_LOAD",
    "MARK_STEP",
    "PARABOLAS",
    "ROD_DENSITY",
    "ROD_RADIUS",
    "TABLE2",
    "TABLE3_COLUMNS",
    "TABLE3_FILENAME",
    "TABLE3_PRINTED_ROWS",
]

# --- the rotor (Section 2.2.2): two steel balls joined by an aluminium rod, a steel collar ---
BALL_RADIUS = 0.02
"""Radius of the rotor's steel balls (and of the ball in the contact study), m."""
BALL_DENSITY = 7800.0
"""Steel, kg/m^3."""
CENTRE_DISTANCE = 0.14
"""Distance between the balls' centres, m."""
ROD_RADIUS = 0.006
"""Radius of the aluminium rod, m."""
ROD_DENSITY = 2700.0
"""Aluminium, kg/m^3."""
COLLAR_LENGTH = 0.05
"""Length of the steel collar, m."""
COLLAR_OUTER_RADIUS = 0.019
"""Outer radius of the collar, m."""
COLLAR_INNER_RADIUS = 0.006
"""Bore of the collar (the rod's radius), m."""
COLLAR_DENSITY = 7800.0
"""Steel, kg/m^3."""

# --- the film (Section 4, Table 3) ---
FPS = 120.0
"""Frame rate of the camera that filmed the launches, 1/s."""
MARK_STEP = math.pi / 2
"""Rotation between successive rows of Table 3 (a quarter turn), rad."""
TABLE3_COLUMNS = ("as1", "as2", "as3", "s1", "s2", "s3")
"""Table 3's columns: ``as1..as3`` the asymmetric collar (tests 1-3), ``s1..s3`` the
symmetric collar."""
TABLE3_PRINTED_ROWS = (
    "120712314596511226",
    "2220037517510821131351",
    "3226343323411371681406",
    "4230747727811832131451",
    "5234851631712232561492",
    "6238455235412572911526",
    "7241757438612883231558",
    "8244761441613183521587",
    "9247564144513443791614",
    "10250066747213714041639",
    "11252669249813954291663",
    "12255071552314174511686",
    "13257373754614394731707",
    "14259676056914614941729",
    "15261878259114815151749",
    "16263980361215015351769",
    "17266082363315215541789",
    "18268184465415405731808",
    "19270186467315595911826",
    "20272188469315776001844",
    "21274090371315956271864",
    "22276092273216136451869",
    "23278094175116386641896",
    "24279995177016476781912",
    "25281897878816676951928",
)
"""Table 3 as printed (row number first, then the six frame indices, no spaces)."""
TABLE3_FILENAME = "table3_frames.tsv"
"""Name of the split table (``k`` then the six columns) where it is shipped as data."""
PARABOLAS = {"phi_s": (0.821, 1.134, -0.527), "phi_a": (0.951, 1.0254, -0.249)}
"""The paper's fitted parabolas ``phi = c2 t^2 + c1 t + c0`` (rad, t in s), symmetric and
asymmetric rotor, as printed."""

# --- the Hertz check (Section 3) ---
HERTZ_CHECK_LOAD = 10.0
"""Load of the paper's Hertz check ("the rotor weight"), N."""
HERTZ_CHECK = {"delta": 0.936e-6, "a": 136e-6}
"""The paper's Hertz check at :data:`HERTZ_CHECK_LOAD`: approach and contact radius, m."""

# --- the roughness of the contact pair (Table 2) ---
TABLE2 = {
    "plate": ({"Ra": 1.776e-6, "Rq": 2.342e-6, "Rz": 11.220e-6, "Rt": 16.256e-6},
              {"Ra": 1.263e-6, "Rq": 1.629e-6, "Rz": 9.277e-6, "Rt": 11.337e-6},
              {"Ra": 2.165e-6, "Rq": 2.639e-6, "Rz": 13.566e-6, "Rt": 13.566e-6}),
    "ball": ({"Ra": 0.209e-6, "Rq": 0.330e-6, "Rz": 2.453e-6, "Rt": 3.889e-6},
             {"Ra": 0.230e-6, "Rq": 0.329e-6, "Rz": 1.109e-6, "Rt": 2.553e-6},
             {"Ra": 0.192e-6, "Rq": 0.290e-6, "Rz": 2.137e-6, "Rt": 3.948e-6}),
}
"""Table 2: the R-parameters of the three measured profiles of the aluminium plate and of
the steel ball, as printed, m."""
