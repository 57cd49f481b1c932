"""Hertz theory against the paper's numbers and against independent integrals."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy import integrate

from contact._errors import ContactInputError
from contact._hertz import hertz_cylinder, hertz_sphere, hertz_sphere_from_approach
from contact._materials import composite_modulus, material


@pytest.fixture
def paper(paperdata):
    return json.loads(paperdata("paper_values.json").read_text())["hertz_check_in_paper"]


def test_reproduces_the_paper_hertz_check(paper):
    m = paper["materials_assumed_here"]
    P = (1 - m["steel"]["nu"] ** 2) / m["steel"]["E_Pa"] + (
        1 - m["aluminium"]["nu"] ** 2) / m["aluminium"]["E_Pa"]
    hz = hertz_sphere(paper["sphere_radius_m"], paper["normal_force_N"], 1 / P)
    # the paper prints delta = 0.936 um and a = 136 um (a = 136.8 um, printed truncated)
    assert round(hz.delta * 1e6, 3) == paper["max_approach_um"]
    assert hz.a * 1e6 == pytest.approx(paper["contact_radius_um"], rel=0.01)
    # and the paper's own formulas, written with P
    N, R = paper["normal_force_N"], paper["sphere_radius_m"]
    assert hz.delta == pytest.approx((9 * P**2 * N**2 / (16 * R)) ** (1 / 3), rel=1e-13)
    assert hz.a == pytest.approx((0.75 * N * R * P) ** (1 / 3), rel=1e-13)


def test_table_materials_give_the_same_result(paper):
    E = composite_modulus(material("steel"), material("aluminium"))
    hz = hertz_sphere(0.02, 10.0, E)
    assert round(hz.delta * 1e6, 3) == paper["max_approach_um"]


def test_sphere_identities():
    hz = hertz_sphere(0.01, 3.0, 1e11)
    assert hz.delta == pytest.approx(hz.a**2 / hz.radius, rel=1e-14)
    assert hz.load == pytest.approx(4 / 3 * hz.e_star * math.sqrt(hz.radius) * hz.delta**1.5,
                                    rel=1e-13)
    assert hz.p0 == pytest.approx(1.5 * hz.mean_pressure, rel=1e-14)
    back = hertz_sphere_from_approach(0.01, hz.delta, 1e11)
    assert back.load == pytest.approx(3.0, rel=1e-12)
    # stiffness dW/d(delta) by finite difference
    d = 1e-4 * hz.delta
    k = (hertz_sphere_from_approach(0.01, hz.delta + d, 1e11).load
         - hertz_sphere_from_approach(0.01, hz.delta - d, 1e11).load) / (2 * d)
    assert hz.stiffness == pytest.approx(k, rel=1e-7)


def test_sphere_pressure_integrates_to_the_load():
    hz = hertz_sphere(0.02, 10.0, 58.6e9)
    total, _ = integrate.quad(lambda r: 2 * math.pi * r * float(hz.pressure(r)), 0, hz.a)
    assert total == pytest.approx(10.0, rel=1e-8)
    assert float(hz.pressure(1.01 * hz.a)) == 0.0


def test_sphere_displacement_against_boussinesq_integral():
    # u(r) = 1/(pi E*) * integral of p(s) / |r - s| dA, done numerically in polar
    # coordinates around the field point (an independent evaluation of Johnson's result).
    hz = hertz_sphere(0.02, 10.0, 58.6e9)
    a = hz.a

    def u_numeric(r):
        def inner(phi):
            # distance rho from the field point along direction phi to the contact edge
            c = r * math.cos(phi)
            disc = c * c - (r * r - a * a)
            if disc <= 0:
                return 0.0
            lo = max(0.0, -c - math.sqrt(disc))
            hi = -c + math.sqrt(disc)
            if hi <= 0:
                return 0.0
            def f(rho, phi=phi):
                return float(hz.pressure(math.hypot(r + rho * math.cos(phi),
                                                    rho * math.sin(phi))))

            return integrate.quad(f, lo, hi, limit=200)[0]

        return integrate.quad(inner, 0, 2 * math.pi, limit=200)[0] / (math.pi * hz.e_star)

    for r in (0.0, 0.5 * a, 1.5 * a, 3.0 * a):
        assert float(hz.displacement(r)) == pytest.approx(u_numeric(r), rel=2e-6)
    # inside, the surfaces conform to the sphere: u = delta - r^2 / 2R
    r = np.linspace(0, a, 7)
    np.testing.assert_allclose(hz.displacement(r), hz.delta - r**2 / (2 * hz.radius), rtol=1e-13)
    # far away, the point-load (Boussinesq) limit W / (pi E* r)
    assert float(hz.displacement(200 * a)) == pytest.approx(10.0 / (math.pi * hz.e_star * 200 * a),
                                                            rel=1e-5)
    assert np.all(hz.gap(r) == 0) and float(hz.gap(2 * a)) > 0


def test_cylinder_pressure_and_relative_displacement():
    hc = hertz_cylinder(0.01, 2e4, 1e11)
    total, _ = integrate.quad(lambda x: float(hc.pressure(x)), -hc.a, hc.a)
    assert total == pytest.approx(2e4, rel=1e-8)
    assert hc.p0 == pytest.approx(math.sqrt(2e4 * 1e11 / (math.pi * 0.01)), rel=1e-13)

    # u(0) - u(x) = -(2/(pi E*)) * integral p(s) ln(|s| / |x - s|) ds (2D Boussinesq),
    # integrated numerically with s = a sin(theta) to tame the square root
    def rel_numeric(x):
        def f(th):
            s = hc.a * math.sin(th)
            return hc.p0 * math.cos(th) ** 2 * hc.a * math.log(abs(x - s) / abs(s))

        pts = [0.0] + ([math.asin(x / hc.a)] if abs(x) < hc.a else [])
        val = integrate.quad(f, -math.pi / 2, math.pi / 2, points=pts, limit=400)[0]
        return 2 / (math.pi * hc.e_star) * val

    for x in (0.3 * hc.a, hc.a, 2.0 * hc.a, 5.0 * hc.a):
        assert float(hc.relative_displacement(x)) == pytest.approx(rel_numeric(x), rel=1e-6)


@pytest.mark.parametrize(("args", "match"), [((0.0, 10.0, 1e11), "radius"),
                                             ((0.02, -1.0, 1e11), "load"),
                                             ((0.02, 10.0, math.nan), "E")])
def test_bad_input_is_refused(args, match):
    with pytest.raises(ContactInputError, match=match):
        hertz_sphere(*args)
