"""What an interaction law is: the base every law derives from, and its parameters.

An interaction law is a frozen dataclass deriving from :class:`InteractionLaw`, registered
in the one table of :mod:`contact.adhesion.laws._registry` by its :attr:`~InteractionLaw.name`.
It states, as the solvers, the facades and the commands ask:

- ``name`` and ``summary`` (class attributes): what the commands call it and one line
  saying what it is;
- ``parameters`` (class attribute): the numbers it is built from
  (:class:`LawParameter`, with their SI units), and :meth:`InteractionLaw.from_parameters`;
- ``work``, ``peak``, ``range``, ``reach``: work of adhesion (J/m^2), largest tension (Pa),
  the length its range is stated by and the gap beyond which it no longer attracts (m);
- :meth:`~InteractionLaw.traction` and :meth:`~InteractionLaw.potential` (numpy);
- :meth:`~InteractionLaw.kernel_args`: the (form code, reach, width) the numba kernels of
  :mod:`contact.adhesion.kernels` take;
- and, with defaults here: its Maugis parameter, its form on a grid (a step smoothed on
  the grid's scale), the step smoothing, and the rigid cylinder's pull-off.

Writing the energy per unit area phi(g) with phi(0) = -w and phi -> 0 far away, the
attractive traction is t(g) = phi'(g) >= 0 (a tension of magnitude t pulls the surfaces
together).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np


def maugis_parameter(sigma0: float, work: float, radius: float, e_star: float) -> float:
    """Maugis' lambda = 2 sigma0 (R / (pi w K^2))^(1/3), K = 4 E* / 3 (Maugis 1992, eq. 6)."""
    k = 4.0 * e_star / 3.0
    return 2.0 * sigma0 * (radius / (math.pi * work * k * k)) ** (1.0 / 3.0)


def tabor_parameter(work: float, radius: float, e_star: float, length: float) -> float:
    """Tabor's mu = (R w^2 / (E*^2 z^3))^(1/3) with the interaction length z (Tabor 1977)."""
    return (radius * work * work / (e_star * e_star * length ** 3)) ** (1.0 / 3.0)


@dataclass(frozen=True)
class LawParameter:
    """One number a law is built from.

    Attributes
    ----------
    keyword : str
        The keyword of :meth:`InteractionLaw.from_parameters`; a command's option is it
        with ``_`` as ``-`` (a trailing ``_`` dropped: ``range_`` is ``--range``).
    unit : str
        Its SI unit: ``"J/m^2"``, ``"N/m"``, ``"m"``, ``"Pa"`` or ``"rad"``.
    help : str
        What it is, for a command's help.
    """

    keyword: str
    unit: str
    help: str

    @property
    def option(self) -> str:
        """The command-line option: ``--work-of-adhesion`` for ``work_of_adhesion``."""
        return "--" + self.keyword.rstrip("_").replace("_", "-")


#: The two numbers of the laws stated by a work and a range.
WORK = LawParameter("work_of_adhesion", "J/m^2", "work of adhesion w, e.g. 50mJ/m2")
RANGE = LawParameter("range_", "m", "interaction range, e.g. 2nm")


class InteractionLaw:
    """The base of every interaction law (module notes): the defaults a law may keep.

    A law derives from this class as a frozen dataclass with the attributes ``work``,
    ``peak``, ``range`` and ``reach``, the methods :meth:`traction`, :meth:`potential` and
    :meth:`kernel_args`, the class attributes ``name`` and ``summary``, and registers
    itself with :func:`contact.adhesion.laws._registry.register_law`.
    """

    #: The name the commands and the records give the law.
    name: ClassVar[str] = ""
    #: One line saying what the law is (the commands' help).
    summary: ClassVar[str] = ""
    #: The numbers :meth:`from_parameters` takes.
    parameters: ClassVar[tuple[LawParameter, ...]] = (WORK, RANGE)
    #: Whether :meth:`on_grid` smooths a step (the default grid then resolves the
    #: cohesive zone at :data:`contact._zone_resolution.MIN_ZONE_PIXELS`).
    grid_smoothed: ClassVar[bool] = False
    #: The width of a smoothed step (m); 0 for a law without one.
    smoothing: float = 0.0

    if TYPE_CHECKING:  # a law's own fields or properties (none here: a dataclass field
        # could not shadow a property of its base)
        @property
        def work(self) -> float:
            """Work of adhesion w (J/m^2)."""

        @property
        def peak(self) -> float:
            """The largest tension (Pa)."""

        @property
        def range(self) -> float:
            """The length the law's range is stated by (m)."""

        @property
        def reach(self) -> float:
            """The gap beyond which the surfaces no longer attract (m)."""

    @classmethod
    def from_parameters(cls, **values: Any) -> Any:
        """The law of the :attr:`parameters` ``values`` (SI); by default ``cls(**values)``."""
        return cls(**values)

    def traction(self, g: np.ndarray | float) -> np.ndarray:  # pragma: no cover - abstract
        """The attractive traction t(g) (Pa) at the gap ``g`` (m)."""
        raise NotImplementedError

    def potential(self, g: np.ndarray | float) -> np.ndarray:  # pragma: no cover - abstract
        """The energy per unit area phi(g) (J/m^2), phi(0) = -w."""
        raise NotImplementedError

    def kernel_args(self, single: bool) -> tuple[int, float, float]:  # pragma: no cover
        """(form code, reach, width) of :mod:`contact.adhesion.kernels`; ``single``: the
        float32 solve's form, where the law has one."""
        raise NotImplementedError

    def maugis(self, radius: float, e_star: float) -> float:
        """Maugis' lambda of a sphere of radius ``radius`` (m) with modulus ``e_star`` (Pa):
        that of the Dugdale law of the same work and peak tension."""
        return maugis_parameter(self.peak, self.work, radius, e_star)

    def on_grid(self, dx: float, e_star: float) -> Any:
        """This law as a grid of pitch ``dx`` (m) solves it best; by default unchanged."""
        return self

    def rigid_line_pull_off(self, radius: float) -> float:
        """The pull-off (N/m) of a rigid cylinder of radius ``radius`` (m): the traction
        integrated over the undeformed gap x^2 / (2 R), 2 sqrt(2 R) int_0^inf t(s^2) ds
        (by quadrature; a law with a closed form states it instead)."""
        from scipy import integrate

        head = math.sqrt(self.reach)  # s = head u: quad sees the law's scale as 1

        def f(u: float) -> float:
            return float(self.traction((head * u) ** 2))

        near = integrate.quad(f, 0.0, 1.0, limit=200)[0]
        far = integrate.quad(f, 1.0, math.inf, limit=200)[0]
        return 2.0 * math.sqrt(2.0 * radius) * head * (near + far)
