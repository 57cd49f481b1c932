"""The rotor's residual figure hides no data and names each model one way (issue 16, item 14):
no legend inside a panel, one legend for the figure, and each panel's title names the
chosen model exactly as the analysis does."""

from __future__ import annotations

import pytest

from rotor._groups import analyse_table
from rotor._simulator import simulate_random_run


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
    assert "model rest" in labels  # the paper's model, as the demo's table names it
    assert any(lab.startswith("chosen model") for lab in labels)


def test_titles_print_the_paper_models_rms_as_the_demos_table(figure):
    # issue 34 item 16: the titles said "rms const 5.27" where the demo's table says
    # "rms rest 13.36": one quantity, one name. The truth: the rms of the paper's model's
    # residuals over the rows it used, in frames
    import numpy as np

    fig, an = figure
    titles = {ax.get_title().split(":")[0]: ax.get_title() for ax in fig.axes if ax.has_data()}
    for t in an.tests:
        fit = t.fits["rest"]
        used = np.asarray(fit.used)
        rms = float(np.sqrt(np.mean(np.asarray(fit.residuals)[used] ** 2))) * an.fps
        assert f"rms rest {rms:.2f}," in titles[t.name]


def test_law_of_motion_legend_names_every_drawn_series():
    # issue 34 item 16: the legend listed only the paper's parabolas; every series drawn
    # (marks read, misread marks, chosen models, parabolas) has its entry, and every line
    # drawn looks like one of the entries
    from rotor._groups import analyse_table
    from rotor._simulator import simulate_random_run
    from surfmet.plots._style import close
    from surfmet.plots.rotor import law_of_motion_figure

    cols = {f"x{i}": list(simulate_random_run(seed, "none", n_misread=1).frames)
            for i, seed in ((1, 40), (2, 41))}
    an = analyse_table(cols)
    fig = law_of_motion_figure(an)
    ax = fig.axes[0]
    legend = ax.get_legend()
    entries = [txt.get_text() for txt in legend.get_texts()]
    style = {(h.get_color(), h.get_linestyle(), h.get_marker()): lab
             for h, lab in zip(legend.legend_handles, entries)}
    for line in ax.get_lines():
        if len(line.get_xdata()):
            key = (line.get_color(), line.get_linestyle(), line.get_marker())
            assert key in style, key
    for g in an.groups:
        assert any(e.startswith(f"{g.name}: marks read") for e in entries)
        assert any(e.startswith(f"{g.name}: chosen models") for e in entries)
    if any(len(t.outliers) for t in an.tests):
        assert any(e.startswith("misread") for e in entries)
    close(fig)
