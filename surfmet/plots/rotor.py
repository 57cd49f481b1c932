"""Figures of the rotor's law-of-motion analysis (:mod:`rotor`)."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from surfmet.plots._style import finish, new_figure

#: The paper's model of the law of motion (constant acceleration from rest at the first
#: mark, :data:`rotor.MODELS`): the baseline the residual figure and the
#: demo's table compare the chosen models with.
PAPER_MODEL = "rest"


def rms_frames(test: Any, model: str, fps: float) -> float:
    """The rms residual of ``model``'s fit of ``test``, in frames: the one number the
    residual figure's titles and the demo's table print for it."""
    return float(test.fits[model].rms) * float(fps)


def _grid(analysis: Any) -> tuple[list[str], int]:
    groups = [g.name for g in analysis.groups]
    ncols = max(len(g.tests) for g in analysis.groups)
    return groups, ncols


def residual_figure(
    analysis: Any,
    path: str | Path | None = None,
    baseline: str = PAPER_MODEL,
) -> Any:
    """Residuals (frames) of the paper's model (``baseline``, default constant acceleration
    from rest at the first mark) and of each test's chosen model, against time; one panel
    per test, one row per group.

    The grey band is the frame quantisation (one frame wide), the dashed lines the chosen
    model's reading-noise envelope (2 sigma); crosses mark rows judged misread, at their
    prediction error (clipped to the axes, with the value written beside). Each panel's
    title names the chosen model as the legend does, with both rms values
    (:func:`rms_frames`, as the demo's table and ``surfmet rotor`` print them) and whether
    the chosen model explains the data; one legend, below the panels, hides no data.
    """
    groups, ncols = _grid(analysis)
    fig, axes = new_figure(len(groups), ncols, size=(3.6 * ncols, 2.8 * len(groups) + 0.4))
    axes = np.atleast_2d(axes)
    fps = analysis.fps
    for gi, gname in enumerate(groups):
        g = analysis.group(gname)
        for ti in range(ncols):
            ax = axes[gi, ti]
            if ti >= len(g.tests):
                ax.set_visible(False)
                continue
            t = analysis.test(g.tests[ti])
            base, sel = t.fits[baseline], t.fit
            used = np.asarray(sel.used)
            time = np.asarray(t.times)
            ax.axhspan(-0.5, 0.5, color="0.88", zorder=0, label="±½ frame")
            rb = np.asarray(base.residuals) * fps
            rs = np.asarray(sel.residuals) * fps
            ax.plot(time[used], rb[used], "o-", ms=3, lw=0.8, color="tab:orange",
                    label=f"model {baseline}")
            ax.plot(time[used], rs[used], "o-", ms=3, lw=0.8, color="tab:blue",
                    label="chosen model (named in each title)")
            env = 2 * np.asarray(sel.sigma) * fps
            ax.plot(time, env, "--", color="tab:blue", lw=0.6,
                    label="chosen model's 2σ reading noise")
            ax.plot(time, -env, "--", color="tab:blue", lw=0.6)
            lim = max(2.0, float(np.nanmax(np.abs(rb[used]))) * 1.15)
            ax.set_ylim(-lim, lim)
            for i in np.flatnonzero(~used):
                y = float(np.clip(rs[i], -0.95 * lim, 0.95 * lim))
                ax.plot(time[i], y, "x", color="tab:red", ms=8, mew=2)
                ax.annotate(f"k={int(t.k[i])}: {rs[i]:+.1f}", (time[i], y), fontsize=7,
                            color="tab:red", xytext=(3, 3), textcoords="offset points")
            ax.axhline(0, color="k", lw=0.5)
            ok = t.adequacy is None or t.adequacy.adequate
            ax.set_title(f"{t.name}: chosen model {sel.model}{'' if ok else ' (NOT adequate)'}\n"
                         f"rms {baseline} {rms_frames(t, baseline, fps):.2f}, {sel.model} "
                         f"{sel.rms * fps:.2f} frame", fontsize=8)
            ax.tick_params(labelsize=7)
            if gi == len(groups) - 1:
                ax.set_xlabel("time since first mark (s)", fontsize=8)
            if ti == 0:
                ax.set_ylabel("model − measured (frames)", fontsize=8)
    handles, labels = axes[0, 0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside lower center", ncol=len(labels), fontsize=7)
    paper = " (the paper's: constant acceleration from rest at the first mark)"
    fig.suptitle(f"Law of motion: residuals of model {baseline}"
                 f"{paper if baseline == PAPER_MODEL else ''} vs the chosen model",
                 fontsize=10)
    return finish(fig, path)


def law_of_motion_figure(analysis: Any, path: str | Path | None = None) -> Any:
    """Angle against time for every test, with the paper's parabola of each group (through
    the mean times) and each test's chosen model."""
    from rotor import PARAM_NAMES, crossing_times

    fig, ax = new_figure(1, 1, size=(6.4, 4.8))
    colours = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple"]
    misread = False
    for gi, g in enumerate(analysis.groups):
        col = colours[gi % len(colours)]
        tmax = 0.0
        chosen = ", ".join(f"{name} {analysis.test(name).fit.model}" for name in g.tests)
        # every series is named once in the legend: the first artist of its kind carries
        # the label, the group's other tests repeat its colour and style unlabelled
        for k, name in enumerate(g.tests):
            t = analysis.test(name)
            used = np.asarray(t.used)
            ax.plot(t.times[used], t.angles[used], "o", ms=3, color=col, alpha=0.6,
                    label=f"{g.name}: marks read" if k == 0 else "_nolegend_")
            if np.any(~used):
                ax.plot(t.times[~used], t.angles[~used], "x", ms=7, color="k",
                        label="_nolegend_" if misread else "misread marks (left out)")
                misread = True
            p = {key: t.fit.params[key] for key in PARAM_NAMES}
            phi = np.linspace(0, float(t.angles.max()), 200)
            ax.plot(crossing_times(phi, **p), phi, "-", lw=0.7, color=col,
                    label=f"{g.name}: chosen models ({chosen})" if k == 0 else "_nolegend_")
            tmax = max(tmax, float(t.times.max()))
        c2, c1, c0 = g.paper_parabola
        if all(math.isfinite(c) for c in (c2, c1, c0)):
            tt = np.linspace(0, tmax, 200)
            ax.plot(tt, c2 * tt**2 + c1 * tt + c0, "--", color=col, lw=1.2,
                    label=f"{g.name}: paper parabola {c2:.3f} t² + {c1:.3f} t {c0:+.3f}")
    ax.set_xlabel("time since first mark (s)")
    ax.set_ylabel("rotation angle (rad)")
    handles, labels = ax.get_legend_handles_labels()
    order = sorted(range(len(labels)), key=lambda i: labels[i].startswith("misread"))
    ax.legend([handles[i] for i in order], [labels[i] for i in order], fontsize=6.5,
              loc="upper left")
    ax.set_title("Law of motion: data (x = misread), chosen models (—), paper's fits (--)",
                 fontsize=9)
    return finish(fig, path)


