"""Lazy public faces: a package lists its public names in ``__all__`` and imports each
module only when one of its names is first used (the pattern of scientific-python's
``lazy_loader.attach``, written here so that no dependency is added).

The user layer's copy: ``surfmet`` and its subpackages use it. The engines never import
``surfmet``, and loading a scan with ``surfmet`` must not import ``contact``
(tests/test_registry.py), so ``contact._lazy`` holds the same twenty lines for the engine.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Iterable, Mapping
from typing import Any


def attach(
    package: str,
    submodules: Iterable[str] = (),
    attributes: Mapping[str, str] | None = None,
) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """``__getattr__`` and ``__dir__`` for a package whose names load on first use.

    Parameters
    ----------
    package : str
        The package's ``__name__``.
    submodules : iterable of str
        Submodules reachable as ``package.name`` without an explicit import.
    attributes : mapping of str to str, optional
        ``{name: module}``: ``package.name`` is ``module.name``, imported on first use.

    Returns
    -------
    __getattr__, __dir__ : callable
        To be assigned at the package's module level.
    """
    subs = frozenset(submodules)
    attrs = dict(attributes or {})
    module = importlib.import_module(package)

    def __getattr__(name: str) -> Any:
        if name in attrs:
            value = getattr(importlib.import_module(attrs[name]), name)
        elif name in subs:
            value = importlib.import_module(f"{package}.{name}")
        else:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        setattr(module, name, value)  # the next look-up is a plain attribute
        return value

    def __dir__() -> list[str]:
        return sorted(set(vars(module)) | subs | set(attrs))

    return __getattr__, __dir__
