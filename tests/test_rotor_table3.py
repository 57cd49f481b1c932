"""Table 3 typed from the paper: the run-together rows split back into frame indices."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from contact._errors import ContactInputError
from rotor._frames import split_rows, table3, table3_tsv
from rotor._paper import TABLE3_COLUMNS as COLUMNS
from rotor._paper import TABLE3_PRINTED_ROWS as PRINTED_ROWS

SHIPPED = Path(__file__).resolve().parents[1] / "surfmet" / "data" / "table3_frames.tsv"


def test_split_equals_the_shared_parse(paperdata):
    ref = np.loadtxt(paperdata("table3_frames.tsv"), skiprows=1, dtype=int)
    header = paperdata("table3_frames.tsv").read_text().splitlines()[0].split("\t")
    assert tuple(header[1:]) == COLUMNS
    got = split_rows(PRINTED_ROWS)
    assert np.array_equal(got, ref[:, 1:])
    assert np.array_equal(ref[:, 0], np.arange(1, 26))


def test_shipped_tsv_is_the_parser_output(paperdata):
    assert SHIPPED.read_text() == table3_tsv()
    assert SHIPPED.read_text() == paperdata("table3_frames.tsv").read_text()


def test_every_printed_row_is_its_split_run_together():
    t = table3()
    for k, row in enumerate(PRINTED_ROWS, start=1):
        assert row == str(k) + "".join(str(int(t[c][k - 1])) for c in COLUMNS)


def test_increasing_columns_alone_are_ambiguous():
    # the first row and an s2/s3 alternative ('1131 351' for '113 1351') need the launch
    # physics to be settled
    with pytest.raises(ContactInputError, match="not unique"):
        split_rows(PRINTED_ROWS, first_ratio=None)
    with pytest.raises(ContactInputError, match="not unique"):
        split_rows(PRINTED_ROWS, duration_factor=None)


def test_malformed_rows_raise():
    with pytest.raises(ContactInputError, match="start with its number"):
        split_rows(["2123", "3456"], n_columns=1)
    with pytest.raises(ContactInputError, match="digits"):
        split_rows(["1 2 3"], n_columns=2)
    with pytest.raises(ContactInputError, match="increasing"):
        split_rows(["19", "25"], n_columns=1, first_ratio=None)
    with pytest.raises(ContactInputError):
        split_rows([])
