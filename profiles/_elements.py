"""Profile elements: a profile peak and the adjacent valley (ISO 4287:1997, 3.2.3-3.2.5).

Used by RSm (mean element width Xs) and Rc (mean element height Zt). The profile is cut at
its mean line into runs of constant sign (z >= 0 is the peak side); a run of non-measured
points breaks the chain of elements. A run is significant when its extreme reaches the
height discrimination and its width (between its interpolated mean-line crossings) reaches
the width discrimination (ISO 4287: 10 % of Rz and 1 % of the sampling length, both to be
met); a run cut by the profile end or a gap is judged on what is visible. Insignificant
runs are absorbed by their neighbours, so significant peaks separated only by insignificant
valleys form one peak. An element starts at the up-crossing that opens a significant peak
whose preceding significant run (with no gap between) is a valley, and ends at the next
such up-crossing; its height is the peak height plus the valley depth inside it.

``start="first-crossing"`` pairs the elements from the first mean-line crossing of the
stretch instead: a stretch that begins above the mean line (in a peak cut by its start)
has valley-first elements opening at significant down-crossings, one that begins below has
the peak-first elements above. This is what a Mitutoyo SurfTest does per sampling length:
on its export ``mitutoyo_2_mock.xlsx`` it reproduces the printed RSm 419.9 µm and Rc
13.306 µm to the printed digits, where the peak-first rule gives 416.6 and 13.217
(``benchmarks/mitutoyo_rsm_rules.py``, docs/parameters.md).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from profiles._errors import ProfileError

#: How the elements of a stretch are paired (see the module docstring).
ELEMENT_STARTS = ("peak", "first-crossing")


@dataclass(frozen=True)
class ProfileElements:
    """The complete profile elements of a profile (SI).

    Attributes
    ----------
    widths : ndarray
        Element widths Xs, metres.
    heights : ndarray
        Element heights Zt (highest point minus lowest point of the element), metres.
    """

    widths: np.ndarray
    heights: np.ndarray


def profile_elements(z: np.ndarray, pos: np.ndarray, height: float, width: float,
                     start: str = "peak") -> ProfileElements:
    """The profile elements of ``z`` (heights from the mean line) at positions ``pos``.

    Parameters
    ----------
    z : ndarray
        Heights from the mean line, NaN where not measured.
    pos : ndarray
        Positions of the points, metres.
    height, width : float
        Height and width discrimination, metres (see the module docstring).
    start : {"peak", "first-crossing"}
        Elements open with a peak, or as the stretch's first crossing (module docstring).

    Examples
    --------
    A cosine (λ 100 µm) over 250 µm: up-crossings at 75 and 175 µm close one peak-first
    element, down-crossings at 25, 125 and 225 µm (the first crossing) two valley-first:

    >>> import numpy as np
    >>> x = np.arange(250) * 1e-6
    >>> z = np.cos(2 * np.pi * x / 100e-6)
    >>> for start in ("peak", "first-crossing"):
    ...     e = profile_elements(z, x, 0.1, 1e-6, start=start)
    ...     print(start, [f"{w * 1e6:.1f} µm" for w in e.widths], [f"{h:.3f}" for h in e.heights])
    peak ['100.0 µm'] ['2.000']
    first-crossing ['100.0 µm', '100.0 µm'] ['2.000', '2.000']
    """
    if start not in ELEMENT_STARTS:
        raise ProfileError(f"start must be one of {ELEMENT_STARTS}, got {start!r}")
    n = z.size
    if n < 2:
        return ProfileElements(np.empty(0), np.empty(0))
    finite = z[np.isfinite(z)]
    if start == "first-crossing" and finite.size and finite[0] >= 0:
        z = -z  # valley-first elements are the peak-first ones of the mirrored profile
    valid = np.isfinite(z)
    sign = np.where(valid, np.where(z >= 0, 1, -1), 0)
    change = np.flatnonzero(sign[1:] != sign[:-1]) + 1
    starts = np.concatenate(([0], change))
    ends = np.concatenate((change, [n])) - 1
    s = sign[starts]
    extreme = np.maximum.reduceat(np.where(valid, z * sign, -np.inf), starts)

    prev_sign = np.concatenate(([0], sign[starts[1:] - 1]))
    next_sign = np.concatenate((sign[ends[:-1] + 1], [0]))
    open_start = prev_sign != -s
    open_end = next_sign != -s

    def crossing(i: np.ndarray) -> np.ndarray:
        # mean-line crossing between points i-1 and i (linear interpolation)
        i = np.clip(i, 1, n - 1)
        z0, z1 = z[i - 1], z[i]
        with np.errstate(invalid="ignore", divide="ignore"):
            return pos[i - 1] + (pos[i] - pos[i - 1]) * z0 / (z0 - z1)

    x_start = np.where(open_start, pos[starts], crossing(starts))
    x_end = np.where(open_end, pos[ends], crossing(ends + 1))
    significant = (s != 0) & (extreme >= height) & (x_end - x_start >= width)

    events = np.flatnonzero(significant | (s == 0))
    ev_sign = s[events]
    prev_ev = np.concatenate(([0], ev_sign[:-1]))
    is_up = (ev_sign > 0) & (prev_ev < 0)
    chain = np.cumsum(ev_sign == 0)
    up_run = events[is_up]
    up_x = x_start[up_run]
    same_chain = np.diff(chain[is_up]) == 0
    widths = np.diff(up_x)[same_chain]
    # element k spans the points from the first point of its opening peak run to the last
    # point before the next element's opening peak run
    first = starts[up_run]
    if first.size < 2:
        return ProfileElements(np.empty(0), np.empty(0))
    zf = np.where(valid, z, np.nan)
    top = np.fmax.reduceat(zf, first)[:-1]
    bottom = np.fmin.reduceat(zf, first)[:-1]
    heights = (top - bottom)[same_chain]
    return ProfileElements(widths, heights)
