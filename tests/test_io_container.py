"""contact.engineering containers (container-2.zip from SurfaceTopography's test files): the
three measurements that meta.yml names, with the sizes and units meta.yml states. The
scale-dependent statistics SurfaceTopography asserts on this container are checked in
tests/test_scales.py."""

from __future__ import annotations

import io
import zipfile

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet._model import Profile, Topography
from surfmet.io import read_bytes, read_container


@pytest.mark.realdata
def test_three_measurements_with_meta_yml_sizes(realdata):
    tem, afm, stylus = read_container(realdata("container-2.zip"))
    # TEM line scan: nonuniform text in nm, meta.yml size 228.9070382 nm
    assert isinstance(tem, Profile) and not tem.is_uniform and tem.n == 76
    assert tem.length == pytest.approx(228.9070382e-9, rel=1e-9)
    # AFM map: Nanoscope, 100 nm x 100 nm (file and meta.yml agree)
    assert isinstance(afm, Topography) and afm.shape == (512, 512)
    assert afm.nx * afm.dx == pytest.approx(100e-9, rel=1e-12)
    assert afm.metadata["height_scale"] == pytest.approx(0.112075538798523)
    # stylus profile: text in mm, uniform by the peer's rule, meta.yml size 0.2987835613 mm
    assert isinstance(stylus, Profile) and stylus.is_uniform and stylus.n == 3001
    assert stylus.n * stylus.dx == pytest.approx(0.29878356133333334e-3, rel=1e-9)
    assert [s.metadata["detrend_mode"] for s in (tem, afm, stylus)] == \
        ["height", "height", "curvature"]
    assert surfmet.read(realdata("container-2.zip")).metadata["member"] == tem.metadata["member"]


def _rezip(buf: bytes, drop: str) -> bytes:
    src = zipfile.ZipFile(io.BytesIO(buf))
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w") as zf:
        for name in src.namelist():
            if name != drop:
                zf.writestr(name, src.read(name))
    return out.getvalue()


@pytest.mark.realdata
def test_missing_member_and_bad_index_are_one_line(realdata):
    buf = realdata("container-2.zip").read_bytes()
    broken = _rezip(buf, "uncd_stylus_300um_5mar_3_k0HpKJt.txt")
    with pytest.raises(SurfmetFormatError, match=r"names 'uncd_stylus.*does not hold"):
        read_bytes(broken, name="c.zip")
    with pytest.raises(SurfmetFormatError, match="measurement 5 does not exist"):
        read_bytes(buf, name="c.zip", measurement=5)


def test_units_scale_and_tip_radius_from_meta_yml():
    # A container written here: one text profile in µm with a 2x height scale and a tip.
    rng = np.random.default_rng(3)
    z = np.cumsum(rng.normal(size=400)) * 1e-3
    text = "\n".join(f"{0.05 * i:.4f}\t{v:.6f}" for i, v in enumerate(z))
    meta = ("surfaces:\n- topographies:\n  - datafile: {original: p.txt}\n    unit: um\n"
            "    height_scale: 2.0\n    detrend_mode: center\n"
            "    instrument: {parameters: {tip_radius: {value: 40, unit: nm}}}\n")
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w") as zf:
        zf.writestr("meta.yml", meta)
        zf.writestr("p.txt", text)
    (p,) = [read_bytes(out.getvalue(), name="c.zip")]
    assert p.is_uniform and p.dx == pytest.approx(0.05e-6, rel=1e-9)
    assert np.allclose(p.z, 2 * np.round(z, 6) * 1e-6, rtol=1e-9, atol=1e-18)
    assert p.metadata["tip_radius"] == {"value": pytest.approx(40e-9), "unit": "m"}
    assert p.metadata["detrend_mode"] == "center"
