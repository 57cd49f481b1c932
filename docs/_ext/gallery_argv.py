"""The command line the documentation's gallery gives each example (sphinx-gallery's
``reset_argv``).

The how-tos take no arguments. The paper's scripts (``examples/paper_2022``) take minutes
each in their full form, so the gallery runs each as ``SCRIPT [OUTDIR] --gallery``: the
reduced run the script's own page describes (smaller grids, fewer loads), with its files
written to a folder under the system's temporary directory, not into the checkout (the
default folder of ``make_surfaces.py`` is ``surfmet/data``, the shipped scans). A reader
reproduces a page with the same command line, and runs the full study without
``--gallery``.
"""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Any

#: the paper's scripts that write files take their output folder as first argument
WRITES_FILES = ("contact.py", "make_surfaces.py", "rotor.py")


def gallery_argv(script: str | Path) -> list[str]:
    """``sys.argv[1:]`` for one example run by the gallery."""
    path = Path(script)
    if path.parent.name != "paper_2022":
        return []
    args = ["--gallery"]
    if path.name in WRITES_FILES:
        out = Path(tempfile.gettempdir()) / "surfmet_gallery" / path.stem
        args.insert(0, str(out))
    return args


def reset_argv(gallery_conf: dict[str, Any], script_vars: dict[str, Any]) -> list[str]:
    """sphinx-gallery's hook: the arguments of the example ``script_vars["src_file"]``."""
    return gallery_argv(script_vars["src_file"])
