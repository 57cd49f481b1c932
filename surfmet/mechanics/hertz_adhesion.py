"""Does adhesion change this ball-on-plate contact? The adhesion section of ``hertz-check``.

From the work of adhesion w, the interaction range z0 (default :data:`DEFAULT_RANGE`), the
materials' E* and the scans' spectral moments (the combined GW summit parameters of
:func:`surfmet.mechanics.hertz_check.scan_summits`):

- Tabor's parameter of the contact (the ball's radius) and of a typical asperity (the
  spectral summit radius, Nayak 1971 / McCool 1986), :func:`contact.adhesion.laws.tabor_parameter`;
- the smooth-ball pull-off forces 2 pi w R (DMT) and 3/2 pi w R (JKR), against the load:
  the most adhesion can add to a contact of this ball;
- Pastewka & Robbins' stickiness parameter of the roughness
  (:func:`contact.adhesion.stickiness.pastewka_robbins`, sticky when below 1).

Verdict: with a roughness spectrum, adhesion changes the contact when the surfaces are
sticky by Pastewka & Robbins' criterion; a smooth pair (no spectrum) when the DMT
pull-off reaches :data:`PULL_OFF_SHARE` of the load. The default range 0.3 nm is of the
order of an interatomic equilibrium spacing, the z0 of Tabor (1977) and of Johnson's
Lennard-Jones surfaces (Johnson & Greenwood 1997, J. Colloid Interface Sci. 192:326).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from contact.roughcontact import SummitParameters

#: Interaction range z0 when none is given (m).
DEFAULT_RANGE = 0.3e-9
#: A smooth pair's DMT pull-off above this share of the load changes the contact.
PULL_OFF_SHARE = 0.01


@dataclass(frozen=True)
class HertzAdhesion:
    """The adhesion assessment of a ball on a plate (SI; None where no spectrum).

    See Also
    --------
    assess_adhesion : makes it.

    Examples
    --------
    >>> from surfmet.mechanics.hertz_adhesion import assess_adhesion
    >>> a = assess_adhesion(None, radius=0.02, load=10.0, e_star=58.6e9, work=0.05)
    >>> print(f"DMT pull-off 2πwR = {a.dmt_pull_off * 1e3:.2f} mN", a.changes_contact)
    DMT pull-off 2πwR = 6.28 mN False
    """

    work: float
    range: float
    e_star: float
    radius: float
    load: float
    tabor_contact: float
    summit_radius: float | None
    tabor_asperity: float | None
    slope_rms: float | None
    curvature_rms: float | None
    pastewka_robbins: float | None

    @property
    def dmt_pull_off(self) -> float:
        """2 pi w R (N): the pull-off of the smooth ball, rigid side (Derjaguin et al. 1975)."""
        return 2.0 * math.pi * self.work * self.radius

    @property
    def jkr_pull_off(self) -> float:
        """3/2 pi w R (N): the pull-off of the smooth ball, compliant side (JKR 1971)."""
        return 1.5 * math.pi * self.work * self.radius

    @property
    def sticky(self) -> bool | None:
        """Pastewka & Robbins: sticky when their parameter is below 1 (None: no spectrum)."""
        return None if self.pastewka_robbins is None else self.pastewka_robbins < 1.0

    @property
    def changes_contact(self) -> bool:
        """Whether adhesion changes the contact (see the module)."""
        if self.sticky is not None:
            return self.sticky
        return self.dmt_pull_off >= PULL_OFF_SHARE * self.load

    @property
    def reason(self) -> str:
        share = f"{100 * self.dmt_pull_off / self.load:.3g} % of the load"
        bound = f"the smooth-ball pull-off 2 pi w R = {self.dmt_pull_off:.3g} N is {share}"
        if self.sticky is None:
            return (f"no roughness spectrum: {bound}, "
                    f"{'at or above' if self.changes_contact else 'below'} "
                    f"{100 * PULL_OFF_SHARE:g} %")
        if self.sticky:
            return (f"Pastewka-Robbins parameter {self.pastewka_robbins:.3g} < 1: the rough "
                    f"surfaces are sticky, adhesion adds a finite pull-off and contact area; "
                    f"{bound}")
        return (f"Pastewka-Robbins parameter {self.pastewka_robbins:.3g} > 1: the roughness "
                f"makes the surfaces non-sticky, adhesion only adds area in proportion to its "
                f"strength; {bound}")


def assess_adhesion(summits: SummitParameters | None, *, radius: float, load: float,
                    e_star: float, work: float, range_: float = DEFAULT_RANGE) -> HertzAdhesion:
    """The assessment for GW ``summits`` (or None, a smooth pair); see the module.

    Parameters
    ----------
    summits : SummitParameters or None
        The combined Greenwood-Williamson summit parameters of the scans
        (:func:`surfmet.mechanics.hertz_check.scan_summits`); None for a smooth pair.
    radius, load : float
        Ball radius (m) and load (N).
    e_star : float
        Composite modulus (Pa).
    work : float
        Work of adhesion (J/m²).
    range_ : float
        Interaction range z0 (m).

    Returns
    -------
    HertzAdhesion
        Tabor's parameters, the pull-off forces, Pastewka & Robbins' stickiness and the
        verdict ``changes_contact`` with its ``reason``.

    See Also
    --------
    surfmet.mechanics.hertz_check.hertz_check : adds it with ``work_of_adhesion``.
    surfmet.mechanics.adhesion.adhesion : the adhesive solve itself.

    References
    ----------
    .. [1] D. Tabor, "Surface forces and surface interactions", J. Colloid Interface Sci.
       58 (1977) 2-13.
    .. [2] L. Pastewka, M. O. Robbins, "Contact between rough surfaces and a criterion for
       macroscopic adhesion", PNAS 111 (2014) 3298-3303.
    .. [3] B. V. Derjaguin, V. M. Muller, Yu. P. Toporov, "Effect of contact deformations
       on the adhesion of particles", J. Colloid Interface Sci. 53 (1975) 314-326.

    Examples
    --------
    The paper's smooth ball at 10 N: the most adhesion can add (DMT, 6 mN) is far below the
    load; at 0.1 mN it is not:

    >>> from surfmet.mechanics.hertz_adhesion import assess_adhesion
    >>> assess_adhesion(None, radius=0.02, load=10.0, e_star=58.6e9, work=0.05).changes_contact
    False
    >>> assess_adhesion(None, radius=0.02, load=1e-4, e_star=58.6e9, work=0.05).changes_contact
    True
    """
    from contact.adhesion.laws import tabor_parameter
    from contact.adhesion.stickiness import pastewka_robbins, rms_gradient_curvature
    from surfmet._errors import SurfmetInputError

    if not (math.isfinite(work) and work > 0):
        raise SurfmetInputError(f"the work of adhesion must be positive, got {work!r} J/m^2")
    if not (math.isfinite(range_) and range_ > 0):
        raise SurfmetInputError(f"the interaction range must be positive, got {range_!r} m")
    rs = mu_s = hp = hpp = pr = None
    if summits is not None:
        rs = float(summits.radius)
        mu_s = tabor_parameter(work, rs, e_star, range_)
        hp, hpp = rms_gradient_curvature(summits.m2, summits.m4)
        pr = pastewka_robbins(hp, hpp, e_star, work, range_)
    return HertzAdhesion(work=float(work), range=float(range_), e_star=float(e_star),
                         radius=float(radius), load=float(load),
                         tabor_contact=tabor_parameter(work, radius, e_star, range_),
                         summit_radius=rs, tabor_asperity=mu_s, slope_rms=hp,
                         curvature_rms=hpp, pastewka_robbins=pr)
