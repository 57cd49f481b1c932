"""``--resolution-study`` of ``contact``, ``hertz-check`` and ``rolling``: the command-line
options turned into a call of :func:`surfmet.mechanics.resolution_study.contact_study` or
:func:`surfmet.mechanics.resolution_study.rolling_study`, and the study printed as a table
or JSON."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet._errors import SurfmetInputError
from surfmet.cli._common import emit_json, log


def add_resolution_study_flag(parser: Any) -> None:
    """The ``--resolution-study`` flag (run by :func:`run_study`)."""
    parser.add_argument("--resolution-study", action="store_true",
                        help="solve on the scans coarsened 8x, 4x, 2x and native; report each "
                        "quantity per pixel and which converged "
                        "(surfmet.mechanics.resolution_study)")


def run_study(args: argparse.Namespace, command: str) -> int:
    """``--resolution-study`` for ``contact``, ``hertz-check`` and ``rolling``."""
    from surfmet.mechanics.resolution_study import contact_study, rolling_study, study_lines
    from surfmet.records import study_record

    def progress(label: str) -> None:
        log(f"resolution study: solving at {label}")

    # the study sets each level's grid and domain itself; these options would be ignored
    for opt in ("grid", "size", "out", "plot"):
        if getattr(args, opt, None) is not None:
            raise SurfmetInputError(f"--{opt} does not apply to --resolution-study (each "
                                    "level's grid follows its pixel on one common domain)")
    if getattr(args, "periodic", False):
        raise SurfmetInputError("--periodic does not apply to --resolution-study")

    if command == "rolling":
        # the facade resolves the materials, the lossy body's share and the hardness
        study, _ = rolling_study(args.plate, args.ball, radius=args.radius,
                                 loads=args.loads,
                                 materials=args.materials, hardness=args.hardness,
                                 lossy=args.lossy, spikes=args.spikes, progress=progress,
                                 model=args.model, alpha_h=args.alpha_h,
                                 kinematics=args.kinematics)
    else:
        plastic = ((command == "contact" and args.plastic)
                   or (command == "hertz-check" and not args.elastic))
        study, _ = contact_study(args.plate, args.ball, radius=args.radius, load=args.load,
                                 materials=args.materials,
                                 hardness=getattr(args, "hardness", None), plastic=plastic,
                                 spikes=getattr(args, "spikes", "remove"),
                                 progress=progress)
    if args.json:
        emit_json({"command": command, "resolution_study": study_record(study)})
        return 0
    for line in study_lines(study):
        print(line)
    return 0
