"""Batch engine: identical results serial / local processes / Dask, failures kept in rows."""

from __future__ import annotations

import os
from functools import partial
from pathlib import Path

import pytest

from surfmet._batch import batch_map, default_workers
from surfmet._errors import SurfmetInputError
from surfmet.roughness import roughness_file

ROOT = Path(__file__).resolve().parents[1]

# real files of several formats, profiles and areal scans, one with 27 % NaN; x3p-2 is a
# complete 650 x 650 grid, large enough for a multi-threaded BLAS to split its sums (which
# made Dask's single-threaded workers differ in the last bits before every engine ran
# single-threaded BLAS)
REAL = ["al3d-1.al3d", "frt-2.frt", "matrix-4.txt", "hfm-1.hfm", "opdx-3.opdx",
        "dektak-1.csv", "test.gwy", "sdf-1.sdf", "x3p-2.x3p"]


@pytest.fixture
def files(realdata, tmp_path):
    paths = [str(realdata(name)) for name in REAL]
    # a truncated copy of a real file (in tmp, never in the repository)
    bad = tmp_path / "truncated.al3d"
    bad.write_bytes(realdata("al3d-1.al3d").read_bytes()[:3000])
    paths.insert(3, str(bad))
    return paths, str(bad)


def _check_rows(rows, paths, bad):
    assert [r["file"] for r in rows] == paths  # order preserved
    for r in rows:
        if r["file"] == bad:
            assert r["status"] == "error" and "truncated.al3d" in r["error"]
        else:
            assert r["status"] == "ok", r
            assert r["parameters"]


def _square(x):
    if x == 3:
        raise ValueError("three is not allowed")
    return x * x


def _die(x):
    if x == 2:
        os._exit(13)  # the worker process disappears, as under the OOM killer
    return x + 100


def test_local_processes_identical_to_serial(files):
    paths, bad = files
    func = partial(roughness_file, level="plane")
    serial = batch_map(func, paths, workers=1)
    _check_rows(serial, paths, bad)
    parallel = batch_map(func, paths, workers=2)
    assert parallel == serial  # bitwise-equal floats, same errors, same order


@pytest.fixture(scope="module")
def dask_address():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  host="127.0.0.1", dashboard_address=None) as cluster:
        assert cluster.scheduler_address.startswith("tcp://127.0.0.1:")
        yield cluster.scheduler_address


def _close(a, b, path=""):
    """Equal structures, floats within 1e-12 relative (for the non-bitwise check)."""
    if isinstance(a, dict):
        assert a.keys() == b.keys(), path
        for k in a:
            _close(a[k], b[k], f"{path}/{k}")
    elif isinstance(a, list):
        assert len(a) == len(b), path
        for k, (x, y) in enumerate(zip(a, b)):
            _close(x, y, f"{path}[{k}]")
    elif isinstance(a, float) and isinstance(b, float):
        assert b == pytest.approx(a, rel=1e-12, abs=1e-300), path
    else:
        assert a == b, path


def test_dask_local_cluster_rows(files, dask_address):
    paths, bad = files
    func = partial(roughness_file, level="plane")
    serial = batch_map(func, paths, workers=1)
    on_cluster = batch_map(func, paths, scheduler=dask_address)
    _check_rows(on_cluster, paths, bad)
    _close(serial, on_cluster)
    # a raising function on the cluster: its row, not the batch's end
    rows = batch_map(_square, [1, 2, 3, 4], scheduler=dask_address)
    assert rows[:2] == [1, 4] and rows[3] == 16
    assert rows[2]["status"] == "error" and "three is not allowed" in rows[2]["error"]




def test_dask_local_cluster_bitwise_identical_to_serial(files, dask_address):
    paths, _ = files
    func = partial(roughness_file, level="plane")
    serial = batch_map(func, paths, workers=1)
    assert batch_map(func, paths, scheduler=dask_address) == serial


def test_exception_becomes_its_row_in_every_engine():
    for workers in (1, 2):
        rows = batch_map(_square, [1, 2, 3, 4], workers=workers)
        assert rows[:2] == [1, 4] and rows[3] == 16
        assert rows[2] == {"file": "3", "status": "error",
                           "error": "internal error: ValueError: three is not allowed"}
    custom = batch_map(_square, [3], workers=1, on_error=lambda item, msg: ("bad", item))
    assert custom == [("bad", 3)]


def test_dead_worker_fails_only_its_item():
    rows = batch_map(_die, [0, 1, 2, 3, 4, 5], workers=2)
    assert rows[:2] == [100, 101] and rows[3:] == [103, 104, 105]
    assert rows[2]["status"] == "error" and "died" in rows[2]["error"]


def test_arguments():
    assert batch_map(_square, []) == []
    assert default_workers() >= 1
    with pytest.raises(SurfmetInputError, match="workers"):
        batch_map(_square, [1], workers=0)
    with pytest.raises(SurfmetInputError, match="module-level"):
        batch_map(lambda x: x, [1, 2], workers=2)
    assert batch_map(lambda x: x + 1, [1, 2], workers=1) == [2, 3]  # serial: anything goes
    with pytest.raises(SurfmetInputError, match="Dask scheduler"):
        batch_map(_square, [1], scheduler="tcp://127.0.0.1:1", connect_timeout=1)


def test_cli_workers_and_scheduler(files, dask_address, capsys):
    import json

    from surfmet.cli import main

    paths, _ = files
    runs = {}
    for extra in (["--workers", "1"], ["--workers", "2"], ["--scheduler", dask_address]):
        rc = main(["roughness", *paths, "--json", *extra])
        out, err = capsys.readouterr()
        assert rc == 1  # one file failed; the others are there
        runs[extra[0] + extra[1][:3]] = json.loads(out)
        assert err.count("surfmet: error:") == 1 and "truncated.al3d" in err
    serial = runs["--workers1"]
    assert [r["file"] for r in serial] == paths
    assert runs["--workers2"] == serial
    _close(serial, runs["--schedulertcp"])


_SCRIPT = """
import sys
from surfmet.sweep import run_sweep, sweep_items

print("BODY", file=sys.stderr)
items = sweep_items(task="contact", loads=[2.0, 5.0], radius=0.02, grid=16)
{call}
"""
_SHOW = "print([r['status'][0] for r in rows])"


@pytest.mark.parametrize("call, ok", [
    (f"rows = run_sweep(items, workers=2)\n{_SHOW}", False),
    (f"rows = run_sweep(items, workers=1)\n{_SHOW}", True),
    ("def main():\n    return run_sweep(items, workers=2)\n\n\n"
     f"if __name__ == '__main__':\n    rows = main()\n    {_SHOW}", True),
], ids=["unguarded", "serial", "guarded"])
def test_an_unguarded_script_is_told_the_cause(tmp_path, call, ok):
    """A script that starts worker processes at its top level, without the __main__
    guard, is refused at once with the cause and the line, its body run once (main: the
    body ran five times and every row read "worker process died"); guarded or serial,
    it runs."""
    import subprocess
    import sys

    script = tmp_path / "my_sweep.py"
    script.write_text(_SCRIPT.format(call=call))
    run = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                         cwd=tmp_path, timeout=300,
                         env={**os.environ, "PYTHONPATH": str(ROOT)})
    if ok:
        assert run.returncode == 0 and "['ok', 'ok']" in run.stdout, run.stderr
    else:
        assert run.stderr.count("BODY") == 1, run.stderr
        assert run.returncode != 0
        assert f"{script}, line 7" in run.stderr
        assert 'if __name__ == "__main__":' in run.stderr
