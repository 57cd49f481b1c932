"""Scans and results in a notebook: ``_repr_html_`` shows the key numbers with their units
(and a scan a small height map), ``repr`` is one short line. Expected numbers are closed
forms of the cases built here, not the code's own output."""

from __future__ import annotations

import base64
import math
import re
import struct
import zlib

import numpy as np
import pytest

from surfmet._model import Profile, Topography


def _png(html: str) -> tuple[int, int, np.ndarray]:
    data = base64.b64decode(re.search(r"data:image/png;base64,([A-Za-z0-9+/=]+)", html)[1])
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", data[16:24])
    n = struct.unpack(">I", data[33:37])[0]
    assert data[37:41] == b"IDAT"
    raw = zlib.decompress(data[41:41 + n])
    rows = np.frombuffer(raw, np.uint8).reshape(height, width + 1)
    assert (rows[:, 0] == 0).all()  # filter type none
    return width, height, rows[:, 1:]


def test_topography_shows_a_small_map_and_its_grid():
    # a ramp from 0 to 3 µm along x: 300 x 150 points of 1 µm x 2 µm
    heights = np.tile(np.linspace(0.0, 3e-6, 300), (150, 1))
    heights[0, 0] = np.nan
    topo = Topography(heights, 1e-6, 2e-6, metadata={"format": "x3p"})
    html = topo._repr_html_()
    width, height, grey = _png(html)
    assert max(width, height) <= 128 and (width, height) == (100, 50)  # every 3rd point
    assert grey[:, -1].max() == 255 and grey[:-1, 0].min() == 30  # high bright, low dark
    assert grey[-1, 0] == 0  # the non-measured corner (y up: last row) is black
    for text in ("300 × 150", "300 µm × 300 µm", "1 µm × 2 µm", "3", "µm", "x3p"):
        assert text in html, text
    assert len(repr(topo)) < 120


def test_profile_shows_its_line_and_numbers():
    x = np.arange(1001) * 0.5e-6
    profile = Profile(1e-6 * np.sin(2 * np.pi * x / 100e-6), 0.5e-6)
    html = profile._repr_html_()
    assert "<polyline" in html and "<svg" in html
    for text in ("1001", "500", "µm", "0.5", "uniform", "2"):  # 500 µm long, range 2 µm
        assert text in html, text


def test_roughness_result_table_and_short_repr():
    from surfmet.roughness import roughness

    # a ±1 µm checkerboard: Sa = Sq = 1 µm, Sz = 2 µm exactly (its best plane is z = 0)
    z = np.where(np.add.outer(np.arange(64), np.arange(64)) % 2 == 0, 1e-6, -1e-6)
    result = roughness(Topography(z, 1e-6, 1e-6))
    html = result._repr_html_()
    for name, number in (("Sa", "1"), ("Sq", "1"), ("Sz", "2")):
        assert re.search(rf"<th[^>]*>{name}</th><td[^>]*>{number}</td><td[^>]*>µm</td>", html)
    text = repr(result)
    assert text.startswith("RoughnessResult(areal") and "Sa=1 µm" in text
    assert len(text) < 120 and "\n" not in text


@pytest.fixture(scope="module")
def smooth_contact():
    from surfmet.mechanics.ball_contact import ball_contact

    return ball_contact(radius=0.02, load=10.0, materials="steel,aluminium", grid=64)


def _hertz(e_star: float, load: float = 10.0, radius: float = 0.02) -> tuple[float, float]:
    a = (3 * load * radius / (4 * e_star)) ** (1 / 3)
    return a, 3 * load / (2 * math.pi * a * a)


def _e_star() -> float:
    # steel on aluminium, E and nu of contact's table, composed by hand
    from contact import material

    s, al = material("steel"), material("aluminium")
    return 1 / ((1 - s.nu ** 2) / s.E + (1 - al.nu ** 2) / al.E)


def test_ball_contact_shows_load_radius_and_hertz(smooth_contact):
    html = smooth_contact._repr_html_()
    a, p0 = _hertz(_e_star())
    for text in (f"{a * 1e6:.4g}</td><td style='padding:1px 8px;text-align:left'>µm",
                 f"{p0 / 1e6:.4g}</td><td style='padding:1px 8px;text-align:left'>MPa",
                 f"{_e_star() / 1e9:.4g}", ">N<", ">mm<", "µm²"):
        assert text in html, text
    text = repr(smooth_contact)
    assert text.startswith("BallContact(load=10 N, radius=20 mm") and len(text) < 120
    # the engine's record too: one line, not every array in full
    engine = repr(smooth_contact.result)
    assert engine.startswith("ContactResult(64 x 64 cells, load=10 N")
    assert f"contact_radius={a:.4g} m"[:20] in engine and len(engine) < 160


def test_hertz_check_shows_verdict_and_numbers():
    from surfmet.data import path
    from surfmet.mechanics.hertz_check import hertz_check

    check = hertz_check(path("paper_plate.x3p"), radius=0.02, load=10.0, grid=64)
    html = check._repr_html_()
    a, p0 = _hertz(_e_star())
    for text in ("verdict", check.verdict, "GJM alpha", f"{a * 1e6:.4g}", f"{p0 / 1e6:.4g}",
                 "MPa", "µm", "GPa"):
        assert text in html, text
    text = repr(check)
    assert text.startswith("HertzCheck(verdict=") and "load=10 N" in text and len(text) < 120
