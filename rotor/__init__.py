"""rotor: the rotor study of Alaci, Ciornei & Romanu (2022), an engine of its own.

A two-ball rotor rolls on a plate; a camera films its marks. Frame tables in (the printed
rows, or columns of frame indices per launch), small frozen dataclasses out: the law of
motion of each launch (noise model, model family, BIC selection, misreads, adequacy) and the
verdict on the paper's question (a joint model of all launches, its calibrated p, the
friction arm against the contact radius that bounds it, a budget of confounds).

The public face is this package's ``__all__``: the names below, each loaded on first use
from the private module that holds it (scikit-image's split of a public face over its
modules), so that ``import rotor`` imports none of them. Callers (``surfmet``'s command
line and facades) import names from ``rotor``, never from ``rotor.<module>``
(tests/test_rotor_engine.py). One module per concept:

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
``adequacy``     whether the chosen model explains a column (``adequacy_calibration.json``)
``analysis``     the analysis of one test (one column)
``groups``       groups of tests and the whole table
``track``        the joint law of motion of a table on the plate's track
``joint``        fits of the joint model to all launches of a table
``verdict``      the verdict on the paper's question (``verdict_calibration.json``)
``arm``          the friction arm against the contact radius: the least lambda an offset needs
``rig``          the rig (rotor, camera, groups) that turns an offset into a torque
``permutation``  the design's exact permutation tests over the launches' group labels
``reconcile``    the four differences between the groups, and the two misread rules
``lanes``        the lane test: the groups' tracks against the launches' own
                 (``lane_calibration.json``)
``windows``      model-free windowed accelerations from the frames alone
``tables``       whole tables simulated from a stated prior
``sensitivity``  every assumption's weight on the verdict

The engine imports nothing from ``surfmet``; from ``contact`` only the error family, the
input checks, the materials and their pair (the friction arm's Hertz bound) and the
lazy-face helper.
"""

from __future__ import annotations

from contact._lazy import attach

#: ``{module: its public names}``: the one list of the public face and where each name lives.
_FACE: dict[str, str] = {
    "paper": ("BALL_RADIUS FPS HERTZ_CHECK HERTZ_CHECK_LOAD MARK_STEP PARABOLAS TABLE2 "
              "TABLE3_COLUMNS TABLE3_FILENAME"),
    "frames": "table3 table3_tsv",
    "mechanics": ("G_STANDARD MassProperties angular_acceleration mass_properties normal_reactions "
                  "optimal_collar_length paper_ball_loads paper_rotor rolling_torque"),
    "inference": "IDENTIFIABILITY RollingLawInference infer_rolling_law",
    "simulator": "HiddenEffects SimulatedRun simulate_random_run",
    "forward": "PARAM_NAMES crossing_times",
    "family": "EXTENSION MODELS PARAM_UNITS SELECTABLE ModelFit",
    "parabola": "paper_parabola",
    "selection": "false_alarm_floor",
    "adequacy": "ALPHA MIN_ROWS AdequacyCheck check_adequacy named_wave",
    "analysis": "TestReport analyse_test group_of",
    "groups": "LawOfMotionAnalysis analyse_table",
    "arm": "ArmBound arm_bound",
    "joint": ("GroupOffset fit_table group_offset lane_f launchwise_fit local_accelerations "
              "prepare_table shared_track_f"),
    "lanes": "LaneTest lane_calibration",
    "rig": "Rig RigGroup paper_rig rig_from_mapping solve_lambda",
    "reconcile": "Difference MisreadRules differences_table misread_rules",
    "sensitivity": "Experiment Sensitivity sensitivity_table settling_experiment",
    "tables": "LANE_PRIOR Scenario draw_scenario simulate_table",
    "track": "track_acceleration",
    "verdict": "RotorVerdict frame_windows judge_table verdict_calibration",
    "windows": "WindowedDifference",
}

_ATTRIBUTES = {name: f"{__name__}.{module}" for module, names in _FACE.items()
               for name in names.split()}

__all__ = sorted(_ATTRIBUTES)

__getattr__, __dir__ = attach(__name__, (), _ATTRIBUTES)
