"""
Multi-scale analysis of a container
===================================

A contact.engineering container holds several measurements of one surface, each reliable
over its own band of scales. ``surfmet.io.read_container`` reads them all;
:func:`surfmet.scale_dependent.analyze_scales` computes the scale-dependent rms slope and
curvature, the height-difference ACF and the PSD, each averaged over the measurements that
resolve each scale (Sanner et al. 2022).

The container is one of the instrument files in ``../shared/realdata`` beside the checkout
(they are not redistributed with surfmet); without it this example builds a container of
two measurements of one synthetic surface.
"""

from pathlib import Path

import numpy as np

from surfmet.io import read_container
from surfmet.plots.scales import scales_figure
from surfmet.scale_dependent import analyze_scales
from surfmet.units import format_quantity

try:
    HERE = Path(__file__).resolve().parent
except NameError:  # run interactively
    HERE = Path.cwd()
CONTAINER = HERE.parents[1] / ".." / "shared" / "realdata" / "container-2.zip"

if CONTAINER.exists():
    measurements = read_container(CONTAINER)
else:
    from surfmet.synth import self_affine

    big = self_affine(128, 1e-6, hurst=0.8, slope_rms=0.1, seed=1)
    fine = self_affine(128, 0.1e-6, hurst=0.8, slope_rms=0.1, seed=2)
    measurements = [big, fine]
for m in measurements:
    print(type(m).__name__, m.metadata.get("name", ""))

# %%
# The averaged statistics, and which measurement contributes at which scale:

a = analyze_scales(measurements)
d = a.distance[np.isfinite(a.rms_slope)]
print(f"rms slope measured from {format_quantity(d.min(), 'm')} to {format_quantity(d.max(), 'm')}")
fig = scales_figure(a)
