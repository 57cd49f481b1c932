"""What a new user's walk of every command found (issue 34, "Done means"): each test
fails on the code before its fix."""

from __future__ import annotations

import numpy as np
import pytest

from surfmet.cli import main


def test_top_level_help_states_the_pressure_rule(capsys):
    """The help epilog states the rule every pressure option follows (h7's rule)."""
    with pytest.raises(SystemExit):
        main(["--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "Pressures always need their unit (--hardness 1GPa, --e-star, --pressures)" in text


def test_spike_caveat_names_the_option_not_the_api():
    """The spike warning a command prints names --spikes, not roughness(..., spikes=True)."""
    from surfmet.spikes import spike_diagnosis

    z = np.random.default_rng(0).normal(size=(40, 40))
    z[5, 5] = 200.0
    diag = spike_diagnosis(z)
    assert diag.suspected
    assert "--spikes" in diag.message
    assert "spikes=True" not in diag.message and "roughness(" not in diag.message


def test_spike_caveat_of_a_result_names_the_option_not_the_api():
    """The restated diagnosis a roughness result carries says --spikes too."""
    from surfmet.roughness_result import consistent_diagnosis
    from surfmet.spikes import spike_diagnosis

    z = np.random.default_rng(0).normal(size=(40, 40))
    z[5, 5] = 200.0
    d = z - z.mean()
    values = {"Sq": float(np.sqrt(np.mean(d * d))), "Sa": float(np.abs(d).mean()),
              "Sku": float(np.mean(d**4) / np.mean(d * d) ** 2) + 0.5}
    diag = consistent_diagnosis(spike_diagnosis(z), values, "S", None)
    assert diag.suspected and "--spikes" in diag.message
    assert "spikes=True" not in diag.message and "roughness(" not in diag.message


def test_inputs_echo_names_the_plate_file_not_its_topography(capsys):
    """The text's inputs name the scan the user gave, as the JSON does (was the
    Topography's repr, ``Topography(nx=1024, ... dx=5e-06 m ...)``)."""
    from surfmet.data import path

    plate = str(path("paper_plate.x3p"))
    rc = main(["rolling-contact", plate, "--radius", "20mm", "--materials",
               "steel,aluminium", "--load", "5N", "--mu", "0.3", "--grid", "16", "-q"])
    out = capsys.readouterr().out
    assert rc == 0
    lines = out.split("\ninputs\n", 1)[1].splitlines()
    assert any(ln.split() == ["plate", plate] for ln in lines), lines
    assert "Topography(" not in out
