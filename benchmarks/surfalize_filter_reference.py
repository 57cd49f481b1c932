"""Reference numbers of surfalize's Gaussian L-filter for tests/test_filters_beside_surfalize.py.

Run with a Python that has surfalize (a separate virtualenv; the package and its tests
never import it):

    python3 -m venv /tmp/w5venv && /tmp/w5venv/bin/pip install surfalize
    /tmp/w5venv/bin/python benchmarks/surfalize_filter_reference.py \
        > tests/data/surfalize_gaussian_l_filter.json

The map (:func:`reference_map`): tests/areal_synth.gaussian_surface with the seed below
(numpy's PCG64 stream, stable across versions), 1024 x 1024 points at 1 µm, rms 1 µm,
correlation length 12 px, plus a long wave 2 µm sin(2 pi x / 700 µm) + a tilt, so that the
filter's ends matter. surfalize 0.19 filters with scipy.ndimage.gaussian_filter (its
GaussianFilter, endeffect_mode "reflect" by default: the map mirrored at its border,
sigma = lambda_c sqrt(ln 2 / 2) / pi, kernel truncated at 4 sigma). Stated: Sa, Sq, Ssk of
the high-pass (roughness) map over the whole map, and over the inner area that leaves out
lambda_c / 2 along each border (where the Gaussian weights are complete: there the
treatments of the ends do not enter).
"""

from __future__ import annotations

import datetime
import json
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

SEED, N, DX_UM, LC_UM = 38, 1024, 1.0, 250.0


def reference_map() -> np.ndarray:
    """The test map, heights in µm (module notes)."""
    from areal_synth import gaussian_surface

    z = gaussian_surface(np.random.default_rng(SEED), N, N, 1.0, 12.0)
    x = np.arange(N) * DX_UM
    return z + 2.0 * np.sin(2 * np.pi * x / 700.0)[None, :] + 1e-3 * x[:, None]


def stats(z: np.ndarray) -> dict[str, float]:
    """Sa, Sq (µm) and Ssk of ``z`` about its mean (ISO 25178-2)."""
    d = z - z.mean()
    sq = float(np.sqrt(np.mean(d * d)))
    return {"Sa": float(np.mean(np.abs(d))), "Sq": sq, "Ssk": float(np.mean(d**3) / sq**3)}


def main() -> None:
    import surfalize

    surf = surfalize.Surface(reference_map(), DX_UM, DX_UM)
    rough = surf.filter("highpass", LC_UM)
    band = round(LC_UM / 2 / DX_UM)
    out = {
        "provenance": {
            "tool": "surfalize", "version": surfalize.__version__,
            "command": "surfalize.Surface(z_um, 1.0, 1.0).filter('highpass', 250.0) "
                       "(benchmarks/surfalize_filter_reference.py)",
            "numpy": np.__version__, "date": datetime.date.today().isoformat(),
            "end_effect_mode": "reflect (surfalize's default)",
        },
        "map": {"seed": SEED, "points": N, "pixel_um": DX_UM, "lambda_c_um": LC_UM,
                "recipe": "benchmarks/surfalize_filter_reference.reference_map"},
        "whole": stats(rough.data),
        "inner_band_px": band,
        "inner": stats(rough.data[band:-band, band:-band]),
        "units": {"Sa": "µm", "Sq": "µm", "Ssk": ""},
    }
    json.dump(out, sys.stdout, indent=1, ensure_ascii=False)
    print()


if __name__ == "__main__":
    main()
