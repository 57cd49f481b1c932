"""3D rendering (pyvista, off-screen) and ``surfmet show``: pictures that show the surface,
coloured by height, on a machine without a display."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography
from surfmet._render import auto_exaggeration, decimate, render_3d
from surfmet.cli import main


def _surface_region(img: np.ndarray) -> np.ndarray:
    """The part of the picture where the surface is drawn: below the caption, left of the
    colour bar."""
    h, w, _ = img.shape
    return img[int(0.1 * h): int(0.97 * h), int(0.02 * w): int(0.8 * w)].astype(float)


def _yellowness(px: np.ndarray) -> np.ndarray:
    # viridis runs from purple (68, 1, 84) at the bottom to yellow (253, 231, 37) at the top
    return px[..., 0] + px[..., 1] - 2 * px[..., 2]


@pytest.mark.parametrize("seed", [0, 1])
def test_render_colours_follow_height(seed):
    rng = np.random.default_rng(seed)
    n = 96
    yy, xx = np.mgrid[:n, :n]
    slope = rng.uniform(0.5e-8, 3e-8)
    texture = rng.uniform(0.05, 0.2) * slope * n * np.sin(yy / rng.uniform(3, 8))
    means = {}
    for sign in (1, -1):
        z = sign * slope * xx + texture  # height rises to the right (+) or to the left (-)
        img = render_3d(Topography(z, 1e-6, 1e-6), window_size=(480, 360))
        assert img.shape == (360, 480, 3) and img.dtype == np.uint8
        reg = _surface_region(img)
        drawn = ~np.all(reg > 245, axis=-1)  # not the white background
        assert 0.15 < drawn.mean() < 0.95, drawn.mean()
        assert len(np.unique(reg[drawn].astype(np.uint8), axis=0)) > 200  # shaded, coloured
        w = reg.shape[1]
        y = _yellowness(reg)
        left = y[:, : w // 3][drawn[:, : w // 3]].mean()
        right = y[:, 2 * w // 3:][drawn[:, 2 * w // 3:]].mean()
        means[sign] = right - left
    # x runs to the right in the default view, so colour follows the height, not the place
    assert means[1] > 100 and means[-1] < -100, means


def test_render_writes_png_and_leaves_holes(tmp_path):
    import matplotlib.image as mpimg

    rng = np.random.default_rng(3)
    z = rng.standard_normal((80, 100)) * 1e-7
    full = render_3d(Topography(z, 1e-6, 1e-6), tmp_path / "a.png", window_size=(320, 240),
                     exaggeration=50)
    back = mpimg.imread(tmp_path / "a.png")
    assert back.shape[:2] == (240, 320)
    assert np.array_equal((back[..., :3] * 255).round().astype(np.uint8), full)
    holed = z.copy()
    holed[20:60, 30:70] = np.nan  # a big hole in the middle
    img = render_3d(Topography(holed, 1e-6, 1e-6), window_size=(320, 240), exaggeration=50)
    bg_full = np.all(_surface_region(full) > 245, axis=-1).mean()
    bg_holed = np.all(_surface_region(img) > 245, axis=-1).mean()
    assert bg_holed > bg_full + 0.03  # the hole shows the background through


def test_decimate_block_means():
    z = np.arange(48.0).reshape(6, 8)
    z[0, 0] = np.nan
    z[4:6, 6:8] = np.nan
    t = Topography(z, 1e-6, 2e-6)
    out, dx, dy, f = decimate(t, max_points=12)
    assert f == (2, 2) and out.shape == (3, 4) and (dx, dy) == (2e-6, 4e-6)
    assert out[0, 0] == pytest.approx(np.mean([1.0, 8.0, 9.0]))  # NaN ignored
    assert np.isnan(out[2, 3])  # a block with no measured point stays NaN
    assert out[1, 1] == pytest.approx(np.mean(z[2:4, 2:4]))
    same, *_ , f1 = decimate(t, max_points=10_000)
    assert f1 == (1, 1) and np.array_equal(same, z, equal_nan=True)
    # an elongated scan is decimated along its long axis only
    long_, _, _, f2 = decimate(Topography(np.zeros((3, 3000)), 1e-6, 1e-6), max_points=1000)
    assert f2[0] == 1 and long_.shape[0] == 3 and long_.size <= 1000


def test_auto_exaggeration_is_round_and_stated():
    assert auto_exaggeration(1e-6, 1e-3) == 200  # 0.25 mm / 1 µm = 250 -> 200
    assert auto_exaggeration(1e-3, 1e-3) == 1  # a ball needs none
    assert auto_exaggeration(0.0, 1e-3) == 1


def test_render_rejects_what_it_cannot_draw():
    with pytest.raises(SurfmetInputError, match="profile"):
        render_3d(Profile(np.zeros(10), 1e-6))
    with pytest.raises(SurfmetInputError, match="2 x 2"):
        render_3d(Topography(np.zeros((1, 10)), 1e-6, 1e-6))
    with pytest.raises(SurfmetInputError, match="exaggeration"):
        render_3d(Topography(np.zeros((4, 4)), 1e-6, 1e-6), exaggeration=-2)


def test_show_cli_without_display(realdata, tmp_path):
    # a fresh process with no DISPLAY: the 3D view renders off-screen, quietly
    out = tmp_path / "view.png"
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    run = subprocess.run(
        [sys.executable, "-m", "surfmet", "show", str(realdata("nms-1.nms")), "-o", str(out),
         "--size", "400x300", "--json"], capture_output=True, text=True, env=env, timeout=120)
    assert run.returncode == 0, run.stderr
    rec = json.loads(run.stdout)
    assert rec["view"] == "3d" and rec["size"] == [400, 300] and rec["output"] == str(out)
    assert "X server" not in run.stderr and "Traceback" not in run.stderr
    import matplotlib.image as mpimg

    img = mpimg.imread(out)
    assert img.shape[:2] == (300, 400)
    drawn = ~np.all(_surface_region(img[..., :3] * 255) > 245, axis=-1)
    assert drawn.mean() > 0.15


def test_show_2d_profile_and_errors(tmp_path, capsys, realdata):
    rng = np.random.default_rng(0)
    scan = surfmet.write(Topography(rng.standard_normal((40, 50)) * 1e-7, 1e-6, 1e-6),
                         tmp_path / "s.npz")
    assert main(["show", str(scan), "-o", str(tmp_path / "m.svg"), "--2d", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["view"] == "2d" and (tmp_path / "m.svg").read_text().lstrip().startswith("<?xml")
    assert main(["show", str(realdata("dektak-1.csv")), "-o", str(tmp_path / "p.png")]) == 0
    err = capsys.readouterr().err
    assert "no 3D view" in err and (tmp_path / "p.png").stat().st_size > 10_000
    for argv, needle in (
        (["show", str(scan), "-o", str(tmp_path / "v.pdf")], "PNG"),
        (["show", str(scan), "-o", str(tmp_path / "nope" / "v.png")], "does not exist"),
        (["show", str(tmp_path / "absent.x3p"), "-o", str(tmp_path / "v.png")], "absent"),
        (["show", str(scan), "-o", str(tmp_path / "v.png"), "--size", "10x10"], "size"),
        (["show", str(scan), "-o", str(tmp_path / "v.png"), "--level", "banana"], "banana"),
    ):
        assert main(argv) == 1
        out, err = capsys.readouterr()
        assert out == "" and err.count("\n") == 1 and needle in err, (argv, err)
