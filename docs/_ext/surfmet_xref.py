"""Sphinx extension: every reference to the project's own names must name a real object.

With ``nitpicky = True`` Sphinx warns on every reference it cannot link. The API pages
document the public faces only, so a docstring's reference to an engine's inner function
(``contact._rolling.sphere_sweep``) has no page to link to; this extension silences such a
warning when the dotted name resolves to a real module, attribute or dataclass field of
surfmet, contact or profiles, and lets it through when it resolves to nothing (a typo, a
renamed or removed function). Under ``-W`` that warning fails the build.
"""

from __future__ import annotations

from importlib import import_module
from typing import Any

PACKAGES = ("surfmet", "contact", "profiles")


def resolves(target: str) -> bool:
    """Whether a dotted name is an object of the project (a module, or an attribute of one,
    a dataclass field included)."""
    parts = target.split(".")
    for cut in range(len(parts), 0, -1):
        try:
            obj: Any = import_module(".".join(parts[:cut]))
        except ImportError:
            continue
        for attr in parts[cut:]:
            fields = getattr(obj, "__dataclass_fields__", {})
            if attr in fields:
                obj = fields[attr]
                continue
            try:
                obj = getattr(obj, attr)
            except AttributeError:
                return False
        return True
    return False


def own_object(app: Any, domain: Any, node: Any) -> bool | None:
    """``warn-missing-reference`` handler: True (no warning) for a real object of the
    project, None (the warning stands) otherwise."""
    if getattr(domain, "name", None) != "py":
        return None
    target = node.get("reftarget", "")
    module = node.get("py:module") or ""
    if target.split(".")[0] not in PACKAGES and module:
        target = f"{module}.{target}"
    if target.split(".")[0] in PACKAGES and resolves(target):
        return True
    return None


def setup(app: Any) -> dict[str, Any]:
    app.connect("warn-missing-reference", own_object)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
