"""A file without calibrated units carries its caveat into every output built from it
(issue 16, item 12): ``info`` says test.gwy states no lateral unit; ``roughness`` already
carried that caveat, ``spectrum``, ``flat-contact`` and the contact preparation did not.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from surfmet._model import Topography
from surfmet.cli import main


@pytest.fixture
def gwy(realdata):
    # the conftest fixture skips outside CI and fails under CI=true when the file is missing
    return str(realdata("test.gwy"))


def _uncalibrated(caveats):
    return {("lateral" if "lateral" in c else "height") for c in caveats
            if "assumed" in c}


def test_spectrum_carries_the_caveat(gwy, capsys):
    assert main(["spectrum", gwy, "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert _uncalibrated(rec["caveats"]) == {"lateral", "height"}
    assert main(["spectrum", gwy]) == 0
    assert capsys.readouterr().out.count(" assumed: the file states none") == 2


def test_flat_contact_carries_the_caveat(gwy, capsys):
    assert main(["flat-contact", gwy, "--materials", "steel,aluminium", "--pressures", "1MPa",
                 "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert _uncalibrated(rec["caveats"]) == {"lateral", "height"}


def test_calibrated_scan_has_no_caveat(capsys):
    """No unit caveat on a calibrated scan (other caveats, such as a Hurst band under a
    decade, are the spectrum's own business)."""
    assert main(["spectrum", "surfmet/data/paper_plate.x3p", "--json"]) == 0
    caveats = json.loads(capsys.readouterr().out)["caveats"]
    assert _uncalibrated(caveats) == set()
    assert not any("calibrat" in c for c in caveats)


def test_contact_preparation_states_the_caveat():
    from surfmet.mechanics.scan_preparation import prepare_scans

    rng = np.random.default_rng(3)
    z = 1e-6 * rng.standard_normal((64, 64))
    plain = Topography(z, 5e-6, 5e-6)
    bare = Topography(z, 5e-6, 5e-6, metadata={"lateral_calibrated": False})
    assert not [n for n in prepare_scans(plate=plain).notes if "CAVEAT" in n]
    notes = [n for n in prepare_scans(plate=bare).notes if "CAVEAT" in n]
    assert len(notes) == 1 and "plate" in notes[0] and "lateral" in notes[0]
