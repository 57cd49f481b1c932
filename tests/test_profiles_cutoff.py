"""ISO 4288 automatic cut-off: tabulated λc for profiles of known Ra / RSm."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.ndimage import gaussian_filter1d

from profiles import ProfileError, iso4288_cutoff
from profiles._cutoff import LS_FOR_LC, table_cutoff


def _random_profile(ra: float, length: float, dx: float, seed: int, corr: float = 1.5e-6):
    """Random profile with little power beyond ~20 µm wavelength (Ra hardly depends on λc).

    Differenced white noise (spectrum ~ k^2 at long wavelengths), Gaussian-smoothed.
    """
    rng = np.random.default_rng(seed)
    z = gaussian_filter1d(np.diff(rng.normal(size=int(length / dx) + 1)), corr / dx)
    z -= z.mean()
    return z * ra / np.mean(np.abs(z))


# ISO 4288 Table 1 (Ra, non-periodic): value in the middle of each row -> λc
RA_ROWS = [(0.012e-6, 0.08e-3), (0.045e-6, 0.25e-3), (0.45e-6, 0.8e-3), (4.5e-6, 2.5e-3)]


@pytest.mark.parametrize(("ra", "lc"), RA_ROWS)
def test_non_periodic_profile_gets_tabulated_cutoff(ra, lc):
    rng = np.random.default_rng(int(ra * 1e9))
    ra_true = ra * rng.uniform(0.8, 1.25)
    dx = 0.5e-6
    z = _random_profile(ra_true, 6e-3, dx, seed=int(ra * 1e10))
    if lc <= 0.8e-3:
        # hidden waviness far beyond the cut-off: the procedure must filter it away
        x = np.arange(z.size) * dx
        z = z + rng.uniform(2, 5) * ra * np.sin(2 * np.pi * x / 5e-3 + rng.uniform(0, 6))
    choice = iso4288_cutoff(z, dx)
    assert choice.lc == pytest.approx(lc)
    assert not choice.periodic
    assert choice.parameter == "Ra"
    assert choice.value == pytest.approx(ra_true, rel=0.1)
    assert choice.evaluation_length == pytest.approx(5 * lc)
    assert choice.ls == LS_FOR_LC[choice.lc]
    assert float(choice) == choice.lc


@pytest.mark.parametrize(("rsm", "lc"), [(0.025e-3, 0.08e-3), (0.1e-3, 0.25e-3), (0.3e-3, 0.8e-3)])
def test_periodic_profile_uses_rsm_table(rsm, lc):
    rng = np.random.default_rng(int(rsm * 1e7))
    dx = 0.5e-6
    x = np.arange(int(8e-3 / dx)) * dx
    amp = rng.uniform(0.2, 2) * 1e-6
    z = amp * np.sin(2 * np.pi * x / rsm + rng.uniform(0, 6))
    z += rng.normal(0, 0.1 * amp, x.size)  # hidden noise
    choice = iso4288_cutoff(z, dx)
    assert choice.periodic
    assert choice.parameter == "Rsm"
    assert choice.value == pytest.approx(rsm, rel=0.02)
    assert choice.lc == pytest.approx(lc)


def test_table_boundaries_and_outside_values():
    assert table_cutoff("Ra", 0.1e-6)[0] == 1  # (0.02, 0.1] µm -> 0.25 mm
    assert table_cutoff("Ra", 0.1001e-6)[0] == 2  # (0.1, 2] µm -> 0.8 mm
    assert table_cutoff("Rz", 0.5e-6)[0] == 1
    assert table_cutoff("Rz", 0.6e-6)[0] == 2
    k, note = table_cutoff("Ra", 0.003e-6)
    assert k == 0 and "below" in note
    k, note = table_cutoff("Ra", 100e-6)
    assert k == 4 and "above" in note


def test_rz_table_can_be_chosen():
    z = _random_profile(0.45e-6, 6e-3, 0.5e-6, seed=3)
    choice = iso4288_cutoff(z, 0.5e-6, parameter="Rz", periodic=False)
    assert choice.parameter == "Rz"
    assert 0.5e-6 < choice.value <= 10e-6
    assert choice.lc == pytest.approx(0.8e-3)


def test_cutoff_errors():
    with pytest.raises(ProfileError, match="all heights are NaN"):
        iso4288_cutoff(np.full(1000, np.nan), 1e-6)
    with pytest.raises(ProfileError, match="at least 8"):
        iso4288_cutoff(np.arange(5.0), 1e-6)
    with pytest.raises(ProfileError, match="parameter"):
        iso4288_cutoff(np.random.default_rng(0).normal(size=1000), 1e-6, parameter="Rk")


def test_coarse_sampling_cannot_realise_short_cutoff_and_says_so():
    # 50 µm step (the paper's ball scan): 0.08 mm is under 4 samples, 0.25 mm is the
    # shortest realisable cut-off; a very smooth profile would ask ISO 4288 for 0.08 mm
    rng = np.random.default_rng(9)
    z = rng.normal(size=300) * rng.uniform(1, 3) * 1e-9
    choice = iso4288_cutoff(z, 50e-6)
    assert choice.lc == pytest.approx(0.25e-3)
    assert "not ISO 4288 conformant" in choice.note
    # a rough one is unaffected
    rough = iso4288_cutoff(z * 300, 50e-6)
    assert rough.lc == pytest.approx(0.8e-3) and "conformant" not in rough.note
