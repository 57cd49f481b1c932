"""Benchmark: areal levelling + parameters and the areal Gaussian filter on 2048 x 2048.

Run ``python benchmarks/areal.py [--peers /path/to/venv/bin/python]``. Times are the
minimum of N repeats (the machine is shared; read them as noisy). With ``--peers`` the
same set is timed in surfalize (its own level() + Sa, Sq, Sdr, and the full height set)
in that interpreter, in the same run.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import textwrap

import numpy as np
from _timing import min_time

from surfmet._model import Topography
from surfmet.areal._filters import l_filter
from surfmet.areal._form import remove_form
from surfmet.areal._height import height_parameters
from surfmet.areal._hybrid import gradient_parameters

N = 2048


def surface(seed: int = 0) -> np.ndarray:
    rng = np.random.default_rng(seed)
    z = rng.standard_normal((N, N)) * 1e-7
    j, i = np.mgrid[:N, :N]
    return z + 1e-4 * i * 1e-6 - 3e-5 * j * 1e-6


PEER_SCRIPT = textwrap.dedent("""
    import sys, time, numpy as np, surfalize
    N, repeats = int(sys.argv[1]), int(sys.argv[2])
    rng = np.random.default_rng(0)
    z = rng.standard_normal((N, N)) * 0.1
    j, i = np.mgrid[:N, :N]
    z = z + 1e-4 * i - 3e-5 * j
    def run(full):
        s = surfalize.Surface(z.copy(), 1.0, 1.0).level()
        if full:
            s.height_parameters(); s.Sdq(); s.Sdr()
        else:
            s.Sa(); s.Sq(); s.Sdr()
    res = {}
    for full in (False, True):
        ts = []
        for _ in range(repeats):
            t0 = time.perf_counter(); run(full); ts.append(time.perf_counter() - t0)
        res[full] = min(ts)
    print(res[False], res[True])
""")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--peers", help="python of a virtualenv with surfalize installed")
    args = ap.parse_args()
    topo = Topography(surface(), 1e-6, 1e-6)

    def pipeline():
        lev, _ = remove_form(topo, "plane")
        height_parameters(lev)
        gradient_parameters(lev)

    t_set = min_time(pipeline, args.repeats)
    t_plane = min_time(lambda: remove_form(topo, "plane"), args.repeats)
    lev, _ = remove_form(topo, "plane")
    t_h = min_time(lambda: height_parameters(lev), args.repeats)
    t_g = min_time(lambda: gradient_parameters(lev), args.repeats)
    print(f"surfmet {N}x{N}: plane + Sa..Sku, Sz + Sdq + Sdr: {t_set:.3f} s "
          f"(plane {t_plane:.3f}, height {t_h:.3f}, Sdq+Sdr {t_g:.3f}), min of {args.repeats}")
    for lc, edge in ((25e-6, "moment"), (250e-6, "moment"), (800e-6, "moment"),
                     (250e-6, "renormalise")):
        t = min_time(lambda lc=lc, edge=edge: l_filter(topo, lc, edge=edge), args.repeats)
        print(f"surfmet L-filter lc={lc * 1e6:.0f} um edge={edge}: {t:.3f} s")
    if args.peers:
        out = subprocess.run([args.peers, "-c", PEER_SCRIPT, str(N), str(args.repeats)],
                             capture_output=True, text=True, check=True).stdout.split()
        print(f"surfalize {N}x{N}: level + Sa, Sq, Sdr: {float(out[0]):.3f} s; "
              f"level + height set + Sdq + Sdr: {float(out[1]):.3f} s, min of {args.repeats}")


if __name__ == "__main__":
    sys.exit(main())
