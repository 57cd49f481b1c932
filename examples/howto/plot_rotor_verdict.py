"""
The rotor verdict
=================

Alaci, Ciornei & Romanu (2022) read a difference between the rotor's two collar positions as
evidence that the rolling-friction moment is not linear in the normal force. The verdict
fits all six launches of their Table 3 together and says whether that difference can be laid
to rolling friction at all (``surfmet rotor paper2022`` prints the same lines).
"""

import matplotlib.pyplot as plt

from surfmet.mechanics.rotor_verdict import paper_verdict, verdict_lines
from surfmet.plots.rotor_verdict import draw_verdict

v = paper_verdict()
print("\n".join(verdict_lines(v)[:6]))

# %%
# The local accelerations of both groups along the track with the joint model, and the
# exponent λ the offset would need against the plate's slope:

fig = draw_verdict(v)
plt.show()
