"""Two ways of asking the same question give the same answer (issue 16, item 5): the CLI,
the API and the report share one default per quantity (the grid: the scans' own pixel)
and every result states its grid and pixel.

On main the CLI's hertz-check gave approach 2.634 µm and a* 311 µm at 4.7 N while the API
and the report gave 3.851 µm and 318 µm (different default grids, unstated).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from surfmet.cli import main
from surfmet.records._hertz import hertz_check_record
from surfmet.records._rolling import rolling_record

DATA = Path(__file__).resolve().parents[1] / "surfmet" / "data"
PLATE, BALL = str(DATA / "paper_plate.x3p"), str(DATA / "paper_ball.x3p")
SETUP = {"radius": 0.01, "load": 4.7, "materials": "steel,aluminium"}


def _cli(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


@pytest.fixture(scope="module")
def api_check():
    from surfmet.mechanics.hertz_check import hertz_check

    return hertz_check(PLATE, ball=BALL, **SETUP)


def test_hertz_check_cli_and_api_agree(capsys, api_check):
    cli = _cli(capsys, ["hertz-check", PLATE, "--ball", BALL, "--radius", "10mm", "--load",
                        "4.7N", "--materials", "steel,aluminium", "--json"])
    api = hertz_check_record(api_check)
    assert api["grid"] == cli["grid"]  # the API states its grid too
    assert api["grid"]["pixel_source"] == "the scans' own pixel"
    for key in ("approach", "effective_radius", "contact_radius", "pmax"):
        assert api["bem"][key] == cli["bem"][key]
    assert api["hertz_holds"] == cli["hertz_holds"]


def test_report_states_the_same_grid_and_numbers(tmp_path, api_check):
    import surfmet
    from surfmet._report_hertz import HertzOptions, run_hertz_check

    rec = run_hertz_check(surfmet.read(PLATE), HertzOptions(0.01, 4.7, "steel,aluminium",
                                                              ball=BALL))
    api = hertz_check_record(api_check)
    assert rec["grid"] == api["grid"] and rec["bem"] == api["bem"]
    import html as html_lib

    from surfmet._report_hertz import hertz_html

    html = html_lib.unescape(hertz_html(rec, None, HertzOptions(0.01, 4.7, "steel,aluminium",
                                                                 ball=BALL)))
    g = rec["grid"]
    assert f"{g['nx']} × {g['ny']} cells" in html and "the scans' own pixel" in html


def test_rolling_cli_and_api_agree(capsys):
    from surfmet.mechanics.rolling_resistance import rolling_resistance

    cli = _cli(capsys, ["rolling", "--plate", PLATE, "--ball", BALL, "--radius", "20mm",
                        "--materials", "steel,aluminium", "--loads", "1N:10N:3", "--json"])
    api = rolling_record(rolling_resistance(PLATE, BALL, radius=0.02,
                                            materials="steel,aluminium", loads="1N:10N:3"))
    assert api["lambda_eff"] == cli["lambda_eff"]
    assert api["lambda_ci"] == cli["lambda_ci"]
    for key in ("grid", "dx", "pixel_source"):
        assert api["settings"][key] == cli["settings"][key]
