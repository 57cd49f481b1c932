"""Steady rolling on linear viscoelastic bodies (standard linear solid, Prony series).

Modules: :mod:`.rheology` (SLS in CONTACT's convention, Prony series, the pair's creep
series), :mod:`.hunter` (Hunter's 1961 closed form for a rigid cylinder), :mod:`.line`
(plane-strain boundary elements, exact influence coefficients), :mod:`.surface` (3D FFT
boundary elements on a grid), :mod:`.loss` (loss data of materials, with sources),
:mod:`.traction` (plane-strain steady rolling tractions with creep), :mod:`.traction3d`
(3D tractions: the tangential solver with a creep-filtered Cerruti operator), :mod:`.kernels`
(numba: the exponential creep filter), :mod:`.sweep` (load sweep and lambda),
:mod:`.mechanisms` (rolling-friction mechanisms side by side at the rotor's loads),
:mod:`.result` (the result record). Guide: docs/viscoelastic_rolling.md.
"""

from contact.viscoelastic._hunter import HunterSolution, hunter_cylinder
from contact.viscoelastic._line import rolling_cylinder, solve_line
from contact.viscoelastic._loss import LossData, loss_data
from contact.viscoelastic._result import RollingResult
from contact.viscoelastic._rheology import (
    CreepSeries,
    PronySeries,
    StandardLinearSolid,
    pair_creep,
)
from contact.viscoelastic._traction import TractionResult, steady_traction
from contact.viscoelastic._traction3d import (
    ViscoHalfSpacePair,
    ViscoRolling,
    visco_steady_tractions,
)

__all__ = [
    "CreepSeries",
    "HunterSolution",
    "LossData",
    "PronySeries",
    "RollingResult",
    "StandardLinearSolid",
    "TractionResult",
    "ViscoHalfSpacePair",
    "ViscoRolling",
    "hunter_cylinder",
    "loss_data",
    "pair_creep",
    "rolling_cylinder",
    "solve_line",
    "steady_traction",
    "visco_steady_tractions",
]
