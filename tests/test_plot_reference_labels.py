"""Issue 34 item 16: the pictures' labels lie inside their figures and name what is drawn.

The rolling figure's "λ = 4/3" was text written at the reference line, cut off by the
axes' edge (or crossed by the data); the reference exponents are now legend entries, and
both reference lines lie within the axes whatever the data's range.
"""

from __future__ import annotations

import numpy as np
import pytest


def _sweep(exponent: float):
    from contact.viscoelastic.sweep import sweep_record

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
