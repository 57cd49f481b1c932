"""The sweep's output files: --resume rewrites only what a sweep wrote, one file is one
lock and one write whichever name reaches it (symbolic links), and one file is not given
for two outputs."""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from surfmet._atomic import write_text
from surfmet.cli import main

ROOT = Path(__file__).resolve().parents[1]
PLATE = str(ROOT / "surfmet" / "data" / "paper_plate.x3p")
SMOOTH = ["sweep", "--task", "contact", "--radius", "20mm", "--loads", "1N:10N:3",
          "--grid", "16", "--workers", "1", "--quiet"]


def _one_error_line(capsys) -> str:
    err = [ln for ln in capsys.readouterr().err.splitlines() if ln.strip()]
    assert len(err) == 1, err
    return err[0]


def test_resume_refuses_a_json_lines_file_no_sweep_wrote(tmp_path, capsys):
    """A notebook's JSON Lines file given to --resume is refused and kept byte for byte
    (main: erased to nothing, exit 0)."""
    notes = tmp_path / "notebook.jsonl"
    text = '{"cell": 1, "note": "keep me"}\n{"cell": 2}\n'
    notes.write_text(text)
    assert main([*SMOOTH, "--json", str(notes), "--resume"]) == 1
    line = _one_error_line(capsys)
    assert "notebook.jsonl" in line and "not the JSON Lines output of a contact sweep" in line
    assert notes.read_text() == text


def test_resume_refuses_a_csv_of_one_unterminated_line(tmp_path, capsys):
    """A CSV whose only line has no newline is not a sweep's (main: erased to a header)."""
    table = tmp_path / "table.csv"
    table.write_text("a,b,c")
    assert main([*SMOOTH, "--csv", str(table), "--resume"]) == 1
    assert "not the CSV output of a contact sweep" in _one_error_line(capsys)
    assert table.read_text() == "a,b,c"


def test_resume_of_a_header_cut_short_starts_afresh(tmp_path):
    """A stop while the JSON header was being written leaves part of it: a fresh file."""
    out = tmp_path / "s.jsonl"
    assert main([*SMOOTH, "--json", str(out)]) == 0
    whole = out.read_text()
    out.write_text(whole[:30])
    assert main([*SMOOTH, "--json", str(out), "--resume"]) == 0
    assert len(out.read_text().splitlines()) == 4  # the header and three rows


def test_resume_of_a_hertz_check_file_as_contact_is_refused(tmp_path, capsys):
    out = tmp_path / "s.jsonl"
    assert main([*SMOOTH, "--task", "hertz-check", "--json", str(out)]) == 0
    before = out.read_text()
    capsys.readouterr()
    assert main([*SMOOTH, "--json", str(out), "--resume"]) == 1
    assert "not the JSON Lines output of a contact sweep" in _one_error_line(capsys)
    assert out.read_text() == before


def test_one_file_for_csv_and_json_is_named_as_such(tmp_path, capsys):
    """--csv X --json X: one line saying so (main: "being written by another run (process
    <its own id>)"); a link to X for the other output is the same file."""
    out = tmp_path / "s.out"
    link = tmp_path / "link.out"
    link.symlink_to(out)
    for other in (out, link):
        assert main([*SMOOTH, "--csv", str(out), "--json", str(other)]) == 1
        line = _one_error_line(capsys)
        assert "are the same file" in line and "another run" not in line


def test_an_atomic_write_through_a_link_writes_its_target(tmp_path):
    """The new content replaces the file the link points to and the link stays (main:
    the link was replaced by a new file, its target left unchanged)."""
    target = tmp_path / "real.txt"
    target.write_text("old")
    link = tmp_path / "link.txt"
    link.symlink_to(target)
    write_text(link, "new")
    assert link.is_symlink() and os.readlink(link) == str(target)
    assert target.read_text() == "new"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.txt", "real.txt"]


def test_resume_through_a_link_keeps_the_link(tmp_path):
    """A --resume that drops a cut row rewrites the file the link names (main: it
    replaced the link with a new file and the sweep's own file kept its cut row)."""
    real = tmp_path / "real.csv"
    link = tmp_path / "link.csv"
    assert main([*SMOOTH, "--csv", str(real)]) == 0
    lines = real.read_text().splitlines(keepends=True)
    real.write_text("".join(lines[:3]) + lines[3][:25])  # header, two rows, a cut row
    link.symlink_to(real)
    assert main([*SMOOTH, "--csv", str(link), "--resume"]) == 0
    assert link.is_symlink()
    assert real.read_text() == "".join(lines)  # the cut row run again (deterministic)


@pytest.mark.skipif(not hasattr(os, "symlink"), reason="needs symbolic links")
def test_a_link_to_a_file_a_sweep_is_writing_is_refused(tmp_path):
    """Two processes: a sweep writes real.csv; a second one given link.csv -> real.csv is
    refused in one line while the first runs, and no row is written twice (main: each
    took its own lock and both appended, every row twice)."""
    real = tmp_path / "real.csv"
    link = tmp_path / "link.csv"
    link.symlink_to(real)
    cmd = [sys.executable, "-m", "surfmet", "sweep", "--plates", PLATE, "--radius", "20mm",
           "--loads", "1N:20N:8", "--positions", "0:0,0.2mm:0", "--grid", "96",
           "--workers", "1", "--quiet"]  # 16 items: long enough for the second to start
    first = subprocess.Popen([*cmd, "--csv", str(real)], cwd=ROOT, stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL, start_new_session=True)
    try:
        deadline = time.monotonic() + 120
        lock = tmp_path / ".real.csv.lock"
        while time.monotonic() < deadline and first.poll() is None and not (
                lock.exists() and lock.read_text().strip()):
            time.sleep(0.05)
        assert first.poll() is None, "the first sweep ended before the second could start"
        second = subprocess.run([*cmd, "--csv", str(link), "--resume"], cwd=ROOT,
                                capture_output=True, text=True, timeout=300)
        lines = [ln for ln in second.stderr.splitlines() if ln.startswith("surfmet:")]
        assert second.returncode == 1 and len(lines) == 1, second.stderr
        assert "being written by another run" in lines[0]
        assert str(first.pid) in lines[0]
        assert first.poll() is None  # refused while the first was writing, not after it
    finally:
        if first.poll() is None:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(first.pid, signal.SIGKILL)  # only this test's process
            first.wait()
    rows = [r for r in real.read_text().splitlines()[1:] if r.count(",") > 10]
    indices = [r.split(",")[0] for r in rows]
    assert len(indices) == len(set(indices))  # the first run's rows only, each once
