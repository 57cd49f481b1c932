"""Areal figures: the height map, the Abbott–Firestone (material ratio) curve, the PSD, and
the 3D view (:func:`render_3d`, pyvista off-screen: an image, not a matplotlib figure).

Units everywhere in surfmet's figures: heights in µm, lateral lengths in µm (or mm when
the extent passes 2 mm, :func:`lateral_unit`), pressures in MPa, wavevectors in rad/µm.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography
from surfmet._render import render_3d as render_3d  # re-exported: the 3D view of a scan
from surfmet.plots._style import (
    UM,
    add_scale_bar,
    finish,
    lateral_unit,
    new_figure,
    scan_title,
)

HEIGHT_LABEL = "height (µm)"


def height_map(
    topo: Topography,
    path: str | Path | None = None,
    *,
    ax: Any = None,
    cmap: str = "viridis",
    title: str | None = None,
    scale_bar: bool = True,
) -> Any:
    """2D height map with a colour bar in µm and a lateral scale bar.

    Row ``j`` (y = j dy) is drawn upwards and pixels keep their aspect (non-square pixels
    are drawn non-square); non-measured points are light grey.

    Parameters
    ----------
    topo : Topography
    path : str or Path, optional
        Save the figure there (PNG, PDF, SVG... by extension).
    ax : matplotlib Axes, optional
        Draw into this axes instead of a new figure.
    cmap : str
    title : str, optional
    scale_bar : bool

    Returns
    -------
    matplotlib.figure.Figure
    """
    if not isinstance(topo, Topography):
        raise SurfmetInputError(f"height_map needs a Topography, got {type(topo).__name__}")
    import matplotlib as mpl

    if ax is None:
        fig, ax = new_figure(size=map_figure_size(topo.size_x, topo.size_y))
    else:
        fig = ax.figure
    scale, unit = lateral_unit(max(topo.size_x, topo.size_y))
    z = np.asarray(topo.heights) / UM
    cm = mpl.colormaps[cmap].with_extremes(bad="#d0d0d0")
    extent = (-0.5 * topo.dx / scale, (topo.nx - 0.5) * topo.dx / scale,
              -0.5 * topo.dy / scale, (topo.ny - 0.5) * topo.dy / scale)
    finite = z[np.isfinite(z)]
    vmin, vmax = (np.percentile(finite, [0.1, 99.9]) if finite.size else (0.0, 1.0))
    if not vmax > vmin:
        vmin, vmax = vmin - 0.5, vmax + 0.5
    im = ax.imshow(np.ma.masked_invalid(z), origin="lower", extent=extent, cmap=cm,
                   vmin=vmin, vmax=vmax, interpolation="antialiased", aspect="equal")
    ax.set_xlabel(f"x ({unit})")
    ax.set_ylabel(f"y ({unit})")
    cb = fig.colorbar(im, ax=ax, shrink=0.9, extend="both")
    cb.set_label(HEIGHT_LABEL)
    if scale_bar:
        add_scale_bar(ax, max(topo.size_x, topo.size_y), scale, unit)
    ax.set_title(title if title is not None else scan_title(topo))
    return finish(fig, path)


def map_figure_size(size_x: float, size_y: float) -> tuple[float, float]:
    """Figure size (inches) for a map of ``size_x`` by ``size_y`` drawn at equal aspect: the
    figure takes the map's shape (plus room for the labels and the colour bar), so a narrow
    or a wide scan fills its panel instead of leaving half of it blank."""
    aspect = size_x / size_y if size_x > 0 and size_y > 0 else 1.0
    if aspect >= 1.0:
        w_ax = min(8.0, 4.2 * aspect)
        h_ax = max(1.2, w_ax / aspect)
    else:
        h_ax = 4.2
        w_ax = max(1.2, h_ax * aspect)
    return (w_ax + 2.4, h_ax + 1.3)


def _heights_of(scan: Any) -> np.ndarray:
    if isinstance(scan, Topography):
        z = np.asarray(scan.heights).ravel()
    elif isinstance(scan, Profile):
        z = np.asarray(scan.z)
    else:
        z = np.asarray(scan, dtype=float).ravel()
    z = z[np.isfinite(z)]
    if z.size < 2:
        raise SurfmetInputError("the material ratio curve needs at least 2 measured points")
    return z - z.mean()


def abbott_firestone(
    scan: Topography | Profile | np.ndarray,
    path: str | Path | None = None,
    *,
    ax: Any = None,
    parameters: dict[str, Any] | None = None,
    title: str | None = None,
    points: int = 1001,
) -> Any:
    """The Abbott–Firestone (material ratio) curve, heights about the mean (µm).

    With ``parameters`` holding the ISO 13565-2 / ISO 25178-2 functional family (``Sk,
    Spk, Svk, Smr1, Smr2`` or ``Rk, Rpk, Rvk, Mr1, Mr2``; values SI, ratios in %), the
    construction is drawn: the core limits at Smr1 and Smr2, the equivalent straight line
    and the peak and dale triangles of heights Spk and Svk.

    Parameters
    ----------
    scan : Topography, Profile or array
        The evaluated (levelled, filtered) surface; NaN ignored.
    parameters : dict, optional
        ``{symbol: value}`` or ``{symbol: (value, unit)}`` (as in ``RoughnessResult``).
    points : int
        Material ratios at which the curve is drawn.
    """
    from profiles import height_at_ratio, material_ratio_curve

    z = _heights_of(scan)
    if ax is None:
        fig, ax = new_figure(size=(5.6, 4.2))
    else:
        fig = ax.figure
    mr, h = material_ratio_curve(z, n=points)
    ax.plot(100 * mr, h / UM, color="C0", lw=1.6, label="material ratio curve")
    ax.set_xlim(0, 100)
    ax.set_xlabel("material ratio (%)")
    ax.set_ylabel("height about the mean (µm)")
    ax.grid(True, alpha=0.3)
    vals = {k: (v[0] if isinstance(v, (tuple, list)) else v) for k, v in (parameters or {}).items()}
    names = None
    for fam in (("Sk", "Spk", "Svk", "Smr1", "Smr2"), ("Rk", "Rpk", "Rvk", "Mr1", "Mr2"),
                ("Pk", "Ppk", "Pvk", "Mr1", "Mr2")):
        if all(vals.get(k) is not None and np.isfinite(vals[k]) for k in fam):
            names = fam
            break
    if names is not None:
        k_, pk, vk, m1, m2 = (float(vals[n]) for n in names)
        upper = float(height_at_ratio(z, min(max(m1 / 100, 0.0), 1.0)))
        lower = upper - k_
        ax.plot([0, 100], [upper / UM, lower / UM], "--", color="C3", lw=1,
                label="equivalent straight line")
        for level in (upper, lower):
            ax.axhline(level / UM, color="0.4", lw=0.8, ls=":")
        ax.fill([0, 0, m1], [upper / UM, (upper + pk) / UM, upper / UM], color="C1", alpha=0.35,
                label=f"{names[1]} = {pk / UM:.4g} µm")
        ax.fill([m2, 100, 100], [lower / UM, lower / UM, (lower - vk) / UM], color="C2",
                alpha=0.35, label=f"{names[2]} = {vk / UM:.4g} µm")
        ax.annotate(f"{names[0]} = {k_ / UM:.4g} µm\n{names[3]} = {m1:.3g} %, "
                    f"{names[4]} = {m2:.3g} %", xy=(0.5, 0.97), xycoords="axes fraction",
                    ha="center", va="top", fontsize=8)
    note = _frame_heights(ax, z, h, (upper + pk, lower - vk) if names is not None else ())
    if note is not None:
        # the note is the legend's last entry (no marker), so the legend never covers it
        ax.plot([], [], " ", label=note)
    if names is not None or note is not None:
        ax.legend(loc="lower left", fontsize=7 if note is not None else 8)
    ax.set_title(title if title is not None else "Abbott–Firestone curve")
    return finish(fig, path)


def _frame_heights(ax: Any, z: np.ndarray, h: np.ndarray, keep: Sequence[float]
                   ) -> str | None:
    """Height axis of an Abbott–Firestone curve: the heights between 0.5 % and 99.5 %
    material ratio with half their span as margin (and the construction), so that a few
    extreme points (spikes, outliers) do not squeeze the curve into a line; when the
    curve runs beyond, the axis is clipped and the returned note says how far it runs
    (None when not clipped)."""
    from profiles import height_at_ratio

    hi, lo = float(height_at_ratio(z, 0.005)), float(height_at_ratio(z, 0.995))
    margin = 0.5 * max(hi - lo, 1e-300)
    top = max([hi + margin, *keep])
    bottom = min([lo - margin, *keep])
    full_top, full_bottom = float(np.max(h)), float(np.min(h))
    if full_top <= top and full_bottom >= bottom:
        return None
    top, bottom = min(top, full_top), max(bottom, full_bottom)
    pad = 0.03 * (top - bottom)
    ax.set_ylim((bottom - pad) / UM, (top + pad) / UM)
    return (f"axis clipped: the curve runs from {full_bottom / UM:.4g}\nto "
            f"{full_top / UM:.4g} µm (extreme points: spikes?)")


def psd_figure(
    spectra: Any,
    path: str | Path | None = None,
    *,
    ax: Any = None,
    labels: Sequence[str] | None = None,
    fits: Sequence[Any] | None = None,
    title: str | None = None,
) -> Any:
    """Log–log PSD ``C(q)`` against the wavevector ``q`` (rad/µm), with the wavelength
    ``λ = 2π/q`` (µm) on the top axis.

    Parameters
    ----------
    spectra : PSD or sequence of PSD
        From :mod:`surfmet.psd`; profile PSDs in µm³, radial (areal) PSDs in µm⁴. Mixing
        the two kinds on one axes is refused (different units).
    labels : sequence of str, optional
    fits : sequence of HurstFit or None, optional
        Power laws to overlay over their fitted band, labelled with H.
    """
    from surfmet.psd import PSD

    items = [spectra] if isinstance(spectra, PSD) else list(spectra)
    if not items:
        raise SurfmetInputError("psd_figure needs at least one PSD")
    kinds = {s.kind for s in items}
    if len(kinds) > 1:
        raise SurfmetInputError("profile (m³) and radial (m⁴) PSDs have different units; "
                                "draw them on separate axes")
    kind = kinds.pop()
    power = 3 if kind == "profile" else 4
    if ax is None:
        fig, ax = new_figure(size=(6.0, 4.2))
    else:
        fig = ax.figure
    for k, s in enumerate(items):
        lab = labels[k] if labels is not None and k < len(labels) else None
        ok = s.C > 0
        ax.loglog(s.q[ok] * UM, s.C[ok] / UM**power, lw=1.2, label=lab, color=f"C{k}")
    for k, f in enumerate(fits or []):
        if f is None:
            continue
        q = np.geomspace(f.q_range[0], f.q_range[1], 50)
        c = f.prefactor * q**f.slope
        ax.loglog(q * UM, c / UM**power, "--", color=f"C{k}", lw=1.5, alpha=0.8,
                  label=f"power-law fit: H = {f.hurst:.3f}")
    ax.set_xlabel("wavevector q (rad/µm)")
    ax.set_ylabel(f"PSD C(q) (µm{'³' if power == 3 else '⁴'})")
    ax.grid(True, which="both", alpha=0.25)
    top = ax.secondary_xaxis("top", functions=(_q_to_lambda, _q_to_lambda))
    top.set_xlabel("wavelength λ (µm)")
    if labels is not None or fits:
        ax.legend(fontsize=8)
    default = "PSD of the profile" if kind == "profile" else "radially averaged PSD"
    ax.set_title(title if title is not None else default, fontsize=10)
    return finish(fig, path)


def _q_to_lambda(q: Any) -> Any:
    # λ = 2π/q is its own inverse; guard q = 0 for matplotlib's transform probes
    q = np.asarray(q, dtype=float)
    with np.errstate(divide="ignore"):
        return np.where(q > 0, 2 * np.pi / np.where(q > 0, q, 1.0), np.inf)
