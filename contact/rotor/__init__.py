"""The rotor study of Alaci, Ciornei & Romanu (2022): a two-ball rotor rolling on a plate.

One module per concept:

``paper``        the paper's facts: rotor dimensions, frame rate, mark step, Table 3 as printed
``frames``       the frame table: the printed rows split into frame indices
``mechanics``    mass properties, normal reactions, accelerations, tangential forces
``inference``    ``lambda`` and ``s_r`` from a symmetric and an asymmetric rotor's accelerations
``simulator``    the rotor's exact motion with hidden effects, read out as frame indices
``forward``      the law of motion's forward model: mark-crossing times
``noise``        the reading-noise model and its estimate
``family``       the model family and the fitted-model record
``diagnostics``  residual diagnostics (likelihood, runs test, lag-1 autocorrelation)
``fitting``      weighted least-squares fits of one model and of the whole family
``parabola``     the paper's parabola fits
``selection``    BIC selection with its simulation calibration (``effect_calibration.json``)
``misreads``     misread-row detection
``analysis``     the analysis of one test (one column)
``groups``       groups of tests and the whole table
``arm``          the friction arm against the contact radius: the least lambda an offset needs
``permutation``  the design's exact permutation tests over the launches' group labels
``reconcile``    the four differences between the groups, and the two misread rules
``lanes``        the lane test: the groups' tracks against the launches' own (lanes in the null)
``windows``      model-free windowed accelerations from the frames alone

The rotor study imports nothing from the contact-mechanics modules but the error family and
the input checks, and nothing from ``surfmet``.
"""

from contact._lazy import attach

# Each room loads on first use (contact.rotor.<room>), so that importing the package
# imports none of them.
__all__ = [
    "adequacy",
    "alignment",
    "analysis",
    "arrays",
    "confounds",
    "diagnostics",
    "extension",
    "family",
    "fitting",
    "forward",
    "frames",
    "groups",
    "inference",
    "joint",
    "mechanics",
    "misreads",
    "noise",
    "paper",
    "parabola",
    "rig",
    "selection",
    "simulator",
    "smooth",
    "starts",
    "tables",
    "track",
    "verdict",
]

__getattr__, __dir__ = attach(__name__, __all__)
