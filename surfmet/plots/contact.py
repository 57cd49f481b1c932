"""Contact figures: the pressure map with its contact clusters, the radial pressure profile
(Hertz against the boundary-element solution).

Pressures in MPa, lengths in µm (mm beyond 2 mm), as in every surfmet figure.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet.plots._style import MPA, add_scale_bar, finish, lateral_unit, new_figure


def pressure_map(
    result: Any,
    path: str | Path | None = None,
    *,
    ax: Any = None,
    cmap: str = "inferno_r",
    outline: bool = True,
    max_labels: int = 20,
    zoom: bool = True,
    title: str | None = None,
) -> Any:
    """Contact pressure (MPa) with the contact clusters outlined and numbered.

    Clusters (4-connected cells with p > 0, as :attr:`contact.ContactResult.n_clusters`
    counts them) are numbered by decreasing load (1 carries the most), each number just
    off the top right corner of its cluster, so that it never hides the cells it names;
    when there are more than ``max_labels`` only the largest are numbered and the title
    says so. The colour scale ends at the 99.5th percentile of the loaded cells when more
    than 200 cells carry load (rough contacts have a few extreme asperity pressures); the
    title gives pmax.
    With more than 50 clusters only the numbered ones are outlined.

    Parameters
    ----------
    result : contact.ContactResult
        Uses ``pressure``, ``x``, ``y``, ``dx``, ``dy``, ``periodic``, ``load``,
        ``contact_area``, ``pmax``.
    max_labels : int
        Number the ``max_labels`` clusters carrying the most load.
    zoom : bool
        Frame the contact region (with a margin) rather than the whole solver domain.

    Returns
    -------
    matplotlib.figure.Figure
        ``fig.surfmet_clusters`` holds the number of clusters found and
        ``fig.surfmet_labelled`` the number labelled.
    """
    for name in ("pressure", "x", "y", "dx", "dy"):
        if not hasattr(result, name):
            raise SurfmetInputError("pressure_map needs a contact.ContactResult")
    import matplotlib as mpl

    p = np.asarray(result.pressure, dtype=float)
    x, y = np.asarray(result.x), np.asarray(result.y)
    if ax is None:
        fig, ax = new_figure(size=(6.4, 5.2))
    else:
        fig = ax.figure
    width = max(x[-1] - x[0] + result.dx, y[-1] - y[0] + result.dy)
    scale, unit = lateral_unit(width)
    extent = ((x[0] - result.dx / 2) / scale, (x[-1] + result.dx / 2) / scale,
              (y[0] - result.dy / 2) / scale, (y[-1] + result.dy / 2) / scale)
    import matplotlib.patheffects as pe

    # no contact is drawn white, so that sparse asperity contacts stand out
    cm = mpl.colormaps[cmap].with_extremes(bad="white")
    contact = p > 0
    pmax = float(p.max()) if p.size else 0.0
    # Rough contacts have a few cells far above the rest: a colour scale up to the 99.5th
    # percentile of the loaded cells keeps the field readable (the bar says "extend").
    vmax = float(np.percentile(p[contact], 99.5)) if contact.sum() > 200 else pmax
    vmax = vmax if vmax > 0 else 1.0
    im = ax.imshow(np.ma.masked_where(~contact, p / MPA), origin="lower", extent=extent,
                   cmap=cm, vmin=0.0, vmax=vmax / MPA, interpolation="nearest", aspect="equal")
    cb = fig.colorbar(im, ax=ax, shrink=0.9, extend="max" if pmax > vmax else "neither")
    cb.set_label("contact pressure (MPa)")
    from contact.bem._result import cluster_labels

    labels, n = cluster_labels(contact, bool(getattr(result, "periodic", False)))
    if zoom and contact.any():
        # frame the contact (with a margin), not the whole solver domain
        jj, ii = np.nonzero(contact)
        half = 0.6 * max(x[ii].max() - x[ii].min() + result.dx,
                         y[jj].max() - y[jj].min() + result.dy)
        mx, my = (x[ii].max() + x[ii].min()) / 2, (y[jj].max() + y[jj].min()) / 2
        ax.set_xlim(max(extent[0], (mx - half) / scale), min(extent[1], (mx + half) / scale))
        ax.set_ylim(max(extent[2], (my - half) / scale), min(extent[3], (my + half) / scale))
    labelled = 0
    if n:
        load = np.bincount(labels.ravel(), weights=p.ravel(), minlength=n + 1)[1:]
        order = np.argsort(-load, kind="stable")[: max(0, int(max_labels))]
        from scipy.ndimage import find_objects

        boxes = find_objects(labels)
        if outline:
            # all spots when they are few; otherwise the numbered ones only, so that the
            # outlines do not bury the pressure field
            mask = contact if n <= 50 else np.isin(labels, order + 1)
            ax.contour(x / scale, y / scale, mask.astype(float), levels=[0.5],
                       colors="tab:blue", linewidths=0.8, alpha=0.9)
        for rank, k in enumerate(order, start=1):
            # beside the cluster, just off the top right corner of its bounding box: a
            # label on the centre would hide a cluster of a few cells
            rows, cols = boxes[k]
            corner = ((x[cols.stop - 1] + result.dx / 2) / scale,
                      (y[rows.stop - 1] + result.dy / 2) / scale)
            ax.annotate(str(rank), xy=corner, xytext=(1.5, 1.5), textcoords="offset points",
                        color="white", fontsize=7, ha="left", va="bottom", fontweight="bold",
                        path_effects=[pe.withStroke(linewidth=1.5, foreground="black")])
            labelled += 1
    ax.set_xlabel(f"x ({unit})")
    ax.set_ylabel(f"y ({unit})")
    add_scale_bar(ax, width, scale, unit, color="black")
    if title is None:
        load_txt = f"W = {getattr(result, 'load', float('nan')):.4g} N, "
        more = f" (largest {labelled} numbered)" if labelled < n else ""
        title = (f"{load_txt}pmax = {pmax / MPA:.4g} MPa, "
                 f"{n} contact cluster{'s' if n != 1 else ''}{more}")
    ax.set_title(title, fontsize=10)
    fig.surfmet_clusters = n
    fig.surfmet_labelled = labelled
    return finish(fig, path)


def radial_pressure(
    r: Any,
    p_bem: Any,
    p_hertz: Any,
    a0: float,
    path: str | Path | None = None,
    *,
    ax: Any = None,
    title: str | None = None,
    normalise: bool = False,
) -> Any:
    """Radial pressure profile: boundary-element solution against Hertz.

    Parameters
    ----------
    r : array_like
        Radii (m) from the contact centre.
    p_bem, p_hertz : array_like
        Pressures (Pa) at ``r``: the (azimuthally averaged) BEM solution and Hertz's
        ``p0 sqrt(1 - r²/a0²)``.
    a0 : float
        Hertz contact radius (m), drawn as a vertical line.
    normalise : bool
        Plot ``p/p0`` against ``r/a0`` (p0 = max of the Hertz curve) instead of MPa / µm.
    """
    r = np.asarray(r, dtype=float)
    pb = np.asarray(p_bem, dtype=float)
    ph = np.asarray(p_hertz, dtype=float)
    if not (r.shape == pb.shape == ph.shape) or r.ndim != 1 or r.size < 2:
        raise SurfmetInputError("r, p_bem and p_hertz must be 1D arrays of the same length (>= 2)")
    if not (np.isfinite(a0) and a0 > 0):
        raise SurfmetInputError(f"a0 must be a positive length in metres, got {a0!r}")
    if ax is None:
        fig, ax = new_figure(size=(6.0, 4.0))
    else:
        fig = ax.figure
    if normalise:
        p0 = float(np.nanmax(ph)) if np.nanmax(ph) > 0 else 1.0
        xs, fy = r / a0, p0
        ax.set_xlabel("r / a₀")
        ax.set_ylabel("p / p₀")
        a_line = 1.0
    else:
        scale, unit = lateral_unit(float(r.max()))
        xs, fy = r / scale, MPA
        ax.set_xlabel(f"radius r ({unit})")
        ax.set_ylabel("pressure (MPa)")
        a_line = a0 / scale
    ax.plot(xs, ph / fy, "--", color="k", lw=1.4, label="Hertz")
    ax.plot(xs, pb / fy, color="C3", lw=1.4, label="boundary elements")
    ax.axvline(a_line, color="0.5", lw=0.8, ls=":")
    ax.annotate("a₀ (Hertz)", xy=(a_line, 0.02), xycoords=("data", "axes fraction"),
                rotation=90, ha="right", va="bottom", fontsize=8, color="0.35")
    ax.set_xlim(left=0)
    ax.set_ylim(bottom=0)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(title if title is not None else "radial pressure profile", fontsize=10)
    return finish(fig, path)
