"""Contact problem set-ups: what is pressed on what, on the grid, ready for the solvers.

- :mod:`contact.setups._composite`: :class:`CompositeRoughness`, the measured composite
  roughness under a ball (heights, pitch, apex position, levelling);
- :mod:`contact.setups._ball_on_plate`: a (rough) ball on a plate (:class:`SphereContact`,
  :func:`solve_sphere`), elastic or elastic-perfectly-plastic;
- :mod:`contact.setups._line`: a cylinder or 2D profile on a half-plane (plane strain);
- :mod:`contact.setups._flat`: a rough surface pressed on a flat over a pressure sweep.
"""

from __future__ import annotations

from contact.setups._composite import CompositeRoughness

__all__ = ["CompositeRoughness"]
