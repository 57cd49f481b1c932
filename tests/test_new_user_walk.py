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
    from surfmet._spikes import spike_diagnosis

    z = np.random.default_rng(0).normal(size=(40, 40))
    z[5, 5] = 200.0
    diag = spike_diagnosis(z)
    assert diag.suspected
    assert "--spikes" in diag.message
    assert "spikes=True" not in diag.message and "roughness(" not in diag.message


def test_spike_caveat_of_a_result_names_the_option_not_the_api():
    """The restated diagnosis a roughness result carries says --spikes too."""
    from surfmet._roughness_result import consistent_diagnosis
    from surfmet._spikes import spike_diagnosis

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


def test_engine_quantities_in_text_as_the_one_formatter_writes_them():
    """An engine's SI value (the engines cannot import surfmet.units) in text as
    format_quantity writes it: 1.45e-05 m is 14.5 µm, 5.86e+10 Pa is 58.6 GPa."""
    from surfmet.units import readable_quantities

    assert readable_quantities("zone (= 1.45e-05 m) spans") == "zone (= 14.5 µm) spans"
    assert readable_quantities("E* = 5.86e+10 Pa, W = 10 N") == "E* = 58.6 GPa, W = 10 N"
    assert readable_quantities("this domain (1e-06 m^2)") == "this domain (1 mm²)"
    assert readable_quantities("2 mm at 5 m/s") == "2 mm at 5 m/s"  # already readable


def test_adhesion_warning_states_the_zone_in_nm(capsys):
    """adhesion's coarse-grid warning: the cohesive zone pi E* w / (4 sigma0^2) of
    E* = 1 GPa, w = 50 mJ/m², sigma0 = w / range = 25 MPa is 62.8 nm (was '6.28e-08 m')."""
    rc = main(["adhesion", "--radius", "10um", "--e-star", "1GPa", "--work-of-adhesion",
               "50mJ/m2", "--range", "2nm", "--grid", "32", "--steps", "8", "-q"])
    out = capsys.readouterr().out
    assert rc == 0
    warning = next(ln for ln in out.splitlines() if ln.startswith("warning"))
    assert "= 62.8 nm)" in warning and "e-08 m" not in warning
    assert "E* = 1 GPa" in out and "peak tension 25 MPa" in out


def test_contact_pressure_warning_and_hertz_row_in_the_formatters_units(capsys):
    """contact's elastic-limit warning and hertz-check's Hertz/BEM row write pressures as
    format_quantity does (aluminium's H = 1.04935 GPa, as the inputs print it; was
    '1049 MPa' beside '1.04935 GPa')."""
    from surfmet.data import path

    plate = str(path("paper_plate.x3p"))
    base = [plate, "--radius", "20mm", "--load", "10N", "--materials", "steel,aluminium",
            "--grid", "32", "-q"]
    assert main(["contact", *base]) == 0
    out = capsys.readouterr().out
    warning = next(ln for ln in out.splitlines() if "exceeds the softer" in ln)
    assert "hardness (1.049 GPa)" in warning and "MPa" not in warning.split("(")[1]
    assert main(["hertz-check", *base]) == 0
    out = capsys.readouterr().out
    row = next(ln for ln in out.splitlines() if ln.startswith("peak pressure "))
    # the BEM's peak is capped at the hardness where asperities yield
    assert row.split()[1:] == ["pressure", "255.2", "MPa", "1.049", "GPa"], row


