"""The facades' results name their types (no ``Any``), and where a field may hold several
kinds the callers that need one kind say so with a clear error, not an AttributeError on
None or on the other kind (``PreparedScans.pair`` is None for two smooth bodies;
``Adhesion.result`` is a line's result for a cylinder). On main ``PreparedScans`` had no
``paired()`` and ``adhesion.plot`` of a line run died on ``dmt_pull_off``."""

from __future__ import annotations

import pytest

from surfmet import SurfmetInputError


def test_paired_names_what_is_missing_for_smooth_bodies():
    from surfmet.mechanics.scan_preparation import prepare_scans

    smooth = prepare_scans(None, None)
    assert smooth.pair is None
    with pytest.raises(SurfmetInputError, match="needs a scan"):
        smooth.paired()


def test_paired_is_the_pair_of_scans():
    import surfmet
    from surfmet.data import path
    from surfmet.mechanics.scan_preparation import prepare_scans

    prep = prepare_scans(surfmet.read(path("paper_plate.x3p")))
    assert prep.paired() is prep.pair


def test_the_sphere_plot_refuses_a_line_run():
    from surfmet.mechanics.adhesion import plot
    from surfmet.mechanics.adhesion_line import line_adhesion

    run = line_adhesion(1e-5, work=0.05, range_=2e-9, e_star=1e9, grid=64, steps=8)
    with pytest.raises(SurfmetInputError, match="line_plot"):
        plot(run)
