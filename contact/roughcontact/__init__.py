"""contact.roughcontact: rough-contact theories, measured against the boundary elements.

The room for the statistical and spectral models of rough contact (Greenwood-Williamson,
Bush-Gibson-Thomas, Persson, Greenwood-Tripp) and the spectral summit parameters they take.
Arrays and SI floats in, small frozen dataclasses out; never imports surfmet.
"""

from contact.roughcontact.summits import (
    SummitParameters,
    isotropic_moments,
    plasticity_index,
    summit_parameters,
)

__all__ = [
    "SummitParameters",
    "isotropic_moments",
    "plasticity_index",
    "summit_parameters",
]
