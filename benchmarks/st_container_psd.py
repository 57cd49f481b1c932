"""SurfaceTopography's averaged 1D PSD of container-2.zip (run in a peer virtualenv).

The provenance of ``tests/data/st_container2_psd.json``. It never runs in the test suite
and nothing in the package imports SurfaceTopography; it needs SurfaceTopography only::

    python3 -m venv /tmp/w6venv && /tmp/w6venv/bin/pip install SurfaceTopography numpy
    /tmp/w6venv/bin/python benchmarks/st_container_psd.py ../shared/realdata/container-2.zip \
        --out tests/data/st_container2_psd.json

What contact.engineering shows as a surface's PSD: ``read_container(file)`` and
``container.power_spectrum(unit="m", nb_points_per_decade=N)`` (each measurement's 1D PSD
on its own DFT wavevectors, reliable ones only, bin-averaged per measurement and averaged
over the measurements with equal votes; SurfaceTopography/Container/Averaging.py), at
N = 5 and 10, the masked bins left out; the time of the call, the best of 3.
"""

from __future__ import annotations

import argparse
import datetime
import json
import time
import warnings
from pathlib import Path

import numpy as np


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("container", type=Path)
    ap.add_argument("--out", type=Path)
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    import SurfaceTopography
    from SurfaceTopography import read_container

    record = {
        "provenance": {
            "peer": f"SurfaceTopography {SurfaceTopography.__version__} (PyPI), in a "
                    "separate virtualenv; never imported by surfmet or its tests",
            "file": "../shared/realdata/container-2.zip",
            "script": "benchmarks/st_container_psd.py",
            "code": "c, = read_container(file); q, C = c.power_spectrum(unit='m', "
                    "nb_points_per_decade=N)",
            "numpy": np.__version__,
            "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%MZ"),
            "units": {"q": "rad/m", "C": "m^3", "seconds": "s"},
        },
    }
    for n in (5, 10):
        best = float("inf")
        for _ in range(3):
            t0 = time.perf_counter()
            c, = read_container(str(args.container))
            q, psd = c.power_spectrum(unit="m", nb_points_per_decade=n)
            best = min(best, time.perf_counter() - t0)
        keep = ~np.ma.getmaskarray(psd)
        record[f"per_decade_{n}"] = {"q": np.asarray(q)[keep].tolist(),
                                     "C": np.asarray(psd)[keep].tolist(), "seconds": best}
    text = json.dumps(record, indent=1)
    if args.out:
        args.out.write_text(text + "\n")
    else:
        print(text)


if __name__ == "__main__":
    main()
