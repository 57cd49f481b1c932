"""Benchmark: ISO 4287 per-sampling-length averaging and ISO 21920-2 feature parameters
on a 100 000-point roughness profile (issue 18 target: under 0.5 s).

Run ``python benchmarks/profile_standards.py``. Times are the minimum of 5 repeats (the
machine may be shared: read them as noisy). The profile is a seeded Gaussian random
roughness (correlation length ~ 20 steps), the hard case for the feature segmentation:
tens of thousands of motifs before Wolf pruning.
"""

from __future__ import annotations

import numpy as np
from _timing import min_time
from scipy.ndimage import gaussian_filter1d

from profiles import feature_parameters, probability_parameters, profile_parameters, rk_parameters

N = 100_000
DX = 0.5e-6


def profile(seed: int = 0) -> np.ndarray:
    rng = np.random.default_rng(seed)
    z = gaussian_filter1d(rng.standard_normal(N), 8.0)
    return z / z.std() * 1e-6


def main() -> None:
    z = profile()
    noise = np.random.default_rng(1).standard_normal(N) * 1e-6  # worst case: most motifs
    cases = {
        "ISO 4287 averaging (5 sampling lengths)":
            lambda: profile_parameters(z, DX, n_sampling=5, standard="iso4287"),
        "ISO 21920-2 over the evaluation length":
            lambda: profile_parameters(z, DX, n_sampling=5, standard="iso21920"),
        "feature parameters (Rpd..R10z, Wolf 5 % Rz)": lambda: feature_parameters(z, DX),
        "feature parameters, white noise (33k motifs)": lambda: feature_parameters(noise, DX),
        "ISO 13565-2 Rk family (secant)": lambda: rk_parameters(z),
        "ISO 13565-3 Rpq, Rvq, Rmq": lambda: probability_parameters(z),
    }
    print(f"profile: {N} points, seeded Gaussian roughness")
    total = 0.0
    for name, fn in cases.items():
        t = min_time(fn)
        total += t
        print(f"  {name:<45s} {t * 1e3:8.1f} ms")
    print(f"  {'all of the above':<45s} {total * 1e3:8.1f} ms")
    iso = min_time(cases["ISO 4287 averaging (5 sampling lengths)"])
    feat = min_time(cases["feature parameters, white noise (33k motifs)"])
    print(f"issue 18 target (ISO 4287 averaging + feature parameters, worst case < 500 ms): "
          f"{(iso + feat) * 1e3:.0f} ms")


if __name__ == "__main__":
    main()
