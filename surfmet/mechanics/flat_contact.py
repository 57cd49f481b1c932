"""Which model holds for this scan? A rough scan on a flat: BEM against Persson, GW and BGT.

:func:`flat_contact` levels the scan (a periodic one keeps its heights, see
:func:`surfmet.mechanics.spectrum.prepare`), describes its spectrum
(:func:`surfmet.mechanics.spectrum.spectrum`),
runs the boundary elements along the nominal pressures (:func:`contact.setups._flat.flat_contact`:
periodic for a periodic scan, free boundary otherwise) and evaluates the three theories on
the same spectrum:

- Persson (2001, 2007): area erf(√2 p/(E* h'_rms)); mean gap and stiffness after Yang &
  Persson (2008, PRL 100, 024303);
- Greenwood & Williamson (1966) with the Nayak/McCool spectral summit parameters;
- Bush, Gibson & Thomas (1975): A/A0 = √(2π) p/(E* h'_rms) (area only).

Each model's relative error against the BEM is ``model/BEM - 1``. The h'_rms and the summit
parameters are those of the whole discrete spectrum, i.e. of the same grid the BEM sees, so
that the comparison is between theories and not between resolutions.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from contact.roughcontact import ModelCurve
from contact.setups._flat import FlatContact
from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.mechanics.scan_preparation import SPIKES
from surfmet.mechanics.spectrum import Spectrum

if TYPE_CHECKING:
    from collections.abc import Callable

    from contact._material_pair import MaterialPair
    from contact.adhesion.flat import AdhesiveFlat
    from surfmet.mechanics._types import AdhesionLaw, Loads, Materials, PathLike, Spikes
    from surfmet.mechanics.scan_preparation import FlatPreparation


@dataclass(frozen=True, eq=False)
class FlatContactReport:
    """BEM and theories at each nominal pressure (SI).

    Attributes
    ----------
    bem : contact.setups._flat.FlatContact
        The boundary-element sweep.
    models : dict of str to ModelCurve
        The theories (``"persson"``, ``"gw"``, ``"bgt"``) at the same pressures.
    spectrum : Spectrum
        The scan's spectrum the theories are fed with.
    levelling : str
        How the scan was levelled.
    settings, preparation, caveats, adhesion, materials
        What was asked, done and doubted.

    See Also
    --------
    flat_contact : makes it.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.flat_contact import flat_contact
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:64, :64], plate.dx, plate.dy)
    >>> report = flat_contact(patch, pressures="10MPa,30MPa", materials="aluminium")
    >>> sorted(report.models), report.bem.pressure.tolist()
    (['bgt', 'gw', 'persson'], [10000000.0, 30000000.0])
    """

    bem: FlatContact
    models: dict[str, ModelCurve]
    spectrum: Spectrum
    levelling: str
    settings: dict[str, Any] = field(default_factory=dict)
    preparation: FlatPreparation | None = None
    caveats: tuple[str, ...] = ()
    adhesion: AdhesiveFlat | None = None  # when a law was given
    materials: MaterialPair | None = None  # when materials were given

    @property
    def periodic(self) -> bool:
        return self.bem.periodic

    def kappa(self, area_fraction: np.ndarray) -> np.ndarray:
        """``κ = (A/A0) E* h'_rms / p`` with this scan's spectral h'_rms."""
        return (np.asarray(area_fraction) * self.bem.e_star * self.spectrum.slope_rms
                / self.bem.pressure)


def parse_pressures(text: str) -> np.ndarray:
    """``P[,P...]`` or ``P1:P2[:N]`` (N log-spaced values), the grammar of
    :func:`surfmet.value_lists.parse_values` -> the distinct pressures in Pa, ascending.

    Parameters
    ----------
    text : str
        ``"1MPa,10MPa"`` or ``"1MPa:100MPa:3"``; a number without a unit is in Pa.

    Returns
    -------
    ndarray
        The pressures in Pa.

    Raises
    ------
    SurfmetInputError
        Text that is not a pressure list or range.

    Examples
    --------
    >>> from surfmet.mechanics.flat_contact import parse_pressures
    >>> parse_pressures("1MPa,10MPa").tolist(), parse_pressures("1MPa:100MPa:3").tolist()
    ([1000000.0, 10000000.0], [1000000.0, 10000000.0, 100000000.0])
    >>> parse_pressures("ten")
    Traceback (most recent call last):
    ...
    surfmet._errors.SurfmetInputError: cannot read pressure 'ten': ...
    """
    from surfmet.units import parse_pressure
    from surfmet.value_lists import parse_values

    return np.unique(parse_values(str(text), parse_pressure, "pressures"))


