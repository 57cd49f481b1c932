"""Issue 34 item 16: the pictures' labels lie inside their figures and name what is drawn.

The rolling figure's "λ = 4/3" was text written at the reference line, cut off by the
axes' edge (or crossed by the data); the reference exponents are now legend entries, and
both reference lines lie within the axes whatever the data's range.
"""

from __future__ import annotations

import numpy as np
import pytest


def _sweep(exponent: float):
    from contact.viscoelastic._sweep import sweep_record

    loads = np.geomspace(1.0, 100.0, 5)
    return sweep_record("hysteresis", loads, 1e-4 * loads**exponent, 0.02,
                        {"alpha_h": 1.0})


@pytest.mark.parametrize("exponent", [1.9, 1.1, 0.6])
def test_rolling_reference_exponents_are_named_and_inside(exponent):
    from surfmet.plots._style import close
    from surfmet.plots.hertz import rolling_figure

    fig = rolling_figure(_sweep(exponent))
    fig.canvas.draw()
    ax_l = fig.axes[1]
    lo, hi = ax_l.get_ylim()
    assert lo < 1.0 < 4.0 / 3.0 < hi  # both reference lines are drawn inside the axes
    entries = [t.get_text() for t in ax_l.get_legend().get_texts()]
    assert any(e.startswith("λ = 4/3") for e in entries)
    assert any(e.startswith("λ = 1 ") for e in entries)
    # every text of the figure (titles, axis labels, texts, legends) lies inside it
    box = fig.bbox
    renderer = fig.canvas.get_renderer()
    texts = list(fig.texts)
    for ax in fig.axes:
        texts += [ax.title, ax.xaxis.label, ax.yaxis.label, *ax.texts]
        if ax.get_legend() is not None:
            texts += ax.get_legend().get_texts()
    for text in texts:
        if not text.get_text() or not text.get_visible():
            continue
        ext = text.get_window_extent(renderer)
        assert ext.x0 >= box.x0 - 1 and ext.x1 <= box.x1 + 1, text.get_text()
        assert ext.y0 >= box.y0 - 1 and ext.y1 <= box.y1 + 1, text.get_text()
    # and no "λ" text is written on the axes, where their edge or the data would cut it
    assert not [t for t in ax_l.texts if t.get_text().startswith("λ")]
    close(fig)


def test_abbott_legend_does_not_cover_its_note():
    # a spiky surface: the height axis is clipped and the figure says so; the note was
    # drawn in the lower right, under the legend of the construction (the report's page)
    from surfmet._model import Topography
    from surfmet.plots._style import close
    from surfmet.plots.areal import abbott_firestone
    from surfmet.roughness import roughness

    rng = np.random.default_rng(3)
    z = rng.normal(0, 1e-6, (128, 128))
    z[rng.integers(0, 128, 30), rng.integers(0, 128, 30)] = 40e-6
    topo = Topography(heights=z, dx=1e-6, dy=1e-6)
    res = roughness(topo, which=("functional",))
    params = {k: res.value(k) for k in ("Sk", "Spk", "Svk", "Smr1", "Smr2")}
    fig = abbott_firestone(topo, parameters=params)
    fig.canvas.draw()
    ax = fig.axes[0]
    legend = ax.get_legend()
    box = legend.get_window_extent()
    shown = [t.get_text() for t in ax.texts] + [t.get_text() for t in legend.get_texts()]
    assert any(s.startswith("axis clipped") for s in shown)
    for text in ax.texts:
        assert not text.get_window_extent().overlaps(box), text.get_text()
    close(fig)


@pytest.mark.parametrize("shape", [(650, 650, 1.28e-7, 3.15e-7), (1000, 400, 1e-6, 1e-6),
                                   (512, 1024, 5e-6, 5e-6)])
def test_height_map_fills_its_panel(shape):
    # the narrow x3p-2 map (650 x 650 points of 0.128 x 0.315 µm: 83 x 204 µm) left half
    # its panel blank: the figure takes the map's shape, so the map spans most of the
    # figure along its long side and a good share along the other (labels and the colour
    # bar take the rest)
    from surfmet._model import Topography
    from surfmet.plots._style import close
    from surfmet.plots.areal import height_map

    ny, nx, dx, dy = shape
    z = np.random.default_rng(0).normal(0, 1e-7, (ny, nx))
    fig = height_map(Topography(heights=z, dx=dx, dy=dy))
    fig.canvas.draw()
    image, figure = fig.axes[0].get_window_extent(), fig.bbox
    shares = sorted((image.width / figure.width, image.height / figure.height))
    assert shares[1] > 0.75 and shares[0] > 0.4, shares
    close(fig)
