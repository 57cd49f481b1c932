"""Execute notebooks with nbclient; exit 1 naming the first that fails.

Usage: python3 .ci/run_notebooks.py NOTEBOOK...

Each runs in its own folder with a fresh kernel (the ``python3`` kernelspec of
ipykernel), nothing is written back: the committed notebooks carry no outputs.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path


def run_notebook(path: str | Path, timeout: int = 600) -> float:
    """Execute one notebook; the seconds it took. Raises nbclient's CellExecutionError."""
    import nbformat
    from nbclient import NotebookClient

    p = Path(path)
    nb = nbformat.read(p, as_version=4)
    start = time.perf_counter()
    NotebookClient(nb, timeout=timeout, kernel_name="python3",
                   resources={"metadata": {"path": str(p.parent)}}).execute()
    return time.perf_counter() - start


def main(paths: list[str]) -> int:
    if not paths:
        print("usage: run_notebooks.py NOTEBOOK...", file=sys.stderr)
        return 1
    from nbclient.exceptions import CellExecutionError

    for p in paths:
        try:
            seconds = run_notebook(p)
        except CellExecutionError as exc:
            print(f"{p}: a cell raised:\n{exc}", file=sys.stderr)
            return 1
        print(f"{p}: ran in {seconds:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