def flat_contact(topo: Topography, *, e_star: float | None = None,
                 pressures: Loads | float | str,
                 hardness: float | None = None, periodic: bool | None = None,
                 stiffness: str = "curve", progress: Callable[[int, int], Any] | None = None,
                 spikes: Spikes = SPIKES,
                 adhesion: AdhesionLaw | None = None, materials: Materials | None = None
                 ) -> FlatContactReport:
    """BEM and the Persson, GW and BGT theories for a scan pressed on a flat.

    Parameters
    ----------
    topo : Topography
        The rough scan (heights in m).
    e_star : float, optional
        Composite modulus E*, Pa; or give ``materials``.
    pressures : array_like or str
        Nominal pressures (Pa) or text for :func:`parse_pressures`.
    hardness : float, optional
        Cap of the BEM pressure (elastic-perfectly-plastic); the theories stay elastic.
    periodic : bool, optional
        None: detect from the edges.
    stiffness : {"curve", "solve"}
        How the BEM stiffness is measured (see :func:`contact.setups._flat.flat_contact`).
    spikes : {"remove", "keep"} or bool
        The scan's spikes, removed by default; non-measured points are filled with the
        nearest measured value (:func:`surfmet.mechanics.scan_preparation.prepare_flat`).
    adhesion : InteractionLaw, optional
        An adhesion law (:func:`surfmet.mechanics.adhesion.interaction_law`): the scan is
        also pressed with adhesion at each pressure (:func:`adhesive_sweep`), beside the
        non-adhesive BEM.
    materials : str or MaterialPair, optional
        ``"A"`` (the scan on a rigid flat), ``"A,B"`` (on an elastic flat of B) or a resolved
        pair, instead of ``e_star`` (:func:`surfmet.mechanics.material_spec.scan_pair`):
        E* and the hardness from the pair (``hardness`` when given, else the softer body's):
        a nominal pressure above that hardness gets a caveat, since the whole nominal area
        would flow there and no elastic theory holds; kept in
        :attr:`FlatContactReport.materials`.

    A scan dominated by a curved form (a ball's cap) has its second-order surface removed,
    and a caveat says so (:func:`surfmet.mechanics.spectrum.prepare`).

    Returns
    -------
    FlatContactReport
        The BEM sweep and the theories at each pressure, and ``figure()`` (its record:
        :func:`surfmet.records._flat.flat_contact_record`).

    Raises
    ------
    SurfmetInputError
        Not an areal scan, bad pressures or moduli, unmeasured points.

    See Also
    --------
    contact.flat_contact : the engine's sweep, on arrays.
    surfmet.mechanics.spectrum.spectrum : the spectrum the theories use.

    References
    ----------
    .. [1] B. N. J. Persson, "Theory of rubber friction and contact mechanics", J. Chem.
       Phys. 115 (2001) 3840-3861.
    .. [2] J. A. Greenwood, J. B. P. Williamson, "Contact of nominally flat surfaces",
       Proc. R. Soc. Lond. A 295 (1966) 300-319.
    .. [3] A. W. Bush, R. D. Gibson, T. R. Thomas, "The elastic contact of a rough
       surface", Wear 35 (1975) 87-111.
    .. [4] C. Yang, B. N. J. Persson, "Contact mechanics: contact area and interfacial
       separation from small contact to full contact", J. Phys.: Condens. Matter 20
       (2008) 215214 (the mean gap).

    Examples
    --------
    A 0.32 mm patch of the bundled plate on a rigid flat: the BEM's real contact area
    beside Persson's, Greenwood-Williamson's and Bush-Gibson-Thomas's:

    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.flat_contact import flat_contact
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:64, :64], plate.dx, plate.dy)
    >>> report = flat_contact(patch, pressures="10MPa,30MPa", materials="aluminium")
    >>> for name, curve in [("bem", report.bem)] + sorted(report.models.items()):
    ...     print(name, [f"{a:.1e}" for a in curve.area_fraction])
    bem ['7.3e-04', '2.7e-03']
    bgt ['7.0e-04', '2.1e-03']
    gw ['8.1e-04', '2.3e-03']
    persson ['4.5e-04', '1.3e-03']
    """
    from contact._errors import ContactInputError
    from contact._grid import gap_grid
    from contact.roughcontact import bush_gibson_thomas, greenwood_williamson, persson
    from contact.setups._flat import flat_contact as bem_sweep
    from surfmet.mechanics.spectrum import prepared_scan, spectrum

    p = parse_pressures(pressures) if isinstance(pressures, str) else np.sort(
        np.atleast_1d(np.asarray(pressures, dtype=float)))
    pair, yield_hardness = None, hardness
    if materials is not None:
        from surfmet.mechanics.material_spec import scan_pair

        pair = scan_pair(materials, e_star=e_star, hardness=hardness)
        e_star = pair.e_star
        yield_hardness = pair.hardness  # resolve_pair's: the user's, else the softer body's
    if not (isinstance(e_star, (int, float)) and math.isfinite(e_star) and e_star > 0):
        raise SurfmetInputError(f"E* must be a positive pressure, got {e_star!r}")
    if p.max() >= e_star:  # before any solve: strains of order 1, no elastic half-space
        raise SurfmetInputError(
            f"the pressures reach {p.max():.4g} Pa, not below E* = {e_star:.4g} Pa: the "
            "scan would be pressed flat at strains of order one, outside linear elasticity; "
            "give pressures well below E* (or E* with its unit, e.g. --e-star 100GPa)")
    scan, per, level, preparation = prepared_scan(topo, periodic=periodic, spikes=spikes)
    if adhesion is not None:
        _check_adhesive(scan, per, hardness)
    spec = spectrum(scan, periodic=per, e_star=e_star if hardness else None,
                    hardness=hardness)
    try:
        z = np.asarray(scan.heights, dtype=float)
        bem = bem_sweep(gap_grid(float(z.max()) - z, scan.dx, scan.dy, periodic=per),
                        pressures=p, e_star=e_star if pair is None else pair,
                        hardness=hardness, stiffness=stiffness, progress=progress)
        ps = spec.psd
        models = {
            "persson": persson(p, e_star, ps.q, ps.C, ps.weights, ps.dq),
            "gw": greenwood_williamson(p, e_star, spec.summits),
            "bgt": bush_gibson_thomas(p, e_star, spec.slope_rms),
        }
        adhesive = None if adhesion is None else adhesive_sweep(scan, bem, adhesion)
    except ContactInputError as exc:
        raise SurfmetInputError(str(exc)) from None
    form = (("a curved form dominated the plane-levelled scan: its second-order surface "
             "was removed (levelling poly:2), so this is the contact of its texture on a "
             "flat; for the curved body itself use contact or hertz-check",)
            if level == "poly:2" else ())
    bem = dataclasses.replace(bem, notes=_edge_notes(bem.notes))
    return FlatContactReport(bem=bem, models=models, spectrum=spec, levelling=level,
                             settings={"pressures": p.tolist()}, preparation=preparation,
                             caveats=form + _yield_caveats(p, yield_hardness)
                             + gap_caveats(models),
                             adhesion=adhesive, materials=pair)


