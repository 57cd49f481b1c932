"""Matplotlib figures, one module per subject (imported on demand, never at package import).

Every figure function takes the result objects of the analysis layer, returns a
``matplotlib.figure.Figure`` and optionally saves it (``path=``). Lengths are shown in µm
(or mm for scan extents) and pressures in MPa, through :mod:`surfmet.plots._style`.
"""
