"""Benchmark: ``surfmet sweep`` serial against 2 local processes and a 2-worker Dask
LocalCluster, with the rows checked bitwise equal.

Run ``python benchmarks/sweep.py [--grid 256] [--loads 8]``: a hertz-check sweep of the
bundled paper plate with a smooth 20 mm steel ball, ``--loads`` log-spaced loads 1-20 N x
2 track positions. Each engine is timed once, after one warm-up item (numba's cache
and the file read), on this machine's 2 cores.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from surfmet.sweep import run_sweep, sweep_items

PLATE = str(Path(__file__).resolve().parents[1] / "surfmet" / "data" / "paper_plate.x3p")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--grid", type=int, default=256)
    ap.add_argument("--loads", type=int, default=8)
    args = ap.parse_args()
    items = sweep_items(task="hertz-check", loads=np.geomspace(1, 20, args.loads),
                        radius=0.02, plates=[PLATE], positions=[(0.0, 0.0), (2e-4, 0.0)],
                        grid=args.grid)
    run_sweep(items[:1], workers=1)  # warm-up
    t = time.perf_counter()
    serial = run_sweep(items, workers=1, progress=False)
    t_serial = time.perf_counter() - t
    t = time.perf_counter()
    procs = run_sweep(items, workers=2, progress=False)
    t_procs = time.perf_counter() - t
    from distributed import LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None) as cluster:
        run_sweep(items[:2], scheduler=cluster.scheduler_address)  # workers warm up
        t = time.perf_counter()
        dask = run_sweep(items, scheduler=cluster.scheduler_address, progress=False)
        t_dask = time.perf_counter() - t
    same = serial == procs == dask
    print(f"{len(items)} hertz-check items at {args.grid}^2: serial {t_serial:.2f} s; "
          f"2 processes {t_procs:.2f} s ({t_serial / t_procs:.2f}x); Dask LocalCluster "
          f"2 workers {t_dask:.2f} s ({t_serial / t_dask:.2f}x); rows bitwise equal: {same}")
    failed = sum(r["status"][0] != "ok" for r in serial)
    print(f"failed items: {failed}")


if __name__ == "__main__":
    main()
