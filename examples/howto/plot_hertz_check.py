"""
Does Hertz hold for a scan?
===========================

Press the bundled steel ball scan on the bundled aluminium plate scan at 10 N (R = 20 mm)
and ask whether Hertz's smooth-sphere answer holds for this pair of rough surfaces. The
boundary-element solve runs here on a 64 x 64 grid to keep the example fast; the command
(``surfmet hertz-check``) uses the scans' own pixel by default.
"""

from surfmet.data import path
from surfmet.mechanics.hertz_check import hertz_check

chk = hertz_check(path("paper_plate.x3p"), ball=path("paper_ball.x3p"), radius=0.02,
                  load=10.0, materials="steel,aluminium", grid=64)
print("Hertz holds:", chk.hertz_holds)
print(f"GJM alpha = {chk.alpha:.3g}")
for reason in chk.reasons:
    print(" -", reason)

# %%
# The pressure map and the azimuthally averaged pressure against Hertz's:

chk.figure()
