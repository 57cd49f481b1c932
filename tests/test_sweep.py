"""Sweeps (surfmet sweep): the product, bitwise-identical rows in every engine, error rows,
incremental files that survive a kill, --resume, and the CLI's refusals."""

from __future__ import annotations

import contextlib
import csv
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from contact._hertz import hertz_sphere
from contact._materials import composite_modulus, material
from surfmet.cli import main
from surfmet.sweep import RowWriter, run_sweep, sweep_items

PLATE = str(Path(__file__).resolve().parents[1] / "surfmet" / "data" / "paper_plate.x3p")
ROOT = Path(__file__).resolve().parents[1]


def _items(task="contact", plates=(PLATE,), loads=(2.0, 6.0), grid=48):
    return sweep_items(task=task, loads=loads, radius=0.02, plates=list(plates),
                       positions=[(0.0, 0.0), (2e-4, -1e-4)], grid=grid)


def test_product_order_and_stable_keys():
    items = sweep_items(task="contact", loads=[1.0, 2.0, 3.0], radius=0.02,
                        plates=["a", "b"], materials=["steel,aluminium", "steel,copper"],
                        positions=[None, (1e-4, 0.0)])
    assert len(items) == 2 * 2 * 2 * 3
    assert [it.index for it in items] == list(range(24))
    assert [it.load for it in items[:3]] == [1.0, 2.0, 3.0]  # loads vary fastest
    assert len({it.key for it in items}) == 24
    again = sweep_items(task="contact", loads=[3.0, 1.0, 2.0], radius=0.02,
                        plates=["a", "b"], materials=["steel,aluminium", "steel,copper"],
                        positions=[None, (1e-4, 0.0)])
    # a key names the parameters, not the place in the list
    assert {it.key for it in items} == {it.key for it in again}


def test_paths_may_be_pathlib_objects():
    # the quickstart passes surfmet.data.path(...) objects; the key is JSON text
    as_path = sweep_items(task="contact", loads=[1.0], radius=0.02,
                          plates=[Path("plate.x3p")], balls=[Path("ball.x3p")])
    as_text = sweep_items(task="contact", loads=[1.0], radius=0.02,
                          plates=["plate.x3p"], balls=["ball.x3p"])
    assert as_path[0].plate == "plate.x3p" and as_path[0].key == as_text[0].key


def test_smooth_item_is_hertz():
    rows = run_sweep(sweep_items(task="contact", loads=[3.0], radius=0.02, grid=96),
                     workers=1)
    (row,) = rows
    hz = hertz_sphere(0.02, 3.0, composite_modulus(material("steel"), material("aluminium")))
    assert row["status"][0] == "ok"
    assert row["max_pressure"] == (pytest.approx(hz.p0, rel=0.02), "Pa")
    assert row["contact_radius"][0] == pytest.approx(hz.a, rel=0.05)


@pytest.fixture(scope="module")
def dask_address():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  host="127.0.0.1", dashboard_address=None) as cluster:
        yield cluster.scheduler_address


@pytest.mark.campaign
def test_rows_are_bitwise_identical_in_every_engine(dask_address):
    items = _items(task="hertz-check")
    serial = run_sweep(items, workers=1)
    procs = run_sweep(items, workers=2)
    dask = run_sweep(items, scheduler=dask_address)
    assert all(r["status"][0] == "ok" for r in serial), [r["error"] for r in serial]
    assert serial == procs == dask  # floats compared exactly
    # the track positions see different roughness: the answers differ between positions
    assert serial[0]["approach"] != serial[2]["approach"]


def test_a_failed_item_gets_its_row_and_the_sweep_goes_on(tmp_path):
    items = _items(plates=(PLATE, str(tmp_path / "missing.x3p")), loads=(4.0,))
    rows = run_sweep(items, workers=1)
    status = [r["status"][0] for r in rows]
    assert status == ["ok", "ok", "error", "error"]
    assert "missing.x3p" in rows[2]["error"][0]


def test_writer_files_parse_and_resume_skips(tmp_path):
    items = _items(loads=(3.0,))
    c, j = tmp_path / "s.csv", tmp_path / "s.jsonl"
    with RowWriter("contact", c, j) as w:
        first = run_sweep(items[:1], workers=1, writer=w)
    with RowWriter("contact", c, j, resume=True) as w:  # the done rows, as --resume reads them
        assert w.done == {items[0].key}
        rest = run_sweep(items, workers=1, writer=w, skip=w.done)
    assert len(rest) == len(items) - 1
    head, *recs = [json.loads(line) for line in j.read_text().splitlines()]
    assert head["surfmet_sweep"]["task"] == "contact"
    assert head["surfmet_sweep"]["columns"]["max_pressure"] == "Pa"
    assert sorted(r["index"] for r in recs) == list(range(len(items)))
    assert recs[0]["load"] == {"value": 3.0, "unit": "N"}
    with open(c, newline="") as fh:
        table = list(csv.DictReader(fh))
    assert len(table) == len(items) and "max_pressure [Pa]" in table[0]
    assert float(table[0]["max_pressure [Pa]"]) == first[0]["max_pressure"][0]


