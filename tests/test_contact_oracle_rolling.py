"""Steady rolling of the paper's pair against CONTACT run on the identical grid.

Independent truth: CONTACT (E. A. H. Vollebregt and J. J. Kalker, Apache-2.0, github
eve70a/CONTACT; user guide ``doc/user-guide.tex``), run on the decks in
``tests/data/contact_oracle`` (see its README): a steel ball R = 20 mm (body 1) rolling on
aluminium (body 2) at 5 N, mu = 0.3, 3D steady rolling with the normal-tangential coupling
(Panagiotopoulos process), free (F_x = 0) and at prescribed creepages 1e-4 and 1e-3, on
32^2 and 64^2 grids over [-1.25 a, 1.25 a]^2.

The two codes discretise the same equations in the same way on these decks: the same
element centres and undeformed distance, piecewise-constant tractions with the analytical
Boussinesq-Cerruti coefficients (CONTACT's ``C = 2``), the same combined constants G, nu, K
(body 1 receives the tractions in both), and with ``CHI = 0`` and ``DQ = DX`` CONTACT's
steady-state slip is our upwind difference s_j = w_j + (u_j - u_{j+1})/dx. So the answers
must agree to the iteration tolerances (CONTACT ``EPS = 1e-6``, ours 1e-6) and to the
digits CONTACT prints, not merely to a discretisation error. The tolerances:

- free-rolling creepage: half a unit of CONTACT's 4th printed digit (5e-8 here, 0.03 %)
  plus 2e-4 relative for the iteration tolerances; for scale, halving the grid pitch
  moves it by 5 %, and dropping the coupling (K = 0) makes it zero;
- F_x at prescribed creepage and pmax: 1e-4 relative (CONTACT's element table carries 6
  digits; seen: 1e-6);
- approach: half a unit of the 4th printed digit plus 1e-5 relative;
- numbers of contact, adhesion and slip elements: within one element, for an element on
  the adhesion/slip or contact boundary whose slip or pressure sits at the stopping
  tolerance (seen: identical in every case).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from contact.tangential import Creepage, pair_constants_from, sphere_grid, steady_rolling

DATA = Path(__file__).parent / "data" / "contact_oracle" / "contact_reference.json"
REF = json.loads(DATA.read_text())


def _half_unit(v: float, digits: int) -> float:
    """Half a unit of the last of ``digits`` significant digits of v."""
    return 0.5 * 10.0 ** (math.floor(math.log10(abs(v))) - digits + 1)


def _cases():
    for g in REF["grids"]:
        for name in g["cases"]:
            yield pytest.param(g["n"], name, id=f"n{g['n']}-{name}")


@pytest.fixture(scope="module")
def setup():
    case = REF["case"]
    b1, b2 = case["body1"], case["body2"]
    assert (b1["name"], b2["name"]) == ("steel", "aluminium")
    c = pair_constants_from(b1["G"]["value"], b1["nu"]["value"], b2["G"]["value"],
                            b2["nu"]["value"])
    return c, case["radius"]["value"], case["load"]["value"], case["mu"]["value"], \
        case["half_width"]["value"]


@pytest.mark.parametrize(("n", "name"), list(_cases()))
def test_rolling_against_contact(setup, n, name):
    """Creepage or F_x, pmax, approach and element counts as CONTACT's on its grid."""
    c, radius, load, mu, half = setup
    grid_ref = next(g for g in REF["grids"] if g["n"] == n)
    ref = grid_ref["cases"][name]
    grid = sphere_grid(radius, half, n)
    assert grid.dx == pytest.approx(grid_ref["dx"]["value"], rel=1e-12)
    if name == "free":
        r = steady_rolling(grid, c, load, mu, fx=0.0)
        xi = ref["creepage"]["value"]
        tol = _half_unit(xi, ref["creepage"]["significant_digits"]) + 2e-4 * abs(xi)
        assert abs(r.creepage.xi - xi) <= tol, (r.creepage.xi, xi)
        assert abs(r.fx) < 1e-6 * load
    else:
        r = steady_rolling(grid, c, load, mu, Creepage(ref["creepage"]["value"]))
        assert r.fx == pytest.approx(ref["fx"]["value"], rel=1e-4)
    assert r.pmax == pytest.approx(ref["pmax"]["value"], rel=1e-4)
    ap = ref["approach"]["value"]
    assert abs(r.approach - ap) <= _half_unit(ap, ref["approach"]["significant_digits"]) \
        + 1e-5 * ap
    counts = (int((r.p > 0).sum()), r.n_stick, r.n_slip)
    want = tuple(ref[k]["value"] for k in ("n_contact", "n_adhesion", "n_slip"))
    assert all(abs(a - b) <= 1 for a, b in zip(counts, want, strict=True)), (counts, want)
