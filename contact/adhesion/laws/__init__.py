"""Interaction laws: the attractive traction between two surfaces at a local gap g.

Each law is a plug-in: a frozen dataclass deriving from :class:`InteractionLaw`
(:mod:`contact.adhesion.laws._base`: what a law states) in a module of its own here,
registered by name in the one table :data:`LAWS` (:mod:`contact.adhesion.laws._registry`).
Every module of this package is imported with it, so a new law is one new file: the
solvers, the facades and the commands find it in the table. An object that is not a
registered law is refused (:func:`checked_law`), never solved as another.

The laws: :mod:`~contact.adhesion.laws._dugdale` (Maugis' step, optionally smoothed on the
grid), :mod:`~contact.adhesion.laws._exponential`, and every other module here.
"""

from __future__ import annotations

import importlib
import pkgutil

from contact.adhesion.laws._base import (
    RANGE,
    WORK,
    InteractionLaw,
    LawParameter,
    maugis_parameter,
    tabor_parameter,
)
from contact.adhesion.laws._dugdale import EDGE_SMOOTHING, DugdaleLaw
from contact.adhesion.laws._exponential import ExponentialLaw
from contact.adhesion.laws._registry import (
    LAWS,
    build_law,
    checked_law,
    kernel_arguments,
    law_class,
    law_names,
    law_parameters,
    register_law,
)

#: The modules that are not laws.
_NOT_LAWS = frozenset({"_base", "_registry"})

for _module in pkgutil.iter_modules(__path__):
    if _module.name not in _NOT_LAWS:  # each law's module registers its law
        importlib.import_module(f"{__name__}.{_module.name}")

__all__ = ["EDGE_SMOOTHING", "LAWS", "RANGE", "WORK", "DugdaleLaw", "ExponentialLaw",
           "InteractionLaw", "LawParameter", "build_law", "checked_law", "kernel_arguments",
           "law_class", "law_names", "law_parameters", "maugis_parameter", "register_law",
           "tabor_parameter"]
