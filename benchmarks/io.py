"""Benchmark: reading each real sample file, format by format.

Run ``python benchmarks/io.py [--repeats 5] [--only di,ibw]`` from the repository root; the
samples are read from ``../shared/realdata`` (``SURFMET_SHARED`` overrides the folder
holding ``realdata``). Each time is the minimum over the repeats of ``surfmet.io.read``
(file bytes to a validated scan: detection, decoding, checks), in a process that has
already imported the readers. Issue 18 asks for under 1 s per file at the sample's size.
Also checks that reading imports no analysis module.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

SAMPLES = {
    "di": "di-1.di", "ibw": "spot_1-1000nm.ibw", "mi": "mi-1.mi", "nid": "nid-1.nid",
    "tmd": "tmd-1.tmd", "mnt": "mnt-1.mnt", "wsxm (stp)": "stp-1.stp", "wsxm (top)": "top-1.top",
    "nc": "nc-1.nc", "park": "example_ps.tiff", "bcr": "bcrf-1.bcrf",
    "mitutoyo": "mitutoyo_2_mock.xlsx",
    # the formats read before issue 18, for comparison
    "x3p": "x3p-2.x3p", "sur": "sur-3.sur", "plu": "plu-1.plu", "opd": "opd-1.opd",
}
ANALYSIS = ("surfmet.roughness", "surfmet.areal", "surfmet.filters", "surfmet.form",
            "profiles", "contact", "matplotlib", "numba")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--only", default="", help="comma-separated format names")
    args = ap.parse_args()
    root = Path(os.environ.get("SURFMET_SHARED", Path(__file__).resolve().parents[2] / "shared"))
    import surfmet.io as sio
    from surfmet._errors import SurfmetFormatError

    leaked = sorted(m for m in sys.modules if m.split(".")[0] in ("profiles", "contact",
                    "matplotlib", "numba") or m in ANALYSIS)
    print(f"modules imported by surfmet.io beyond the data model: {leaked or 'none'}")
    only = {s.strip() for s in args.only.split(",") if s.strip()}
    print(f"{'format':12s} {'file':38s} {'points':>9s} {'MB':>6s} {'read s':>8s}")
    worst = 0.0
    for fmt, fname in SAMPLES.items():
        if only and fmt.split()[0] not in only:
            continue
        path = root / "realdata" / fname
        if not path.exists():
            print(f"{fmt:12s} {fname:38s} (missing)")
            continue
        best = float("inf")
        try:
            for _ in range(args.repeats):
                t0 = time.perf_counter()
                scan = sio.read(path)
                best = min(best, time.perf_counter() - t0)
        except SurfmetFormatError as exc:
            print(f"{fmt:12s} {fname:38s} not read: {str(exc)[:60]}")
            continue
        pts = scan.heights.size if hasattr(scan, "heights") else scan.z.size
        print(f"{fmt:12s} {fname:38s} {pts:9d} {path.stat().st_size / 1e6:6.2f} {best:8.3f}")
        worst = max(worst, best)
    print(f"slowest read: {worst:.3f} s (target < 1 s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
