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
from profiles._features import feature_characterization, feature_parameters, segment
from profiles._material_ratio import material_ratio_height

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


# Significance rules "open c" / "closed c" (ISO 21920-2 step 3), Wolf pruning 5 % Rz.
# Produced by the reference implementation (commit ab4c9d5) on its profiles:
# feature_characterization(z, 0.5e-3, FT, "Wolfprune 5 %", SIG, AT, STATS); c in µm or as
# a material ratio "p %"; nan where it declares every feature not significant.
SIGNIFICANCE = {
    ("Bu_1_56_ak", "D", "Open 10 %", "Count", "Density"): 199.97500312460943,
    ("Bu_1_56_ak", "D", "Open 10 %", "HDh", "Mean"): 3.08449998202596,
    ("Bu_1_56_ak", "H", "Open 10 %", "Count", "Density"): math.nan,
    ("Bu_1_56_ak", "H", "Open 10 %", "HDh", "Mean"): math.nan,
    ("Bu_1_56_ak", "D", "Closed 10 %", "Count", "Density"): math.nan,
    ("Bu_1_56_ak", "D", "Closed 10 %", "HDh", "Mean"): math.nan,
    ("Bu_1_56_ak", "H", "Closed 10 %", "Count", "Density"): 54.9931258592676,
    ("Bu_1_56_ak", "H", "Closed 10 %", "HDh", "Mean"): 16.618343608089617,
    ("Bu_1_56_ak", "D", "Open 50 %", "Count", "Density"): 104.98687664041996,
    ("Bu_1_56_ak", "D", "Open 50 %", "HDh", "Mean"): 3.0813959617951974,
    ("Bu_1_56_ak", "H", "Open 50 %", "Count", "Density"): 59.992500937382836,
    ("Bu_1_56_ak", "H", "Open 50 %", "HDh", "Mean"): 5.063900172026737,
    ("Bu_1_56_ak", "D", "Closed 50 %", "Count", "Density"): 64.99187601549806,
    ("Bu_1_56_ak", "D", "Closed 50 %", "HDh", "Mean"): 3.671172490945468,
    ("Bu_1_56_ak", "H", "Closed 50 %", "Count", "Density"): 82.48968878890139,
    ("Bu_1_56_ak", "H", "Closed 50 %", "HDh", "Mean"): 10.528004499832761,
    ("Bu_1_56_ak", "D", "Open 90 %", "Count", "Density"): math.nan,
    ("Bu_1_56_ak", "D", "Open 90 %", "HDh", "Mean"): math.nan,
    ("Bu_1_56_ak", "H", "Open 90 %", "Count", "Density"): 74.99062617172854,
    ("Bu_1_56_ak", "H", "Open 90 %", "HDh", "Mean"): 6.067060955420112,
    ("Bu_1_56_ak", "D", "Closed 90 %", "Count", "Density"): 159.98000249968754,
    ("Bu_1_56_ak", "D", "Closed 90 %", "HDh", "Mean"): 3.374415077323386,
    ("Bu_1_56_ak", "H", "Closed 90 %", "Count", "Density"): 127.48406449193853,
    ("Bu_1_56_ak", "H", "Closed 90 %", "HDh", "Mean"): 6.69746524062143,
    ("Bu_1_56_ak", "D", "Open 0.5", "Count", "Density"): 169.97875265591802,
    ("Bu_1_56_ak", "D", "Open 0.5", "HDh", "Mean"): 3.3068987523526534,
    ("Bu_1_56_ak", "H", "Open 0.5", "Count", "Density"): 59.992500937382836,
    ("Bu_1_56_ak", "H", "Open 0.5", "HDh", "Mean"): 5.063900172026737,
    ("Bu_1_56_ak", "D", "Closed 0.5", "Count", "Density"): math.nan,
    ("Bu_1_56_ak", "D", "Closed 0.5", "HDh", "Mean"): math.nan,
    ("Bu_1_56_ak", "H", "Closed 0.5", "Count", "Density"): 24.99687539057618,
    ("Bu_1_56_ak", "H", "Closed 0.5", "HDh", "Mean"): 26.59608386514264,
    ("Bu_1_56_ak", "D", "Open -0.5", "Count", "Density"): 169.97875265591802,
    ("Bu_1_56_ak", "D", "Open -0.5", "HDh", "Mean"): 3.3068987523526534,
    ("Bu_1_56_ak", "H", "Open -0.5", "Count", "Density"): 59.992500937382836,
    ("Bu_1_56_ak", "H", "Open -0.5", "HDh", "Mean"): 5.063900172026737,
    ("Bu_1_56_ak", "D", "Closed -0.5", "Count", "Density"): math.nan,
    ("Bu_1_56_ak", "D", "Closed -0.5", "HDh", "Mean"): math.nan,
    ("Bu_1_56_ak", "H", "Closed -0.5", "Count", "Density"): 24.99687539057618,
    ("Bu_1_56_ak", "H", "Closed -0.5", "HDh", "Mean"): 26.59608386514264,
    ("Luftpresser_1_56_ak", "D", "Open 10 %", "Count", "Density"): 402.4496937882765,
    ("Luftpresser_1_56_ak", "D", "Open 10 %", "HDh", "Mean"): 0.5622274250853206,
    ("Luftpresser_1_56_ak", "H", "Open 10 %", "Count", "Density"): math.nan,
    ("Luftpresser_1_56_ak", "H", "Open 10 %", "HDh", "Mean"): math.nan,
    ("Luftpresser_1_56_ak", "D", "Closed 10 %", "Count", "Density"): 129.98375203099613,
    ("Luftpresser_1_56_ak", "D", "Closed 10 %", "HDh", "Mean"): 0.2756687069013747,
    ("Luftpresser_1_56_ak", "H", "Closed 10 %", "Count", "Density"): 212.47344081989755,
    ("Luftpresser_1_56_ak", "H", "Closed 10 %", "HDh", "Mean"): 0.2728079357426992,
    ("Luftpresser_1_56_ak", "D", "Open 50 %", "Count", "Density"): 224.97187851518564,
    ("Luftpresser_1_56_ak", "D", "Open 50 %", "HDh", "Mean"): 0.613772265934785,
    ("Luftpresser_1_56_ak", "H", "Open 50 %", "Count", "Density"): 64.99187601549806,
    ("Luftpresser_1_56_ak", "H", "Open 50 %", "HDh", "Mean"): 0.19811242688462685,
    ("Luftpresser_1_56_ak", "D", "Closed 50 %", "Count", "Density"): 269.96625421822273,
    ("Luftpresser_1_56_ak", "D", "Closed 50 %", "HDh", "Mean"): 0.4367409838176201,
    ("Luftpresser_1_56_ak", "H", "Closed 50 %", "Count", "Density"): 324.9593800774903,
    ("Luftpresser_1_56_ak", "H", "Closed 50 %", "HDh", "Mean"): 0.3215187557809076,
    ("Luftpresser_1_56_ak", "D", "Open 90 %", "Count", "Density"): 27.4965629296338,
    ("Luftpresser_1_56_ak", "D", "Open 90 %", "HDh", "Mean"): 0.42926005095257974,
    ("Luftpresser_1_56_ak", "H", "Open 90 %", "Count", "Density"): 479.9400074990627,
    ("Luftpresser_1_56_ak", "H", "Open 90 %", "HDh", "Mean"): 0.2666274063020676,
    ("Luftpresser_1_56_ak", "D", "Closed 90 %", "Count", "Density"): 119.98500187476567,
    ("Luftpresser_1_56_ak", "D", "Closed 90 %", "HDh", "Mean"): 1.2223545086992742,
    ("Luftpresser_1_56_ak", "H", "Closed 90 %", "Count", "Density"): 37.49531308586427,
    ("Luftpresser_1_56_ak", "H", "Closed 90 %", "HDh", "Mean"): 0.973565029301442,
    ("Luftpresser_1_56_ak", "D", "Open 0.5", "Count", "Density"): 532.4334458192726,
    ("Luftpresser_1_56_ak", "D", "Open 0.5", "HDh", "Mean"): 0.4922694281577845,
    ("Luftpresser_1_56_ak", "H", "Open 0.5", "Count", "Density"): math.nan,
    ("Luftpresser_1_56_ak", "H", "Open 0.5", "HDh", "Mean"): math.nan,
    ("Luftpresser_1_56_ak", "D", "Closed 0.5", "Count", "Density"): math.nan,
    ("Luftpresser_1_56_ak", "D", "Closed 0.5", "HDh", "Mean"): math.nan,
    ("Luftpresser_1_56_ak", "H", "Closed 0.5", "Count", "Density"): 12.49843769528809,
    ("Luftpresser_1_56_ak", "H", "Closed 0.5", "HDh", "Mean"): 0.587811173573753,
    ("Luftpresser_1_56_ak", "D", "Open -0.5", "Count", "Density"): 37.49531308586427,
    ("Luftpresser_1_56_ak", "D", "Open -0.5", "HDh", "Mean"): 0.4513219999999997,
    ("Luftpresser_1_56_ak", "H", "Open -0.5", "Count", "Density"): 472.44094488188983,
    ("Luftpresser_1_56_ak", "H", "Open -0.5", "HDh", "Mean"): 0.26201072840992407,
    ("Luftpresser_1_56_ak", "D", "Closed -0.5", "Count", "Density"): 127.48406449193853,
    ("Luftpresser_1_56_ak", "D", "Closed -0.5", "HDh", "Mean"): 1.183081578959901,
    ("Luftpresser_1_56_ak", "H", "Closed -0.5", "Count", "Density"): 39.995000624921886,
    ("Luftpresser_1_56_ak", "H", "Closed -0.5", "HDh", "Mean"): 0.9912276971059502,
}
# the reference's inverse material ratio Rcm(z, p) (µm, p in %), its own profiles
RCM = {
    "Bu_1_56_ak": {0.5: -3.7973321192264997, 2.0: -5.548912747473601,
                   10.0: -9.5458811174645, 50.0: -28.823052580786012,
                   87.5: -31.05135221703594, 100.0: -33.7653565680084},
    "Luftpresser_1_56_ak": {0.5: -0.18506820977557692, 2.0: -0.337044956503081,
                            10.0: -0.41691671929955393, 50.0: -0.54421091651516,
                            87.5: -1.155009114492269, 100.0: -3.706617275460439},
}


