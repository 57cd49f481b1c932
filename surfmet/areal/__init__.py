"""Areal (3D) surface texture of a :class:`~surfmet._model.Topography`: the areal layer above
the profile engine (:mod:`profiles`), one concept per module.

Rooms
-----
form            F-operators: plane, polynomial, sphere, cylinder removal (ISO 25178-2)
filters         areal Gaussian S- and L-filters (ISO 16610-61) with edge treatments
height          Sa, Sq, Sp, Sv, Sz, Ssk, Sku
hybrid          Sdq, Sdr
spatial         autocorrelation, Sal, Str, angular spectrum, Std
features        Wolf-pruned hill segmentation, Spd, Spc
material_ratio  Smr(c), Smc(mr), Sk, Spk, Svk, Smr1, Smr2 (the "functional" family)
parameters      all of them in one call (:func:`areal_parameters`), units and groups

Every parameter uses the measured (non-NaN) points of the scan and nothing else.
"""

from surfmet.areal._parameters import GROUPS, PARAMETER_UNITS, ArealParameters, areal_parameters

__all__ = ["GROUPS", "PARAMETER_UNITS", "ArealParameters", "areal_parameters"]