def test_sweep_rows_carry_the_scans_unit_caveats(tmp_path, capsys):
    """A sweep row of a scan whose file states no units says so in its CSV and JSON Lines
    row (h5-multiple.h5 states neither height unit nor pixel), as the command's stderr
    and --json caveats do; a scan with its units stated has none."""
    import csv
    import json

    from conftest import REALDATA, shared_file

    from surfmet.data import path

    h5 = shared_file(REALDATA / "h5-multiple.h5")  # under CI a missing file fails
    out_csv, out_jsonl = tmp_path / "s.csv", tmp_path / "s.jsonl"
    rc = main(["sweep", "--plates", str(h5), str(path("paper_plate.x3p")), "--radius", "20mm",
               "--loads", "1N", "--materials", "steel,aluminium", "--grid", "16", "-q",
               "--csv", str(out_csv), "--json", str(out_jsonl)])
    capsys.readouterr()
    assert rc == 0
    rows = list(csv.DictReader(out_csv.open(encoding="utf-8")))
    lines = [json.loads(ln) for ln in out_jsonl.read_text(encoding="utf-8").splitlines()[1:]]
    for row in (rows, lines):
        by_plate = {r["plate"]: r["caveats"] for r in row}
        assert "height unit assumed" in by_plate[str(h5)]
        assert "pixel size assumed" in by_plate[str(h5)]
        assert not by_plate[str(path("paper_plate.x3p"))]


