"""rotor: the rotor study of Alaci, Ciornei & Romanu (2022), an engine of its own.

A two-ball rotor rolls on a plate; a camera films its marks. Frame tables in (the printed
rows, or columns of frame indices per launch), small frozen dataclasses out: the law of
motion of each launch (noise model, model family, BIC selection, misreads, adequacy) and the
verdict on the paper's question (a joint model of all launches, its calibrated p, the
friction arm against the contact radius that bounds it, a budget of confounds).

The public face is this package's ``__all__``: the names below, each loaded on first use
from the private module that holds it (scikit-image's split of a public face over private
modules), so that ``import rotor`` imports none of them. Callers (``surfmet``'s command
line, facades, demo and plots; the examples and benchmarks) import names from ``rotor``,
never from ``rotor._<module>`` (tests/test_rotor_engine.py); the tests of the internals
may. One private module per concept:

``_paper``       the paper's facts: rotor dimensions, frame rate, mark step, Table 3 as printed
``_frames``      the frame table: the printed rows split into frame indices
``_mechanics``   mass properties, normal reactions, accelerations, tangential forces
``_inference``   ``lambda`` and ``s_r`` from a symmetric and an asymmetric rotor's accelerations
``_simulator``   the rotor's exact motion with hidden effects, read out as frame indices
``_forward``     the law of motion's forward model: mark-crossing times
``_noise``       the reading-noise model and its estimate
``_family``      the model family and the fitted-model record
``_diagnostics`` residual diagnostics (likelihood, runs test, lag-1 autocorrelation)
``_fitting``     weighted least-squares fits of one model and of the whole family
``_parabola``    the paper's parabola fits
``_selection``   BIC selection with its simulation calibration (``effect_calibration.json``)
``_misreads``    misread-row detection
``_adequacy``    whether the chosen model explains a column (``adequacy_calibration.json``)
``_analysis``    the analysis of one test (one column)
``_groups``      groups of tests and the whole table
``_track``       the joint law of motion of a table on the plate's track
``_joint``       fits of the joint model to all launches of a table
``_verdict``     the verdict on the paper's question (``verdict_calibration.json``)
``_arm``         the friction arm against the contact radius: the least lambda an offset needs
``_rig``         the rig (rotor, camera, groups) that turns an offset into a torque
``_permutation`` the design's exact permutation tests over the launches' group labels
``_reconcile``   the four differences between the groups, and the two misread rules
``_lanes``       the lane test: the groups' tracks against the launches' (``lane_calibration.json``)
``_windows``     model-free windowed accelerations from the frames alone
``_tables``      whole tables simulated from a stated prior
``_sensitivity`` every assumption's weight on the verdict

The engine imports nothing from ``surfmet``; from ``contact`` only the error family, the
input checks, the materials and their pair (the friction arm's Hertz bound) and the
lazy-face helper.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from contact._lazy import attach

#: ``{module: its public names}``: the one list of the public face and where each name lives.
_FACE: dict[str, str] = {
    "_paper": ("BALL_RADIUS FPS HERTZ_CHECK HERTZ_CHECK_LOAD MARK_STEP PARABOLAS TABLE2 "
               "TABLE3_COLUMNS TABLE3_FILENAME"),
    "_frames": "table3 table3_tsv",
    "_mechanics": ("G_STANDARD MassProperties angular_acceleration mass_properties "
                   "normal_reactions optimal_collar_length paper_ball_loads paper_rotor "
                   "rolling_torque"),
    "_inference": "IDENTIFIABILITY RollingLawInference infer_rolling_law",
    "_simulator": "HiddenEffects SimulatedRun simulate_random_run",
    "_forward": "PARAM_NAMES crossing_times",
    "_family": "EXTENSION MODELS PARAM_UNITS SELECTABLE ModelFit",
    "_parabola": "paper_parabola",
    "_selection": "false_alarm_floor",
    "_adequacy": "ALPHA MIN_ROWS AdequacyCheck check_adequacy named_wave",
    "_analysis": "TestReport analyse_test group_of",
    "_groups": "LawOfMotionAnalysis analyse_table",
    "_arm": "ArmBound arm_bound",
    "_joint": ("GroupOffset fit_table group_offset lane_f launchwise_fit local_accelerations "
               "prepare_table shared_track_f"),
    "_lanes": "LaneTest lane_calibration",
    "_rig": "Rig RigGroup paper_rig rig_from_mapping solve_lambda",
    "_reconcile": "Difference MisreadRules differences_table misread_rules",
    "_sensitivity": "Experiment Sensitivity sensitivity_table settling_experiment",
    "_tables": "LANE_PRIOR Scenario draw_scenario simulate_table",
    "_track": "track_acceleration",
    "_verdict": "RotorVerdict frame_windows judge_table verdict_calibration",
    "_windows": "WindowedDifference",
}

_ATTRIBUTES = {name: f"{__name__}.{module}" for module, names in _FACE.items()
               for name in names.split()}

__all__ = sorted(_ATTRIBUTES)

__getattr__, __dir__ = attach(__name__, (), _ATTRIBUTES)

if TYPE_CHECKING:  # the same names for a type checker (tests/test_rotor_engine.py checks
    # this block against _FACE); at run time each loads on first use
    from rotor._adequacy import ALPHA, MIN_ROWS, AdequacyCheck, check_adequacy, named_wave
    from rotor._analysis import TestReport, analyse_test, group_of
    from rotor._arm import ArmBound, arm_bound
    from rotor._family import EXTENSION, MODELS, PARAM_UNITS, SELECTABLE, ModelFit
    from rotor._forward import PARAM_NAMES, crossing_times
    from rotor._frames import table3, table3_tsv
    from rotor._groups import LawOfMotionAnalysis, analyse_table
    from rotor._inference import IDENTIFIABILITY, RollingLawInference, infer_rolling_law
    from rotor._joint import (
        GroupOffset,
        fit_table,
        group_offset,
        lane_f,
        launchwise_fit,
        local_accelerations,
        prepare_table,
        shared_track_f,
    )
    from rotor._lanes import LaneTest, lane_calibration
    from rotor._mechanics import (
        G_STANDARD,
        MassProperties,
        angular_acceleration,
        mass_properties,
        normal_reactions,
        optimal_collar_length,
        paper_ball_loads,
        paper_rotor,
        rolling_torque,
    )
    from rotor._paper import (
        BALL_RADIUS,
        FPS,
        HERTZ_CHECK,
        HERTZ_CHECK_LOAD,
        MARK_STEP,
        PARABOLAS,
        TABLE2,
        TABLE3_COLUMNS,
        TABLE3_FILENAME,
    )
    from rotor._parabola import paper_parabola
    from rotor._reconcile import Difference, MisreadRules, differences_table, misread_rules
    from rotor._rig import Rig, RigGroup, paper_rig, rig_from_mapping, solve_lambda
    from rotor._selection import false_alarm_floor
    from rotor._sensitivity import Experiment, Sensitivity, sensitivity_table, settling_experiment
    from rotor._simulator import HiddenEffects, SimulatedRun, simulate_random_run
    from rotor._tables import LANE_PRIOR, Scenario, draw_scenario, simulate_table
    from rotor._track import track_acceleration
    from rotor._verdict import RotorVerdict, frame_windows, judge_table, verdict_calibration
    from rotor._windows import WindowedDifference

