"""profiles: the 1D engine (profile parameters, ISO Gaussian filtering, circle fitting).

Arrays and SI floats in, arrays and small frozen dataclasses out. Never imports surfmet.

Main entry points
-----------------
analyze_profile      window, levelling, λs/λc filters and ISO parameters in one call
profile_parameters   Ra, Rq, Rp, Rv, Rz, Rt, Rsk, Rku, Rsm, Rdq of a profile
split_profile        primary / waviness / roughness by the ISO 16610-21 Gaussian filter
iso4288_cutoff       automatic λc per ISO 4288
fit_circle           radius of a ball or roller from a profile
material_ratio, material_ratio_curve   Abbott-Firestone curve, Rmr(c)
material_ratio_height   ISO 21920-2 Rcm(p), the level at material ratio p below the top
rk_parameters, probability_parameters   ISO 13565-2 Rk family, ISO 13565-3 Rpq, Rvq, Rmq
feature_parameters   ISO 21920-2 Rpd, Rvd, Rmpc, Rmvc, R5p, R5v, R10z (Wolf pruning)
remove_form          least-squares line / polynomial removal

Scale-dependent statistics (slope and curvature over a distance, tip-radius cut-off,
variable bandwidth) live in :mod:`profiles._scales`, imported on demand.
"""

from profiles._analysis import ProfileAnalysis, analyze_profile
from profiles._circle import CircleFit, fit_circle
from profiles._cutoff import CutoffChoice, iso4288_cutoff
from profiles._errors import ProfileError
from profiles._features import FeatureParameters, feature_parameters
from profiles._filters import (
    ALPHA,
    ProfileSplit,
    gaussian_mean_line,
    gaussian_transmission,
    split_profile,
)
from profiles._form import FormFit, level_profile, remove_form
from profiles._material_ratio import (
    height_at_ratio,
    material_ratio,
    material_ratio_curve,
    material_ratio_height,
    section_height_difference,
)
from profiles._parameters import ProfileParameters, profile_parameters
from profiles._positions import RegularProfile, regularize
from profiles._rk import (
    ProbabilityParameters,
    RkParameters,
    probability_parameters,
    rk_parameters,
)

__all__ = [
    "ALPHA",
    "CircleFit",
    "CutoffChoice",
    "FeatureParameters",
    "FormFit",
    "ProbabilityParameters",
    "ProfileAnalysis",
    "ProfileError",
    "ProfileParameters",
    "ProfileSplit",
    "RegularProfile",
    "RkParameters",
    "analyze_profile",
    "feature_parameters",
    "fit_circle",
    "gaussian_mean_line",
    "gaussian_transmission",
    "height_at_ratio",
    "iso4288_cutoff",
    "level_profile",
    "material_ratio",
    "material_ratio_curve",
    "material_ratio_height",
    "probability_parameters",
    "profile_parameters",
    "regularize",
    "remove_form",
    "rk_parameters",
    "section_height_difference",
    "split_profile",
]
