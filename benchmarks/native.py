"""Native-resolution contact: whole-CLI time and peak memory, and time per iteration.

The problem (issue 12): the bundled paper pair, a rough ball (``paper_ball.x3p``, 50 um
pixel) on the bundled plate (``paper_plate.x3p``, 5 um pixel), R = 20 mm, 10 N, steel on
aluminium, free boundary, run as ``surfmet contact`` with ``--grid N``.

Three measurements, each in its own subprocess so that one size's memory never inflates
the next:

``cli``
    The whole command under ``/usr/bin/time -v`` (wall time and peak resident set size),
    plus the memory model's estimate (:mod:`contact.bem._memory`) for the same grid.
``iter``
    The same problem's fine-grid solve: time per Polonsky-Keer iteration (from the
    solver's per-iteration callback, first to last call, so the coarse nested levels and
    the set-up are not counted), against one padded free-boundary FFT convolution (rfft2,
    multiply, irfft2 on the 2N x 2N grid) in float32, as the search direction runs it, and
    in float64; their ratio says how much of an iteration is not the FFT.
``native``
    The command with no ``--grid`` (the scans' own pixel), to show the grid it picks.

Runs above a few GB must not overlap other big jobs on a shared machine: run the whole
script under ``flock /tmp/surfmet_bigmem.lock`` and check ``free -g`` first::

    flock /tmp/surfmet_bigmem.lock python3 benchmarks/native.py --cli 1024,2048,4096,8192 \\
        --iter 1024,2048,4096,8192
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DATA = ROOT / "surfmet" / "data"
CLI = ["contact", "--plate", str(DATA / "paper_plate.x3p"), "--ball",
       str(DATA / "paper_ball.x3p"), "--radius", "20mm", "--load", "10N",
       "--materials", "steel,aluminium"]


def _env() -> dict[str, str]:
    env = dict(os.environ)
    env["PYTHONPATH"] = str(ROOT) + os.pathsep + env.get("PYTHONPATH", "")
    return env


def run_cli(extra: list[str]) -> dict:
    """The whole CLI under /usr/bin/time -v: wall time, peak RSS, exit status, grid line."""
    cmd = ["/usr/bin/time", "-v", sys.executable, "-m", "surfmet", *CLI, *extra]
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True, env=_env(), cwd=ROOT)
    wall = time.perf_counter() - t0
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", proc.stderr)
    grid = next((ln for ln in proc.stdout.splitlines() if ln.startswith("grid")), "")
    solver = next((ln for ln in proc.stdout.splitlines() if ln.startswith("solver")), "")
    errors = [ln for ln in proc.stderr.splitlines() if ln.startswith("surfmet:")]
    return {"wall_s": wall, "peak_rss_bytes": int(rss.group(1)) * 1024 if rss else None,
            "rc": proc.returncode, "grid": grid.strip(), "solver": solver.strip(),
            "error": errors[-1] if errors else None}


def iteration_child(n: int, repeats: int) -> dict:
    """(In a child process) fine-grid time per iteration and one padded convolution."""
    import numpy as np

    import surfmet
    from contact import DomainSpec, SolveOptions
    from contact._materials import composite_modulus, material
    from contact.bem._state import SolverStats  # live counters, read in the callback
    from contact.halfspace.convolution import convolution
    from contact.setups import CompositeRoughness
    from contact.setups._ball_on_plate import SphereContact
    from surfmet.mechanics.pairing import prepare_pair

    pair = prepare_pair(surfmet.read(DATA / "paper_plate.x3p"),
                        surfmet.read(DATA / "paper_ball.x3p"))
    e_star = composite_modulus(material("steel"), material("aluminium"))
    rough = CompositeRoughness(pair.roughness, pair.dx, pair.dy)
    prob = SphereContact(0.02, e_star, 10.0, roughness=rough, domain=DomainSpec(grid=n))
    stamps: list[float] = []
    stats = SolverStats()
    t0 = time.perf_counter()
    counts: list[tuple[int, int]] = []

    def tick(it: int, r: float) -> None:
        stamps.append(time.perf_counter())
        counts.append((stats.fft_single, stats.fft_double))

    res = prob.solve(10.0, on_edge="warn", options=SolveOptions(callback=tick, stats=stats))
    total = time.perf_counter() - t0
    k = len(stamps) - 1
    per_it = (stamps[-1] - stamps[0]) / k if k > 0 else float("nan")
    # padded convolutions per fine iteration (float32 search and correction steps,
    # float64 exact re-syncs), over the same iterations as the time
    f32_it = (counts[-1][0] - counts[0][0]) / k if k > 0 else float("nan")
    f64_it = (counts[-1][1] - counts[0][1]) / k if k > 0 else float("nan")
    dx = prob.domain.dx
    conv = convolution(n, n, dx, dx, False)
    rng = np.random.default_rng(0)
    x = rng.random((n, n))
    x32 = x.astype(np.float32)
    fft = {}
    for name, arr, single in (("float32", x32, True), ("float64", x, False)):
        conv(arr, single=single)  # plan and warm up
        best = float("inf")
        for _ in range(repeats):
            t = time.perf_counter()
            conv(arr, single=single)
            best = min(best, time.perf_counter() - t)
        fft[name] = best
    return {"n": n, "solve_s": total, "fine_iterations": res.iterations,
            "levels": [list(lv) for lv in stats.levels], "per_iteration_s": per_it,
            "f32_convolutions_per_iteration": f32_it,
            "f64_convolutions_per_iteration": f64_it,
            "sparse_corrections": stats.sparse_corrections,
            "fft_float32_s": fft["float32"], "fft_float64_s": fft["float64"],
            "ratio_float32": per_it / fft["float32"], "ratio_float64": per_it / fft["float64"],
            "pmax_Pa": res.pmax}


def run_iter(n: int, repeats: int) -> dict:
    cmd = [sys.executable, __file__, "--child", str(n), "--repeats", str(repeats)]
    proc = subprocess.run(cmd, capture_output=True, text=True, env=_env(), cwd=ROOT)
    if proc.returncode != 0:
        return {"n": n, "error": proc.stderr.strip().splitlines()[-1:]}
    return json.loads(proc.stdout.strip().splitlines()[-1])


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cli", default="1024,2048,4096", help="grids for the whole CLI")
    ap.add_argument("--iter", default="1024,2048,4096", help="grids for time per iteration")
    ap.add_argument("--native", action="store_true", help="also run with no --grid")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--child", type=int, help=argparse.SUPPRESS)
    ap.add_argument("--json", metavar="FILE", help="write all results")
    args = ap.parse_args()
    if args.child:
        print(json.dumps(iteration_child(args.child, args.repeats)))
        return 0
    from contact.bem._memory import estimate_peak_bytes

    out: dict = {"cli": [], "iter": [], "native": None}
    for n in (int(v) for v in args.cli.split(",") if v):
        r = run_cli(["--grid", str(n)])
        r.update(n=n, estimate_bytes=estimate_peak_bytes(n))
        out["cli"].append(r)
        rss = r["peak_rss_bytes"] or 0
        print(f"cli  {n:5d}^2  wall {r['wall_s']:7.1f} s  peak RSS {rss / 1e9:6.2f} GB  "
              f"estimate {r['estimate_bytes'] / 1e9:6.2f} GB  rc {r['rc']}  {r['solver']}"
              f"{'  ' + r['error'] if r['error'] else ''}", flush=True)
    for n in (int(v) for v in args.iter.split(",") if v):
        r = run_iter(n, args.repeats)
        out["iter"].append(r)
        if "error" in r:
            print(f"iter {n:5d}^2  failed: {r['error']}", flush=True)
            continue
        print(f"iter {n:5d}^2  {r['per_iteration_s'] * 1e3:8.1f} ms/iteration "
              f"({r['fine_iterations']} fine iterations, levels {r['levels']}); "
              f"padded FFT convolution {r['fft_float32_s'] * 1e3:7.1f} ms (f32) "
              f"{r['fft_float64_s'] * 1e3:7.1f} ms (f64); ratio {r['ratio_float32']:.2f} "
              f"(f32) {r['ratio_float64']:.2f} (f64); solve {r['solve_s']:.1f} s; padded "
              f"convolutions per fine iteration {r['f32_convolutions_per_iteration']:.2f} "
              f"f32 + {r['f64_convolutions_per_iteration']:.2f} f64 (+ one unpadded "
              "preconditioner FFT pair)", flush=True)
    if args.native:
        r = run_cli([])
        out["native"] = r
        print(f"native  wall {r['wall_s']:.1f} s  peak RSS "
              f"{(r['peak_rss_bytes'] or 0) / 1e9:.2f} GB  {r['grid']}", flush=True)
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
