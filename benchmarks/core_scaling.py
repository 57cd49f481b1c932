"""The contact core's cost against the FFT's own: the 4096^2 command, iterations, memory.

Issue 37 item 7 asks three things of the normal solver, each measured here beside the
cost of the FFT itself, in the same run (the machine may be shared: only ratios to a
yardstick timed in the same run mean anything):

``command``
    ``surfmet contact --plate surfmet/data/paper_plate.x3p --radius 20mm --load 10N
    --materials steel,aluminium --grid N`` in a subprocess under ``/usr/bin/time -v``: its
    wall time over the time of one padded (2N)^2 convolution (the yardstick: ``rfft2`` of
    the N^2 grid zero-padded to (2N)^2, a multiply by a real spectrum, ``irfft2``, float64,
    all cores, the best of a few) timed in this process just before and just after (the
    smaller is used). Bound: 25 at N = 4096. Its peak memory is the subprocess's maximum
    resident set size (the interpreter and the scan included) over N^2 cells. Bound:
    110 bytes a cell.
``periodic``
    Iterations and time of :func:`contact.bem.solve_normal` on a periodic self-affine
    surface (``surfmet.synth.self_affine``: Hurst 0.8, rms slope 0.1, 1 µm pixel, roll-off
    at the side, seed 1; mean pressure 0.005 E*, about 11 % contact; tol 1e-8) from
    128^2 up: the finest grid's iterations (bound: 40 at 4096^2) and the exponent of the
    solve time against the number of cells N^2 over 512^2 .. the largest (least squares on
    the logarithms; bound 1.15; an FFT alone grows as N^2 log N^2, an exponent of about
    1.05 over that span).

Run it alone on the machine (it uses every core)::

    python3 benchmarks/core_scaling.py --command 4096 --periodic 128,256,512,1024,2048,4096

The figures measured are in ``benchmarks/core_scaling.md``.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import re
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from _timing import min_time  # noqa: E402

COMMAND = ["contact", "--plate", str(ROOT / "surfmet" / "data" / "paper_plate.x3p"),
           "--radius", "20mm", "--load", "10N", "--materials", "steel,aluminium"]


def yardstick(n: int, repeats: int = 3) -> float:
    """Seconds of one padded (2n)^2 float64 convolution (rfft2, multiply, irfft2)."""
    import scipy.fft as sfft

    x = np.random.default_rng(0).random((n, n))
    k = np.random.default_rng(1).random((2 * n, n + 1))

    def once() -> None:
        spec = sfft.rfft2(x, s=(2 * n, 2 * n), workers=-1)
        spec *= k
        sfft.irfft2(spec, s=(2 * n, 2 * n), workers=-1)

    return min_time(once, repeats)


def run_command(n: int) -> dict:
    """The whole command in a subprocess: wall time, peak RSS, the solver's line."""
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    cmd = ["/usr/bin/time", "-v", sys.executable, "-m", "surfmet", *COMMAND, "--grid", str(n)]
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=ROOT)
    wall = time.perf_counter() - t0
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", proc.stderr)
    lines = proc.stdout.splitlines()
    pick = {key: next((ln[len(key):].strip() for ln in lines if ln.startswith(key)), "")
            for key in ("solver", "max pressure", "contact radius")}
    peak = int(rss.group(1)) * 1024 if rss else 0
    return {"n": n, "rc": proc.returncode, "wall_s": wall, "peak_rss_bytes": peak,
            "bytes_per_cell": peak / n ** 2, **pick}


def command(n: int, repeats: int) -> dict:
    """The command's time over the yardstick's, timed around it in this process."""
    before = yardstick(n, repeats)
    out = run_command(n)
    after = yardstick(n, repeats)
    out["yardstick_s"] = min(before, after)
    out["ratio"] = out["wall_s"] / out["yardstick_s"]
    return out


def periodic_case(n: int) -> tuple[np.ndarray, float, float]:
    """The periodic self-affine gap (m), its pitch (m) and the load (N) for E* = 1 Pa."""
    from surfmet.synth import self_affine

    pixel = 1e-6
    z = np.asarray(self_affine(n, pixel, hurst=0.8, slope_rms=0.1, seed=1).heights)
    return z.max() - z, pixel, 0.005 * (n * pixel) ** 2


def periodic(sizes: list[int]) -> list[dict]:
    """Finest-grid iterations and solve time of the periodic case at each size."""
    from contact._grid import gap_grid
    from contact.bem import SolveOptions, solve_normal
    from contact.bem._state import SolverStats

    rows = []
    for n in sizes:
        gap, pixel, load = periodic_case(n)
        solve_normal(gap_grid(gap[:64, :64], pixel, periodic=True), e_star=1.0,
                     load=load / (n / 64) ** 2,
                     options=SolveOptions(tol=1e-4))  # compiled kernels loaded before timing
        stats = SolverStats()
        t0 = time.perf_counter()
        res = solve_normal(gap_grid(gap, pixel, periodic=True), e_star=1.0, load=load,
                           options=SolveOptions(tol=1e-8, stats=stats))
        rows.append({"n": n, "seconds": time.perf_counter() - t0,
                     "iterations": res.iterations, "levels": [list(v) for v in stats.levels],
                     "area_fraction": float(np.mean(np.asarray(res.pressure) > 0))})
        print(f"periodic {n:5d}^2  {rows[-1]['iterations']:4d} iterations  "
              f"{rows[-1]['seconds']:8.2f} s  levels {stats.levels}", flush=True)
    return rows


def exponent(rows: list[dict], smallest: int = 512) -> float:
    """Least-squares slope of log(time) against log(cells) over sizes >= ``smallest``."""
    pts = [(math.log(r["n"] ** 2), math.log(r["seconds"])) for r in rows if r["n"] >= smallest]
    if len(pts) < 2:
        return math.nan
    x, y = np.array(pts).T
    return float(np.polyfit(x, y, 1)[0])


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--command", default="4096", help="grids for the whole command")
    ap.add_argument("--periodic", default="128,256,512,1024",
                    help="grids for the periodic iteration counts")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--json", metavar="FILE", help="write the figures")
    args = ap.parse_args(argv)
    out: dict = {"command": [], "periodic": []}
    for n in (int(v) for v in args.command.split(",") if v):
        r = command(n, args.repeats)
        out["command"].append(r)
        print(f"command {n:5d}^2  {r['wall_s']:7.1f} s = {r['ratio']:5.1f} padded "
              f"{2 * n}^2 convolutions ({r['yardstick_s']:.3f} s each; bound 25)  peak RSS "
              f"{r['peak_rss_bytes'] / 1e9:.2f} GB = {r['bytes_per_cell']:.0f} B/cell "
              f"(bound 110)  rc {r['rc']}  {r['solver']}", flush=True)
    sizes = [int(v) for v in args.periodic.split(",") if v]
    if sizes:
        out["periodic"] = periodic(sizes)
        out["exponent"] = exponent(out["periodic"])
        print(f"periodic time exponent over 512^2..{sizes[-1]}^2: {out['exponent']:.3f} "
              "(bound 1.15)")
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
