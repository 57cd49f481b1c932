"""The plate-wave fits start from a fixed grid of periods (issue 17): the start set is the
periodogram's peak plus periods evenly spaced in frequency, and the paper's Table 3 gives the
same selections however often, and in whatever order, its columns are analysed."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rotor._adequacy import WaveScan
from rotor._analysis import analyse_test
from rotor._extension import GRID_STARTS, start_indices
from rotor._frames import table3
from rotor._paper import TABLE3_COLUMNS


def _scan(periods, share):
    n = len(periods)
    return WaveScan(periods=np.asarray(periods, float), share=np.asarray(share, float),
                    amplitude=np.ones(n), phase=np.zeros(n), span=40.0, n=25, p=3)


def test_start_grid_is_even_in_frequency_and_holds_the_peak():
    freq = np.linspace(1 / 20.0, 1 / 2.0, 31)
    share = np.exp(-((np.arange(31) - 17.0) / 3.0) ** 2)  # one peak, at index 17
    peak, grid = start_indices(_scan(1 / freq, share))
    assert peak == [17]
    assert len(grid) + (17 in np.linspace(0, 30, GRID_STARTS).round()) == GRID_STARTS
    assert 17 not in grid and len(set(grid)) == len(grid)
    f = freq[grid]
    # evenly spaced in frequency from the first period to the last, within one scan step
    assert f[0] == freq[0] and f[-1] == freq[-1]
    assert np.allclose(np.diff(f), (freq[-1] - freq[0]) / (GRID_STARTS - 1),
                       atol=freq[1] - freq[0])
    # the grid does not depend on the share: only the peak does
    assert start_indices(_scan(1 / freq, share[::-1]))[1] == [
        j for j in np.linspace(0, 30, GRID_STARTS).round().astype(int) if j != 13]


def _summary(rep):
    return (rep.selected, rep.outliers, rep.adequacy.adequate,
            None if rep.smooth is None else rep.smooth.modes,
            {m: round(f.bic, 6) for m, f in rep.fits.items()})


@pytest.mark.campaign
def test_table3_selections_are_reproducible():
    # the forward model keeps caches (grid layout, speed-term buffers) between calls: a
    # second pass, in the reverse order, must give the same selections and the same BICs
    t = table3()
    first = {c: _summary(analyse_test(c, t[c])) for c in TABLE3_COLUMNS}
    again = {c: _summary(analyse_test(c, t[c])) for c in reversed(TABLE3_COLUMNS)}
    assert first == again
    assert not math.isnan(sum(b for s in first.values() for b in s[4].values()))
