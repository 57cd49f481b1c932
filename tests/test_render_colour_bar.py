"""Issue 34 item 16: the 3D view's colour bar is labelled at round heights (it showed
1.07e+03, 146, -779 µm: equal fractions of the 1-99 % height range)."""

from __future__ import annotations

import math

import numpy as np
import pytest


def _is_round(values: list[float]) -> bool:
    """Equally spaced by 1, 2, 2.5 or 5 × 10ⁿ, each a whole multiple of that step."""
    if len(values) < 2:
        return False
    steps = np.diff(values)
    step = float(steps[0])
    if not np.allclose(steps, step, rtol=1e-9):
        return False
    scale = 10 ** math.floor(math.log10(step))
    nominal = [m * scale for m in (1, 2, 2.5, 5) if abs(step / scale - m) < 1e-6]
    return bool(nominal) and all(abs(v / nominal[0] - round(v / nominal[0])) < 1e-6
                                 for v in values)


@pytest.mark.parametrize("lo, hi", [(-779.0, 1070.0), (0.0123, 0.0876), (-3.3e-3, 2.1e-3),
                                    (146.0, 147.0), (5.0, 5.0001)])
def test_round_ticks_are_round_and_inside(lo, hi):
    from surfmet.plots._style import round_ticks

    ticks = round_ticks(lo, hi)
    assert 3 <= len(ticks) <= 7 and _is_round(ticks)
    assert lo <= ticks[0] and ticks[-1] <= hi


def test_the_3d_colour_bar_has_round_labels(monkeypatch):
    pv = pytest.importorskip("pyvista")
    from surfmet._model import Topography
    from surfmet._render import render_3d

    seen = {}
    shot = pv.Plotter.screenshot

    def spy(self, *args, **kwargs):
        bar = self.scalar_bar
        arr = bar.GetCustomLabels()
        seen["custom"] = bool(bar.GetUseCustomLabels())
        seen["labels"] = ([arr.GetValue(i) for i in range(arr.GetNumberOfTuples())]
                          if arr is not None else [])
        seen["range"] = bar.GetLookupTable().GetRange()
        return shot(self, *args, **kwargs)

    monkeypatch.setattr(pv.Plotter, "screenshot", spy)
    rng = np.random.default_rng(1)
    z = rng.normal(0, 400e-6, (60, 80)) + np.linspace(0, 300e-6, 80)
    render_3d(Topography(z, 1e-5, 1e-5), window_size=(320, 240))
    assert seen["custom"] and _is_round(seen["labels"]), seen
    lo, hi = seen["range"]
    assert all(lo <= v <= hi for v in seen["labels"])
