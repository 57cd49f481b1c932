"""Figure of the rotor verdict (:mod:`rotor._verdict`): the acceleration read off the
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
    from rotor import local_accelerations, track_acceleration

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
    from rotor import solve_lambda

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


def _difference_panel(ax: Any, v: Any) -> None:
    """The groups' difference along the track: the joint model's with its two-standard-error
    band (group-specific tracks; the shared offset's interval when one track explains both),
    the model-free windowed points, and what lambda = 4/3 gives with the arm at its bound."""
    from rotor import frame_windows

    o = v.offset
    radius = v.rig.ball_radius if v.rig is not None else 0.02
    d = v.difference
    if d is not None and d.curve is not None:
        x, c, se = d.curve
        w = d.windows
        what = "joint model (group tracks), ±2 s.e."
    else:
        x = np.linspace(0.0, float(np.max(v.data.angles)) * radius, 50)
        c, se = np.full(x.size, o.value), np.full(x.size, o.stderr)
        w = frame_windows(v.data, v.shared, 1, 0, radius)
        what = "joint model (shared track), ±2 s.e."
    ax.fill_between(x * 1e3, c - 2 * se, c + 2 * se, color="tab:blue", alpha=0.2, lw=0)
    ax.plot(x * 1e3, c, color="tab:blue", lw=1.6, label=what)
    ax.errorbar(w.centres * 1e3, w.difference, yerr=2 * w.stderr, fmt="s", color="k", ms=4,
                capsize=3, label="frames alone, windows, ±2 s.e.")
    ax.axhline(0.0, color="grey", lw=0.8)
    ax.axhline(o.value, color="tab:blue", ls=":", lw=1.0,
               label=f"constant offset on one shared track ({o.value:+.3f})")
    if v.arm is not None:
        from rotor import settling_experiment

        e = settling_experiment(v)
        ax.axhline(e.rows[0].offset_4_3, color="tab:red", ls="--", lw=1.2,
                   label=f"lambda = 4/3, arm at its bound ({e.rows[0].offset_4_3:+.3f})")
    # the limits follow the model and the windows' values, not the end points' error bars
    core = slice(x.size // 10, x.size - x.size // 10)
    vals = np.concatenate([(c - 2 * se)[core], (c + 2 * se)[core],
                           w.difference[np.isfinite(w.difference)], [0.0]])
    pad = 0.15 * max(float(np.ptp(vals)), 0.1)
    ax.set_ylim(float(np.min(vals)) - pad, float(np.max(vals)) + pad)
    ax.set_xlabel("track position from the release (mm)")
    ax.set_ylabel(f"acceleration difference {o.minuend} - {o.subtrahend} (rad/s²)")
    ax.set_title("the groups' difference along the track", fontsize=9)
    ax.legend(fontsize=7, loc="best")


def draw_verdict(v: Any, path: str | Path | None = None) -> Any:
    """Three panels (two without a rig): local acceleration along the track with the joint
    model per group, the groups' difference along the track (band, windowed points and
    lambda = 4/3 at the arm bound), and the lambda the offset needs against the slope."""
    panels = 3 if v.exponent is not None else 2
    fig, axes = new_figure(1, panels, size=(5.5 * panels, 4.4))
    axes = np.atleast_1d(axes)
    _track_panel(axes[0], v)
    _difference_panel(axes[1], v)
    if panels == 3:
        _lambda_panel(axes[2], v)
    return finish(fig, path)
