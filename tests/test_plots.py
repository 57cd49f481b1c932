"""Matplotlib figures: not blank, the data drawn are the inputs in the stated units, the
contact clusters found are those the contact engine counts."""

from __future__ import annotations

import io

import numpy as np
import pytest

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.plots._style import close


def _pixels(fig) -> np.ndarray:
    import matplotlib.image as mpimg

    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=60)
    return mpimg.imread(io.BytesIO(buf.getvalue()), format="png")[..., :3]


def assert_not_blank(fig, min_ink: float = 0.05) -> None:
    px = _pixels(fig)
    ink = np.mean(np.any(px < 0.95, axis=-1))  # share of non-white pixels
    assert px.std() > 0.05 and ink > min_ink, (px.std(), ink)
    assert len(np.unique((px * 255).astype(np.uint8).reshape(-1, 3), axis=0)) > 20


def _line(ax, label_part: str):
    for ln in ax.get_lines():
        if label_part in (ln.get_label() or ""):
            return ln
    names = [ln.get_label() for ln in ax.get_lines()]
    raise AssertionError(f"no line labelled {label_part!r} in {names}")


@pytest.mark.parametrize("size, unit", [(128e-6, "µm"), (6e-3, "mm")])
def test_height_map_units_and_scale(tmp_path, size, unit):
    from surfmet.plots.areal import height_map

    rng = np.random.default_rng(1)
    n = 64
    z = rng.standard_normal((n, n)) * 0.2e-6
    z[10:20, 30:40] = np.nan
    t = Topography(z, size / n, size / n, {"source": "/x/scan.x3p"})
    out = tmp_path / "map.png"
    fig = height_map(t, out)
    assert out.stat().st_size > 1000
    assert_not_blank(fig)
    ax, cax = fig.axes[0], fig.axes[1]
    assert ax.get_xlabel() == f"x ({unit})" and ax.get_ylabel() == f"y ({unit})"
    assert cax.get_ylabel() == "height (µm)"
    # the image holds the heights in µm, NaN masked
    arr = ax.get_images()[0].get_array()
    assert np.ma.is_masked(arr) and arr.mask[15, 35]
    assert np.allclose(arr.filled(np.nan)[0, :5], z[0, :5] / 1e-6)
    # extent in the axis unit: the scan's physical size
    x0, x1, _, _ = ax.get_images()[0].get_extent()
    factor = 1e-6 if unit == "µm" else 1e-3
    assert (x1 - x0) * factor == pytest.approx(size)
    # a scale bar with a round length
    texts = [t.get_text() for t in ax.findobj(lambda a: hasattr(a, "get_text"))]
    assert any(s.endswith(f" {unit}") and s.split()[0].lstrip("0123456789.") == ""
               for s in texts), texts
    close(fig)


def test_abbott_firestone_of_uniform_heights_is_a_line():
    # heights uniform in [-a, a]: the material ratio curve is z(mr) = a (1 - 2 mr)
    from surfmet.plots.areal import abbott_firestone

    rng = np.random.default_rng(2)
    a = rng.uniform(0.1e-6, 2e-6)
    z = rng.uniform(-a, a, size=(200, 200))
    fig = abbott_firestone(Topography(z, 1e-6, 1e-6))
    ln = _line(fig.axes[0], "material ratio curve")
    mr, h = ln.get_xdata() / 100, ln.get_ydata() * 1e-6
    inner = (mr > 0.02) & (mr < 0.98)
    assert np.allclose(h[inner], a * (1 - 2 * mr[inner]), atol=0.02 * a)
    assert fig.axes[0].get_ylabel() == "height about the mean (µm)"
    assert_not_blank(fig)
    close(fig)


