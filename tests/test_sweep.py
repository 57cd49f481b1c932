"""Sweeps (surfmet sweep): the product, bitwise-identical rows in every engine, error rows,
incremental files that survive a kill, --resume, and the CLI's refusals."""

from __future__ import annotations

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

from contact.hertz import hertz_sphere
from contact.materials import composite_modulus, material
from surfmet.cli import main
from surfmet.sweep import RowWriter, done_keys, run_sweep, sweep_items

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
    assert done_keys(c, None) == done_keys(None, j) == {items[0].key}
    with RowWriter("contact", c, j, resume=True) as w:
        rest = run_sweep(items, workers=1, writer=w, skip=done_keys(c, j))
    assert len(rest) == len(items) - 1
    recs = [json.loads(line) for line in j.read_text().splitlines()]
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
