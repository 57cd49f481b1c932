"""ISO 21920-2 feature parameters against closed forms and the reference implementation.

Reference implementation: RPTU / MTS "feature-characterization-for-profile-surface-texture"
(MIT, commit ab4c9d5; Müller et al., Surf. Topogr.: Metrol. Prop. 13 (2025) 015003). Its
values below were produced by its own code on its own test profiles (tests/data/mts), in its
units (z in µm, x in mm, densities per cm, curvatures in 1/µm, signed).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.io import loadmat

from profiles import ProfileError
from profiles.features import feature_characterization, feature_parameters, segment

DATA = Path(__file__).parent / "data" / "mts"
DX = 0.5e-6  # the reference case studies' step

# (file, feature type, significant, attribute, statistic): reference value (MTS units)
REFERENCE = {
    ("Bu_1_56_ak", "H", "all", "count", "density"): 202.47469066366705,
    ("Bu_1_56_ak", "D", "all", "count", "density"): 199.97500312460943,
    ("Bu_1_56_ak", "P", "all", "curvature", "mean"): -0.3177278899929565,
    ("Bu_1_56_ak", "V", "all", "curvature", "mean"): 0.713521787335836,
    ("Bu_1_56_ak", "P", "top", "PVh", "mean"): 19.41560756719316,
    ("Bu_1_56_ak", "V", "top", "PVh", "mean"): 10.153135302946648,
    ("Bu_1_56_ak", "D", "all", "HDh", "mean"): 3.08449998202596,
    ("Bu_1_56_ak", "D", "all", "HDw", "mean"): 0.029122171860409374,
    ("Luftpresser_1_56_ak", "H", "all", "count", "density"): 532.4334458192726,
    ("Luftpresser_1_56_ak", "P", "all", "curvature", "mean"): -0.20858842528904892,
    ("Luftpresser_1_56_ak", "V", "all", "curvature", "mean"): 0.3757743584815192,
    ("Luftpresser_1_56_ak", "P", "top", "PVh", "mean"): 0.6150271165695967,
    ("Luftpresser_1_56_ak", "V", "top", "PVh", "mean"): 2.254139046734776,
    ("Luftpresser_1_56_ak", "D", "all", "HDh", "mean"): 0.4922694281577845,
    ("Luftpresser_1_56_ak", "D", "all", "HDw", "mean"): 0.014646990266677372,
}
# ours (SI) -> theirs: density 1/m -> 1/cm; curvature 1/m -> 1/µm with the sign of z'' at
# the feature (theirs is negative at peaks); heights m -> µm; widths m -> mm
TO_MTS = {"count": 1e-2, "curvature": 1e-6, "PVh": 1e6, "HDh": 1e6, "HDw": 1e3}


def _profile(name: str) -> np.ndarray:
    return loadmat(DATA / f"{name}.mat")["z"].reshape(-1).astype(float) * 1e-6


@pytest.mark.parametrize("key", list(REFERENCE), ids=lambda k: "-".join(map(str, k)))
def test_reference_implementation_values(key):
    name, ft, sig, attr, stat = key
    z = _profile(name)
    ours = feature_characterization(z, DX, ft, significant="all" if sig == "all" else
                                    ("top", 5), attr=attr, statistic=stat)
    sign = -1.0 if (attr == "curvature" and ft == "P") else 1.0
    assert sign * ours * TO_MTS[attr] == pytest.approx(REFERENCE[key], rel=1e-9)


def test_named_parameters_on_a_reference_profile():
    z = _profile("Bu_1_56_ak")
    fp = feature_parameters(z, DX)
    assert fp.Rpd * 1e-2 == pytest.approx(REFERENCE[("Bu_1_56_ak", "H", "all", "count",
                                                     "density")], rel=1e-9)
    assert fp.Rmvc * 1e-6 == pytest.approx(0.713521787335836, rel=1e-9)
    assert fp.R10z == pytest.approx((19.41560756719316 + 10.153135302946648) * 1e-6,
                                    rel=1e-9)


def _sine(amp=1e-6, lam=100e-6, periods=40, dx=0.25e-6, phase=0.3):
    x = np.arange(round(periods * lam / dx)) * dx
    return amp * np.sin(2 * np.pi * x / lam + phase), dx, lam


def test_sine_closed_forms():
    amp = 1e-6
    z, dx, lam = _sine(amp)
    fp = feature_parameters(z, dx)
    length = z.size * dx
    # one hill and one dale per period, except the open ones at the ends
    assert fp.Rpd * length == pytest.approx(length / lam - 1, abs=1)
    assert fp.Rvd * length == pytest.approx(length / lam - 1, abs=1)
    k = amp * (2 * np.pi / lam) ** 2  # curvature of A sin at its extrema
    assert fp.Rmpc == pytest.approx(k, rel=1e-4)
    assert fp.Rmvc == pytest.approx(k, rel=1e-4)
    assert fp.R5p == pytest.approx(amp, rel=1e-4) and fp.R5v == pytest.approx(amp, rel=1e-4)
    assert fp.R10z == pytest.approx(2 * amp, rel=1e-4)
    assert feature_characterization(z, dx, "D", attr="HDh", statistic="mean") == \
        pytest.approx(2 * amp, rel=1e-4)
    assert feature_characterization(z, dx, "D", attr="HDw", statistic="mean") == \
        pytest.approx(lam, rel=1e-3)
    # each dale's area below its rim level is A λ; HDv divides by the evaluation length
    assert feature_characterization(z, dx, "D", attr="HDv", statistic="mean") == \
        pytest.approx(amp * lam / length, rel=1e-3)


def test_wolf_pruning_removes_small_motifs():
    # a ripple of 1 % of Rz on a sine: every ripple motif is below 5 % Rz and merges away
    z, dx, lam = _sine(1e-6)
    x = np.arange(z.size) * dx
    rippled = z + 0.01e-6 * np.sin(2 * np.pi * x / (lam / 37))
    raw = segment(rippled, dx, "D", wolf=None)
    pruned = segment(rippled, dx, "D")
    clean = segment(z, dx, "D")
    assert raw.pit.size > 5 * clean.pit.size
    assert pruned.pit.size == clean.pit.size
    # a threshold above the sine's own motif height (2 A = Rz) removes everything
    assert segment(z, dx, "D", wolf=1.01).pit.size == 0


def test_bad_feature_input():
    z, dx, _ = _sine()
    with pytest.raises(ProfileError, match="feature type"):
        segment(z, dx, "X")
    with pytest.raises(ProfileError, match="attribute"):
        feature_characterization(z, dx, "D", attr="bogus")
    bad = z.copy()
    bad[10] = np.nan
    with pytest.raises(ProfileError, match="non-measured"):
        segment(bad, dx)
    assert math.isnan(feature_characterization(np.linspace(0, 1e-6, 50), dx, "D",
                                               attr="HDh", statistic="mean"))
