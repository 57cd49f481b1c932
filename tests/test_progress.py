"""Long commands show their progress on stderr, and --quiet turns it off (issue 16, item 15).

Under pytest stderr is not a terminal, so the progress comes as plain lines, the form logs
and pipes get: one per stage, "desc: n/n (t s)" as it ends (issue 34, item 14: a line per
step flooded them); stdout (the JSON) never carries it.
"""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

from surfmet.cli import main


def _run(capsys, argv):
    rc = main(argv)
    cap = capsys.readouterr()
    assert rc == 0, cap.err
    return cap.out, cap.err


@pytest.mark.parametrize("quiet", [False, True])
def test_rolling_progress_per_load(capsys, quiet):
    argv = ["rolling", "--radius", "20mm", "--materials", "steel,aluminium", "--loads",
            "1N:10N:3", "--grid", "32", "--json"] + (["--quiet"] if quiet else [])
    out, err = _run(capsys, argv)
    json.loads(out)  # the JSON stays clean
    lines = [ln for ln in err.splitlines() if "loads:" in ln]
    assert len(lines) == (0 if quiet else 1)
    assert all(re.fullmatch(r"rolling \(hysteresis\), loads: 3/3 \(\d+\.\d s\)", ln)
               for ln in lines)


@pytest.mark.parametrize("quiet", [False, True])
def test_sweep_progress_per_item(capsys, quiet):
    argv = ["sweep", "--task", "contact", "--radius", "20mm", "--loads", "1N,2N", "--grid", "32",
            "--workers", "1", "--json"] + (["--quiet"] if quiet else [])
    out, err = _run(capsys, argv)
    assert len(json.loads(out)["rows"]) == 2
    lines = [ln for ln in err.splitlines() if ln.startswith("sweep:")]
    assert len(lines) == (0 if quiet else 1)
    assert all(re.fullmatch(r"sweep: 2/2 \(\d+\.\d s\)", ln) for ln in lines)


@pytest.mark.parametrize("quiet", [False, True])
def test_report_progress_per_scan(tmp_path, capsys, quiet):
    import surfmet
    from surfmet import Topography

    rng = np.random.default_rng(15)
    paths = [surfmet.write(Topography(rng.normal(0, 1e-7, (32, 32)), 1e-6, 1e-6),
                           tmp_path / f"s{k}.npz") for k in range(2)]
    argv = ["report", *map(str, paths), "-o", str(tmp_path / "r.html"), "--no-3d"]
    _, err = _run(capsys, argv + (["--quiet"] if quiet else []))
    lines = [ln for ln in err.splitlines() if ln.startswith("report:")]
    assert len(lines) == (0 if quiet else 1)
    assert all(re.fullmatch(r"report: 2/2 \(\d+\.\d s\)", ln) for ln in lines)


def test_a_long_stage_adds_a_line_now_and_then(monkeypatch, capsys):
    """Off a terminal a stage longer than _Lines.EVERY seconds says how far it is, so a
    long run's log is not silent until its end."""
    from surfmet import _batch as batch

    clock = iter(range(0, 1000, 40))  # each call 40 s later
    monkeypatch.setattr("time.monotonic", lambda: float(next(clock)))
    bar = batch.progress_bar(4, "stage", True)
    for _ in range(4):
        bar.update(1)
    bar.close()
    lines = capsys.readouterr().err.splitlines()
    assert lines == ["stage: 2/4 (80.0 s)", "stage: 4/4 (200.0 s)"]
