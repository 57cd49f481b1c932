"""Figures of the Hertz check (pressure map beside the radial profile against Hertz) and of
the rolling-resistance exponent (M_r against N on log axes, with the local exponent).

The panels reuse :func:`surfmet.plots.contact.pressure_map` and
:func:`surfmet.plots.contact.radial_pressure`.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet.plots._style import finish, new_figure


def hertz_check_figure(check: Any, path: str | Path | None = None, *,
                       normalise: bool = False) -> Any:
    """Pressure map (left) and the azimuthally averaged pressure against Hertz (right).

    Parameters
    ----------
    check : surfmet.mechanics.hertz_check.HertzCheck
        Uses ``result`` (the solution compared), ``comparison`` (profile, Hertz, verdict).
    path : str or Path, optional
        Where to save the figure (PNG, PDF, SVG... by extension).
    normalise : bool
        Plot the profile as p/p0 against r/a0.
    """
    from surfmet.plots.contact import pressure_map, radial_pressure

    comp = getattr(check, "comparison", None)
    res = getattr(check, "result", None)
    if comp is None or res is None:
        raise SurfmetInputError("hertz_check_figure needs a "
                                "surfmet.mechanics.hertz_check.HertzCheck")
    fig, (ax_map, ax_prof) = new_figure(1, 2, size=(13.0, 5.0))
    pressure_map(res, ax=ax_map)
    prof = comp.profile
    radial_pressure(prof.r, prof.p, prof.p_hertz, comp.hertz.a, ax=ax_prof,
                    normalise=normalise,
                    title=f"azimuthal average about the apex (α = {comp.alpha:.3g})")
    fig.suptitle(f"{comp.headline} at W = {res.load:.4g} N", fontsize=12)
    return finish(fig, path)


def rolling_figure(sweeps: Any, path: str | Path | None = None, *,
                   labels: list[str] | None = None) -> Any:
    """M_r(N) on log axes with the fitted power laws (left) and the local exponent (right).

    Parameters
    ----------
    sweeps : contact._rolling.RollingSweep or a list of them
    labels : list of str, optional
        Legend entries (default: the model names).
    """
    items = list(sweeps) if isinstance(sweeps, (list, tuple)) else [sweeps]
    if not items or not all(hasattr(s, "moments") and hasattr(s, "loads") for s in items):
        raise SurfmetInputError("rolling_figure needs contact._rolling.RollingSweep results")
    # the hysteresis moments scale with the assumed loss fraction: the label says which
    labels = labels or [s.model + (f" (α_h = {s.settings['alpha_h']:g})"
                                   if s.settings.get("alpha_h") is not None else "")
                        for s in items]
    fig, (ax, ax_l) = new_figure(1, 2, size=(11.0, 4.4))
    for k, (s, lab) in enumerate(zip(items, labels)):
        pos = s.moments > 0
        color = f"C{k}"
        ax.loglog(s.loads[pos], s.moments[pos], "o", color=color, ms=4)
        if s.fit is not None:
            nn = np.geomspace(s.loads[pos].min(), s.loads[pos].max(), 50)
            lo, hi = s.fit.ci
            ax.loglog(nn, s.fit.prefactor * nn**s.fit.exponent, "-", color=color, lw=1.2,
                      label=f"{lab}: λ = {s.fit.exponent:.3f} [{lo:.3f}, {hi:.3f}]")
        else:
            ax.plot([], [], "o", color=color, label=f"{lab}: no fit")
        ax_l.semilogx(s.loads[pos], s.local_lambda[pos], "o-", color=color, ms=4, label=lab)
    # the reference exponents are legend entries, not text on the axes: a label written
    # at the line was cut by the axes' edge when the line fell outside the data's range,
    # and crossed by the data inside it; both lines stay within the axes
    for ref, style, name in ((1.0, ":", "λ = 1 (M_r ∝ N)"),
                             (4.0 / 3.0, "--", "λ = 4/3 (smooth Hertz contact)")):
        ax_l.axhline(ref, color="0.4", ls=style, lw=0.9, label=name)
    lo, hi = ax_l.get_ylim()
    ax_l.set_ylim(min(lo, 0.95), max(hi, 4.0 / 3.0 + 0.05))
    unit = "N m/m" if items[0].settings.get("contact") == "cylinder" else "N m"
    load_unit = "N/m" if unit == "N m/m" else "N"
    ax.set_xlabel(f"normal load N ({load_unit})")
    ax.set_ylabel(f"rolling-resistance moment M_r ({unit})")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("M_r = s_r N^λ", fontsize=10)
    ax_l.set_xlabel(f"normal load N ({load_unit})")
    ax_l.set_ylabel("local exponent d ln M_r / d ln N")
    ax_l.grid(True, which="both", alpha=0.3)
    ax_l.legend(fontsize=8)
    ax_l.set_title("local exponent", fontsize=10)
    return finish(fig, path)
