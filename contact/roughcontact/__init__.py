"""contact.roughcontact: rough-contact theories, measured against the boundary elements.

The room for the statistical and spectral models of rough contact (Greenwood-Williamson,
Bush-Gibson-Thomas, Persson, Greenwood-Tripp) and the spectral summit parameters they take.
Arrays and SI floats in, small frozen dataclasses out; never imports surfmet.
"""

from contact.roughcontact.greenwood_tripp import GreenwoodTripp, greenwood_tripp
from contact.roughcontact.hierarchy import ModelHierarchy, ModelPrediction, model_hierarchy
from contact.roughcontact.summits import (
    SummitParameters,
    isotropic_moments,
    plasticity_index,
    summit_parameters,
)

__all__ = [
    "GreenwoodTripp",
    "ModelHierarchy",
    "ModelPrediction",
    "SummitParameters",
    "greenwood_tripp",
    "isotropic_moments",
    "model_hierarchy",
    "plasticity_index",
    "summit_parameters",
]
