"""The example scripts start: their imports resolve (examples/paper_2022/contact.py shares
its name with the contact package, which must not shadow it) and they parse arguments."""

import subprocess
import sys
from pathlib import Path

import pytest

# the command-line scripts; the gallery's how-tos (plot_*.py) take no arguments and run in
# the docs build (docs/conf.py)
EXAMPLES = sorted(p for p in (Path(__file__).resolve().parents[1] / "examples").rglob("*.py")
                  if not p.name.startswith("plot_"))


@pytest.mark.parametrize("script", EXAMPLES, ids=lambda p: p.name)
def test_example_imports_and_shows_help(script):
    out = subprocess.run([sys.executable, str(script), "--help"], capture_output=True,
                         text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-2000:]
    assert out.stdout.startswith("usage:")


def test_examples_are_found():
    assert {p.name for p in EXAMPLES} >= {"contact.py", "rotor.py", "make_surfaces.py"}


# issue 16, item 18: the numbers the README quotes from examples/paper_2022/contact.py are
# asserted here, computed the way the example computes them (the 10 N check on the bundled
# pair at the scans' own pixel); the README text is read so that the two cannot drift.
def test_readme_numbers_of_the_paper_pair():
    import re

    from contact.materials import contact_hardness
    from contact.roughcontact import plasticity_index
    from surfmet.mechanics.hertz_check import hertz_check

    root = Path(__file__).resolve().parents[1]
    readme = " ".join((root / "README.md").read_text(encoding="utf-8").split())
    m = re.search(r"GT removes (\d+) % of Hertz's effective-radius error and (\d+) % of its "
                  r"profile error at 10 N \(a\* off the BEM by −(\d+\.\d) %, profile by "
                  r"(\d+\.\d) % of p0", readme)
    psi_text = re.search(r"ψ = \(E\*/H\)√\(σ_s/R_s\) = (\d+\.\d)", readme)
    assert m and psi_text, "the README paragraph on the model hierarchy changed its wording"
    data = root / "surfmet" / "data"
    chk = hertz_check(data / "paper_plate.x3p", ball=data / "paper_ball.x3p", radius=0.02,
                      load=10.0, materials="steel,aluminium")
    h = chk.hierarchy
    gt = h.models["greenwood_tripp"]
    assert round(100 * h.gain("greenwood_tripp", "radius")) == int(m.group(1))
    assert round(100 * h.gain("greenwood_tripp", "profile")) == int(m.group(2))
    assert round(-100 * gt.radius_error, 1) == float(m.group(3))
    assert round(100 * gt.profile_error, 1) == float(m.group(4))
    psi = plasticity_index(chk.e_star, contact_hardness(chk.ball_material, chk.plate_material),
                           chk.summits)
    assert round(psi, 1) == float(psi_text.group(1))
    # the share of the real contact area at the hardness (quoted over 10 N and the rotor's
    # loads): the 10 N value lies in the quoted range
    share = re.search(r"(\d+)–(\d+) % of the real contact area is at the hardness", readme)
    assert share
    c = chk.comparison
    assert int(share.group(1)) <= round(100 * c.plastic_fraction / c.area_fraction) \
        <= int(share.group(2))