#: How a flat contact states contact at its scan's edge (once: the solve's own warning,
#: "the domain is too small", does not apply to a scan pressed over its whole area).
EDGE_INHERENT = (
    "contact reaches the edge of the scan, as it must for a rough scan pressed on a flat "
    "over its whole area (not a domain too small): on the free boundary the missing "
    "neighbours make the surface near the edges softer than in the bulk (a periodic scan, "
    "--periodic yes, has no edge)")

_MODEL_NAMES = {"persson": "Persson", "gw": "Greenwood-Williamson (GW)", "bgt": "BGT"}


def _edge_notes(notes: tuple[str, ...]) -> tuple[str, ...]:
    """The BEM's notes with its edge-contact note stated as inherent to a flat contact."""
    return tuple(EDGE_INHERENT if n.startswith("contact reaches the edge") else n
                 for n in notes)


def gap_caveats(models: dict[str, ModelCurve]) -> tuple[str, ...]:
    """A model whose mean gap comes out zero or negative is outside its validity there.

    A mean gap is the mean separation of two surfaces that do not interpenetrate, so it is
    positive; GW's comes out negative at high pressure, where its independent asperities
    (valid for a small contact fraction) no longer describe the contact. Such a value is
    not a gap: it is kept in the table and the JSON, flagged here, and left out of the plot.

    Parameters
    ----------
    models : dict of str to ModelCurve
        The theories' curves.

    Returns
    -------
    tuple of str
        One sentence per model with a mean gap at or below zero.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.flat_contact import flat_contact, gap_caveats
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:64, :64], plate.dx, plate.dy)
    >>> gap_caveats(flat_contact(patch, pressures="10MPa,30MPa", materials="aluminium").models)
    ()
    """
    from surfmet.units import format_length

    out = []
    for name, m in models.items():
        if m.mean_gap is None:
            continue
        gap = np.asarray(m.mean_gap, dtype=float)
        bad = ~(gap > 0)
        if not bad.any():
            continue
        at = ", ".join(f"{pk / 1e6:.4g} MPa ({format_length(g)}, A/A0 {a:.3g})"
                       for pk, g, a in zip(np.asarray(m.pressure)[bad], gap[bad],
                                           np.asarray(m.area_fraction)[bad]))
        out.append(f"{_MODEL_NAMES.get(name, name)}'s mean gap is not positive at {at}: the "
                   "contact is outside the model's validity there (its asperities are no "
                   "longer few and independent), so that value is not a gap and is left out "
                   "of the plot")
    return tuple(out)


