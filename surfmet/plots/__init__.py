"""Matplotlib figures, one module per subject (imported on demand, never at package import).

Every figure function takes the result objects of the analysis layer, returns a
``matplotlib.figure.Figure`` and optionally saves it (``path=``). Lengths are shown in µm
(or mm for scan extents) and pressures in MPa, through :mod:`surfmet.plots._style`.
"""

from surfmet._lazy import attach

# Each room loads on first use (surfmet.plots.<room>), so that importing the package
# imports none of them.
__all__ = [
    "areal",
    "contact",
    "hertz",
    "profile",
    "rotor",
    "rotor_verdict",
    "scales",
    "spectrum",
]

__getattr__, __dir__ = attach(__name__, __all__)
