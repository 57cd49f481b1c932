"""The elastic half-space: the one operator family under every contact solver.

- :mod:`contact.halfspace.operator`: the one operator protocol (apply, stiffness,
  self-influence; periodic, free, extended ahead; 3D, plane strain, axisymmetric) that
  every implementation below follows;
- :mod:`contact.halfspace.influence`: Love's influence coefficients of a uniformly loaded
  rectangle (the normal block), their free-boundary layout and spectrum, the periodised
  Love spectrum, and the Love spectrum of a grid extended ahead;
- :mod:`contact.halfspace.alias`: the periodic alias sum of every half-space symbol;
- :mod:`contact.halfspace.cerruti`: Boussinesq, Cerruti and Kalker's coupling on elements
  and, in plane strain, on strips (the blocks of the pair operator);
- :mod:`contact.halfspace.constants`: the pair's combined constants G, nu, K;
- :mod:`contact.halfspace.padding`: the zero-padded layouts (free, extended ahead, plane
  strain) and the pruned FFTs that every operator runs on, in float64 or float32;
- :mod:`contact.halfspace.convolution`: u = K * p for the normal solvers (free boundary
  by DC-FFT, periodic, or extended ahead for viscoelastic rolling), cached per grid, and
  :func:`~contact.halfspace.convolution.convolution`, the factory of the 3D operators;
- :mod:`contact.halfspace.spectral`: the periodic spectral kernel 2/|q| (Tamaas',
  ContactMechanics'), the other 3D implementation;
- :mod:`contact.halfspace.plane_strain`: the strip integral and the plane-strain operator;
- :mod:`contact.halfspace.axisymmetric`: the ring operator (uniform pressure on rings);
- :mod:`contact.halfspace.pair`: u = A t for the tractions (p, q_x, q_y) of two bodies
  (free, plane strain, extended ahead), for the tangential and viscoelastic solvers.

The Love kernels are for a composite modulus E* = 1 (divide by E* for metres); the pair's
blocks carry the pair's constants (m/Pa).
"""

from contact._lazy import attach

# Each room loads on first use (contact.halfspace.<room>), so that importing the package
# imports none of them.
__all__ = [
    "alias",
    "axisymmetric",
    "cerruti",
    "constants",
    "convolution",
    "influence",
    "operator",
    "padding",
    "pair",
    "plane_strain",
    "spectral",
]

__getattr__, __dir__ = attach(__name__, __all__)
