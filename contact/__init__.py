"""contact: the contact-mechanics engine (materials, Hertz, FFT boundary elements, rolling
resistance). The rotor study of Alaci et al. 2022 is an engine of its own, ``rotor``.

Arrays and SI floats in, arrays and small frozen dataclasses out. Never imports surfmet.

Main entry points::

    from contact import material, composite_modulus, hertz_sphere, solve_sphere
    E = composite_modulus(material("steel"), material("aluminium"))
    hertz_sphere(0.02, 10.0, E)            # a, delta, p0 of the paper's ball
    res = solve_sphere(0.02, 10.0, E)      # FFT-BEM, smooth ball: ContactResult
    rough = CompositeRoughness(z, 5e-6)    # composite roughness, pitch, apex position
    res = solve_sphere(0.02, 10.0, E, roughness=rough)                  # rough
    prob = SphereContact(0.02, E, 100.0, roughness=rough)
    results = prob.sweep([1, 3, 10, 30, 100])   # warm-started load sweep
    check_sphere(...)                      # BEM against Hertz, with a verdict (hertzcheck)

Rooms are subpackages (``contact.setups``: ball on plate, line, flat, the composite
roughness; ``contact.bem``, ``contact.adhesion``, ``contact.roughcontact``...); the modules
behind the names below are private (scikit-image's split: ``contact._hertz``,
``contact._hertzcheck``, ``contact._rolling``, ``contact._exponent``...), so import the
names from ``contact``: theories (``hertz_sphere``), verdicts (``check_sphere``), roughness
statistics (``gjm_alpha``), rolling resistance and its load exponent::

    sphere_sweep(...); fit_exponent(...)   # rolling resistance (rolling), its exponent (exponent)
    hysteresis_work(res, R); local_exponent(loads, moments)   # one solution; the drift
    radial_average(res.pressure, res.x, res.y)                # azimuthal pressure profile

Heavy modules (numba kernels, scipy.fft) load on first use of the solver.
"""

from __future__ import annotations

from contact._errors import (
    ContactError,
    ContactInputError,
    ContactMemoryError,
    ConvergenceError,
    EdgeContactError,
    EdgeContactWarning,
)
from contact._hertz import (
    HertzCylinder,
    HertzSphere,
    hertz_cylinder,
    hertz_sphere,
    hertz_sphere_from_approach,
)
from contact._lazy import attach
from contact._materials import (
    MATERIALS,
    Material,
    compliance,
    composite_modulus,
    contact_hardness,
    displacement_shares,
    material,
)

_LAZY = {
    "MaterialPair": "contact._material_pair",
    "resolve_pair": "contact._material_pair",
    "CompositeRoughness": "contact.setups._composite",
    "flat_contact": "contact.setups._flat",
    "solve_normal": "contact.bem",
    "SolveOptions": "contact.bem._options",
    "PressureBounds": "contact.bem._bounds",
    "Grid": "contact._grid",
    "DomainSpec": "contact._geometry",
    "Dissipation": "contact._dissipation",
    "ContactResult": "contact.bem._result",
    "SphereContact": "contact.setups._ball_on_plate",
    "solve_sphere": "contact.setups._ball_on_plate",
    "auto_domain": "contact._geometry",
    "sphere_gap": "contact._geometry",
    "cylinder_gap": "contact._geometry",
    "gjm_alpha": "contact._roughstats",
    "check_sphere": "contact._hertzcheck",
    "sphere_sweep": "contact._rolling",
    "cylinder_sweep": "contact._rolling",
    "fit_exponent": "contact._exponent",
    "local_exponent": "contact._exponent",
    "RollingSweep": "contact._rolling",
    "hysteresis_work": "contact._rolling",
    "RadialProfile": "contact._fields",
    "radial_average": "contact._fields",
    "solve_cylinder": "contact.setups._line",
}


#: The engine's rooms, reachable as ``contact.<room>`` without an explicit import.
SUBPACKAGES = ("adhesion", "bem", "halfspace", "roughcontact", "setups", "tangential",
               "viscoelastic")

__getattr__, __dir__ = attach(__name__, SUBPACKAGES, _LAZY)


__all__ = [
    "MATERIALS",
    "CompositeRoughness",
    "ContactError",
    "ContactInputError",
    "ContactMemoryError",
    "ContactResult",
    "ConvergenceError",
    "Dissipation",
    "DomainSpec",
    "EdgeContactError",
    "EdgeContactWarning",
    "Grid",
    "HertzCylinder",
    "HertzSphere",
    "Material",
    "MaterialPair",
    "PressureBounds",
    "RadialProfile",
    "RollingSweep",
    "SolveOptions",
    "SphereContact",
    "auto_domain",
    "check_sphere",
    "compliance",
    "composite_modulus",
    "contact_hardness",
    "cylinder_gap",
    "cylinder_sweep",
    "displacement_shares",
    "fit_exponent",
    "flat_contact",
    "gjm_alpha",
    "hertz_cylinder",
    "hertz_sphere",
    "hertz_sphere_from_approach",
    "hysteresis_work",
    "local_exponent",
    "material",
    "radial_average",
    "resolve_pair",
    "solve_cylinder",
    "solve_normal",
    "solve_sphere",
    "sphere_gap",
    "sphere_sweep",
]
