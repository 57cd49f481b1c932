"""Shared test fixtures.

The real instrument files live in ``../shared/realdata`` beside the checkout (never copied
into the repository). Outside CI a missing file skips the tests that need it; under CI
(``CI=true``) it fails them, because a silently skipped check is no check.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SHARED = Path(os.environ.get("SURFMET_SHARED", ROOT.parent / "shared"))
REALDATA = SHARED / "realdata"
PAPER = SHARED / "data" / "paper_2022"
IN_CI = os.environ.get("CI", "").strip().lower() in {"1", "true", "yes"}


def shared_file(path: Path) -> Path:
    """Return ``path`` if it exists; otherwise fail under CI, skip elsewhere."""
    if path.exists():
        return path
    message = f"shared data file {path} is missing"
    if IN_CI:
        pytest.fail(message + " (under CI a missing data file is a failure)")
    pytest.skip(message)
    return path  # pragma: no cover


@pytest.fixture
def realdata():
    """``realdata("plu-1.plu")`` -> Path of a file in ../shared/realdata."""
    return lambda name: shared_file(REALDATA / name)


@pytest.fixture
def paperdata():
    """``paperdata("table3_frames.tsv")`` -> Path of a file in ../shared/data/paper_2022."""
    return lambda name: shared_file(PAPER / name)
