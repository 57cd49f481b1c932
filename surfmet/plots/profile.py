"""Profile figure: the primary profile and its mean line, the waviness, the roughness.

Takes a :class:`profiles.ProfileAnalysis` (from :func:`profiles.analyze_profile`), so the
figure shows exactly the arrays the parameters were computed from. Terms after ISO 3274 /
ISO 4287 / ISO 16610-21: the primary profile's mean line is the least-squares form; the
waviness is the λc Gaussian mean line; roughness = levelled primary − waviness.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet.plots._style import UM, finish, lateral_unit, new_figure


def profile_figure(analysis: Any, path: str | Path | None = None, *, title: str | None = None
                   ) -> Any:
    """Primary profile with its mean line, waviness, and roughness, stacked (heights in µm).

    Panels:

    1. the primary profile (after the λs filter, with its form) and its least-squares mean
       line (the form removed by the levelling);
    2. the levelled primary profile and the waviness, the λc Gaussian mean line (omitted
       when no λc filter was applied);
    3. the roughness profile, with the evaluation length shaded and Ra, Rq in the legend.

    Parameters
    ----------
    analysis : profiles.ProfileAnalysis
    path : str or Path, optional
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    for name in ("x", "form", "primary", "waviness", "roughness", "evaluated", "settings"):
        if not hasattr(analysis, name):
            raise SurfmetInputError(
                "profile_figure needs a profiles.ProfileAnalysis (from analyze_profile)"
            )
    x = np.asarray(analysis.x)
    scale, unit = lateral_unit(float(x[-1] - x[0]) if x.size else 0.0)
    xs = x / scale
    st = analysis.settings
    has_w = analysis.waviness is not None
    fig, axes = new_figure(3 if has_w else 2, 1, size=(7.2, 7.0 if has_w else 5.0))
    axes = list(np.atleast_1d(axes))
    for a in axes[1:]:
        a.sharex(axes[0])

    ax = axes[0]
    raw = np.asarray(analysis.primary) + np.asarray(analysis.form)
    ax.plot(xs, raw / UM, color="0.35", lw=0.7, label="primary profile")
    ax.plot(xs, np.asarray(analysis.form) / UM, "--", color="C3", lw=1.2,
            label=f"mean line (least squares, {st.get('level', 'line')})")
    ax.set_title("primary profile and mean line", fontsize=10)

    if has_w:
        ax = axes[1]
        ax.plot(xs, np.asarray(analysis.primary) / UM, color="0.6", lw=0.7,
                label="levelled primary")
        ax.plot(xs, np.asarray(analysis.waviness) / UM, color="C0", lw=1.6,
                label=f"waviness (λc = {_fmt_len(st.get('lc'))} Gaussian mean line)")
        ax.set_title("waviness", fontsize=10)

    ax = axes[-1]
    rough = np.asarray(analysis.roughness)
    ev = np.asarray(analysis.evaluated, dtype=bool)
    p = analysis.parameters
    # the primary profile's parameters carry P names (ISO 21920-2; surfmet._profile_evaluation)
    r = st.get("parameter_letter", "R")
    ax.plot(xs, rough / UM, color="C2", lw=0.7,
            label=f"{r}a = {p.Ra / UM:.4g} µm, {r}q = {p.Rq / UM:.4g} µm")
    ax.axhline(0.0, color="k", lw=0.6)
    if ev.any() and not ev.all():
        i0, i1 = np.flatnonzero(ev)[[0, -1]]
        ax.axvspan(xs[i0], xs[i1], color="C2", alpha=0.08, label="evaluation length")
    ax.set_title("roughness profile" if has_w else
                 "levelled primary profile (no λc filter: parameters of this profile)",
                 fontsize=10)
    ax.set_xlabel(f"x ({unit})")
    for a in axes:
        a.set_ylabel("height (µm)")
        a.grid(True, alpha=0.3)
        a.legend(loc="upper right", fontsize=7)
    if title:
        fig.suptitle(title, fontsize=11)
    return finish(fig, path)


def _fmt_len(v: Any) -> str:
    from surfmet.units import format_length

    try:
        return format_length(float(v))
    except (TypeError, ValueError):
        return "?"
