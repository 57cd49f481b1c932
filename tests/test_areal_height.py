"""Areal height parameters: analytic truths, valid-points-only, and agreement with peers."""

from __future__ import annotations

import math

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.areal import PARAMETER_UNITS, areal_parameters
from surfmet.areal._form import remove_form
from surfmet.areal._height import height_parameters
from surfmet.roughness import roughness

HEIGHT = ("Sa", "Sq", "Sp", "Sv", "Sz", "Ssk", "Sku")


def _sine_grid(n_periods: int, samples_per_period: int, amp: float, ny: int = 8):
    """z = A sin(2πx/λ) sampled with an integer number of periods (no end effects)."""
    nx = n_periods * samples_per_period
    x = (np.arange(nx) + 0.5) / samples_per_period * 2 * np.pi
    z = np.tile(amp * np.sin(x), (ny, 1))
    return Topography(z, 1e-6, 1e-6)


def test_sine_height_parameters_are_the_analytic_values():
    amp = 1.7e-6
    p = height_parameters(_sine_grid(16, 512, amp))
    # Sa = 2A/π, Sq = A/√2, Sp = Sv ≈ A, Ssk = 0, Sku = 3/2 for a sine.
    assert p["Sa"] == pytest.approx(2 * amp / math.pi, rel=1e-5)
    assert p["Sq"] == pytest.approx(amp / math.sqrt(2), rel=1e-9)
    assert p["Sp"] == pytest.approx(amp, rel=1e-4)
    assert p["Sv"] == pytest.approx(amp, rel=1e-4)
    assert p["Sz"] == pytest.approx(2 * amp, rel=1e-4)
    assert abs(p["Ssk"]) < 1e-9
    assert p["Sku"] == pytest.approx(1.5, rel=1e-9)


def test_separable_product_surface_statistics():
    # z = A sin(kx) sin(ky): Sq = A/2, Sa = A (2/π)², Sku = (3/2)² = 9/4, Ssk = 0.
    amp, n = 2e-6, 512
    u = (np.arange(n) + 0.5) / 64 * 2 * np.pi
    z = amp * np.outer(np.sin(u), np.sin(u))
    p = height_parameters(Topography(z, 1e-6, 1e-6))
    assert p["Sq"] == pytest.approx(amp / 2, rel=1e-9)
    assert p["Sa"] == pytest.approx(amp * (2 / math.pi) ** 2, rel=1.5e-3)  # 64 samples/period
    assert p["Sku"] == pytest.approx(9 / 4, rel=1e-9)
    assert abs(p["Ssk"]) < 1e-9


def test_skewed_surface_sign_and_value():
    # A sum of a positive exponential distribution: Ssk of Exp(1) = 2, Sku = 9.
    rng = np.random.default_rng(3)
    z = rng.exponential(1e-6, size=(600, 600))
    p = height_parameters(Topography(z, 1e-6, 1e-6))
    assert p["Ssk"] == pytest.approx(2.0, abs=0.05)
    assert p["Sku"] == pytest.approx(9.0, abs=0.5)
    assert p["Sv"] < p["Sp"]


def test_nan_points_are_ignored_not_zero_filled():
    rng = np.random.default_rng(7)
    z = rng.normal(5e-6, 1e-6, size=(300, 400))
    hole = rng.random(z.shape) < 0.4
    z[hole] = np.nan
    p = height_parameters(Topography(z, 1e-6, 1e-6))
    v = z[~hole]
    d = v - v.mean()
    assert p["Sq"] == pytest.approx(np.sqrt(np.mean(d**2)), rel=1e-12)
    assert p["Sa"] == pytest.approx(np.mean(np.abs(d)), rel=1e-12)
    assert p["Sp"] == pytest.approx(d.max(), rel=1e-12)
    # a zero-filled computation would be far off: guard that the test can fail
    zero = np.nan_to_num(z)
    assert abs(np.std(zero) - p["Sq"]) > 0.5 * p["Sq"]


