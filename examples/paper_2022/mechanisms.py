"""Which mechanism makes the rotor's rolling friction
==================================================

Which mechanism makes the rolling friction of the paper's rotor? (Alaci et al. 2022)

Run:  python examples/paper_2022/mechanisms.py [--scans] [--grid N] [--gallery]

For the smooth steel ball (R = 20 mm) on the aluminium plate, at the rotor's ball loads
(3.97, 4.67, 5.36 N), sets side by side the rolling-friction moment of

- viscoelastic hysteresis, computed (contact.viscoelastic) from the metals' loss factors
  with each loss peak placed at the contact frequency V/a (an upper bound),
- the hysteresis rule with alpha_h = 2 pi eta (contact._rolling),
- first-pass plastic work at the aluminium's hardness (contact._rolling),
- micro-slip of free rolling between the dissimilar elastic bodies (contact.tangential,
  mu = 0.3 assumed),

for the typical and the highest loss factor (the loss peak follows V/a, so the bound
does not depend on the speed), and sets the symmetric-minus-asymmetric angular
acceleration each implies beside the one Table 3 measures. ``--scans`` repeats the
comparison on the bundled stand-in scans (one track position; plastic and hysteresis from
the scans' contact, viscoelastic with the roughness frozen in the contact frame).

The output and figure on the documentation's page are ``mechanisms.py --gallery``, run
while the documentation is built: the smooth pair with the typical loss factors only
(the full run adds the highest ones), without the micro-slip mechanism (a 3D frictional
solve per load, minutes; in the full run it is the smallest of them, some 100 times below
the hysteresis rule), on 64-cell grids and 5 loads (2-12 N; the rotor's three ball loads
are always added) instead of 128 cells and 7 loads, so its moments and exponents are
coarser than the full run's (the computed viscoelastic local exponent wobbles at the
rotor's closely spaced loads); the figure draws each mechanism's M_r(N). The full
comparison: ``python examples/paper_2022/mechanisms.py`` (add ``--scans`` for the rough
pair).
"""

from __future__ import annotations

import argparse
import sys
from importlib import resources
from pathlib import Path

try:
    _HERE = Path(__file__).resolve().parent
except NameError:  # the documentation's gallery defines no __file__; it runs in this folder
    _HERE = Path.cwd()
sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != _HERE]

import numpy as np  # noqa: E402

from contact.viscoelastic import loss_data  # noqa: E402
from surfmet.mechanics.viscoelastic_rolling import rolling_mechanisms  # noqa: E402

RADIUS = 0.02


def smooth(grid: int, loads: tuple[float, float, int] = (2.0, 12.0, 7),
           gallery: bool = False) -> None:
    steel, alu = loss_data("steel"), loss_data("aluminium")
    print("Smooth pair, steel ball R = 20 mm on Al 6061-T6, loads of the paper's rotor")
    print(f"{'case':34}{'mechanism':>13}{'M_r(4.67 N)':>13}{'lambda':>8}"
          f"{'eps_s-eps_a':>13}{'measured/it':>13}")
    # micro-slip does not depend on the loss factor: computed once (mu = 0.3 assumed)
    cases = (("typical eta, V = 0.1 m/s", (steel.typical, alu.typical), 0.1, 0.3),
             ("highest eta, V = 0.1 m/s", (steel.high, alu.high), 0.1, None))
    for label, loss, speed, mu in cases[:1] if gallery else cases:
        rep = rolling_mechanisms(radius=RADIUS, loads=loads, speed=speed, loss=loss,
                                 grid=grid, mu=None if gallery else mu)
        if gallery:
            draw(rep.comparison.mechanisms, label)
        measured, lo, hi = rep.group_offset
        for m in rep.comparison.mechanisms:
            ratio = measured / m.delta_eps if m.delta_eps > 0 else float("inf")
            print(f"{label:34}{m.name:>13}{m.rotor_moments[0]:13.3g}"
                  f"{m.sweep.lambda_eff:8.3f}{m.delta_eps:13.3g}{ratio:13.3g}")
        name, factor = rep.comparison.dominant()
        print(f"{'':34}dominant: {name} ({factor:.3g} x the next)")
    print(f"Table 3 (the rotor verdict's joint model): eps_s - eps_a = {measured:.3f} "
          f"rad/s^2, 95 % CI [{lo:.3f}, {hi:.3f}]")


def draw(mechanisms: list, label: str) -> None:
    """Each mechanism's M_r(N) and local exponent (left open for the gallery to show)."""
    from surfmet.plots.hertz import rolling_figure

    fig = rolling_figure([m.sweep for m in mechanisms],
                         labels=[m.name for m in mechanisms])
    fig.suptitle(f"smooth steel ball on Al 6061-T6, {label}", fontsize=11)


def scans(grid: int) -> None:
    from surfmet.mechanics.rolling_resistance import rolling_resistance
    from surfmet.mechanics.viscoelastic_rolling import viscoelastic_rolling

    data = Path(str(resources.files("surfmet").joinpath("data")))
    plate, ball = data / "paper_plate.x3p", data / "paper_ball.x3p"
    loads = np.array([3.968, 4.665, 5.363, 8.0, 12.0])
    print("\nBundled stand-in scans, one track position (the middle)")
    for model in ("hysteresis", "plastic"):
        kw = {"alpha_h": 2 * np.pi * 4e-4} if model == "hysteresis" else {}
        rep = rolling_resistance(plate, ball, radius=RADIUS, materials="steel,aluminium",
                                 loads=loads, model=model, grid=grid, **kw)
        m = rep.sweep.moments
        print(f"{model:13} M_r(3.97, 4.67, 5.36 N) = {m[0]:.3g}, {m[1]:.3g}, {m[2]:.3g} N m;"
              f" lambda = {rep.lambda_eff:.3f}")
    rep = viscoelastic_rolling(plate, ball, radius=RADIUS, materials="steel,aluminium",
                               loads=loads, speed=0.1, loss=(3e-4, 5e-4), grid=grid)
    m = rep.sweep.moments
    print(f"{'viscoelastic':13} M_r(3.97, 4.67, 5.36 N) = {m[0]:.3g}, {m[1]:.3g}, {m[2]:.3g} "
          f"N m; lambda = {rep.sweep.lambda_eff:.3f} (roughness frozen)")


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(
        description="Which mechanism makes the rotor's rolling friction.")
    ap.add_argument("--scans", action="store_true", help="also on the bundled scans")
    ap.add_argument("--grid", type=int, default=None, help="cells per side (default 128, "
                    "64 with --gallery)")
    ap.add_argument("--gallery", action="store_true",
                    help="the documentation's run: coarser grid, 5 loads, the figure")
    args = ap.parse_args(argv)
    grid = args.grid or (64 if args.gallery else 128)
    if args.gallery:
        smooth(grid, loads=(2.0, 12.0, 5), gallery=True)
    else:
        smooth(grid)
    if args.scans:
        scans(grid)
    return 0


# %%
# The run
# -------
# The documentation's gallery runs this file as ``mechanisms.py --gallery`` (see the top);
# the output and the figure below are that run's.

if __name__ == "__main__":
    # no SystemExit on success: the gallery runs this file inside the documentation build
    if status := main(sys.argv[1:]):
        sys.exit(status)
