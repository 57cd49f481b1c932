"""Campaign: Persson's theory from several measurements against the known spectrum.

Run ``python benchmarks/all_scales_persson.py [--seeds N]`` from the checkout root (with the
checkout on ``PYTHONPATH``). For H = 0.5 and 0.8 and each seed, a 1024² surface with the
isotropic PSD ``c0 q^(-2-2H)`` is generated (``tests/test_all_scales.py``'s generator: exact
amplitudes, random phases) and measured three times (pixels 2, 4 and 8 times the
generator's, sizes a quarter, half and all of it). ``surfmet.mechanics.all_scales`` turns
the averaged profile PSD into the isotropic PSD; printed are the relative errors, against
the known spectrum over the same band, of the rms slope (closed form), the rms height
(closed form), Persson's area at low pressure (closed form) and the Yang-Persson mean gap
(:func:`contact.roughcontact.persson` on the known spectrum, same quadrature), and the
time of the analysis (the machine is shared: the minimum over the runs).
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np
from scipy.special import erf

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from test_all_scales import _measurements

from contact.roughcontact import persson
from surfmet.mechanics.all_scales import all_scales_spectrum, persson_all_scales
from surfmet.scale_dependent import analyze_scales


def one(hurst: float, seed: int) -> tuple[list[float], float]:
    """Relative errors (slope, h_rms, area, gap) and the analysis time for one surface."""
    scans, c0 = _measurements(hurst, seed)
    t0 = time.perf_counter()
    s = all_scales_spectrum(analyze_scales(scans, per_decade=10))
    took = time.perf_counter() - t0
    lo, hi = s.band
    e2, e0 = 2 - 2 * hurst, -2 * hurst
    slope = math.sqrt(c0 / (2 * math.pi) * (hi**e2 - lo**e2) / e2)
    h = math.sqrt(c0 / (2 * math.pi) * (hi**e0 - lo**e0) / e0)
    e_star = 1e10
    p = np.array([0.05 * slope * e_star])
    got = persson_all_scales(s, p, e_star)
    known = persson(p, e_star, s.q, c0 * s.q ** (-2 - 2 * hurst), s.weights, s.dq)
    area = float(erf(math.sqrt(2) * p[0] / (e_star * slope)))
    return [s.slope_rms / slope - 1, s.h_rms / h - 1, float(got.area_fraction[0]) / area - 1,
            float(got.mean_gap[0] / known.mean_gap[0]) - 1], took


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=5)
    args = ap.parse_args()
    best = math.inf
    print(f"{'H':>4} {'seed':>4} {'slope':>8} {'h_rms':>8} {'area':>8} {'gap':>8}")
    rows = []
    for hurst in (0.5, 0.8):
        for seed in range(1, args.seeds + 1):
            err, took = one(hurst, seed)
            best = min(best, took)
            rows.append(err)
            print(f"{hurst:4.1f} {seed:4d} " + " ".join(f"{100 * e:+7.1f}%" for e in err))
    r = np.array(rows)
    for k, name in enumerate(("slope", "h_rms", "area", "gap")):
        print(f"{name:>6}: {100 * r[:, k].min():+.1f} % .. {100 * r[:, k].max():+.1f} %")
    print(f"analysis of three 128² maps, 10 points per decade: {best:.2f} s (best run)")


if __name__ == "__main__":
    main()
