"""The figure of ``surfmet spectrum``: the isotropic PSD, the power law over its fitted band,
the cut-offs and the noise floor.

Axes as in :func:`surfmet.plots.areal.psd_figure` (and as contact.engineering and
SurfaceTopography show a PSD): the wavevector ``q`` in rad/µm below, the wavelength
``λ = 2π/q`` in µm on top, ``C^iso(q)`` in µm⁴ (Jacobs, Junge & Pastewka 2017, Surf. Topogr.:
Metrol. Prop. 5, 013001).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from surfmet.plots._style import UM, finish, new_figure
from surfmet.plots.areal import _q_to_lambda

#: The y-axis label, in matplotlib's mathtext.
C_ISO_LABEL = r"PSD $C^{\mathrm{iso}}(q)$ (µm$^4$)"
Q_LABEL = r"wavevector $q$ (rad/µm)"
LAMBDA_LABEL = r"wavelength $\lambda = 2\pi/q$ (µm)"


def spectrum_figure(s: Any, path: str | Path | None = None) -> Any:
    """Log–log figure of a :class:`surfmet.mechanics.spectrum.Spectrum`.

    The power law is drawn over its fitted band only (``s.hurst.q_range``); where the
    spectrum turns into a noise floor, the floor's side is shaded and left unfitted.
    """
    from surfmet.units import format_length

    fig, ax = new_figure(size=(6.4, 4.4))
    psd = s.psd
    ok = psd.C > 1e-12 * float(psd.C.max())  # wavevectors with no power: off the plot
    ax.loglog(psd.q[ok] * UM, psd.C[ok] / UM**4, ".", ms=2, color="0.5",
              label="isotropic PSD")
    lo, hi = s.hurst.q_range
    qq = np.geomspace(lo, hi, 50)
    ax.loglog(qq * UM, s.hurst.prefactor * qq**s.hurst.slope / UM**4, "r-", lw=2,
              label=rf"power law over its band, $H$ = {s.hurst.hurst:.3f}")
    for q, name, style in ((s.roll_off, "roll-off", "--"), (s.short_cutoff, "short cut-off", ":")):
        if q:
            ax.axvline(q * UM, color="k", ls=style,
                       label=rf"{name}, $\lambda$ = {format_length(2 * np.pi / q)}")
    floor = getattr(s, "noise_floor", None)
    if floor:
        ax.axvspan(floor * UM, float(psd.q.max()) * UM, color="0.85", zorder=0,
                   label=rf"noise floor from $\lambda$ = {format_length(2 * np.pi / floor)}")
    ax.set_xlabel(Q_LABEL)
    ax.set_ylabel(C_ISO_LABEL)
    ax.grid(True, which="both", alpha=0.25)
    top = ax.secondary_xaxis("top", functions=(_q_to_lambda, _q_to_lambda))
    top.set_xlabel(LAMBDA_LABEL)
    ax.set_title("periodic, unwindowed" if s.periodic else "Hann-windowed", fontsize=10)
    ax.legend(fontsize=8)
    return finish(fig, path)


def all_scales_figure(s: Any, path: str | Path | None = None) -> Any:
    """Two log–log panels of an :class:`surfmet.mechanics.all_scales.AllScalesSpectrum`:
    each measurement's profile PSD where it contributes and their average (left), the
    isotropic PSD derived from the average over the measured band (right)."""
    fig, (a1, a2) = new_figure(1, 2, size=(11.0, 4.4))
    a = s.analysis
    for m in a.measurements:
        a1.loglog(a.q * UM, m.psd / UM**3, ".-", lw=1, ms=3, label=Path(m.file).name)
    a1.loglog(a.q * UM, a.psd / UM**3, "k--", lw=1.5, label="average")
    a1.set_ylabel(r"PSD $C^{1\mathrm{D}}(q)$ (µm$^3$)")
    a2.loglog(s.q * UM, s.c_iso / UM**4, "k-", lw=1.5,
              label="from the average (inverse Abel transform)")
    a2.set_ylabel(C_ISO_LABEL)
    for ax in (a1, a2):
        ax.set_xlabel(Q_LABEL)
        ax.axvspan(s.band[0] * UM, s.band[1] * UM, color="0.93", zorder=0)
        ax.grid(True, which="both", alpha=0.25)
        ax.legend(fontsize=8)
    return finish(fig, path)