def test_unwritable_output_is_one_line_exit_1(tmp_path, capsys):
    code = main(["sweep", "--radius", "20mm", "--loads", "5N",
                 "--csv", str(tmp_path / "no" / "such" / "dir.csv")])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 1 and len(err) == 1 and "cannot write the sweep output" in err[0]


@pytest.mark.slow
@pytest.mark.campaign
def test_killed_sweep_keeps_valid_rows_and_resume_completes(tmp_path):
    out = tmp_path / "kill.csv"
    args = [sys.executable, "-m", "surfmet", "sweep", "--task", "contact", "--plates", PLATE,
            "--radius", "20mm", "--loads", "1N:20N:8", "--positions", "0:0,0.2mm:0",
            "--grid", "96", "--workers", "1", "--csv", str(out)]
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    proc = subprocess.Popen(args, env=env, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None:
        if out.exists() and len(out.read_text().splitlines()) >= 3:  # header + 2 rows
            break
        time.sleep(0.02)
    killed = proc.poll() is None
    if killed:
        os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    with open(out, newline="") as fh:
        part = list(csv.DictReader(fh))
    assert part and all(r["status"] == "ok" for r in part)  # every written row is whole
    n_before = len(part)
    assert not killed or n_before < 16
    done = subprocess.run([*args, "--resume"], env=env, capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    with open(out, newline="") as fh:
        full = list(csv.DictReader(fh))
    assert sorted(int(r["index"]) for r in full) == list(range(16))
    # the rows written before the kill equal a fresh serial run's
    fresh = run_sweep(sweep_items(task="contact", loads=np.geomspace(1, 20, 8), radius=0.02,
                                  plates=[PLATE], positions=[(0.0, 0.0), (2e-4, 0.0)],
                                  grid=96), workers=1)
    by_index = {r["index"][0]: r for r in fresh}
    for r in part:
        assert float(r["max_pressure [Pa]"]) == by_index[int(r["index"])]["max_pressure"][0]


def test_rolling_track_positions_identical_in_every_engine(dask_address):
    from surfmet.mechanics.rolling_resistance import rolling_resistance, rolling_tracks

    opts = dict(radius=0.02, materials="steel,aluminium", loads=(2.0, 5.0, 12.0), grid=64,
                max_grid=None)
    pos = [(0.0, 0.0), (-1e-4, 1e-4)]
    serial = rolling_tracks(PLATE, positions=pos, workers=1, **opts)
    procs = rolling_tracks(PLATE, positions=pos, workers=2, **opts)
    dask = rolling_tracks(PLATE, positions=pos, scheduler=dask_address, **opts)
    assert not any(t.get("error") for t in serial.tracks)
    for other in (procs, dask):
        assert np.array_equal(other.mean_moments, serial.mean_moments)
        for a, b in zip(serial.tracks, other.tracks):
            assert np.array_equal(a["moments"], b["moments"])
    # each track is the single-position analysis at that offset; the mean is their mean
    one = rolling_resistance(PLATE, offset=pos[1], **opts)
    assert np.array_equal(serial.tracks[1]["moments"], one.sweep.moments)
    np.testing.assert_allclose(serial.mean_moments,
                               0.5 * (serial.tracks[0]["moments"] + one.sweep.moments),
                               rtol=1e-15)
    assert not np.array_equal(serial.tracks[0]["moments"], serial.tracks[1]["moments"])


def test_rolling_cli_positions_json(capsys):
    code = main(["rolling", "--plate", PLATE, "--radius", "20mm", "--materials",
                 "steel,aluminium", "--loads", "2N:12N:3", "--grid", "64",
                 "--positions", "0:0,-0.1mm:0.1mm", "--workers", "1", "--json"])
    rec = json.loads(capsys.readouterr().out)
    assert code == 0
    assert len(rec["tracks"]) == 2 and rec["tracks"][1]["offset"]["value"] == [-1e-4, 1e-4]
    assert rec["mean_moments"]["unit"] == "N m" and rec["loads"]["unit"] == "N"
    assert np.isfinite(rec["lambda_eff"]["value"])


SMOOTH = ["sweep", "--task", "contact", "--radius", "20mm", "--loads", "1N:10N:6",
          "--grid", "32", "--workers", "1", "--quiet"]


def _tables(c, j):
    with open(c, newline="") as fh:
        rows = list(csv.reader(fh))
    head, *recs = [json.loads(line) for line in j.read_text().splitlines()]
    assert "surfmet_sweep" in head
    return rows[0], rows[1:], recs


def test_resume_drops_a_cut_row_and_completes_both_files(tmp_path, capsys):
    """A stop mid-write leaves the CSV's last row cut after its status and the JSON one
    row behind, its last line cut too. --resume runs the cut row and the row the JSON
    lacks again, so that both files hold every row once, whole (main counted both rows
    done: 2 rows lost in JSON, the cut CSV row merged with the next one)."""
    c, j = tmp_path / "s.csv", tmp_path / "s.jsonl"
    assert main([*SMOOTH, "--csv", str(c), "--json", str(j)]) == 0
    header, _, recs = _tables(c, j)
    whole = {r["index"]: r for r in recs}
    lines = c.read_text().splitlines(keepends=True)
    cut = lines[5][:lines[5].index(",ok,") + 4]  # row 4 cut after its status
    c.write_text("".join(lines[:5]) + cut)
    jl = j.read_text().splitlines(keepends=True)
    j.write_text("".join(jl[:4]) + jl[4][:40])  # header, rows 0-2, then half of row 3
    capsys.readouterr()
    assert main([*SMOOTH, "--csv", str(c), "--json", str(j), "--resume"]) == 0
    assert "3 of 6 items already written" in capsys.readouterr().err
    header2, rows2, recs2 = _tables(c, j)
    assert header2 == header
    assert all(len(r) == len(header) for r in rows2)
    assert sorted(int(r[0]) for r in rows2) == list(range(6))
    assert sorted(r["index"] for r in recs2) == list(range(6))
    for r in recs2:  # the rerun rows equal the first run's (the solve is deterministic)
        assert r == whole[r["index"]]


def test_two_runs_on_one_file_are_refused(tmp_path, capsys):
    """While one run writes a file, a second (e.g. another --resume) is refused in one
    line instead of interleaving rows (main: duplicated rows and a garbled line)."""
    c = tmp_path / "s.csv"
    with RowWriter("contact", c):
        assert main([*SMOOTH, "--csv", str(c), "--resume"]) == 1
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and "being written by another run" in err[0]
        assert str(os.getpid()) in err[0]
    # released at the end: the next run may write
    assert main([*SMOOTH, "--csv", str(c), "--resume"]) == 0


def test_a_full_disk_keeps_whole_rows_and_resume_finishes(tmp_path):
    """The disk refuses a row half-way (file size capped): one line, exit 1, both files
    hold the same whole rows; a --resume with room finishes the sweep."""
    import resource

    c, j = tmp_path / "s.csv", tmp_path / "s.jsonl"
    cmd = [sys.executable, "-m", "surfmet", *SMOOTH, "--csv", str(c), "--json", str(j)]

    def cap():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (3000, 3000))

    run = subprocess.run(cmd, capture_output=True, text=True, preexec_fn=cap, cwd=ROOT,
                         timeout=300)
    lines = [ln for ln in run.stderr.splitlines() if ln.startswith("surfmet:")]
    assert run.returncode == 1 and len(lines) == 1 and "cannot write row" in lines[0], \
        run.stderr
    _, rows, recs = _tables(c, j)
    assert 0 < len(rows) < 6 and all(len(r) == len(_tables(c, j)[0]) for r in rows)
    assert [int(r[0]) for r in rows] == [r["index"] for r in recs]
    done = subprocess.run([*cmd, "--resume"], capture_output=True, text=True, cwd=ROOT,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    _, rows, recs = _tables(c, j)
    assert sorted(int(r[0]) for r in rows) == sorted(r["index"] for r in recs) == \
        list(range(6))


def _descendants(root: int) -> set[int]:
    """Ids of the live (non-zombie) processes below ``root`` (Linux /proc)."""
    parent = {}
    for d in Path("/proc").iterdir():
        if d.name.isdigit():
            try:
                stat = (d / "stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if stat[0] != "Z":
                parent[int(d.name)] = int(stat[1])
    found, frontier = set(), {root}
    while frontier:
        frontier = {p for p, pp in parent.items() if pp in frontier} - found
        found |= frontier
    return found


def _live(pids: set[int]) -> set[int]:
    out = set()
    for p in pids:
        try:
            state = Path(f"/proc/{p}/stat").read_text().rsplit(")", 1)[1].split()[0]
        except OSError:
            continue
        if state != "Z":
            out.add(p)
    return out


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads Linux /proc")
def test_killing_the_sweep_ends_its_workers(tmp_path):
    """SIGKILL to the main process of ``sweep --workers 2``: its two workers and the
    forkserver end within seconds (main: they ran on indefinitely, ~220 MB each)."""
    cmd = [sys.executable, "-m", "surfmet", "sweep", "--plates", PLATE, "--radius", "20mm",
           "--loads", "1N:20N:8", "--grid", "128", "--workers", "2", "--quiet",
           "--csv", str(tmp_path / "s.csv")]
    proc = subprocess.Popen(cmd, cwd=ROOT, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)
    try:
        deadline = time.monotonic() + 120
        below: set[int] = set()
        while time.monotonic() < deadline and proc.poll() is None:
            below = _descendants(proc.pid)
            if len(below) >= 4:  # resource tracker, forkserver, two workers
                break
            time.sleep(0.1)
        assert proc.poll() is None and len(below) >= 4, "the workers never started"
        time.sleep(1.0)  # the workers are inside their first item
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
        deadline = time.monotonic() + 20
        while _live(below) and time.monotonic() < deadline:
            time.sleep(0.2)
        assert not _live(below), f"left running: {sorted(_live(below))}"
    finally:
        if proc.poll() is None:
            proc.kill()
        with contextlib.suppress(ProcessLookupError):
            os.killpg(proc.pid, signal.SIGKILL)  # only this test's processes