#: Pixels whose sides differ by less than this share are square for the adhesive solve,
#: which takes their geometric mean (instruments' calibrated pitches differ by ~1e-4).
SQUARE_PIXEL = 1e-3


def adhesive_sweep(scan: Topography, bem: FlatContact, law: AdhesionLaw) -> Any:
    """The scan pressed with adhesion at the BEM's pressures, started from its solves
    (:func:`contact.adhesion.flat.adhesive_flat`: periodic, square pixels, elastic).

    A Dugdale law's step is smoothed on the pixel's scale, as the sphere's is
    (:meth:`contact.adhesion.laws.DugdaleLaw.on_grid`: same work and peak), which removes
    most of the pixels' pinning of the cohesive zone's end (Johnson's wavy surface under
    a prescribed pressure, Johnson 1995, is the check).

    Parameters
    ----------
    scan : Topography
        The prepared scan (:func:`surfmet.mechanics.spectrum.prepared_scan`).
    bem : contact.setups._flat.FlatContact
        The non-adhesive sweep to start from.
    law : DugdaleLaw or ExponentialLaw
        The adhesion law (:func:`surfmet.mechanics.adhesion.interaction_law`).

    Returns
    -------
    contact.adhesion.flat.AdhesiveFlat
        Area fraction, mean gap and attractive pressure at each pressure, with warnings.

    References
    ----------
    .. [1] D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale model",
       J. Colloid Interface Sci. 150 (1992) 243-269.
    .. [2] K. L. Johnson, "The adhesion of two elastic bodies with slightly wavy surfaces",
       Int. J. Solids Struct. 32 (1995) 423-430.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.adhesion import interaction_law
    >>> from surfmet.mechanics.flat_contact import adhesive_sweep, flat_contact
    >>> from surfmet.mechanics.spectrum import prepared_scan
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:64, :64], plate.dx, plate.dy)
    >>> report = flat_contact(patch, pressures="10MPa,30MPa", materials="aluminium")
    >>> sticky = adhesive_sweep(prepared_scan(patch)[0], report.bem,
    ...                         interaction_law("dugdale", 0.05, 2e-9))
    >>> bool((sticky.area_fraction >= report.bem.area_fraction).all())
    True
    """
    from contact.adhesion.flat import adhesive_flat

    z = np.asarray(scan.heights, dtype=float)
    dx = math.sqrt(scan.dx * scan.dy)
    if law.smoothing == 0.0:  # a step smoothed on the pixel, where the law has one
        law = law.on_grid(dx, bem.e_star)
    return adhesive_flat(z.max() - z, dx, bem.e_star, law, bem.pressure, bem.mean_gap,
                         bem.stiffness)


