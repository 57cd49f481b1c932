"""The one table of interaction laws: name -> law class.

Every law registers itself here (:func:`register_law`, a class decorator), and everything
that once switched on a law's type asks this table or the law: the kernels' arguments
(:func:`kernel_arguments`), the commands' ``--interaction`` choices and parameter options
(:func:`law_names`, :func:`law_parameters`), a law built by name (:func:`build_law`) and
the name written into the records (the law's own ``name``). An object that is not an
instance of a registered law is refused (:func:`checked_law`), never solved as another.

The laws shipped with the engine are the modules of :mod:`contact.adhesion.laws`, each
imported (and so registered) when the package is: a new law is a new module there.
"""

from __future__ import annotations

from typing import Any, TypeVar

from contact._errors import ContactInputError
from contact.adhesion.laws._base import InteractionLaw, LawParameter

__all__ = ["LAWS", "build_law", "checked_law", "kernel_arguments", "law_class", "law_names",
           "law_parameters", "register_law"]

#: name -> law class, in the order of registration.
LAWS: dict[str, type[InteractionLaw]] = {}

L = TypeVar("L", bound=type)


def register_law(cls: L) -> L:
    """Enter the law class ``cls`` in :data:`LAWS` under its ``name`` (a class decorator).

    Raises
    ------
    ContactInputError
        Where ``cls`` is not an :class:`InteractionLaw`, has no name, or its name is taken
        by another class.
    """
    if not (isinstance(cls, type) and issubclass(cls, InteractionLaw)):
        raise ContactInputError(f"an interaction law derives from "
                                f"contact.adhesion.laws.InteractionLaw, got {cls!r}")
    name = cls.name
    if not (isinstance(name, str) and name.isidentifier() and name.islower()):
        raise ContactInputError(f"the law {cls.__name__} needs a lower-case name, got "
                                f"{name!r}")
    if LAWS.get(name, cls) is not cls:
        raise ContactInputError(f"the law name {name!r} is taken by "
                                f"{LAWS[name].__qualname__}")
    LAWS[name] = cls
    return cls


def law_names() -> tuple[str, ...]:
    """The names of the registered laws, in the order of registration."""
    return tuple(LAWS)


def law_class(name: str) -> type[InteractionLaw]:
    """The law class registered as ``name``; an unknown name is one error naming the known."""
    try:
        return LAWS[name]
    except (KeyError, TypeError):
        raise ContactInputError(f"unknown interaction law {name!r}: the laws are "
                                f"{', '.join(LAWS)}") from None


def checked_law(law: Any) -> InteractionLaw:
    """``law`` itself where it is an instance of a registered law; anything else is
    refused, so that no object is solved as a law it is not."""
    cls = type(law)
    if LAWS.get(getattr(cls, "name", "")) is not cls:
        raise ContactInputError(
            f"{cls.__qualname__} is not a registered interaction law (the laws are "
            f"{', '.join(LAWS)}; a new one derives from InteractionLaw and is registered "
            f"with contact.adhesion.laws.register_law)")
    return law


def kernel_arguments(law: Any, single: bool = False) -> tuple[int, float, float]:
    """(form code, reach, width) of a registered law for :mod:`contact.adhesion.kernels`."""
    return checked_law(law).kernel_args(single)


def law_parameters() -> dict[str, LawParameter]:
    """Every registered law's parameters by keyword, each once (the commands' options)."""
    out: dict[str, LawParameter] = {}
    for cls in LAWS.values():
        for p in cls.parameters:
            out.setdefault(p.keyword, p)
    return out


def build_law(name: str, **values: float | None) -> InteractionLaw:
    """The law ``name`` of the parameter ``values`` (SI; None for one not given).

    Raises
    ------
    ContactInputError
        For an unknown name, a parameter the law does not take, or one it needs and was
        not given: one line naming them.
    """
    cls = law_class(name)
    wanted = {p.keyword: p for p in cls.parameters}
    given = {k: v for k, v in values.items() if v is not None}
    extra = [k for k in given if k not in wanted]
    if extra:
        raise ContactInputError(
            f"the {name} law does not take {_options(extra, 'or')} (it takes "
            f"{_options(wanted, 'and')})")
    missing = [k for k in wanted if k not in given]
    if missing:
        raise ContactInputError(f"the {name} law needs {_options(missing, 'and')}")
    return cls.from_parameters(**given)


def _options(keywords: Any, word: str) -> str:
    """'--a, --b and --c' of the keywords (their options' spelling, as the commands
    and the keywords alike name them)."""
    names = [LawParameter(k, "", "").option for k in keywords]
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} {word} {names[-1]}"