ATTR = {"Count": "count", "HDh": "HDh"}  # the reference's spelling -> ours


def _rule(sig: str):
    kind, value = sig.split(" ", 1)
    if value.endswith("%"):
        return kind.lower(), value
    return kind.lower(), float(value) * 1e-6  # the reference's c is in µm


@pytest.mark.parametrize("key", list(SIGNIFICANCE), ids=lambda k: "-".join(map(str, k)))
def test_open_and_closed_significance_match_the_reference(key):
    name, ft, sig, attr, stat = key
    z = _profile(name)
    ours = feature_characterization(z, DX, ft, significant=_rule(sig), attr=ATTR[attr],
                                    statistic=stat.lower())
    ref = SIGNIFICANCE[key]
    if math.isnan(ref):
        assert math.isnan(ours)
    else:
        assert ours * TO_MTS[ATTR[attr]] == pytest.approx(ref, rel=1e-9)


@pytest.mark.parametrize("name", list(RCM))
def test_rcm_matches_the_reference(name):
    z = _profile(name)
    for p, ref in RCM[name].items():
        assert material_ratio_height(z, p / 100) * 1e6 == pytest.approx(ref, rel=1e-12)


def test_rcm_closed_forms():
    # N points at distinct heights: the level of ratio k/N is the k-th highest point
    z = np.array([3.0, -1.0, 2.0, 0.5, -2.0]) * 1e-6
    assert material_ratio_height(z, 0.0) == 0.0
    assert material_ratio_height(z, 0.2) == 0.0
    assert material_ratio_height(z, 0.21) == pytest.approx(-1e-6)
    assert material_ratio_height(z, 0.6) == pytest.approx(-2.5e-6)
    assert material_ratio_height(z, 1.0) == pytest.approx(-5e-6)
    # a sine's share above A cos(pi p) is p: Rcm(p) = A (cos(pi p) - 1)
    amp = 1e-6
    s = amp * np.sin(np.linspace(0, 2 * np.pi, 200_001)[:-1])
    for p in (0.1, 0.25, 0.5, 0.9):
        assert material_ratio_height(s, p) == pytest.approx(amp * (np.cos(np.pi * p) - 1),
                                                            abs=1e-4 * amp)
    with pytest.raises(ProfileError, match="between 0 and 1"):
        material_ratio_height(z, 1.5)


