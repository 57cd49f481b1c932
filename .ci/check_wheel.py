"""Check a built wheel holds every module and data file of the four packages.

Usage: python3 .ci/check_wheel.py DIST/surfmet-*.whl

Every file git tracks under surfmet/, contact/, profiles/ and rotor/ (modules, the bundled scans,
the rotor's calibration JSON, py.typed) must be in the wheel: a subpackage without
``__init__.py`` or a data file left out of ``[tool.setuptools.package-data]`` is named here,
before the smoke run from the installed wheel would trip on it.
"""

from __future__ import annotations

import subprocess
import sys
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("surfmet", "contact", "profiles", "rotor")


def missing_from_wheel(wheel: str | Path) -> list[str]:
    """The tracked package files that the wheel does not hold."""
    tracked = subprocess.run(["git", "ls-files", *PACKAGES], cwd=ROOT, check=True,
                             capture_output=True, text=True).stdout.split()
    held = set(zipfile.ZipFile(wheel).namelist())
    return sorted(f for f in tracked if f not in held)


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        print("usage: check_wheel.py WHEEL", file=sys.stderr)
        return 1
    missing = missing_from_wheel(argv[0])
    if missing:
        print(f"{argv[0]}: {len(missing)} package files are not in the wheel: "
              + ", ".join(missing[:20]), file=sys.stderr)
        return 1
    print(f"{Path(argv[0]).name}: every tracked package file is in the wheel")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
