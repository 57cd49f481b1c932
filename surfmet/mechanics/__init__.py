"""Contact mechanics on scans: one facade per model command, between the command line and
the array-level engine :mod:`contact`.

Each facade takes scans (or file names) and values in SI, prepares the scans, calls the
engine and returns a small result object (its JSON record is built in
:mod:`surfmet.records`, which imports this package; this package never imports it) and,
where it has one, ``figure()``:

- ``contact``: :mod:`~surfmet.mechanics.ball_contact` (BEM, ball on plate);
- ``hertz-check``: :mod:`~surfmet.mechanics.hertz_check` (BEM against Hertz, the verdict);
- ``flat-contact``: :mod:`~surfmet.mechanics.flat_contact` (BEM against the theories);
- ``rolling``: :mod:`~surfmet.mechanics.rolling_resistance` (rolling sweeps);
- ``--resolution-study``: :mod:`~surfmet.mechanics.resolution_study`;
- ``spectrum``: :mod:`~surfmet.mechanics.spectrum` (spectral moments, plasticity index).

Shared by them: :mod:`~surfmet.mechanics.pairing` (a plate and a ball scan on one grid)
and :mod:`~surfmet.mechanics.material_spec` (``steel,aluminium`` text to materials).
"""

from surfmet._lazy import attach

# Each room loads on first use (surfmet.mechanics.<room>), so that importing the package
# imports none of them.
__all__ = [
    "adhesion",
    "adhesion_laws",
    "adhesion_line",
    "all_scales",
    "ball_contact",
    "flat_contact",
    "hertz_adhesion",
    "hertz_check",
    "material_spec",
    "pairing",
    "resolution_study",
    "rolling_contact",
    "rolling_resistance",
    "rotor_rough_bound",
    "rotor_verdict",
    "scan_preparation",
    "spectrum",
    "viscoelastic_rolling",
    "viscoelastic_rolling_contact",
]

__getattr__, __dir__ = attach(__name__, __all__)