def test_open_closed_rules_on_a_sine_with_two_depths():
    # dales alternate between depths A and 2A below a rim at +A: at c = -1.5 A only the
    # deep dales are closed (pit below c, rim above it); at c = +2 A every dale is open
    amp, lam, dx = 1e-6, 100e-6, 0.25e-6
    x = np.arange(round(40 * lam / dx)) * dx
    z = amp * np.cos(2 * np.pi * x / lam)
    # the valley of period k lies inside [k lam, (k + 1) lam]: deepen every other one
    z = np.where((z < 0) & (np.floor(x / lam) % 2 == 0), 2 * z, z)
    dales = segment(z, dx, "D", wolf=None).pit.size
    deep = feature_characterization(z, dx, "D", wolf=None, significant=("closed", -1.5 * amp),
                                    attr="count", statistic="sum")
    assert deep == pytest.approx(round(dales / 2), abs=1)
    assert feature_characterization(z, dx, "D", wolf=None, significant=("open", 2 * amp),
                                    attr="count", statistic="sum") == dales
    assert math.isnan(feature_characterization(z, dx, "D", wolf=None,
                                               significant=("open", 0.0)))
    with pytest.raises(ProfileError, match="significant features"):
        feature_characterization(z, dx, "D", significant=("middle", 1.0))
    with pytest.raises(ProfileError, match="material ratio"):
        feature_characterization(z, dx, "D", significant=("open", "ten"))


def test_profile_output_states_rcm_and_rz_of_the_reference():
    # the reference profiles are R-profiles already: evaluate them as they are
    from surfmet._model import Profile
    from surfmet.records._roughness import roughness_record
    from surfmet.roughness import roughness

    for name in RCM:
        z = _profile(name)
        res = roughness_record(roughness(Profile(z, DX), lc="none",
                                         level="none"))["parameters"]
        for p in (10, 50):
            assert res[f"Rcm({p}%)"]["unit"] == "m"
            assert res[f"Rcm({p}%)"]["value"] * 1e6 == pytest.approx(RCM[name][float(p)],
                                                                     rel=1e-12)
    # the reference's Rz (mean of five sections) of the last one, Luftpresser_1_56_ak, µm
    assert res["Rz"]["value"] * 1e6 == pytest.approx(2.674442617015665, rel=1e-12)
