"""Optional parts of surfmet and the extras that install them.

The core (reading scans, roughness, contact mechanics, figures) needs no optional package.
Two parts do:

- the 3D view (``surfmet show`` without ``--2d``, the report's 3D picture): pyvista and
  VTK, the ``view`` extra;
- the cluster engine (``--scheduler``): dask.distributed, the ``dask`` extra.

``pip install "surfmet[all]"`` installs both. :func:`require` imports a module of an extra
or raises :class:`MissingExtraError`, one line naming the extra to install.
"""

from __future__ import annotations

import importlib
from types import ModuleType

from surfmet._errors import SurfmetError

#: The extras and the modules each provides (as named in ``pyproject.toml``).
EXTRAS = {"view": ("pyvista", "vtk"), "dask": ("dask", "distributed")}


class MissingExtraError(SurfmetError, ImportError):
    """An optional part of surfmet is not installed; the message names the extra."""


def require(module: str, extra: str, what: str) -> ModuleType:
    """Import ``module`` of the extra ``extra``, needed for ``what``.

    Raises
    ------
    MissingExtraError
        The module is not installed: ``what needs pyvista: pip install "surfmet[view]"``.
    """
    try:
        return importlib.import_module(module)
    except ImportError:
        raise MissingExtraError(f"{what} needs {module}, which is not installed: "
                                f'pip install "surfmet[{extra}]" (or "surfmet[all]")'
                                ) from None
