"""A scan's spectrum: Hurst exponent, cut-offs, rms values and Greenwood-Williamson summits.

The isotropic PSD comes from :func:`surfmet.psd.areal_psd` (Jacobs, Junge & Pastewka 2017,
Surf. Topogr.: Metrol. Prop. 5, 013001). A periodic scan (its opposite edges match, or the
user says so) is transformed as it is; any other scan is Hann-windowed, as ``surfmet.psd``
does, so that the edge jump does not leak a ``q⁻²`` tail into the spectrum.

Cut-offs. The binned log-PSD is fitted by a continuous piecewise-linear curve with two
knots, ``log q_r`` (roll-off) and ``log q_s`` (short-wavelength cut-off), chosen by least
squares over all pairs of bin edges. A knot counts as a cut-off only where the slope changes
by more than 1 (a self-affine slope is -2-2H ≤ -2, a plateau is 0); wavevectors that carry
no power at all (below 1e-12 of the peak) end the spectrum and mark the short cut-off
(:mod:`surfmet.mechanics._spectrum_cutoffs`, with the noise floor).
The Hurst exponent is then fitted by :func:`surfmet.psd.fit_hurst` between the cut-offs.

Moments. ``m0, m2, m4`` of the profiles (Nayak 1971) come from the radial PSD with the
DFT-cell weights, so they reproduce the discrete Parseval sums; h_rms = √m0,
h'_rms = √(2 m2), rms Laplacian = √(8 m4/3). The real-space values use finite differences
(central, periodic where the scan is). Summit parameters follow Nayak (1971) and McCool
(1986) via :func:`contact.roughcontact.summit_parameters`.

Resolution. h_rms is set by the long wavelengths and hardly changes with the pixel size; for
a self-affine surface h'_rms ∝ q_s^(1-H) and the curvature ∝ q_s^(2-H) grow without bound as
the pixel shrinks, and so do α, the summit density and 1/R_s. :data:`RESOLUTION_DEPENDENT`
lists them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from contact.roughcontact import (
    SummitParameters,
    isotropic_moments,
    plasticity_index,
    summit_parameters,
)
from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.mechanics._spectrum_cutoffs import cutoffs, noise_floor
from surfmet.psd import PSD, HurstFit, areal_psd, fit_hurst

if TYPE_CHECKING:
    from contact._material_pair import MaterialPair
    from surfmet.mechanics._types import Materials, ScanSource, Spikes
    from surfmet.mechanics.scan_preparation import FlatPreparation

#: Values that change with the scan's lateral resolution (pixel size / short cut-off).
RESOLUTION_DEPENDENT = ("slope_rms", "curvature_rms", "nayak_alpha", "summit_density",
                        "summit_radius", "summit_sigma", "plasticity_index")

#: A Hurst exponent fitted over fewer decades of wavevector than this is not a measured
#: self-affine range (a power law needs at least a decade to be told from a bend).
MIN_HURST_DECADES = 1.0
#: Largest relative difference between the spectral and the real-space h_rms before the
#: spectrum is said not to represent the scan's heights (the spectral moments and summit
#: values then rest on a window or a form, not on the surface).
H_RMS_TOLERANCE = 0.25


@dataclass(frozen=True, eq=False)
class Spectrum:
    """Spectral description of an areal scan (SI units).

    Attributes
    ----------
    psd : PSD
        Isotropic PSD ``C^iso(q)``, m⁴.
    periodic : bool
        Whether the scan was taken as periodic (unwindowed).
    hurst : HurstFit
        Power law fitted between the cut-offs (``q_range`` in rad/m).
    roll_off, short_cutoff : float or None
        Cut-off wavevectors (rad/m), None where the spectrum shows none.
    noise_floor : float or None
        Wavevector (rad/m) from which the spectrum turns flat (an instrument's noise floor,
        :func:`surfmet.mechanics._spectrum_cutoffs.noise_floor`); the power law is fitted
        below it. None where there is none.
    h_rms, slope_rms, curvature_rms : float
        From the spectrum (m, -, 1/m).
    h_rms_real, slope_rms_real, curvature_rms_real : float
        From real space (finite differences).
    summits : SummitParameters
        Nayak/McCool summit statistics (α, η, R_s, σ_s).
    plasticity : float or None
        ψ = (E*/H) √(σ_s/R_s) when E* and the hardness were given.
    materials : MaterialPair or None
        The resolved pair the plasticity index used, when materials were given.

    See Also
    --------
    spectrum : makes it.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.spectrum import spectrum
    >>> spec = spectrum(surfmet.read(path("paper_plate.x3p")))
    >>> print(f"h_rms = {spec.h_rms * 1e6:.2f} µm, slope_rms = {spec.slope_rms:.2f}")
    h_rms = 2.44 µm, slope_rms = 0.61
    """

    psd: PSD
    periodic: bool
    hurst: HurstFit
    roll_off: float | None
    short_cutoff: float | None
    h_rms: float
    slope_rms: float
    curvature_rms: float
    h_rms_real: float
    slope_rms_real: float
    curvature_rms_real: float
    summits: SummitParameters
    plasticity: float | None = None
    settings: dict[str, Any] = field(default_factory=dict)
    noise_floor: float | None = None
    materials: MaterialPair | None = None


def is_periodic(topo: Topography, tol: float = 0.1) -> bool:
    """Whether the scan's opposite edges match (a periodic scan).

    Along each axis, the rms jump across the wrapped edge (last row to first) must not
    exceed ``1 + tol`` times the largest rms jump between neighbouring interior rows: a
    periodic surface wraps as smoothly as it runs anywhere inside, whereas a cropped one
    jumps by about √2 h_rms, far above its interior steps unless it is white noise.

    Parameters
    ----------
    topo : Topography
        The scan.
    tol : float
        Largest edge mismatch, as a fraction of the scan's height range.

    Returns
    -------
    bool
        True when both pairs of opposite edges match within ``tol``.

    See Also
    --------
    spectrum : uses it to choose the window.

    Examples
    --------
    The bundled plate is a periodic synthetic surface; a tilted plane is not periodic:

    >>> import numpy as np
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.spectrum import is_periodic
    >>> is_periodic(surfmet.read(path("paper_plate.x3p")))
    True
    >>> ramp = surfmet.Topography(np.tile(np.arange(32) * 1e-7, (32, 1)), 1e-6, 1e-6)
    >>> is_periodic(ramp)
    False
    """
    z = np.asarray(topo.heights, dtype=float)
    if not np.all(np.isfinite(z)) or min(z.shape) < 4:
        return False
    for ax in (0, 1):
        rows = np.sqrt(np.mean(np.diff(z, axis=ax) ** 2, axis=1 - ax))
        wrap = np.sqrt(np.mean((np.take(z, 0, axis=ax) - np.take(z, -1, axis=ax)) ** 2))
        if not rows.max() > 0 or wrap > (1.0 + tol) * rows.max():
            return False
    return True


def _real_space(z: np.ndarray, dx: float, dy: float, periodic: bool
                ) -> tuple[float, float, float]:
    z = z - np.nanmean(z)
    h = float(np.sqrt(np.nanmean(z**2)))
    if periodic:
        gx = (np.roll(z, -1, 1) - np.roll(z, 1, 1)) / (2 * dx)
        gy = (np.roll(z, -1, 0) - np.roll(z, 1, 0)) / (2 * dy)
        lap = ((np.roll(z, -1, 1) - 2 * z + np.roll(z, 1, 1)) / dx**2
               + (np.roll(z, -1, 0) - 2 * z + np.roll(z, 1, 0)) / dy**2)
    else:
        gx = (z[1:-1, 2:] - z[1:-1, :-2]) / (2 * dx)
        gy = (z[2:, 1:-1] - z[:-2, 1:-1]) / (2 * dy)
        c = z[1:-1, 1:-1]
        lap = ((z[1:-1, 2:] - 2 * c + z[1:-1, :-2]) / dx**2
               + (z[2:, 1:-1] - 2 * c + z[:-2, 1:-1]) / dy**2)
    slope = float(np.sqrt(np.nanmean(gx**2 + gy**2)))
    curv = float(np.sqrt(np.nanmean(lap**2)))
    return h, slope, curv


def spectrum(topo: Topography, *, periodic: bool | None = None, e_star: float | None = None,
             hardness: float | None = None, materials: Materials | None = None) -> Spectrum:
    """Describe a scan's spectrum (see the module docstring).

    Parameters
    ----------
    topo : Topography
        Levelled heights, m.
    periodic : bool, optional
        None detects periodicity from the edges (:func:`is_periodic`).
    e_star, hardness : float, optional
        Composite modulus and the softer body's hardness (Pa) for the plasticity index.
    materials : str or MaterialPair, optional
        ``"A"`` (the scan on a rigid flat) or ``"A,B"``, or a resolved pair, instead of
        ``e_star``: E* and the default hardness come from the pair
        (:func:`surfmet.mechanics.material_spec.scan_pair`; ``hardness`` overrides it), and
        the pair is kept in :attr:`Spectrum.materials`.

    Returns
    -------
    Spectrum
        The isotropic PSD, the Hurst fit, the rms height, slope and curvature (spectral and
        real-space), the Greenwood-Williamson summit parameters and, with materials, the
        plasticity index.

    Raises
    ------
    SurfmetInputError
        Not an areal scan, too small, or a spectrum without a power-law band.

    See Also
    --------
    scan_spectrum : the same from a file, with the shared preparation.
    surfmet.psd : the power spectral density itself.

    References
    ----------
    .. [1] B. N. J. Persson, O. Albohr, U. Tartaglino, A. I. Volokitin, E. Tosatti, "On the
       nature of surface roughness with application to contact mechanics, sealing, rubber
       friction and adhesion", J. Phys.: Condens. Matter 17 (2005) R1-R62.
    .. [2] P. R. Nayak, "Random process model of rough surfaces", J. Lubr. Technol. 93
       (1971) 398-407 (spectral moments).
    .. [3] J. A. Greenwood, J. B. P. Williamson, "Contact of nominally flat surfaces",
       Proc. R. Soc. Lond. A 295 (1966) 300-319 (plasticity index).

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.spectrum import spectrum
    >>> spec = spectrum(surfmet.read(path("paper_plate.x3p")), materials="steel,aluminium")
    >>> print(f"H = {spec.hurst.hurst:.2f}, h_rms = {spec.h_rms * 1e6:.2f} µm, "
    ...       f"plasticity index = {spec.plasticity:.0f}")
    H = 0.91, h_rms = 2.44 µm, plasticity index = 42
    """
    if not isinstance(topo, Topography):
        raise SurfmetInputError(f"spectrum needs an areal scan, got {type(topo).__name__}")
    pair = None
    if materials is not None:
        from surfmet.mechanics.material_spec import scan_pair

        pair = scan_pair(materials, e_star=e_star, hardness=hardness)
        e_star, hardness = pair.e_star, pair.hardness
    if topo.nx < 16 or topo.ny < 16:
        raise SurfmetInputError(f"a spectrum needs at least 16 x 16 points, got "
                                f"{topo.nx} x {topo.ny}")
    if not np.nanmax(topo.heights) > np.nanmin(topo.heights):
        raise SurfmetInputError("the scan is flat (constant heights): it has no spectrum")
    detected = is_periodic(topo)
    per = detected if periodic is None else bool(periodic)
    if per and topo.nan_fraction > 0:
        raise SurfmetInputError("a scan with unmeasured points cannot be taken as periodic; "
                                "use --periodic no")
    spec = areal_psd(topo, window="none" if per else "hann").radial()
    # A Hann window's main lobe spans ±2Δq and flattens the first wavevectors like a
    # roll-off would: a windowed scan resolves no roll-off below 6Δq (a tested margin).
    roll, short, band = cutoffs(spec, 0.0 if per else 6.0 * spec.dq)
    floor = noise_floor(spec, band)
    if floor is not None:
        band = (band[0], floor)
    # keep a margin of one bin off each knot: the transition bends the spectrum there
    lo = max(band[0] * 10**0.1, spec.q[0] if per else 8.0 * spec.dq)
    hi = min(band[1] * 10**-0.1, float(spec.q.max()) if per or short else
             0.5 * float(spec.q.max()))
    if floor is not None:
        # the floor adds to the power law, it does not replace it: at its onset the noise
        # is as strong as the surface; 0.3 decades below, the surface is 4-12 times stronger
        # (0 < H < 1)
        hi = min(hi, floor * 10**-0.3)
    hfit = None
    whole = (float(spec.q[0]), min(short or math.inf, floor or math.inf, float(spec.q.max())))
    for rng in ((lo, hi), band, whole):
        try:
            hfit = fit_hurst(spec, rng)
            break
        except SurfmetInputError:
            continue
    if hfit is None:
        raise SurfmetInputError(
            "the spectrum shows no power-law band between its cut-offs "
            f"({band[0]:.4g}..{band[1]:.4g} rad/m) to fit a Hurst exponent on"
        )
    m0, m2, m4 = isotropic_moments(spec.q, spec.C, spec.weights, spec.dq)
    try:
        summits = summit_parameters(m0, m2, m4)
    except Exception as exc:  # ContactInputError: the spectrum is not Gaussian-like
        raise SurfmetInputError(f"no summit statistics for this scan: {exc}") from None
    h_r, s_r, c_r = _real_space(np.asarray(topo.heights, float), topo.dx, topo.dy, per)
    psi = None
    if e_star is not None and hardness is not None:
        psi = plasticity_index(e_star, hardness, summits)
    from surfmet.roughness import unit_caveats

    settings = {"window": spec.settings.get("window"), "periodic_detected": detected,
                "dx": topo.dx, "dy": topo.dy, "nx": topo.nx, "ny": topo.ny,
                "caveats": [*unit_caveats(topo),
                            *spectrum_caveats(hfit, summits.h_rms, h_r)]}
    return Spectrum(psd=spec, periodic=per, hurst=hfit, roll_off=roll, short_cutoff=short,
                    h_rms=summits.h_rms, slope_rms=summits.slope_rms,
                    curvature_rms=summits.curvature_rms, h_rms_real=h_r, slope_rms_real=s_r,
                    curvature_rms_real=c_r, summits=summits, plasticity=psi,
                    settings=settings, noise_floor=floor, materials=pair)


def prepared_scan(topo: ScanSource, *, periodic: bool | None = None, spikes: Spikes | None = None
                  ) -> tuple[Topography, bool, str, FlatPreparation]:
    """The shared scan preparation for a spectrum or a flat contact: spikes removed (by
    default) and non-measured points filled as every contact command does
    (:func:`surfmet.mechanics.scan_preparation.prepare_flat`), then levelled
    (:func:`prepare`). Returns (scan, periodic, levelling, preparation record).

    Parameters
    ----------
    topo : Topography or path
        The scan.
    periodic : bool, optional
        Force periodic (True) or windowed (False); default detected (:func:`is_periodic`).
    spikes : {"remove", "keep"} or bool, optional
        Spike handling (default remove).

    Returns
    -------
    (Topography, bool, str, FlatPreparation)
        The prepared scan, whether it is treated as periodic, the levelling and the
        preparation record.

    See Also
    --------
    prepare : the levelling step.

    Examples
    --------
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.spectrum import prepared_scan
    >>> scan, periodic, levelling, record = prepared_scan(path("paper_plate.x3p"))
    >>> scan.shape, periodic, levelling
    ((512, 1024), True, 'mean')
    """
    from surfmet.mechanics.scan_preparation import SPIKES, prepare_flat

    scan, record = prepare_flat(topo, spikes=SPIKES if spikes is None else spikes)
    out, per, level = prepare(scan, periodic)
    return out, per, level, replace(record, levelling=level)


def scan_spectrum(topo: ScanSource, *, periodic: bool | None = None, spikes: Spikes | None = None,
                  materials: Materials | None = None, hardness: float | None = None
                  ) -> tuple[Spectrum, str, FlatPreparation]:
    """The spectrum of one scan exactly as ``surfmet spectrum FILE`` gives it: the shared
    preparation (:func:`prepared_scan`) on the scan as read, then :func:`spectrum`.

    Every entry point that shows a scan's spectrum (the command, the report) calls this,
    so that one file has one Hurst exponent, one window and one levelling.

    Returns
    -------
    (Spectrum, str, FlatPreparation)
        The spectrum, the levelling used and the scan-preparation record.

    See Also
    --------
    spectrum, prepared_scan

    Examples
    --------
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.spectrum import scan_spectrum
    >>> spec, levelling, record = scan_spectrum(path("paper_plate.x3p"))
    >>> print(levelling, record.spikes_removed, f"h_rms = {spec.h_rms * 1e6:.2f} µm")
    mean {'scan': 60} h_rms = 2.30 µm
    """
    scan, per, level, preparation = prepared_scan(topo, periodic=periodic, spikes=spikes)
    s = spectrum(scan, periodic=per, materials=materials, hardness=hardness)
    return s, level, preparation


def prepare(topo: Topography, periodic: bool | None = None) -> tuple[Topography, bool, str]:
    """Level a scan for spectral or contact analysis: (scan, periodic, levelling).

    A periodic scan (detected on the raw heights, or declared) only loses its mean, since a
    fitted plane would break its periodicity; any other scan loses its least-squares plane,
    or its second-order surface when a curved form dominates what the plane leaves
    (:func:`surfmet.areal._form.dominant_form`: a ball's cap is form, not roughness; the
    levelling is then ``"poly:2"``).

    Parameters
    ----------
    topo : Topography
        The scan.
    periodic : bool, optional
        As for :func:`prepared_scan`.

    Returns
    -------
    (Topography, bool, str)
        The levelled scan, periodic or not, and the levelling (``"mean"`` for a periodic
        scan, ``"plane"`` otherwise).

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.spectrum import prepare
    >>> scan, periodic, levelling = prepare(surfmet.read(path("paper_plate.x3p")))
    >>> periodic, levelling
    (True, 'mean')
    """
    if not isinstance(topo, Topography):
        raise SurfmetInputError(f"an areal scan is needed, got "
                                f"{getattr(topo, 'kind', type(topo).__name__)}")
    per = is_periodic(topo) if periodic is None else bool(periodic)
    if per:
        z = np.asarray(topo.heights, float)
        out, how = Topography(z - np.nanmean(z), topo.dx, topo.dy, topo.metadata), "mean"
    else:
        from surfmet.areal._form import dominant_form, remove_form

        out, fit = remove_form(topo, "plane")
        how = "plane"
        if dominant_form(topo, fit):
            out, how = remove_form(topo, "poly:2")[0], "poly:2"
    # what levelling leaves of constant or planar heights is rounding: the one criterion
    from profiles._form import is_flat

    if is_flat(topo.heights, out.heights):
        raise SurfmetInputError(f"the scan is flat (constant heights{'' if per else ' or a plane'}"
                                "): it has no roughness")
    return out, per, how


def spectrum_caveats(hfit: HurstFit, h_rms: float, h_rms_real: float) -> list[str]:
    """What makes a spectrum's numbers doubtful: a Hurst exponent fitted over less than
    :data:`MIN_HURST_DECADES`, or a spectral h_rms more than :data:`H_RMS_TOLERANCE` away
    from the real-space one.

    Parameters
    ----------
    hfit : HurstFit
        The Hurst exponent fit.
    h_rms, h_rms_real : float
        The spectral and the real-space rms heights (m).

    Returns
    -------
    list of str
        One sentence per caveat; empty when there is none.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.spectrum import spectrum, spectrum_caveats
    >>> spec = spectrum(surfmet.read(path("paper_plate.x3p")))
    >>> print(spectrum_caveats(spec.hurst, spec.h_rms, spec.h_rms_real)[0])
    the Hurst exponent H = 0.912 is fitted over 0.44 decades of wavevector only ...
    """
    from surfmet.units import format_length

    out = []
    lo, hi = hfit.q_range
    decades = math.log10(hi / lo) if lo > 0 and hi > lo else 0.0
    if decades < MIN_HURST_DECADES:
        out.append(f"the Hurst exponent H = {hfit.hurst:.3g} is fitted over {decades:.2g} "
                   f"decades of wavevector only (q = {lo:.4g}..{hi:.4g} rad/m; at least "
                   f"{MIN_HURST_DECADES:g} needed to tell a power law from a bend): it is not "
                   "a measured self-affine exponent")
    if h_rms_real > 0 and abs(h_rms / h_rms_real - 1.0) > H_RMS_TOLERANCE:
        out.append(f"h_rms from the spectrum ({format_length(h_rms)}) is "
                   f"{h_rms / h_rms_real:.2g} x the real-space value "
                   f"({format_length(h_rms_real)}): the spectrum does not represent this "
                   "scan's heights (a window or a residual form dominates it), so its "
                   "moments, summits and plasticity index are unreliable")
    return out