def test_abbott_firestone_frames_the_curve_not_its_spikes():
    """Gaussian heights (Sq 1 µm) with a few spikes of +-100 µm kept: the height axis
    frames the curve (main: -100...150 µm, the curve a flat line) and says it is clipped;
    without the spikes nothing is clipped."""
    from surfmet.plots.areal import abbott_firestone

    rng = np.random.default_rng(5)
    z = rng.standard_normal((200, 200)) * 1e-6
    fig = abbott_firestone(Topography(z, 1e-6, 1e-6))
    lo, hi = fig.axes[0].get_ylim()
    assert lo <= z.min() * 1e6 and hi >= z.max() * 1e6  # the whole curve
    assert not any("clipped" in t.get_text() for t in fig.axes[0].texts)
    close(fig)
    z[rng.random(z.shape) < 2e-4] = 150e-6
    z[rng.random(z.shape) < 2e-4] = -100e-6
    fig = abbott_firestone(Topography(z, 1e-6, 1e-6))
    lo, hi = fig.axes[0].get_ylim()
    assert -12 < lo < -2.5 and 2.5 < hi < 12  # µm: the core and its tails, visible
    # the note is the legend's last entry (issue 34 item 16: the legend covered it)
    assert any("clipped" in t.get_text() for t in fig.axes[0].get_legend().get_texts())
    close(fig)


def test_abbott_firestone_draws_the_sk_construction():
    from surfmet.plots.areal import abbott_firestone
    from surfmet.roughness import roughness

    rng = np.random.default_rng(3)
    z = rng.standard_normal((150, 150)) * 1e-7
    z[rng.random(z.shape) < 0.03] += 6e-7  # a plateau-honed like peak population
    t = Topography(z, 1e-6, 1e-6)
    res = roughness(t, level="mean", which="functional")
    fig = abbott_firestone(t, parameters=res.parameters)
    labels = [ln.get_label() for ln in fig.axes[0].get_lines()]
    assert "equivalent straight line" in labels
    legend = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    assert any(s.startswith("Spk = ") for s in legend) and any(s.startswith("Svk") for s in legend)
    # the equivalent line spans Sk between Mr = 0 and 100 %
    eq = _line(fig.axes[0], "equivalent straight line")
    y = eq.get_ydata()
    assert (y[0] - y[-1]) * 1e-6 == pytest.approx(res.value("Sk"), rel=1e-9)
    close(fig)


def test_psd_figure_units():
    from surfmet.plots.areal import psd_figure
    from surfmet.psd import areal_psd, fit_hurst, profile_psd

    rng = np.random.default_rng(4)
    t = Topography(rng.standard_normal((64, 64)) * 1e-7, 1e-6, 1e-6)
    spec = areal_psd(t).radial()
    fit = fit_hurst(spec)
    fig = psd_figure(spec, fits=[fit])
    ax = fig.axes[0]
    ln = ax.get_lines()[0]
    ok = spec.C > 0
    assert np.allclose(ln.get_xdata(), spec.q[ok] * 1e-6)
    assert np.allclose(ln.get_ydata(), spec.C[ok] / 1e-24)
    assert ax.get_xlabel() == "wavevector q (rad/µm)" and "µm⁴" in ax.get_ylabel()
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log"
    assert any("H = " in t.get_text() for t in ax.get_legend().get_texts())
    assert_not_blank(fig)
    close(fig)
    fig = psd_figure(profile_psd(t))
    assert "µm³" in fig.axes[0].get_ylabel()
    close(fig)
    with pytest.raises(SurfmetInputError, match="units"):
        psd_figure([spec, profile_psd(t)])


