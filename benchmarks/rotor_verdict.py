"""Time ``surfmet rotor paper2022`` (now with the joint model's verdict) against an earlier
revision, back to back on the same machine (the issue's target: within 2x).

    python benchmarks/rotor_verdict.py --baseline b74dd96 --repeats 3

The baseline runs from a temporary ``git worktree`` of that revision (``python -m surfmet``
with that tree first on the path); both are timed as child processes (wall and CPU). The
numba cache of each tree is warmed by one untimed run.
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _run(tree: Path) -> tuple[float, float]:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "surfmet", "rotor", "paper2022", "--json", "-q"],
                   cwd=tree, check=True, stdout=subprocess.DEVNULL,
                   env={**os.environ, "PYTHONPATH": str(tree)})
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--baseline", default="b74dd96", help="revision to compare with")
    ap.add_argument("--repeats", type=int, default=3)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        base = Path(tmp) / "baseline"
        subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", str(base),
                        a.baseline], check=True, capture_output=True)
        try:
            rows = {}
            for name, tree in (("baseline", base), ("now", ROOT)):
                _run(tree)  # warm the numba cache
                rows[name] = [_run(tree) for _ in range(a.repeats)]
        finally:
            subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(base)],
                           check=False, capture_output=True)
    for name, runs in rows.items():
        wall = min(r[0] for r in runs)
        cpu = min(r[1] for r in runs)
        print(f"{name:9s} wall {wall:7.2f} s   cpu {cpu:7.2f} s   ({a.repeats} runs, best)")
    w = min(r[0] for r in rows["now"]) / min(r[0] for r in rows["baseline"])
    c = min(r[1] for r in rows["now"]) / min(r[1] for r in rows["baseline"])
    print(f"ratio now/baseline: wall {w:.2f}x, cpu {c:.2f}x (target <= 2x)")


if __name__ == "__main__":
    main()
