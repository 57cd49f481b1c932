"""Batch roughness: serial against local processes and a Dask LocalCluster.

Usage: ``python benchmarks/batch.py [REPEATS]`` (each real file of ../shared/realdata listed
REPEATS times, default 4). Local-process timings include the pool start-up, which a user
pays; the Dask cluster is started (and its workers warmed) before timing, as a standing
cluster would be. Rows must be identical in every mode.
"""

from __future__ import annotations

import sys
import time
from functools import partial
from pathlib import Path

from surfmet._batch import batch_map
from surfmet.roughness import roughness_file

REALDATA = Path(__file__).resolve().parents[2] / "shared" / "realdata"


def main(repeats: int) -> None:
    import distributed

    files = sorted(str(p) for p in REALDATA.iterdir() if p.suffix != ".tsv")
    items = files * repeats
    func = partial(roughness_file, level="plane")
    batch_map(func, files, workers=1, progress=False)  # warm imports, numba and file caches
    t = time.perf_counter()
    serial = batch_map(func, items, workers=1, progress=False)
    ts = time.perf_counter() - t
    t = time.perf_counter()
    local = batch_map(func, items, workers=2, progress=False)
    tp = time.perf_counter() - t
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  host="127.0.0.1", dashboard_address=None) as cluster:
        batch_map(func, files[:2], scheduler=cluster.scheduler_address, progress=False)
        t = time.perf_counter()
        dask = batch_map(func, items, scheduler=cluster.scheduler_address, progress=False)
        td = time.perf_counter() - t
    print(f"{len(items)} files: serial {ts:.2f} s | 2 local processes {tp:.2f} s "
          f"({ts / tp:.2f}x) | Dask LocalCluster, 2 workers {td:.2f} s ({ts / td:.2f}x)")
    print(f"identical rows: processes {local == serial}, Dask {dask == serial}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 4)