def test_profile_figure_panels():
    import profiles
    from surfmet.plots.profile import profile_figure

    rng = np.random.default_rng(5)
    n, dx = 8000, 0.5e-6
    x = np.arange(n) * dx
    z = (3e-6 * x / x[-1] + 0.5e-6 * np.sin(2 * np.pi * x / 1.5e-3)
         + 0.05e-6 * rng.standard_normal(n))
    ap = profiles.analyze_profile(z, dx, lc=0.25e-3)
    fig = profile_figure(ap, title="synthetic")
    assert len(fig.axes) == 3
    wav = _line(fig.axes[1], "waviness")
    assert np.allclose(wav.get_ydata(), np.asarray(ap.waviness) / 1e-6, equal_nan=True)
    assert np.allclose(wav.get_xdata(), ap.x / 1e-3)  # 4 mm long: mm
    assert fig.axes[-1].get_xlabel() == "x (mm)"
    assert all(a.get_ylabel() == "height (µm)" for a in fig.axes)
    rough = _line(fig.axes[2], "Ra = ")
    assert f"Ra = {ap.parameters.Ra / 1e-6:.4g} µm" in rough.get_label()
    assert_not_blank(fig)
    close(fig)
    # no λc filter: two panels, the mean line is the least-squares line
    ap2 = profiles.analyze_profile(z, dx, lc=None)
    fig = profile_figure(ap2)
    assert len(fig.axes) == 2
    close(fig)
    with pytest.raises(SurfmetInputError, match="ProfileAnalysis"):
        profile_figure(object())


def _discs(rng, shape, k):
    """k non-touching random discs of pressure; returns the pressure field."""
    ny, nx = shape
    p = np.zeros(shape)
    yy, xx = np.mgrid[:ny, :nx]
    placed = []
    while len(placed) < k:
        cy, cx, r = rng.integers(6, ny - 6), rng.integers(6, nx - 6), rng.integers(2, 5)
        if all((cy - y) ** 2 + (cx - x) ** 2 > (r + s + 2) ** 2 for y, x, s in placed):
            placed.append((cy, cx, r))
            m = (yy - cy) ** 2 + (xx - cx) ** 2 <= r * r
            p[m] = rng.uniform(50e6, 500e6) * (1 - ((yy[m] - cy) ** 2 + (xx[m] - cx) ** 2)
                                               / (r * r + 1))
    return p, placed


def _result(p, periodic=False, dx=2e-6):
    from contact.bem._result import build_result

    ny, nx = p.shape
    z = np.zeros_like(p)
    from contact._grid import Grid

    grid = Grid(x=(np.arange(nx) - nx / 2) * dx, y=(np.arange(ny) - ny / 2) * dx,
                periodic=periodic, pitch=(dx, dx))
    return build_result(pressure=p, gap=z, displacement=z, plastic_displacement=z, grid=grid,
                        e_star=70e9, hardness=None, approach=0.0, iterations=1, residual=0.0,
                        converged=True)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_pressure_map_numbers_every_cluster(tmp_path, seed):
    from surfmet.plots.contact import pressure_map

    rng = np.random.default_rng(seed)
    k = int(rng.integers(3, 12))  # hidden number of contact spots
    p, _ = _discs(rng, (64, 80), k)
    res = _result(p)
    assert res.n_clusters == k
    fig = pressure_map(res, tmp_path / "p.png")
    assert fig.surfmet_clusters == k and fig.surfmet_labelled == k
    ax = fig.axes[0]
    numbers = sorted(int(t.get_text()) for t in ax.texts if t.get_text().isdigit())
    assert numbers == list(range(1, k + 1))
    assert fig.axes[1].get_ylabel() == "contact pressure (MPa)"
    drawn = ax.get_images()[0].get_array()
    assert np.array_equal(np.ma.getmaskarray(drawn), p <= 0)  # no contact: blank
    assert np.allclose(drawn.filled(0.0), p / 1e6)
    assert f"{k} contact clusters" in ax.get_title()
    # "1" names the cluster carrying the most load, from its bounding box's top right
    from skimage.measure import label

    lab = label(p > 0, connectivity=1)
    loads = np.bincount(lab.ravel(), weights=p.ravel())[1:]
    biggest = np.argmax(loads) + 1
    jj, ii = np.nonzero(lab == biggest)
    one = next(t for t in ax.texts if t.get_text() == "1")
    assert one.xy[0] * 1e-6 == pytest.approx(res.x[ii].max() + res.dx / 2)
    assert one.xy[1] * 1e-6 == pytest.approx(res.y[jj].max() + res.dy / 2)
    assert_not_blank(fig)
    close(fig)
    # with a label budget, only the largest are numbered and the title says so
    fig = pressure_map(res, max_labels=2)
    assert fig.surfmet_labelled == 2 and "largest 2 numbered" in fig.axes[0].get_title()
    close(fig)


