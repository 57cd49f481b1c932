"""The report's pictures of one scan (:mod:`surfmet.report`): the evaluated surface's
3D view, height map and Abbott–Firestone curve, the PSD exactly as ``surfmet spectrum``
gives it, and a profile's primary / waviness / roughness figure, each drawn from the
result of the function the commands call (never recomputed here)."""

from __future__ import annotations

from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet._report_html import array_png, figure_png


def _view_installed() -> bool:
    """The 3D view's extra is installed (without it the report leaves the 3D picture out)."""
    import importlib.util

    try:
        return importlib.util.find_spec("pyvista") is not None
    except (ImportError, ValueError, AttributeError):  # a broken or blocked install
        return False


def figures_areal(surface: Topography, params: dict[str, Any], include_3d: bool
                   ) -> list[tuple[str, bytes]]:
    """The evaluated surface's pictures (the PSD is :func:`spectrum_section`'s)."""
    from surfmet.plots.areal import abbott_firestone, height_map

    figs: list[tuple[str, bytes]] = []
    if include_3d and _view_installed():
        from surfmet._render import render_3d

        img = render_3d(surface, window_size=(1000, 750))
        figs.append(("3D view of the evaluated surface (heights exaggerated, see the "
                     "picture)", array_png(img)))
    figs.append(("height map of the evaluated surface", figure_png(height_map(surface))))
    figs.append(("Abbott–Firestone curve with the ISO 13565-2 / 25178-2 Sk construction",
                 figure_png(abbott_firestone(surface, parameters=params))))
    return figs


def spectrum_section(scan: Topography, file: str
                      ) -> tuple[dict[str, Any], tuple[str, bytes] | None]:
    """The scan's spectrum exactly as ``surfmet spectrum FILE`` gives it (the same function
    on the scan as read, with the same preparation: spikes, filling, levelling, window):
    its JSON record and the PSD figure, or ``{"error": message}`` and no figure where the
    command refuses the scan."""
    from surfmet._errors import user_error_types
    from surfmet.mechanics.spectrum import scan_spectrum
    from surfmet.plots.spectrum import spectrum_figure
    from surfmet.records._spectrum import spectrum_command_record

    try:
        s, level, preparation = scan_spectrum(scan)
    except user_error_types() as exc:
        return {"error": str(exc)}, None
    rec = spectrum_command_record(file, s, level, preparation)
    how = "periodic, unwindowed" if s.periodic else "not periodic, Hann window"
    caveats = [c for c in rec["caveats"] if "Hurst" in c]
    caption = (f"radially averaged PSD of the whole scan with the power law fitted over its "
               f"band, as surfmet spectrum gives it: {how}, levelling {level}, "
               f"H = {s.hurst.hurst:.4f}" + (f" (caveat: {caveats[0]})" if caveats else ""))
    return rec, (caption, figure_png(spectrum_figure(s)))


def figures_profile(analysis: Any, name: str
                     ) -> tuple[list[tuple[str, bytes]], dict[str, Any] | None]:
    """The profile's pictures, and the PSD fit drawn in the last one (its numbers)."""
    from surfmet.plots.areal import abbott_firestone, psd_figure
    from surfmet.plots.profile import profile_figure
    from surfmet.psd import fit_hurst, profile_psd

    figs = [("primary profile and mean line, waviness, roughness",
             figure_png(profile_figure(analysis, title=name)))]
    rough = np.asarray(analysis.roughness)[np.asarray(analysis.evaluated)]
    figs.append(("Abbott–Firestone curve of the roughness profile (evaluation length)",
                 figure_png(abbott_firestone(rough))))
    record = None
    if rough.size >= 16:
        spec = profile_psd(rough, float(analysis.settings["dx"]))
        try:
            fit = fit_hurst(spec)
        except SurfmetInputError:
            fit = None
        from surfmet.records._spectrum import profile_psd_record

        record = profile_psd_record(fit)
        figs.append(("PSD of the roughness profile (Hann window)",
                     figure_png(psd_figure(spec, fits=[fit] if fit else None))))
    return figs, record