def acceleration_profile_figure(analysis: Any, path: str | Path | None = None) -> Any:
    """The chosen models' smooth acceleration along the run, ``eps0 - eta (phi - phi0) -
    gamma omega``, per test: where the groups differ, at the start or along the way."""
    from rotor import PARAM_NAMES, crossing_times

    fig, ax = new_figure(1, 1, size=(6.4, 4.2))
    colours = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple"]
    for gi, g in enumerate(analysis.groups):
        col = colours[gi % len(colours)]
        for name in g.tests:
            t = analysis.test(name)
            p = {k: t.fit.params[k] for k in PARAM_NAMES}
            phi = np.linspace(max(p["phi0"], 0.0), float(t.angles.max()), 300)
            d = 1e-4
            tt = crossing_times(np.concatenate([phi, phi + d]), **p)
            omega = d / np.maximum(tt[phi.size:] - tt[: phi.size], 1e-12)
            eps = p["eps0"] - p["eta"] * (phi - p["phi0"]) - p["gamma"] * omega
            ax.plot(phi, eps, color=col, lw=1, label=f"{name} ({t.selected})")
    ax.set_xlabel("rotation angle (rad)")
    ax.set_ylabel("smooth angular acceleration (rad/s²)")
    ax.legend(fontsize=7)
    return finish(fig, path)


def rolling_law_figure(inference: Any, path: str | Path | None = None,
                       label: str = "") -> Any:
    """``lambda`` implied by the two groups' accelerations against the assumed equivalent
    slope (:func:`rotor.infer_rolling_law`), with its 16-84 % band."""
    infs = inference if isinstance(inference, (list, tuple)) else [(label, inference)]
    fig, ax = new_figure(1, 1, size=(6.4, 4.2))
    for lab, inf in infs:
        deg = np.degrees(np.arcsin(np.asarray(inf.slope)))
        line, = ax.plot(deg, inf.lam, lw=1.2, label=lab)
        hi = np.where(np.isfinite(inf.lam_high), inf.lam_high, np.nan)
        ax.fill_between(deg, inf.lam_low, hi, color=line.get_color(), alpha=0.2)
    ax.axhline(1.0, color="k", lw=0.6, ls=":")
    ax.axhline(4 / 3, color="0.5", lw=0.6, ls="--")
    ax.text(ax.get_xlim()[0], 4 / 3, " Hertz 4/3", fontsize=7, va="bottom")
    ax.set_xlabel("assumed equivalent slope asin(sin α sin β) (°)")
    ax.set_ylabel("λ implied by the accelerations")
    ax.set_ylim(0, min(12.0, float(np.nanmax([np.nanmax(i.lam) for _, i in infs] + [2])) * 1.3))
    ax.legend(fontsize=7)
    return finish(fig, path)
