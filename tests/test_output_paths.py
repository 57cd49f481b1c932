"""Every output path is checked before the work starts (issue 16, item 7): a path that
cannot be written is one error line (exit 1) naming the option, and the computation is
never started, so that no result is lost at the end.

The computation of each command is replaced by a function that fails the test if called.
"""

from __future__ import annotations

import pytest

from surfmet.cli import main

PLATE = "surfmet/data/paper_plate.x3p"
BALL = "surfmet/data/paper_ball.x3p"
BALL_ARGS = ["--radius", "20mm", "--materials", "steel,aluminium"]


def _forbid(monkeypatch, target):
    def started(*a, **k):
        raise AssertionError(f"{target} started although the output path is unwritable")

    monkeypatch.setattr(target, started)


CASES = [
    ("surfmet.mechanics.ball_contact.ball_contact", "--out",
     ["contact", "--plate", PLATE, *BALL_ARGS, "--load", "10N", "--out", "{bad}/f.npz"]),
    ("surfmet.mechanics.hertz_check.hertz_check", "--plot",
     ["hertz-check", PLATE, *BALL_ARGS, "--load", "10N", "--plot", "{bad}/h.png"]),
    ("surfmet.mechanics.rolling_resistance.rolling_resistance", "--plot",
     ["rolling", "--plate", PLATE, *BALL_ARGS, "--loads", "1N:10N:3", "--plot",
      "{bad}/r.png"]),
    ("surfmet.mechanics.spectrum.spectrum", "--plot",
     ["spectrum", PLATE, "--plot", "{bad}/s.png"]),
    ("surfmet.mechanics.flat_contact.flat_contact", "--plot",
     ["flat-contact", PLATE, "--materials", "steel,aluminium", "--pressures", "1MPa",
      "--plot", "{bad}/f.png"]),
    ("surfmet.read", "-o", ["show", PLATE, "-o", "{bad}/v.png"]),
    ("surfmet.demo.run.load_scans", "--out", ["demo", "--out", "{file}/demo"]),
    ("surfmet.batch.batch_map", "--csv",
     ["roughness", PLATE, BALL, "--csv", "{bad}/t.csv"]),
    ("surfmet.frames.read_frames_table", "--plot",
     ["rotor", "paper2022", "--plot", "{bad}/r.png"]),
]


@pytest.mark.parametrize(("target", "option", "argv"), CASES,
                         ids=[c[2][0] for c in CASES])
def test_unwritable_output_fails_before_the_work(tmp_path, monkeypatch, capsys, target,
                                                 option, argv):
    _forbid(monkeypatch, target)
    a_file = tmp_path / "a_file"
    a_file.write_text("x")
    argv = [a.format(bad=tmp_path / "missing", file=a_file) for a in argv]
    rc = main(argv)
    err = capsys.readouterr().err
    assert rc == 1, err
    assert option in err and len(err.strip().splitlines()) == 1


def test_a_folder_as_output_file_is_refused(tmp_path, monkeypatch, capsys):
    _forbid(monkeypatch, "surfmet.mechanics.hertz_check.hertz_check")
    rc = main(["hertz-check", PLATE, *BALL_ARGS, "--load", "10N", "--plot", str(tmp_path)])
    err = capsys.readouterr().err
    assert rc == 1 and "is a folder" in err


def test_checking_leaves_no_file_behind(tmp_path):
    from surfmet.cli._common import check_output

    out = tmp_path / "new.png"
    check_output(out, "--plot")
    assert not out.exists()
    keep = tmp_path / "old.png"
    keep.write_bytes(b"data")
    check_output(keep, "--plot")
    assert keep.read_bytes() == b"data"
