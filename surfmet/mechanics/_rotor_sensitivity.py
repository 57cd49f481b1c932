"""Every assumption's weight on the rotor verdict, the experiment that would settle it, and
the paper's swapped labels, in words (:mod:`rotor._sensitivity`; their JSON is
:mod:`surfmet.records._rotor_sensitivity`). Called by :mod:`surfmet.mechanics.rotor_verdict`,
so every entry point says them.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from rotor import Experiment, RotorVerdict

__all__ = ["EXPERIMENT_DESIGN", "EXPERIMENT_RECORDS", "LABEL_SWAP", "SAG_MEANING",
           "experiment_for", "experiment_lines", "label_swap_text", "sensitivity_lines"]

LABEL_SWAP = ("the paper's text labels its parabolas the other way round: its 'symmetric' "
              "phi_s fits Table 3's asymmetric columns and its phi_a the symmetric ones; the "
              "verdict reads Table 3's column labels (the asymmetric rotor slower, as the "
              "text also says); read with the text's labels the offset's sign flips, and "
              "with it the sign of lambda - 1")
"""What every entry point says about the paper's swapped phi_s/phi_a labels."""

def label_swap_text(v: RotorVerdict) -> str | None:
    """The label swap, for the paper's rig and Table 3's groups; None for other rigs."""
    if v.rig is None:
        return None
    from rotor import paper_rig

    return LABEL_SWAP if v.rig == paper_rig() else None


def _lam(x: float) -> str:
    return f"{x:.3g}" if math.isfinite(x) else "none"


def sensitivity_lines(v: RotorVerdict) -> list[str]:
    """The sensitivity table in words."""
    from rotor import sensitivity_table

    rows = sensitivity_table(v)
    if not rows:
        return []
    out = ["  every assumption's weight (code; offset rad/s²; lambda needed at the slope; "
           "least lambda with the arm at its bound, over the offset's interval):"]
    for r in rows:
        out.append(f"    {r.assumption + ': ' + r.setting:66s} {r.code:13s} "
                   f"{r.offset:+.3f}  {_lam(r.lambda_needed):>5s}  {_lam(r.lambda_bound)} "
                   f"[{_lam(r.lambda_bound_low)}, {_lam(r.lambda_bound_high)}]"
                   + (f"  ({r.note})" if r.note else ""))
    return out


EXPERIMENT_DESIGN = ("both collar positions on one lane, interleaved in a randomised run "
                     "order (drawn before the session)")
"""How the settling experiment is run."""

EXPERIMENT_RECORDS = ("alpha and beta at the lane (to 0.01 deg)",
                      "xi_G (both scales' readings for each collar position)",
                      "the run order and the time of each launch",
                      "the lane (lateral position of the release)")
"""What the settling experiment records at each launch."""

SAG_MEANING = ("the sag the asymmetric group's decay implies were the plate's shape its cause "
               "(Delta theta L / 8): a straightedge along the lane shows it or not")
"""What the straightedge check's sag means."""


def experiment_for(e: Experiment) -> str:
    """What the settling experiment ``e`` (:class:`rotor.Experiment`) is sized for."""
    return (f"lambda 4/3 told from 1 with {e.power * 100:g} % power at {e.alpha * 100:g} % "
            f"(two-sided), launch spread {e.launch_sd:.3g} rad/s²")


def experiment_lines(v: RotorVerdict) -> list[str]:
    """The experiment that would settle it, in words."""
    from rotor import settling_experiment

    e = settling_experiment(v)
    if e is None:
        return []
    out = [f"  the experiment that would settle it ({experiment_for(e)}):"]
    for r in e.rows:
        n = r.launches if r.launches else "more than 100000"
        out.append(f"    arm {r.arm * 1e6:6.1f} µm ({r.arm_basis}), loads "
                   f"{r.loads}: lambda = 4/3 gives {r.offset_4_3:+.4f} "
                   f"rad/s², {n} launches per group")
    out += [f"    straightedge check: the asymmetric group's decay, were the plate's shape its "
            f"cause, means the slope falls {math.degrees(e.slope_change):.2f} deg "
            f"over {e.length:.2f} m, a concave sag of {e.sag * 1e3:.2f} mm",
            f"    design: {EXPERIMENT_DESIGN}; record {', '.join(EXPERIMENT_RECORDS)}"]
    return out
