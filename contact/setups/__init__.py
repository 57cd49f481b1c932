"""Contact problem set-ups: what is pressed on what, on the grid, ready for the solvers.

- :mod:`contact.setups.composite`: :class:`CompositeRoughness`, the measured composite
  roughness under a ball (heights, pitch, apex position, levelling);
- :mod:`contact.setups.ball_on_plate`: a (rough) ball on a plate (:class:`SphereContact`,
  :func:`solve_sphere`), elastic or elastic-perfectly-plastic;
- :mod:`contact.setups.line`: a cylinder or 2D profile on a half-plane (plane strain);
- :mod:`contact.setups.flat`: a rough surface pressed on a flat over a pressure sweep.
"""

from __future__ import annotations

from contact.setups.composite import CompositeRoughness

__all__ = ["CompositeRoughness"]
