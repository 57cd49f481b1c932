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
    ("surfmet.demo._run.load_scans", "--out", ["demo", "--out", "{file}/demo"]),
    ("surfmet._batch.batch_map", "--csv",
     ["roughness", PLATE, BALL, "--csv", "{bad}/t.csv"]),
    ("surfmet._frames.read_frames_table", "--plot",
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


def test_report_refuses_a_folder_before_the_work(tmp_path, monkeypatch, capsys):
    """``report -o FOLDER`` is refused before any scan is evaluated (main: internal
    error after the work)."""
    _forbid(monkeypatch, "surfmet.report.scan_section")
    rc = main(["report", PLATE, "-o", str(tmp_path), "--no-3d", "--quiet"])
    err = capsys.readouterr().err
    assert rc == 1 and "is a folder" in err and len(err.strip().splitlines()) == 1


def _limited(max_bytes: int):
    """A child-process set-up that caps the size of any file it writes (RLIMIT_FSIZE: a
    write past the cap fails with EFBIG, as a full disk fails with ENOSPC)."""
    import resource
    import signal

    def setup():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # fail the write, do not kill
        resource.setrlimit(resource.RLIMIT_FSIZE, (max_bytes, max_bytes))

    return setup


@pytest.mark.parametrize("name, argv", [
    ("view.png", ["show", PLATE, "--2d", "-o", "{out}"]),
    ("table.csv", ["roughness", PLATE, BALL, "--csv", "{out}"]),
    ("report.html", ["report", PLATE, "--no-3d", "--quiet", "-o", "{out}"]),
], ids=["show", "roughness-csv", "report"])
def test_a_write_the_disk_refuses_is_one_line_and_keeps_the_old_file(tmp_path, name, argv):
    """The output cannot be written in full (file size capped below its size): one line,
    exit 1, the earlier file untouched and no partial file left; main wrote in place
    (a truncated file that looks complete, the old one destroyed) and, for the report
    and the figure, called it an internal error (exit 2)."""
    import os
    import subprocess
    import sys

    out = tmp_path / name
    out.write_bytes(b"OLD")
    cmd = [sys.executable, "-m", "surfmet", *[a.format(out=out) for a in argv]]
    cap = 200 if name.endswith(".csv") else 20_000
    run = subprocess.run(cmd, capture_output=True, text=True, preexec_fn=_limited(cap),
                         cwd=os.getcwd(), timeout=300)
    lines = [ln for ln in run.stderr.strip().splitlines() if ln.startswith("surfmet:")]
    assert run.returncode == 1, run.stderr
    assert len(lines) == 1 and f"cannot write {out}" in lines[0], run.stderr
    assert out.read_bytes() == b"OLD"
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]


def test_atomic_write_replaces_whole(tmp_path):
    """A successful write replaces the earlier file whole, with a plain file's
    permissions (0666 less the umask), and leaves nothing beside it."""
    import os

    from surfmet._atomic import write_text

    out = tmp_path / "a.txt"
    out.write_text("old")
    write_text(out, "new text")
    assert out.read_text() == "new text"
    umask = os.umask(0)
    os.umask(umask)
    assert out.stat().st_mode & 0o777 == 0o666 & ~umask
    assert [p.name for p in tmp_path.iterdir()] == ["a.txt"]