def test_all_nan_and_profiles_are_refused():
    with pytest.raises(SurfmetInputError):
        areal_parameters(Topography(np.full((4, 4), np.nan), 1e-6, 1e-6))
    with pytest.raises(SurfmetInputError):
        areal_parameters(surfmet.Profile(np.zeros(10), 1e-6))
    with pytest.raises(SurfmetInputError):
        areal_parameters(Topography(np.zeros((4, 4)), 1e-6, 1e-6), which=["Ra"])


def test_units_table_covers_every_parameter():
    p = areal_parameters(_sine_grid(4, 64, 1e-6, ny=64))
    assert set(p.as_dict()) == set(PARAMETER_UNITS)
    assert PARAMETER_UNITS["Sa"] == "m" and PARAMETER_UNITS["Ssk"] == ""
    assert PARAMETER_UNITS["Spd"] == "1/m^2" and PARAMETER_UNITS["Sdr"] == "%"


# --- real files -------------------------------------------------------------------------
# Peer values: scratch script run in a separate virtualenv (surfalize 0.19.2,
# SurfaceTopography 1.27.1), each peer with its own reader and its own plane levelling:
#   surfalize: Surface.load(path).level().height_parameters()   (µm -> m)
#   SurfaceTopography: read_topography(path).detrend("height"); Sq = rms_height_from_area(),
#     the other parameters from its levelled heights() (valid points) with numpy.
# Listed only where the two peers agree (relative difference < 1e-8 on every value).
PEERS_AGREE = {
    "x3p-2.x3p": {
        "Sa": 6.189305824615689e-08, "Sq": 7.719303278901976e-08,
        "Sp": 2.3618629815366246e-07, "Sv": 3.1591574827377833e-07,
        "Sz": 5.521020464274408e-07, "Ssk": -0.3786736066846185, "Sku": 2.9845966454775894,
    },
    "al3d-1.al3d": {
        "Sa": 2.3019610806740892e-07, "Sq": 2.8982210278363125e-07,
        "Sp": 1.0762221670630267e-06, "Sv": 1.0100936253922819e-06,
        "Sz": 2.0863157924553085e-06, "Ssk": -0.00497652536205389, "Sku": 3.0712779006199846,
    },
    "sdf-1.sdf": {
        "Sa": 7.901492346938763e-09, "Sq": 1.0289929442289474e-08,
        "Sp": 2.259151785714283e-08, "Sv": 1.9605892857142913e-08,
        "Sz": 4.219741071428574e-08, "Ssk": 0.1687845022053223, "Sku": 2.8224582097899416,
    },
}

# nms-1.nms: both peers agree with each other but both scale the uint16 heights by
# 1/(2**16 - 2) (surfalize file/nms.py, ST IO/NMS.py), while surfmet's reader uses the
# header's n_high - n_low = 65535 (see surfmet/io/nms.py). The scale-free Ssk and Sku must
# agree exactly; the lengths differ by exactly 65534/65535.
NMS_PEERS = {
    "Sa": 1.2178629052334995e-08, "Sq": 3.3514914588842295e-08,
    "Sp": 2.0080217539079308e-07, "Sv": 5.236154699885039e-07,
    "Sz": 7.24417645379297e-07, "Ssk": -6.825454053159783, "Sku": 57.39868245123046,
}

# SurfaceTopography 1.27.1 only (same calls). surfalize 0.19.2 disagrees on these and is
# wrong: metropro-1.dat heights 8x too large (phase_res mapping, see MANIFEST); plu-1.plu
# its first two samples are denormal floats (8.1e-43, 1.1e-42 µm) where every other height
# is near -101 µm, i.e. a misaligned data offset, which after levelling become 111 µm
# "peaks" (its Sp = 111 µm, Ssk = 51). surfmet and ST agree on both.
ST_ONLY = {
    "plu-1.plu": {
        "Sa": 1.4629038377732818e-08, "Sq": 1.8281955834246168e-08,
        "Sp": 5.99009192688966e-08, "Sv": 5.150064789723497e-07,
        "Sz": 5.749073982412464e-07, "Ssk": -0.44260348311471137, "Sku": 9.244893875940685,
    },
    "metropro-1.dat": {
        "Sa": 1.1105694830941955e-08, "Sq": 1.3334981370330638e-08,
        "Sp": 6.296457445800204e-07, "Sv": 7.337594126792614e-07,
        "Sz": 1.3634051572592818e-06, "Ssk": -1.1467676181341664, "Sku": 52.44229701288252,
    },
}

