"""The Dektak's own roughness numbers, reproduced from its exported profile.

``dektak-1.csv`` carries, in its "Analytical Results" block, what the instrument software
computed between its cursors R = 468 µm and M = 733 µm:

    Ra 0.00525 µm, Rq 0.01143 µm, Skew 6.96, RzDin 0.04917 µm,
    Wa = Ra, Wq = Rq (so no λc filter was applied), WMaxDev 0.12861 µm.

Reverse-engineered processing (see profiles._analysis): the points nearest the two cursors
(inclusive, indices 2995..4691 of 9600), a least-squares line over that window, no filter,
RzDin = mean peak-to-valley of 5 equal parts. The export prints x rounded to 0.1 µm while the
scan is uniform at 1500 µm / 9600 = 0.15625 µm; fitting the line against the printed
(rounded) x changes Rq and Skew in their last printed digit, against the uniform grid it
matches every digit. Tolerances are half a unit of the last printed digit.
"""

from __future__ import annotations

import numpy as np
import pytest

import surfmet
from profiles import analyze_profile
from surfmet.units import parse_length_range

pytestmark = pytest.mark.realdata

UM = 1e-6
PRINTED = {  # value (µm or dimensionless), half a unit of the last printed digit
    "Ra": (0.00525, 0.000005),
    "Rq": (0.01143, 0.000005),
    "Rsk": (6.96, 0.005),
    "Rz": (0.04917, 0.000005),
}


@pytest.fixture
def dektak_analysis(realdata):
    profile = surfmet.read(realdata("dektak-1.csv"))
    return analyze_profile(
        profile.z,
        profile.dx,
        x=profile.x,
        window=parse_length_range("468um:733um"),
        level="plane",
    )


def test_instrument_ra_rq_skew_to_printed_digits(dektak_analysis):
    p = dektak_analysis.parameters
    assert abs(p.Ra / UM - PRINTED["Ra"][0]) <= PRINTED["Ra"][1]
    assert abs(p.Rq / UM - PRINTED["Rq"][0]) <= PRINTED["Rq"][1]
    assert abs(p.Rsk - PRINTED["Rsk"][0]) <= PRINTED["Rsk"][1]


def test_instrument_rzdin(dektak_analysis):
    p = dektak_analysis.parameters
    assert p.Rz / UM == pytest.approx(PRINTED["Rz"][0], rel=0.02)  # the contract
    assert abs(p.Rz / UM - PRINTED["Rz"][0]) <= PRINTED["Rz"][1]  # what we actually get


def test_instrument_unfiltered_results_and_settings(dektak_analysis):
    a = dektak_analysis
    # WMaxDev: largest deviation from the least-squares line in the window
    assert abs(np.nanmax(np.abs(a.roughness)) / UM - 0.12861) <= 0.000005
    s = a.settings
    assert s["window_points"] == [2995, 4691]
    assert s["points_used"] == 1697
    assert s["level"] == "line"
    assert s["positions"]["method"] == "uniform-rounded"
    assert s["dx"] == pytest.approx(1500e-6 / 9600, rel=1e-5)
    # the 265 µm window is shorter than ISO 4288's 0.4 mm for λc = 0.08 mm: no filter, said so
    assert s["lc"] is None
    assert s["lc_iso4288"]["lc"] == pytest.approx(0.08e-3)
    assert "no λc filter" in s["lc_note"]
    assert s["n_sampling"] == 5


def test_the_cli_command_reproduces_the_numbers_in_the_file_header(realdata, capsys):
    """The issue's contract, end to end: ``surfmet roughness dektak-1.csv --window
    468um:733um --level plane`` against the instrument's results as the file itself states
    them (parsed from its header, not typed here): Ra, Rq, Skew to their printed digits,
    RzDin within 2 %."""
    import json

    from surfmet.cli import main

    path = realdata("dektak-1.csv")
    stated = surfmet.read(path).metadata["instrument_results"]
    assert main(["roughness", str(path), "--window", "468um:733um", "--level", "plane",
                 "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)[0]
    got = rec["parameters"]
    # the 265 µm window is too short for ISO 4288's λc: no λc filter, so these are the
    # primary profile's values and carry its names (ISO 21920-2: Pa, Pq, Psk, Pz; issue
    # 34 item 15), which the instrument prints as Ra, Rq, Skew, RzDin
    assert rec["settings"]["profile_kind"].startswith("primary profile")
    for ours, theirs, half_digit in (("Pa", "Ra", 0.000005e-6), ("Pq", "Rq", 0.000005e-6),
                                     ("Psk", "Skew", 0.005)):
        assert got[ours]["unit"] == stated[theirs]["unit"]
        assert abs(got[ours]["value"] - stated[theirs]["value"]) <= half_digit * (1 + 1e-9)
    assert got["Pz"]["value"] == pytest.approx(stated["RzDin"]["value"], rel=0.02)
