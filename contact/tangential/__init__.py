"""Rolling and shift contact with friction: a tangential boundary-element solver.

Tractions (q_x, q_y) with Coulomb friction on a regular grid, stick and slip areas,
Cerruti influence coefficients and, for dissimilar bodies, the normal-tangential coupling
(Kalker's K, Dundurs' beta) iterated with the normal problem; steady rolling with
prescribed creepages or tangential force, shifts (Cattaneo-Mindlin) and stepwise
compression (Spence); plane strain and 3D, smooth or rough.

The influence operator and the pair's constants are those of :mod:`contact.halfspace`
(:mod:`~contact.halfspace.pair`, :mod:`~contact.halfspace.constants`, re-exported here).
Modules: :mod:`~contact.tangential._kinematics` (creepage, slip), :mod:`contact._grid` (the grid),
:mod:`~contact.tangential._normal` (pressure with an extra gap),
:mod:`~contact.tangential._solver` (active-set iteration), :mod:`~contact.tangential._kernels`
(compiled loops), :mod:`~contact.tangential._forcecontrol`, :mod:`~contact.tangential._steady`
(steady rolling), :mod:`~contact.tangential._nested` (coarse-grid start),
:mod:`~contact.tangential._shift`, :mod:`~contact.tangential._results`.
"""

from contact._grid import Grid, cylinder_grid, sphere_grid
from contact.halfspace.constants import PairConstants, pair_constants, pair_constants_from
from contact.tangential._kinematics import Creepage
from contact.tangential._results import TangentialResult
from contact.tangential._shift import compress_in_steps, shift
from contact.tangential._steady import RollingOptions, steady_rolling

__all__ = [
    "Creepage", "Grid", "PairConstants", "RollingOptions", "TangentialResult",
    "compress_in_steps",
    "cylinder_grid", "pair_constants", "pair_constants_from", "shift", "sphere_grid",
    "steady_rolling",
]
