"""``surfmet scales --direction``: a map's scale-dependent slope and curvature along x, y
or both axes, checked against the closed form of h = a sin(k1 x) + b sin(k2 y).

Along x at distance d the slope (h(x + d) - h(x)) / d of a sin(k x) has the mean square
2 a² sin²(k d / 2) / d² (sin(A + δ) - sin A = 2 cos(A + δ/2) sin(δ/2)); the second
difference (h(x - d/2) - 2 h(x) + h(x + d/2)) / (d/2)² of the curvature has the mean
square a² (4 sin²(k d / 4))² / (d/2)⁴ / 2. The y term is constant along x and drops out;
along y the roles swap; ``both`` adds the two axes' variances (the rms gradient). The
map trimmed by the distance holds a non-integer number of periods, which moves the mean
of cos² by up to 1 / (4 k L) (about 1 % here; measured up to 1.1 %), hence the 2 %
tolerance: x and y differ by a factor (B / A)² = 6.25 in the mean square.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import surfmet
from surfmet._model import Topography
from surfmet.cli import main

N, DX = 1024, 1e-6
A, B = 0.2e-6, 0.5e-6  # amplitudes along x and along y
K1, K2 = 2 * math.pi * 24 / (N * DX), 2 * math.pi * 16 / (N * DX)  # 43, 64 px a period


def _slope_ms(amp: float, k: float, d: np.ndarray) -> np.ndarray:
    return 2 * amp**2 * np.sin(k * d / 2) ** 2 / d**2


def _curvature_ms(amp: float, k: float, d: np.ndarray) -> np.ndarray:
    h = d / 2
    return 0.5 * amp**2 * (4 * np.sin(k * h / 2) ** 2) ** 2 / h**4


@pytest.fixture(scope="module")
def wavy_map(tmp_path_factory):
    x = np.arange(N) * DX
    z = A * np.sin(K1 * x)[None, :] + B * np.sin(K2 * x)[:, None]
    return str(surfmet.write(Topography(z, DX, DX), tmp_path_factory.mktemp("w") / "w.npz"))


def _scales(capsys, path, *extra):
    assert main(["scales", path, "--per-decade", "5", "--json", *extra]) == 0
    rec = json.loads(capsys.readouterr().out)["scale_dependent"]

    def arr(key):
        return np.array([np.nan if v is None else v for v in rec[key]["value"]])

    return rec, arr("distance"), arr("rms_slope"), arr("rms_curvature")


@pytest.mark.parametrize("direction, amp_k", [
    (None, [(A, K1)]), ("y", [(B, K2)]), ("both", [(A, K1), (B, K2)])])
def test_slope_and_curvature_along_each_axis_follow_the_closed_form(capsys, wavy_map,
                                                                    direction, amp_k):
    extra = () if direction is None else ("--direction", direction)
    rec, d, slope, curv = _scales(capsys, wavy_map, *extra)
    assert rec["direction"]["value"] == (direction or "x")
    keep = np.isfinite(slope) & (d < 0.1 * N * DX)  # many periods in the trimmed map
    assert keep.sum() >= 5
    want = sum(_slope_ms(a, k, d[keep]) for a, k in amp_k)
    assert slope[keep] ** 2 == pytest.approx(want, rel=2e-2)
    # at d / 2 of a few pixels the interpolated half-steps' error is a large part of the
    # small second difference: compare from five pixels up
    keep = np.isfinite(curv) & (d < 0.1 * N * DX) & (d >= 10 * DX * (1 - 1e-9))
    want = sum(_curvature_ms(a, k, d[keep]) for a, k in amp_k)
    assert curv[keep] ** 2 == pytest.approx(want, rel=2e-2)


def test_text_states_the_direction(capsys, wavy_map):
    assert main(["scales", wavy_map, "--direction", "y"]) == 0
    assert "derivatives along y (columns)" in capsys.readouterr().out
