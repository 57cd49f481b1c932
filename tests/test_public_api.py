"""Each package's public face: ``__all__`` lists names that exist, star imports are clean,
and ``import surfmet`` stays light (the heavy rooms load on first use)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

# Walk every package of the four roots, star-import each in its own namespace and report
# what fails; one interpreter for all of them keeps the test fast.
_STAR = r"""
import importlib, json, pkgutil
failures, seen = {}, []
for root in ("surfmet", "contact", "profiles", "rotor"):
    names = [root] + [m.name for m in pkgutil.walk_packages(
        importlib.import_module(root).__path__, root + ".") if m.ispkg]
    for name in names:
        seen.append(name)
        try:
            exec(f"from {name} import *", {})
            module = importlib.import_module(name)
            public = getattr(module, "__all__", None)
            if public is None:
                failures[name] = "no __all__"
                continue
            missing = [n for n in public if not hasattr(module, n)]
            if missing:
                failures[name] = f"__all__ names missing: {missing}"
            elif len(set(public)) != len(public):
                failures[name] = "__all__ repeats a name"
        except Exception as exc:
            failures[name] = f"{type(exc).__name__}: {exc}"
print(json.dumps({"failures": failures, "seen": seen}))
"""


def _run(code: str) -> dict:
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                         text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_star_import_of_every_package_is_clean():
    result = _run(_STAR)
    # contact raised AttributeError on 'SolverStats' (exported, no longer there)
    assert result["failures"] == {}
    assert {"surfmet", "surfmet.io", "surfmet.mechanics", "contact", "rotor",
            "contact.halfspace", "profiles"} <= set(result["seen"])


_LIGHT = r"""
import json, sys
import surfmet
heavy = ("numba", "matplotlib", "pyvista", "surfmet.io", "surfmet.areal", "surfmet.mechanics")
before = sorted(m for m in heavy if m in sys.modules)
# the rooms are reachable without an explicit import, and load only when named
areal = surfmet.areal.areal_parameters.__module__
hertz = surfmet.mechanics.hertz_check.hertz_check.__name__
room = type(__import__("contact").roughcontact).__name__
try:
    surfmet.no_such_name
    unknown = "resolved"
except AttributeError as exc:
    unknown = str(exc)
print(json.dumps({"unknown": unknown, "before": before, "areal": areal, "hertz": hertz,
                  "room": room, "dir": "mechanics" in dir(surfmet)}))
"""


def test_import_surfmet_stays_light_and_rooms_load_on_first_use():
    result = _run(_LIGHT)
    assert result["before"] == []
    assert result["areal"] == "surfmet.areal._parameters"
    assert result["hertz"] == "hertz_check"
    assert result["room"] == "module"
    assert result["dir"] is True
    assert "no_such_name" in result["unknown"]

