"""Contact from all scales: the isotropic PSD of one surface measured several times.

``surfmet spectrum`` and ``surfmet flat-contact`` given several measurements (or a
contact.engineering container) take the profile (1D) PSD averaged over them as ``surfmet
scales`` computes it (:func:`surfmet.scale_dependent.analyze_scales`: each measurement
counts above its pixel and reliability cut-off and below its size, one vote each where it
counts) and turn it into the isotropic areal PSD ``C^iso`` that Persson's theory integrates
(:func:`contact.roughcontact._isotropic.iso_from_profile_psd`, the inverse of the Abel
projection of Jacobs, Junge & Pastewka 2017, Surf. Topogr. Metrol. Prop. 5, 013001).

The PSD is known only over the band where some measurement contributes: the rms values and
Persson's area, mean gap and stiffness are those of the roughness in that band (the union
of the measurements' bands), stated with it; what lies outside is not extrapolated into
them. The 1D PSD is interpolated log-log between the grid points of the analysis (so a
sharp roll-off is resolved to the grid: 10 points per decade by default).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from contact.roughcontact import ModelCurve, SummitParameters
from surfmet._errors import SurfmetInputError
from surfmet.psd import PSD, HurstFit, fit_hurst
from surfmet.scale_dependent import ScaleAnalysis

if TYPE_CHECKING:
    from contact._material_pair import MaterialPair
    from surfmet.mechanics._types import Materials

#: Quadrature points per decade of the isotropic PSD over the measured band.
QUAD_PER_DECADE = 40


@dataclass(frozen=True, eq=False)
class AllScalesSpectrum:
    """The averaged PSD of several measurements as Persson's theory takes it (SI).

    Attributes
    ----------
    analysis : ScaleAnalysis
        The averaged scale-dependent statistics (``analysis.q``, ``analysis.psd``: 1D PSD).
    band : (float, float)
        Wavevectors (rad/m) between which the averaged PSD is measured.
    q, c_iso, weights, dq :
        Isotropic PSD ``C^iso`` (m⁴) on a log quadrature of the band
        (:func:`contact.roughcontact._isotropic.log_quadrature`).
    h_rms, slope_rms, curvature_rms : float
        Of the roughness in the band (m, -, 1/m): √m0, √(2 m2), √(8 m4/3).
    hurst : HurstFit or None
        Power law fitted to the averaged 1D PSD over the band (None: too few points).
    summits : SummitParameters or None
        Nayak/McCool summit statistics of the band (None where its moments give α < 1.5).
    notes : tuple of str
        What the conversion had to do (negative ``C^iso`` set to zero), or why there are no
        summit statistics.

    See Also
    --------
    all_scales_spectrum : makes it.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.scale_dependent import analyze_scales
    >>> from surfmet.mechanics.all_scales import all_scales_spectrum
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> half = surfmet.Topography(plate.heights[:, :512], plate.dx, plate.dy)
    >>> zoom = surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy)
    >>> spec = all_scales_spectrum(analyze_scales([half, zoom]))
    >>> low, high = spec.band
    >>> print(f"band {low:.3g}..{high:.3g} rad/m, h_rms = {spec.h_rms * 1e6:.2f} µm")
    band 2.45e+03..5.66e+05 rad/m, h_rms = 2.33 µm
    """

    analysis: ScaleAnalysis
    band: tuple[float, float]
    q: np.ndarray
    c_iso: np.ndarray
    weights: np.ndarray
    dq: float
    h_rms: float
    slope_rms: float
    curvature_rms: float
    hurst: HurstFit | None
    summits: SummitParameters | None = None
    notes: tuple[str, ...] = ()

    def measurement_bands(self) -> list[tuple[float, float] | None]:
        """Per measurement, the wavevectors (rad/m) over which it contributes to the PSD."""
        votes = self.analysis.contributors("psd")
        out: list[tuple[float, float] | None] = []
        for row in votes:
            qs = self.analysis.q[row]
            out.append(None if qs.size == 0 else (float(qs.min()), float(qs.max())))
        return out


def _hurst(q: np.ndarray, c: np.ndarray) -> HurstFit | None:
    """Power law of the averaged 1D PSD (every grid point one equal weight)."""
    if q.size < 3:
        return None
    lq = np.log(q)
    edges = np.exp(np.concatenate([[lq[0] - 0.5 * (lq[1] - lq[0])],
                                   0.5 * (lq[1:] + lq[:-1]),
                                   [lq[-1] + 0.5 * (lq[-1] - lq[-2])]]))
    spec = PSD(q=q, C=c, kind="profile", dq=float(q[0]),
               weights=np.diff(edges) / float(q[0]))
    try:
        return fit_hurst(spec, (float(q[0]), float(q[-1])))
    except SurfmetInputError:
        return None


def all_scales_spectrum(analysis: ScaleAnalysis, per_decade: int = QUAD_PER_DECADE
                        ) -> AllScalesSpectrum:
    """The isotropic PSD over the measured band of ``analysis`` and its rms values.

    Parameters
    ----------
    analysis : ScaleAnalysis
        The scale-dependent analysis of the measurements
        (:func:`surfmet.scale_dependent.analyze_scales`).
    per_decade : int
        Quadrature points per decade of wavevector.

    Returns
    -------
    AllScalesSpectrum
        The isotropic PSD over the measured band, its rms height, slope and curvature.

    Raises
    ------
    SurfmetInputError
        Fewer than two points of measured PSD, or a profile PSD with no isotropic inverse.

    See Also
    --------
    persson_all_scales : Persson's theory on it.

    References
    ----------
    .. [1] L. Jacobs, T. Junge, L. Pastewka, "Quantitative characterization of surface
       topography using spectral analysis", Surf. Topogr.: Metrol. Prop. 5 (2017) 013001.

    Examples
    --------
    Half of the bundled plate and a 0.64 mm zoom of it, one surface measured twice:

    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.scale_dependent import analyze_scales
    >>> from surfmet.mechanics.all_scales import all_scales_spectrum
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> half = surfmet.Topography(plate.heights[:, :512], plate.dx, plate.dy)
    >>> zoom = surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy)
    >>> spec = all_scales_spectrum(analyze_scales([half, zoom]))
    >>> print(f"h_rms = {spec.h_rms * 1e6:.2f} µm, slope_rms = {spec.slope_rms:.3f}")
    h_rms = 2.33 µm, slope_rms = 0.488
    """
    from contact._errors import ContactInputError
    from contact.roughcontact import isotropic_moments, summit_parameters
    from contact.roughcontact._isotropic import iso_from_profile_psd, log_quadrature

    good = np.isfinite(analysis.psd) & (analysis.psd > 0)
    if good.sum() < 2:
        raise SurfmetInputError("the measurements give fewer than two points of PSD: no "
                                "spectrum for Persson's theory (too few pixels?)")
    order = np.argsort(analysis.q[good])
    q1, c1 = analysis.q[good][order], analysis.psd[good][order]
    band = (float(q1[0]), float(q1[-1]))
    notes = []
    try:
        q, w, dq = log_quadrature(band[0], band[1], per_decade)
        raw = iso_from_profile_psd(q1, c1, q)
        c_iso = np.maximum(raw, 0.0)
        if np.any(raw < 0):
            notes.append(_negative_note(q, raw, w))
        m0, m2, m4 = isotropic_moments(q, c_iso, w, dq)
    except ContactInputError as exc:
        raise SurfmetInputError(f"averaged PSD: {exc}") from None
    if not m2 > 0:
        raise SurfmetInputError("the averaged PSD gives no isotropic roughness (C_iso ≤ 0 "
                                "over the whole band)")
    try:
        summits = summit_parameters(m0, m2, m4)
    except ContactInputError as exc:
        summits = None
        notes.append(f"no summit statistics for the band: {exc}")
    return AllScalesSpectrum(analysis=analysis, band=band, q=q, c_iso=c_iso, weights=w, dq=dq,
                             h_rms=math.sqrt(m0), slope_rms=math.sqrt(2.0 * m2),
                             curvature_rms=math.sqrt(8.0 * m4 / 3.0), hurst=_hurst(q1, c1),
                             summits=summits, notes=tuple(notes))


def _negative_note(q: np.ndarray, raw: np.ndarray, w: np.ndarray) -> str:
    """Where the inverse went negative and how much squared slope that is."""
    neg = raw < 0
    lost = float(np.sum(-raw[neg] * q[neg] ** 2 * w[neg]))
    total = float(np.sum(np.abs(raw) * q**2 * w))
    return (f"C_iso < 0 (set to 0) at q = {q[neg].min():.4g}..{q[neg].max():.4g} rad/m: the "
            "averaged profile PSD rises with q there, as no isotropic surface's does (noise, "
            "or measurements of different levels meeting); "
            f"{100 * lost / total:.2g} % of the |C_iso| weight of the squared slope")


def persson_all_scales(s: AllScalesSpectrum, pressures: np.ndarray, e_star: float
                       ) -> ModelCurve:
    """Persson's area, Yang-Persson mean gap and stiffness from the averaged PSD's band.

    Parameters
    ----------
    s : AllScalesSpectrum
        The averaged spectrum.
    pressures : ndarray
        Nominal pressures (Pa).
    e_star : float
        Composite modulus (Pa).

    Returns
    -------
    contact.roughcontact.ModelCurve
        Area fraction, mean gap and stiffness at each pressure.

    See Also
    --------
    surfmet.mechanics.flat_contact.flat_contact : the same theory on one scan, beside the
        BEM.

    References
    ----------
    .. [1] B. N. J. Persson, "Theory of rubber friction and contact mechanics", J. Chem.
       Phys. 115 (2001) 3840-3861.
    .. [2] C. Yang, B. N. J. Persson, "Contact mechanics: contact area and interfacial
       separation from small contact to full contact", J. Phys.: Condens. Matter 20
       (2008) 215214.

    Examples
    --------
    At small loads Persson's real contact area grows in proportion to the pressure:

    >>> import numpy as np
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.scale_dependent import analyze_scales
    >>> from surfmet.mechanics.all_scales import all_scales_spectrum, persson_all_scales
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> half = surfmet.Topography(plate.heights[:, :512], plate.dx, plate.dy)
    >>> zoom = surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy)
    >>> spec = all_scales_spectrum(analyze_scales([half, zoom]))
    >>> curve = persson_all_scales(spec, np.array([1e6, 1e7]), 58.6e9)
    >>> print([f"{a:.2e}" for a in curve.area_fraction])
    ['5.59e-05', '5.59e-04']
    """
    from contact._errors import ContactInputError
    from contact.roughcontact import persson

    try:
        return persson(pressures, e_star, s.q, s.c_iso, s.weights, s.dq)
    except ContactInputError as exc:
        raise SurfmetInputError(str(exc)) from None


@dataclass(frozen=True, eq=False)
class AllScales:
    """Several measurements of one surface, with the pair they are pressed as.

    Attributes
    ----------
    analysis : ScaleAnalysis
        Their scale-dependent analysis (:func:`surfmet.scale_dependent.analyze_scales`).
    spectrum : AllScalesSpectrum
        The isotropic PSD of the averaged profile PSD (:func:`all_scales_spectrum`).
    pair : contact._material_pair.MaterialPair or None
        The pair (None: no materials nor E* given), resolved once here with its hardness.
    curve : ModelCurve or None
        Persson's theory at the pressures asked (None: none asked).

    See Also
    --------
    all_scales : makes it.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.all_scales import all_scales
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy)
    >>> run = all_scales([plate, patch], tip_radius=None,
    ...                  per_decade=5, materials="aluminium")
    >>> run.pair.names, run.curve is None
    (['aluminium'], True)
    """

    analysis: ScaleAnalysis
    spectrum: AllScalesSpectrum
    pair: MaterialPair | None = None
    curve: ModelCurve | None = None


def all_scales(scans: list[Any], *, tip_radius: float | None, per_decade: int,
               materials: Materials | None = None, e_star: float | None = None,
               hardness: float | None = None, pressures: np.ndarray | None = None
               ) -> AllScales:
    """``spectrum`` and ``flat-contact`` on several measurements: the pair (materials or
    E*, resolved as for one scan on a flat, :func:`surfmet.mechanics.material_spec.scan_pair`,
    before any analysis), the scale analysis, its averaged isotropic PSD and, with
    ``pressures``, Persson's theory on it.

    Parameters
    ----------
    scans : list of Topography or Profile
        The measurements.
    tip_radius : float or None
        Probe tip radius (m) for measurements whose file states none.
    per_decade : int
        Points per decade of the analysis' distance grid.
    materials : str or MaterialPair, optional
        ``"A"`` or ``"A,B"`` (the scan's material, the flat's).
    e_star : float, optional
        Composite modulus (Pa) instead of materials.
    hardness : float, optional
        Replaces the softer body's table hardness (Pa).
    pressures : ndarray, optional
        Nominal pressures (Pa) for Persson's theory (needs materials or E*).

    Returns
    -------
    AllScales
        The analysis, the spectrum, the pair and the theory's curve.

    Raises
    ------
    SurfmetInputError
        Bad materials, or measurements that give no PSD band.

    Examples
    --------
    >>> import numpy as np
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.all_scales import all_scales
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy)
    >>> run = all_scales([plate, patch], tip_radius=None,
    ...                  per_decade=5, e_star=50e9, pressures=np.array([1e7]))
    >>> run.pair.e_star, run.curve.area_fraction.shape
    (50000000000.0, (1,))
    """
    from surfmet.mechanics.material_spec import scan_pair
    from surfmet.scale_dependent import analyze_scales

    # with pressures the pair is needed: scan_pair then says what is missing
    pair = (None if materials is None and e_star is None and pressures is None
            else scan_pair(materials, e_star=e_star, hardness=hardness))
    analysis = analyze_scales(scans, tip_radius=tip_radius, per_decade=per_decade)
    s = all_scales_spectrum(analysis)
    curve = (None if pressures is None or pair is None
             else persson_all_scales(s, pressures, pair.e_star))
    return AllScales(analysis, s, pair, curve)