def _check_adhesive(scan: Topography, periodic: bool, hardness: float | None) -> None:
    """What the adhesive solve needs, checked before any work."""
    if not periodic:
        raise SurfmetInputError(
            "the adhesive solve is periodic and this scan is not (its opposite edges differ): "
            "pass --periodic yes to take it as periodic (its seams then carry a step)")
    if hardness is not None:
        raise SurfmetInputError("the adhesive solve is elastic: leave out --hardness")
    if not math.isclose(scan.dx, scan.dy, rel_tol=SQUARE_PIXEL):
        raise SurfmetInputError(f"the adhesive solve needs square pixels, the scan's are "
                                f"{scan.dx:.4g} m x {scan.dy:.4g} m: resample it")


def _yield_caveats(p: np.ndarray, hardness: float | None) -> tuple[str, ...]:
    """A nominal pressure at or above the hardness: the nominal area flows (Tabor)."""
    if hardness is None or not np.any(p >= hardness):
        return ()
    from surfmet.units import format_quantity

    over = ", ".join(format_quantity(v, "Pa") for v in p[p >= hardness])
    return (f"nominal pressure {over} at or above the hardness H = "
            f"{format_quantity(hardness, 'Pa')}: "
            "the whole nominal area would flow, so the contact is fully plastic and none of "
            "the elastic theories (nor an elastic BEM) describes it",)


def plot(rep: FlatContactReport | None, path: PathLike | None = None,
         all_scales: ModelCurve | None = None) -> Any:
    """A/A0 and ū against p for the BEM and the three theories, and Persson's theory from
    all scales (:mod:`surfmet.mechanics.all_scales`) when given; ``rep`` None: that alone.

    Parameters
    ----------
    rep : FlatContactReport or None
        The report (None: the all-scales curve alone).
    path : path-like, optional
        Image file to write; None returns the figure only.
    all_scales : ModelCurve, optional
        Persson's theory from all scales.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.flat_contact import flat_contact, plot
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:64, :64], plate.dx, plate.dy)
    >>> fig = plot(flat_contact(patch, pressures="10MPa,30MPa", materials="aluminium"))
    >>> type(fig).__name__
    'Figure'
    """
    from surfmet.plots._style import finish, new_figure

    fig, (a1, a2) = new_figure(1, 2, size=(10, 4.2))
    if rep is not None:
        p = np.asarray(rep.bem.pressure) / 1e6  # MPa, as every surfmet figure
        a1.loglog(p, rep.bem.area_fraction, "ko-", label="BEM")
        a1.loglog(p, [pt.corrected_area_fraction for pt in rep.bem.points], "k^--",
                  label="BEM, perimeter-corrected")
        a2.semilogx(p, rep.bem.mean_gap * 1e6, "ko-", label="BEM")
        styles = {"persson": "C0", "gw": "C1", "bgt": "C2"}
        for name, m in rep.models.items():
            a1.loglog(p, m.area_fraction, "-", color=styles[name], label=name.upper())
            if m.mean_gap is not None:
                # a gap that is not positive is outside the model's validity (gap_caveats)
                gap = np.where(np.asarray(m.mean_gap) > 0, m.mean_gap, np.nan) * 1e6
                a2.semilogx(p, gap, "-", color=styles[name], label=name.upper())
        a1.set_title("periodic BEM" if rep.periodic else "free-boundary BEM")
    if all_scales is not None:
        ps = np.asarray(all_scales.pressure) / 1e6
        # Persson's curve always states its mean gap (contact.roughcontact.persson)
        assert all_scales.mean_gap is not None
        a1.loglog(ps, all_scales.area_fraction, "s:", color="C3",
                  label="PERSSON, all scales")
        a2.semilogx(ps, all_scales.mean_gap * 1e6, "s:", color="C3",
                    label="PERSSON, all scales")
    a1.set_xlabel("nominal pressure p (MPa)")
    a1.set_ylabel("A/A0")
    a2.set_xlabel("nominal pressure p (MPa)")
    a2.set_ylabel("mean gap ū (µm)")
    for ax in (a1, a2):
        ax.legend(fontsize=8)
    return finish(fig, path)
