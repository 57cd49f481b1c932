"""The grid of a tangential problem: :class:`contact._grid.Grid`, re-exported.

The grid holds the contact area with a small margin, as in CONTACT's potential contact
area: tractions outside it are zero. Its one home is :mod:`contact._grid` (shared with the
normal BEM and the viscoelastic solver); this module keeps the import path of the
tangential modules.
"""

from contact._grid import Grid, centres, cylinder_grid, sphere_grid

__all__ = ["Grid", "centres", "cylinder_grid", "sphere_grid"]
