"""Areal height parameters (ISO 25178-2:2012, 4.1), over the measured points.

Sa = mean |z|, Sq = sqrt(mean z²), Sp = max z, Sv = -min z (a positive depth),
Sz = Sp + Sv, Ssk = mean z³ / Sq³, Sku = mean z⁴ / Sq⁴.
"""

from __future__ import annotations

import math

import numpy as np

from surfmet._model import Topography
from surfmet.areal._points import fixed_order_dot, heights_of, valid_values


def height_parameters(topo: Topography) -> dict[str, float]:
    """Sa, Sq, Sp, Sv, Sz, Ssk, Sku of the valid points (heights about their mean)."""
    v = valid_values(heights_of(topo))
    d = v - v.mean()
    d2 = d * d
    sq2 = float(d2.mean())
    sq = math.sqrt(sq2)
    sa = float(np.abs(d).mean())
    sp = float(d.max())
    sv = float(-d.min())
    if sq > 0:
        ssk = fixed_order_dot(d2, d) / d.size / sq**3
        sku = fixed_order_dot(d2, d2) / d.size / sq2**2
    else:
        ssk = sku = float("nan")
    return {"Sa": sa, "Sq": sq, "Sp": sp, "Sv": sv, "Sz": sp + sv, "Ssk": ssk, "Sku": sku}
