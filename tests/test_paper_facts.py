"""The paper's facts have one home, :mod:`rotor._paper` (DEVELOPERS.md: one home per
fact). Checked against the independent transcription in
../shared/data/paper_2022/paper_values.json, and by looking for the printed numbers anywhere
else in the package's source.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rotor import _paper as paper

ROOT = Path(__file__).resolve().parents[1]
SURFACES = {"plate": "aluminium_plate", "ball": "steel_ball"}


@pytest.fixture
def table2(paperdata):
    # the conftest fixture skips outside CI and fails under CI=true when the file is missing
    return json.loads(paperdata("paper_values.json").read_text())["table2_profile_um"]


def test_table2_is_the_printed_table(table2):
    for ours, theirs in SURFACES.items():
        assert len(paper.TABLE2[ours]) == len(table2[theirs])
        for row, printed in zip(paper.TABLE2[ours], table2[theirs]):
            assert set(row) == set(printed)
            for key, um in printed.items():
                assert row[key] == pytest.approx(um * 1e-6, rel=1e-12), (ours, key)


def test_demo_compares_with_the_means_of_table2(table2):
    from surfmet.demo._settings import PAPER_TABLE2_MEAN

    for ours, theirs in SURFACES.items():
        assert PAPER_TABLE2_MEAN[ours]
        for key, mean in PAPER_TABLE2_MEAN[ours].items():
            rows = [r[key] for r in table2[theirs]]
            assert mean == pytest.approx(sum(rows) / len(rows) * 1e-6, rel=1e-12), (ours, key)
    assert set(PAPER_TABLE2_MEAN["plate"]) == {"Ra", "Rq", "Rz", "Rt"}


def test_table2_numbers_live_only_in_paper_py():
    # numbers printed in Table 2 that no other fact shares
    printed = ("1.776", "16.256", "9.277", "2.165", "0.209", "3.889")
    home = ROOT / "rotor" / "_paper.py"
    found = []
    for folder in ("contact", "surfmet", "profiles", "rotor"):
        for src in (ROOT / folder).rglob("*.py"):
            if src == home:
                continue
            text = src.read_text(encoding="utf-8")
            found += [f"{src.relative_to(ROOT)}: {n}" for n in printed if n in text]
    assert not found, found
