"""
Read a scan and compute its roughness
=====================================

Read the bundled stand-in of the paper's aluminium plate, compute its ISO 25178-2
S-parameters after plane levelling with a 0.8 mm λc and a 25 µm λs filter, and draw the
levelled height map. Every value comes back in SI with its unit.
"""

import surfmet
from surfmet.data import path
from surfmet.plots.areal import height_map
from surfmet.roughness import roughness
from surfmet.units import format_quantity

plate = surfmet.read(path("paper_plate.x3p"))
print(f"{plate.nx} x {plate.ny} points, pixel {plate.dx * 1e6:.1f} µm")

# %%
# The roughness call is the one ``surfmet roughness`` makes: the same defaults, the same
# record (``surfmet.records._roughness.roughness_record(res)`` is the command's ``--json``).

res = roughness(plate, level="plane", lc="0.8mm", ls="25um", spikes=True)
for name in ("Sa", "Sq", "Sz", "Ssk", "Sku"):
    value, unit = res.parameters[name]  # SI value and its unit
    print(f"{name:4s} {format_quantity(value, unit)}")

# %%
# The surface the parameters were computed on (plane removed, filtered):

fig = height_map(res.surface)
