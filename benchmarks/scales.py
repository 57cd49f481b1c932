"""Benchmark: ``surfmet scales container-2.zip`` against SurfaceTopography on the same machine
(target: within 2x the peer's time for the same quantities).

Run ``python benchmarks/scales.py [--repeats N] [--peer-python /work/venv-peers/bin/python]``
from the checkout root. Timed, each in its own already-started interpreter (imports
excluded), from the container file to the averaged results at 5 points per decade:
reading the three measurements, the scale-dependent variance of slope (n = 1) and of
curvature (n = 2), the height-difference ACF, the variable-bandwidth rms height and the
averaged 1D PSD. SurfaceTopography (PyPI, in a separate virtualenv, never imported here)
runs the same steps through ``read_container``, ``scale_dependent_statistical_property``,
``autocorrelation``, ``variable_bandwidth`` and ``power_spectrum``. The machine is shared:
times are the minimum of the repeats. The end-to-end CLI time (interpreter start and
imports included) is printed too.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import textwrap
import time
from pathlib import Path

from _timing import min_time

ROOT = Path(__file__).resolve().parents[1]
CONTAINER = Path(os.environ.get("SURFMET_SHARED", ROOT.parent / "shared")) / "realdata" \
    / "container-2.zip"

PEER = textwrap.dedent("""
    import sys, time, warnings
    import numpy as np
    warnings.simplefilter("ignore")
    from SurfaceTopography import read_container
    def run():
        c, = read_container(sys.argv[1])
        for n in (1, 2):
            c.scale_dependent_statistical_property(lambda x, y=None: np.var(x), n=n,
                                                   nb_points_per_decade=5, unit="m")
        if sys.argv[3] == "slopes":
            return
        c.autocorrelation(unit="m", nb_points_per_decade=5)
        c.variable_bandwidth(unit="m", nb_points_per_decade=5)
        c.power_spectrum(unit="m", nb_points_per_decade=5)
    best = float("inf")
    for _ in range(int(sys.argv[2])):
        t0 = time.perf_counter(); run(); best = min(best, time.perf_counter() - t0)
    print(best)
""")


def ours() -> None:
    from surfmet.io import read_container
    from surfmet.scale_dependent import analyze_scales

    analyze_scales(read_container(CONTAINER), per_decade=5)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--peer-python", default="/work/venv-peers/bin/python")
    args = ap.parse_args()
    ours()  # warm numba / scipy caches and imports
    t_ours = min_time(ours, args.repeats)
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "surfmet", "scales", str(CONTAINER), "--json"],
                   cwd=ROOT, check=True, capture_output=True)
    t_cli = time.perf_counter() - t0
    print(f"surfmet scales container-2.zip: {t_ours:.3f} s in process (min of "
          f"{args.repeats}); CLI end to end {t_cli:.2f} s")
    if not Path(args.peer_python).exists():
        print(f"SurfaceTopography not timed: {args.peer_python} does not exist")
        return
    def peer(mode: str) -> float:
        out = subprocess.run([args.peer_python, "-c", PEER, str(CONTAINER), str(args.repeats),
                              mode], check=True, capture_output=True, text=True)
        return float(out.stdout.strip().splitlines()[-1])

    t_peer, t_slopes = peer("all"), peer("slopes")
    ratio = t_ours / t_peer
    print(f"SurfaceTopography, same quantities: {t_peer:.3f} s (min of {args.repeats}); "
          f"surfmet/peer = {ratio:.2f}; target <= 2: {'met' if ratio <= 2 else 'NOT met'}; "
          f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    print(f"SurfaceTopography, reading + slope and curvature variances only: {t_slopes:.3f} s "
          f"(surfmet's whole analysis / this = {t_ours / t_slopes:.2f})")


if __name__ == "__main__":
    main()
