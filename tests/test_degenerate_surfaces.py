"""Degenerate surfaces and what each output says about them (issue 34, item 15).

A plane is flat for every command (one criterion, :func:`profiles._form.is_flat`): its
amplitude parameters are 0 and its shape parameters left out, where roughness printed
Sa 1.9e-15 nm, Ssk -0.106, Sdr -3.3e-14 % and spectrum called it flat. A circle fit whose
curvature a line explains as well is refused, as the sphere fit is; its form deviation and
residual PV are named apart. An unfiltered profile's values carry P names; the CSV's
caveats carry the spike warning; a flat contact states GW's negative gap and its edge
contact once.
"""

from __future__ import annotations

import csv
import io
import json
import math

import numpy as np
import pytest

from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography
from surfmet.cli import main
from surfmet.mechanics.spectrum import prepare
from surfmet.roughness import roughness

HEIGHTS = ("Sa", "Sq", "Sp", "Sv", "Sz", "Sdq", "Sdr")


def test_the_netcdf_plane_is_flat(realdata, capsys):
    path = str(realdata("nc-1.nc"))
    assert main(["roughness", path, "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)[0]
    assert {k: q["value"] for k, q in rec["parameters"].items()} == dict.fromkeys(HEIGHTS, 0.0)
    assert "the scan is flat" in rec["settings"]["notes"][0]
    assert "Ssk" in rec["settings"]["notes"][0]  # named among those left out
    assert rec["settings"]["spike_diagnosis"]["suspected"] is False
    assert main(["spectrum", path]) == 1
    assert "the scan is flat" in capsys.readouterr().err


@pytest.mark.parametrize(("noise", "flat"), [(1e-15, True), (1e-9, False)])
def test_roughness_and_spectrum_call_the_same_scans_flat(noise, flat):
    # a tilted plane 1 µm above zero, with noise of that fraction of its heights
    rng = np.random.default_rng(2)
    j, i = np.mgrid[:32, :32]
    z = 1e-6 + 1e-8 * i + 2e-8 * j
    topo = Topography(z * (1 + noise * rng.standard_normal(z.shape)), 1e-6, 1e-6)
    res = roughness(topo)
    assert ("Ssk" not in res.parameters) is flat
    if flat:
        with pytest.raises(SurfmetInputError, match="flat"):
            prepare(topo, periodic=False)
    else:
        prepare(topo, periodic=False)
        assert res.value("Sq") > 0


def test_a_straight_profile_is_flat():
    x = np.arange(3000) * 1e-6
    res = roughness(Profile(5e-7 + 3e-4 * x, 1e-6))
    assert {k: v for k, (v, _) in res.parameters.items()} == {
        "Ra": 0.0, "Rq": 0.0, "Rp": 0.0, "Rv": 0.0, "Rz": 0.0, "Rt": 0.0, "Rdq": 0.0}
    assert "Rsk" in res.settings["notes"][0]


def test_a_circle_fit_of_a_flat_r_profile_is_refused(realdata, capsys):
    # the Mitutoyo R-profile is levelled roughness: a line explains it as well as the
    # 35 m ± 2.4 m "circle" that was printed
    assert main(["fit", str(realdata("mitutoyo_2_mock.xlsx")), "--shape", "circle"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "curvature not resolved" in err[0]


def test_a_circle_fit_names_its_form_deviation_and_residual_pv(tmp_path, capsys):
    # a 10 mm arc over 2 mm with a quartic form error c u⁴ (u from the centre): the circle
    # absorbs its degree-2 part, leaving c L⁴ (8/35) P4(u/L), whose PV is c L⁴ (8/35)(10/7)
    import surfmet

    r, half, c = 10e-3, 1e-3, 1e6
    x = np.linspace(-half, half, 2001)
    z = np.sqrt(r * r - x * x) + c * x**4
    rng = np.random.default_rng(5)
    noisy = z + 2e-9 * rng.standard_normal(x.size)
    noisy[1000] += 5e-6  # one spike: the residual PV, not the form deviation
    path = tmp_path / "arc.npz"
    surfmet.write(Profile(noisy, x[1] - x[0]), path)
    assert main(["fit", str(path), "--shape", "circle", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    expected = c * half**4 * (8 / 35) * (10 / 7)
    assert rec["form_pv"]["value"] == pytest.approx(expected, rel=0.06)  # 327 nm
    assert rec["pv_form_deviation"]["value"] > 5e-6 > 5 * rec["form_pv"]["value"]
    assert rec["names"]["pv_form_deviation"] == "residual PV (all points)"
    assert main(["fit", str(path), "--shape", "circle"]) == 0
    out = capsys.readouterr().out
    assert "form deviation" in out and "residual PV" in out


def test_an_unfiltered_profile_prints_p_names(realdata, capsys):
    assert main(["roughness", str(realdata("dektak-1.csv")), "--window", "468um:733um"]) == 0
    out = capsys.readouterr().out
    names = [line.split()[0] for line in out.splitlines() if line.startswith("  P")]
    assert names[:4] == ["Pa", "Pq", "Pp", "Pv"]
    assert not any(line.startswith("  Ra ") for line in out.splitlines())
    assert "primary profile" in out


def test_the_csv_caveats_carry_the_spike_warning(tmp_path, capsys):
    import surfmet

    rng = np.random.default_rng(7)
    z = 1e-8 * rng.standard_normal((64, 64))
    z[10, 10] = z[40, 50] = 5e-6  # two spikes dominate Sq and Sz
    path = tmp_path / "spiky.npz"
    surfmet.write(Topography(z, 1e-6, 1e-6), path)
    assert main(["roughness", str(path), "--csv", "-"]) == 0
    row = next(csv.DictReader(io.StringIO(capsys.readouterr().out)))
    assert "dominate Sq, Sz" in row["caveats"]


def test_flat_contact_flags_gw_negative_gap_and_says_edge_contact_once(tmp_path, capsys):
    import surfmet
    from surfmet.mechanics.flat_contact import flat_contact, plot
    from surfmet.synth import self_affine

    topo = self_affine(64, 64e-6, hurst=0.8, slope_rms=0.1, seed=1)
    rep = flat_contact(topo, e_star=1e9, pressures=[1e6, 3e7], periodic=False)
    gw_gap = rep.models["gw"].mean_gap
    assert gw_gap[0] > 0 > gw_gap[1]  # GW's own closed form goes below zero at 30 MPa
    caveats = [c for c in rep.caveats if c.startswith("Greenwood-Williamson")]
    assert len(caveats) == 1 and "30 MPa" in caveats[0] and "validity" in caveats[0]
    fig = plot(rep)
    gw_line = next(ln for ln in fig.axes[1].get_lines() if ln.get_label() == "GW")
    assert math.isnan(gw_line.get_ydata()[1]) and gw_line.get_ydata()[0] > 0
    path = tmp_path / "rough.npz"
    surfmet.write(topo, path)
    assert main(["flat-contact", str(path), "--e-star", "1GPa", "--pressures", "1MPa,30MPa",
                 "--periodic", "no", "--quiet"]) == 0
    out, err = capsys.readouterr()
    assert (out + err).count("contact reaches the edge") == 1
    assert "as it must for a rough scan pressed on a flat" in out + err
    assert "CAVEAT: Greenwood-Williamson" in out


def test_the_profile_figure_names_the_primary_profile_parameters(realdata):
    from surfmet.plots.profile import profile_figure

    res = roughness(realdata("dektak-1.csv"), window="468um:733um")
    fig = profile_figure(res.analysis)
    labels = [ln.get_label() for ax in fig.axes for ln in ax.get_lines()]
    assert any(lb.startswith("Pa = ") for lb in labels)
    assert not any(lb.startswith("Ra = ") for lb in labels)
