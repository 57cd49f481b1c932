"""The elastic half-space: how a pressure on a grid of cells displaces the surface.

- :mod:`contact.halfspace.influence`: Love's influence coefficients of a uniformly loaded
  rectangle, their free-boundary layout and spectrum, and the periodised Love spectrum;
- :mod:`contact.halfspace.convolution`: the FFT convolution u = K * p (free boundary by
  DC-FFT, or periodic), cached per grid.

All kernels are for a composite modulus E* = 1: divide by E* for a displacement in metres.
"""