def test_show_on_a_container_says_which_measurement_it_draws(tmp_path, capsys):
    """show draws one measurement of a container: the text says which, and how to draw
    another; --json names it as the roughness command names its record."""
    import json

    from conftest import REALDATA, shared_file

    zp = shared_file(REALDATA / "container-2.zip")  # under CI a missing file fails
    assert main(["show", str(zp), "-o", str(tmp_path / "c.png"), "--2d", "--channel", "1",
                 "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["measurement"]["index"] == 1 and rec["measurement"]["of"] == 3
    assert rec["roughness"]["file"] == rec["measurement"]["name"]
    assert rec["measurement"]["name"].startswith(f"{zp}:gain_control_uncd_35")
    assert main(["show", str(zp), "-o", str(tmp_path / "d.png"), "--2d"]) == 0
    err = capsys.readouterr().err
    assert "drew measurement 1 of 3 of the container" in err and "--channel" in err


def test_scales_says_no_cut_off_once(capsys):
    """scales on a scan without a tip radius: 'cut-off none (no tip radius)', not
    'cut-off none (no tip radius (no cut-off))'."""
    from surfmet.data import path

    assert main(["scales", str(path("paper_ball.x3p")), "--per-decade", "2"]) == 0
    line = next(ln for ln in capsys.readouterr().out.splitlines() if "cut-off" in ln)
    assert line.endswith("cut-off none (no tip radius)"), line


def test_demo_states_the_ball_fit_as_fit_prints_it(capsys):
    """The demo's sphere line and surfmet fit on the same ball: the same radius,
    uncertainty and residuals in the same units (the demo wrote '± 0.74 µm' and '0.85 µm'
    where fit wrote '± 745 nm' and '845.2 nm')."""
    import importlib
    import json

    from surfmet.data import path

    story = importlib.import_module("surfmet.demo._story")  # the package's story() shadows it
    ball = str(path("paper_ball.x3p"))
    assert main(["fit", ball, "--shape", "sphere", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert main(["fit", ball, "--shape", "sphere"]) == 0
    fit_text = capsys.readouterr().out
    radius_line = next(ln for ln in fit_text.splitlines() if ln.startswith("radius"))
    rms = next(ln for ln in fit_text.splitlines() if ln.startswith("rms residual"))
    form = next(ln for ln in fit_text.splitlines() if ln.startswith("form deviation"))
    t = story._Text()
    circle = {"profile": "row:1", "radius": {"value": 0.02, "unit": "m"}}
    story._ball(t, {"ball": {"sphere": rec, "nominal_radius": {"value": 0.02, "unit": "m"},
                             "radius_minus_nominal": {"value": 0.0, "unit": "m"},
                             "radius_minus_nominal_in_uncertainties": 0.0,
                             "row_circle": circle, "column_circle": circle}})
    demo = "\n".join(t.lines)
    assert f"R = {radius_line.split(None, 1)[1]}" in demo
    assert f"sphere residual {rms.split(None, 2)[2]} rms" in demo
    assert f"form deviation {form.split()[2]} {form.split()[3]} (PV" in demo


def test_demo_states_the_hardness_as_the_hertz_check_does():
    """The demo's contact section gives aluminium's hardness H = 1.04935 GPa (the material
    table) as its Hertz check's bullets do, '1.05 GPa' (was '1049 MPa')."""
    import importlib

    story = importlib.import_module("surfmet.demo._story")
    q = lambda v, u: {"value": v, "unit": u}  # noqa: E731
    solve = {"method": "normal BEM, elastic-plastic", "iterations": 8, "residual": q(1e-7, ""),
             "residual_definition": "rms gap error", "tolerance": q(1e-6, ""),
             "converged": True, "edge_contact": False, "warning": None}
    contact = {"load": q(4.67, "N"), "rotor_loads": {k: q(4.0, "N") for k in (
        "symmetric", "asymmetric_ball1", "asymmetric_ball2")},
        "grid": {"nx": 8, "ny": 8, "dx": q(5e-6, "m")}, "solve": solve,
        "radius_95": q(3e-4, "m"), "hertz": {"a": q(1e-4, "m"), "delta": q(5e-7, "m")},
        "approach": q(2e-6, "m"), "n_clusters": 3, "contact_area": q(4e-9, "m^2"),
        "plastic_area": q(3e-9, "m^2"), "hardness": q(1.04935e9, "Pa"),
        "regime": "plastic"}
    t = story._Text()
    story._contact(t, {"contact": contact})
    line = next(ln for ln in t.lines if "at the hardness" in ln)
    assert line.endswith("at the hardness 1.05 GPa"), line


def test_flat_contact_adhesive_table_states_its_units(tmp_path, capsys):
    """flat-contact --work-of-adhesion: the gap columns name their unit (µm, as the bare
    table's 'gap (µm)'), w = 200 mJ/m², range 5 nm, peak tension w/range = 40 MPa, and
    the engine's warning writes its lengths as the one formatter does."""
    import re

    import surfmet
    from surfmet.synth import self_affine

    topo = self_affine(64, 1e-6, hurst=0.7, slope_rms=0.05, short_cutoff=4e-6, seed=2)
    scan = str(surfmet.write(topo, tmp_path / "sa.npz"))
    assert main(["flat-contact", scan, "--e-star", "1GPa", "--pressures", "1MPa",
                 "--work-of-adhesion", "200mJ/m2", "--range", "5nm", "-q"]) == 0
    out = capsys.readouterr().out
    assert "w = 200 mJ/m², range 5 nm, peak tension 40 MPa" in out
    head = next(ln for ln in out.splitlines() if "A/A0 bare" in ln)
    assert "gap bare (µm)" in head and "gap adh (µm)" in head
    warning = next(ln for ln in out.splitlines() if "WARNING" in ln)
    assert not re.search(r"\de-\d+ m\b", warning), warning


def test_spectrum_curvature_in_the_unit_of_the_all_scales_summary(capsys):
    """spectrum's curvature rms in 1/µm, the unit its several-measurement summary and Spc
    print (it wrote '1.285e+05 1/m' for one file and '0.1285 1/µm' for several); the
    number is the JSON's 1/m value times 1e-6."""
    import json

    from surfmet.data import path

    plate = str(path("paper_plate.x3p"))
    assert main(["spectrum", plate, "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)["curvature_rms"]
    assert main(["spectrum", plate]) == 0
    line = next(ln for ln in capsys.readouterr().out.splitlines() if "curvature rms" in ln)
    words = line.split()
    k = words.index("1/µm")
    assert float(words[k - 1]) == pytest.approx(rec["spectrum"]["value"] * 1e-6, rel=1e-4)
    assert "1/m " not in line


def test_info_text_states_units_once_and_quantities_readably(capsys):
    """info dektak-1.csv: the height unit once, as µm (the metadata dump repeated it as
    'height_unit: um'), and the stylus tip radius 2.5 µm (the file's 'Radius: 2.5 µm'),
    not "{'value': 2.5e-06, 'unit': 'm'}"."""
    from conftest import REALDATA, shared_file

    f = shared_file(REALDATA / "dektak-1.csv")  # under CI a missing file fails
    assert main(["info", str(f)]) == 0
    out = capsys.readouterr().out
    assert "height unit   µm" in out and "height_unit:" not in out
    assert "  tip_radius: 2.5 µm" in out.splitlines()
    assert "'unit': 'm'" not in out
