"""Figure of the rotor verdict (:mod:`contact.rotor.verdict`): the acceleration read off the
frames along the track per group, with the joint model over it, and the exponent the offset
needs against the assumed slope."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from surfmet.plots._style import finish, new_figure

_COLOURS = ("tab:blue", "tab:orange")


def _track_panel(ax: Any, v: Any) -> None:
    from contact.rotor.joint import local_accelerations
    from contact.rotor.track import track_acceleration

    data, sh, gw = v.data, v.shared, v.groupwise
    radius = v.rig.ball_radius if v.rig is not None else 0.02
    s = np.linspace(0.0, float(np.max(data.angles)), 300)
    loc = local_accelerations(data, sh)
    for gi, gname in enumerate(data.group_names):
        c = _COLOURS[gi % 2]
        sel = np.flatnonzero(data.group_of_launch == gi)
        for n, i in enumerate(sel):
            si, ei, se = loc[i]
            ax.errorbar(si * radius * 1e3, ei, yerr=se, fmt="o", ms=2.5, color=c, alpha=0.5,
                        elinewidth=0.6, label=f"{gname}: from the frames" if n == 0 else None)
        for fit, style, what in ((sh, "-", "shared track"), (gw, ":", "own track")):
            beta, delta, _, _ = fit.layout.split(fit.x)
            b = beta[0 if fit.shared else gi]
            ax.plot(s * radius * 1e3, delta[sel].mean() + track_acceleration(s, b, fit.layout.span),
                    style, color=c, lw=1.6, label=f"{gname}: joint model, {what}")
    lo, hi = ax.get_ylim()
    models = [ln.get_ydata() for ln in ax.get_lines()]
    if models:
        m_lo, m_hi = float(np.min([m.min() for m in models])), float(
            np.max([m.max() for m in models]))
        pad = max(0.5 * (m_hi - m_lo), 0.5)
        ax.set_ylim(max(lo, m_lo - pad), min(hi, m_hi + pad))  # noisy fast rows off the axes
    ax.set_xlabel("track position from the release (mm)")
    ax.set_ylabel("angular acceleration (rad/s²)")
    ax.set_title(v.code + (": shared track adequate" if v.shared_track_adequate
                           else ": no shared track explains both groups"), fontsize=9)
    ax.legend(fontsize=7, loc="best")


def _lambda_panel(ax: Any, v: Any) -> None:
    from contact.rotor.rig import solve_lambda

    e, o, rig = v.exponent, v.offset, v.rig
    lo = max(e.slope_lower_bound * 1.02, 1e-6)
    slopes = np.linspace(lo, max(math.radians(2.0), e.slope * 1.5), 80)
    args = (rig, o.minuend, o.subtrahend)
    for val, style, lab in ((o.value, "-", "the offset"), (o.ci_low, ":", f"{o.level:.0%} CI"),
                            (o.ci_high, ":", None)):
        lam = [solve_lambda(val, *args, float(sl), v.mean_acceleration) for sl in slopes]
        ax.plot(np.degrees(slopes), lam, style, color="k", label=lab)
    for y, lab in ((1.0, "lambda = 1"), (4 / 3, "lambda = 4/3")):
        ax.axhline(y, color="grey", lw=0.8, ls="--")
        ax.text(math.degrees(slopes[-1]), y, lab, fontsize=7, ha="right", va="bottom")
    ax.axvline(math.degrees(e.slope), color="tab:red", lw=0.8)
    ax.set_xlabel("assumed slope (deg)")
    ax.set_ylabel("lambda the offset needs")
    ax.set_ylim(0, 8)
    ax.legend(fontsize=7)


def draw_verdict(v: Any, path: str | Path | None = None) -> Any:
    """Two panels (one without a rig): local acceleration along the track with the joint
    model per group, and the lambda the offset needs against the slope."""
    panels = 2 if v.exponent is not None else 1
    fig, axes = new_figure(1, panels, size=(6.0 * panels, 4.4))
    axes = np.atleast_1d(axes)
    _track_panel(axes[0], v)
    if panels == 2:
        _lambda_panel(axes[1], v)
    return finish(fig, path)