def test_pressure_map_labels_leave_small_clusters_visible():
    """Clusters of 2 x 2 cells (the 3-4 cell clusters of the demo's maps): no number
    covers a loaded cell (main: each number sat on the cluster it named, hiding it)."""
    from surfmet.plots.contact import pressure_map

    p = np.zeros((40, 40))
    for cy, cx in ((8, 8), (8, 28), (20, 18), (30, 8), (31, 30)):
        p[cy:cy + 2, cx:cx + 2] = 1e8 * (1 + 0.1 * cx)
    res = _result(p)
    fig = pressure_map(res, zoom=False)
    ax = fig.axes[0]
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    labels = [t.get_window_extent(renderer) for t in ax.texts if t.get_text().isdigit()]
    assert len(labels) == 5
    jj, ii = np.nonzero(p > 0)
    for j, i in zip(jj, ii):
        x0, y0 = ax.transData.transform(((res.x[i] - res.dx / 2) * 1e6,
                                         (res.y[j] - res.dy / 2) * 1e6))
        x1, y1 = ax.transData.transform(((res.x[i] + res.dx / 2) * 1e6,
                                         (res.y[j] + res.dy / 2) * 1e6))
        for b in labels:
            overlap = min(x1, b.x1) - max(x0, b.x0) > 0.5 and min(y1, b.y1) - max(y0, b.y0) > 0.5
            assert not overlap, ((j, i), b)
    close(fig)


def test_cluster_labels_wrap_in_periodic_domains():
    from contact.bem._result import cluster_labels, count_clusters

    c = np.zeros((20, 20), bool)
    c[5:8, 0:3] = True
    c[5:8, 17:20] = True  # the same spot across the x boundary
    c[0:2, 10:12] = True
    c[18:20, 10:12] = True  # and across y
    c[10:13, 8:11] = True
    lab, n = cluster_labels(c, periodic=True)
    assert n == count_clusters(c, periodic=True) == 3
    assert lab[6, 0] == lab[6, 19] and lab[0, 10] == lab[19, 10]
    assert set(np.unique(lab)) == {0, 1, 2, 3}
    assert cluster_labels(c, periodic=False)[1] == count_clusters(c, periodic=False) == 5


def test_radial_pressure_hertz_units():
    from contact._hertz import hertz_sphere
    from contact._materials import composite_modulus, material
    from surfmet.plots.contact import radial_pressure

    h = hertz_sphere(0.01, 4.7, composite_modulus(material("steel"), material("aluminium")))
    r = np.linspace(0, 1.5 * h.a, 60)
    ph = h.pressure(r)
    pb = ph * (1 + 0.05 * np.sin(r / h.a * 7))
    fig = radial_pressure(r, pb, ph, h.a)
    ax = fig.axes[0]
    hz, bem = _line(ax, "Hertz"), _line(ax, "boundary")
    assert np.allclose(hz.get_xdata(), r / 1e-6) and np.allclose(hz.get_ydata(), ph / 1e6)
    assert np.allclose(bem.get_ydata(), pb / 1e6)
    assert ax.get_xlabel() == "radius r (µm)" and ax.get_ylabel() == "pressure (MPa)"
    vlines = [ln for ln in ax.get_lines() if np.ptp(ln.get_xdata()) == 0]
    assert vlines and vlines[0].get_xdata()[0] == pytest.approx(h.a / 1e-6)
    assert_not_blank(fig, min_ink=0.03)
    close(fig)
    fig = radial_pressure(r, pb, ph, h.a, normalise=True)
    assert np.nanmax(_line(fig.axes[0], "Hertz").get_ydata()) == pytest.approx(1.0)
    close(fig)
    with pytest.raises(SurfmetInputError, match="same length"):
        radial_pressure(r, pb[:-1], ph, h.a)
    with pytest.raises(SurfmetInputError, match="a0"):
        radial_pressure(r, pb, ph, -1.0)
