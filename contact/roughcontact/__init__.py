"""contact.roughcontact: rough-contact theories, measured against the boundary elements.

The room for the statistical and spectral models of rough contact (Greenwood-Williamson,
Bush-Gibson-Thomas, Persson, Greenwood-Tripp), the spectral summit parameters they take and
the isotropic PSD from a profile PSD (:mod:`~contact.roughcontact._isotropic`).
Arrays and SI floats in, small frozen dataclasses out; never imports surfmet.
"""

from contact.roughcontact._bgt import KAPPA_BGT, bush_gibson_thomas
from contact.roughcontact._greenwood_tripp import Asperities, GreenwoodTripp, greenwood_tripp
from contact.roughcontact._gw import greenwood_williamson, gw_integral, gw_state
from contact.roughcontact._hierarchy import ModelHierarchy, ModelPrediction, model_hierarchy
from contact.roughcontact._isotropic import (
    iso_from_profile_psd,
    log_quadrature,
    self_affine_factor,
)
from contact.roughcontact._persson import KAPPA_PERSSON, ModelCurve, kappa, persson
from contact.roughcontact._summits import (
    SummitParameters,
    isotropic_moments,
    plasticity_index,
    summit_parameters,
)

__all__ = [
    "KAPPA_BGT",
    "KAPPA_PERSSON",
    "Asperities",
    "GreenwoodTripp",
    "ModelCurve",
    "ModelHierarchy",
    "ModelPrediction",
    "SummitParameters",
    "bush_gibson_thomas",
    "greenwood_tripp",
    "greenwood_williamson",
    "gw_integral",
    "gw_state",
    "iso_from_profile_psd",
    "isotropic_moments",
    "kappa",
    "log_quadrature",
    "model_hierarchy",
    "persson",
    "plasticity_index",
    "self_affine_factor",
    "summit_parameters",
]
