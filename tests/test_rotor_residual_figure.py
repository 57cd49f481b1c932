"""The rotor's residual figure hides no data and names each model one way (issue 16, item 14):
no legend inside a panel, one legend for the figure, and each panel's title names the
chosen model exactly as the analysis does."""

from __future__ import annotations

import pytest

from contact.rotor.groups import analyse_table
from contact.rotor.simulator import simulate_random_run


@pytest.fixture(scope="module")
def figure():
    from surfmet.plots._style import close
    from surfmet.plots.rotor import residual_figure

    cols = {f"x{i}": list(simulate_random_run(seed, "none", n_misread=0).frames)
            for i, seed in ((1, 40), (2, 41))}
    an = analyse_table(cols)
    fig = residual_figure(an)
    yield fig, an
    close(fig)


def test_no_legend_covers_a_panel(figure):
    fig, _ = figure
    panels = [ax for ax in fig.axes if ax.has_data()]
    assert panels and all(ax.get_legend() is None for ax in panels)
    assert len(fig.legends) == 1


def test_titles_name_the_chosen_model_and_the_legend_the_same_roles(figure):
    fig, an = figure
    titles = {ax.get_title().split(":")[0]: ax.get_title() for ax in fig.axes if ax.has_data()}
    for t in an.tests:
        assert f"chosen model {t.fit.model}" in titles[t.name]
    labels = [txt.get_text() for txt in fig.legends[0].get_texts()]
    assert "model const" in labels
    assert any(lab.startswith("chosen model") for lab in labels)
