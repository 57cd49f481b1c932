"""Negative-looking values are values (issue 16, item 10): ``--load -5N`` with a space
reaches the load's own check, so the user reads the domain error ("must be positive"),
not argparse's "expected one argument"."""

from __future__ import annotations

import pytest

from surfmet.cli import main

MAT = ["--materials", "steel,aluminium"]


@pytest.mark.parametrize(("argv", "words"), [
    (["contact", "--radius", "20mm", "--load", "-5N", *MAT], "load must be positive"),
    (["contact", "--radius", "20mm", "--load", "-5", *MAT], "load must be positive"),
    (["contact", "--radius", "-20mm", "--load", "5N", *MAT], "must be positive"),
    (["hertz-check", "surfmet/data/paper_plate.x3p", "--radius", "20mm", "--load", "-5N",
      *MAT], "load must be a positive force"),
    (["rolling", "--radius", "20mm", "--loads", "-1N:10N", *MAT], "0 < START < END"),
    (["contact", "--radius", "20mm", "--load", "5N", "--hardness", "-.5GPa", *MAT],
     "must be positive"),
])
def test_negative_values_reach_their_check(capsys, argv, words):
    rc = main(argv)
    err = capsys.readouterr().err
    assert rc == 1
    assert words in err and "expected one argument" not in err
    assert len(err.strip().splitlines()) == 1


def test_flags_and_positionals_are_untouched():
    from surfmet.cli import build_parser, negative_values

    parser = build_parser()
    argv = ["contact", "--plastic", "--load", "-5N", "--radius", "-1mm"]
    assert negative_values(parser, argv) == ["contact", "--plastic", "--load=-5N",
                                             "--radius=-1mm"]
    assert negative_values(parser, ["info", "-5.x3p"]) == ["info", "-5.x3p"]