# Non-measured points: surfalize refuses them ("Non-measured points must be filled");
# ST 1.27.1 uses valid points only (its Sq for sur-3 = 0.0011132 m unlevelled per the
# MANIFEST; these are after its plane levelling).
ST_VALID_ONLY = {
    "frt-2.frt": {
        "Sa": 1.0794543419470356e-06, "Sq": 8.716550224820226e-06,
        "Sp": 0.0002339597217529451, "Sv": 7.470175736057718e-05,
        "Sz": 0.0003086614791135223, "Ssk": 9.481918951786824, "Sku": 361.3254473391694,
    },
    "sur-3.sur": {
        "Sa": 0.0007417064931243926, "Sq": 0.001110975818106111,
        "Sp": 0.0009919428463628214, "Sv": 0.006081519627453587,
        "Sz": 0.007073462473816409, "Ssk": -2.4391043395145138, "Sku": 9.728952317377423,
    },
    "KautschukInfiniteFocus.x3p": {
        "Sa": 2.704509419972168e-06, "Sq": 3.3983799880303697e-06,
        "Sp": 1.604039360861232e-05, "Sv": 9.548322605334452e-06,
        "Sz": 2.558871621394677e-05, "Ssk": 0.7361674854180001, "Sku": 3.685634726388556,
    },
}


def _check(values, expected, rel=1e-6):
    for sym in HEIGHT:
        assert values[sym] == pytest.approx(expected[sym], rel=rel), sym


@pytest.mark.realdata
@pytest.mark.parametrize("name", sorted(PEERS_AGREE))
def test_equals_surfalize_and_surfacetopography(realdata, name):
    res = roughness(realdata(name), level="plane", which="height")
    _check({k: v for k, (v, _) in res.parameters.items()}, PEERS_AGREE[name])


@pytest.mark.realdata
def test_nms_agrees_with_peers_up_to_their_65534_scale(realdata):
    res = roughness(realdata("nms-1.nms"), level="plane", which="height")
    got = {k: v for k, (v, _) in res.parameters.items()}
    expected = {k: (v * 65534 / 65535 if k not in ("Ssk", "Sku") else v)
                for k, v in NMS_PEERS.items()}
    _check(got, expected)


@pytest.mark.realdata
@pytest.mark.parametrize("name", sorted(ST_ONLY))
def test_equals_surfacetopography_where_surfalize_misreads(realdata, name):
    res = roughness(realdata(name), level="plane", which="height")
    _check({k: v for k, (v, _) in res.parameters.items()}, ST_ONLY[name])


@pytest.mark.realdata
@pytest.mark.parametrize("name, nan_fraction", [("frt-2.frt", 0.274), ("sur-3.sur", 0.889),
                                                ("KautschukInfiniteFocus.x3p", 0.0097)])
def test_non_measured_points_valid_only(realdata, name, nan_fraction):
    topo = surfmet.read(realdata(name))
    assert topo.nan_fraction == pytest.approx(nan_fraction, abs=0.002)
    levelled, _ = remove_form(topo, "plane")
    got = height_parameters(levelled)
    # 1. a peer that uses valid points only
    _check(got, ST_VALID_ONLY[name])
    # 2. a manual numpy computation: plane by lstsq on valid points, statistics on them
    z = topo.heights
    jj, ii = np.nonzero(np.isfinite(z))
    a = np.column_stack([np.ones(ii.size), ii * topo.dx, jj * topo.dy])
    coef, *_ = np.linalg.lstsq(a, z[jj, ii], rcond=None)
    d = z[jj, ii] - a @ coef
    d = d - d.mean()
    sq = np.sqrt(np.mean(d**2))
    manual = {"Sa": np.mean(np.abs(d)), "Sq": sq, "Sp": d.max(), "Sv": -d.min(),
              "Sz": d.max() - d.min(), "Ssk": np.mean(d**3) / sq**3,
              "Sku": np.mean(d**4) / sq**4}
    _check(got, manual, rel=1e-7)
