"""Benchmark: the resolution study on the bundled paper pair (steel ball on aluminium).

Run ``python benchmarks/resolution_study.py``. Times the four-level study (pixel 40, 20,
10, 5 µm) of the elastic-plastic contact at 10 N and of lambda_eff over 1-100 N (7 loads),
each the minimum of 2 repeats (the machine is shared; read them as noisy), and the time
of each level, so the study's overhead over the native solve shows.
"""

from __future__ import annotations

from importlib import resources

from _timing import min_time

import surfmet
from contact._materials import composite_modulus, material
from contact._resolution import sphere_study
from contact._rolling import log_loads
from surfmet.mechanics.resolution_study import rolling_study
from surfmet.mechanics.scan_preparation import prepare_scans


def _data(name: str) -> str:
    return str(resources.files("surfmet").joinpath("data", name))


def main() -> None:
    plate, ball = surfmet.read(_data("paper_plate.x3p")), surfmet.read(_data("paper_ball.x3p"))
    steel, alu = material("steel"), material("aluminium")
    e_star = composite_modulus(steel, alu)
    prep = prepare_scans(plate, ball)
    pair = prep.pair
    args = (0.02, 10.0, e_star, pair.roughness, pair.dx, pair.dy)
    kw = dict(hardness=alu.hardness, sigma=prep.sigma)
    sphere_study(*args, **kw)  # warm the numba cache
    runs = []
    t_all = min_time(lambda: runs.append(sphere_study(*args, **kw)), 2)
    levels = runs[-1].levels
    print(f"contact study 10 N, 4 levels (8x..1x): {t_all:.2f} s; per level "
          + ", ".join(f"{lv.pixel * 1e6:g} µm ({lv.grid}²) {lv.seconds:.2f} s" for lv in levels))
    t_roll = min_time(lambda: rolling_study(plate, ball, radius=0.02, loads=log_loads(1, 100, 7),
                                            materials="steel,aluminium"), 2)
    print(f"rolling study 1-100 N, 7 loads, 4 levels: {t_roll:.2f} s")


if __name__ == "__main__":
    main()
