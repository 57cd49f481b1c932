"""ISO 5436-2 softgauge (.smd) reader. No public .smd sample could be fetched here (the MTS
repository's data/profiles/*.smd are not in the stored snapshot), so the files are written by
hand from the standard's description of the four ETX-separated records; the expected values
are the numbers written into them."""

from __future__ import annotations

import numpy as np
import pytest

from surfmet._errors import SurfmetFormatError
from surfmet.io import detect_format, read_bytes

ETX = "\x03"


def smd(header: list[str], data: list[str], info: str = "DATE 2024-01-01\nCREATED-BY hand",
        checksum: str | None = "auto", sep: str = " ") -> bytes:
    body = ("\r\n".join(line.replace(" ", sep) for line in header) + "\r\n" + ETX + "\r\n"
            + info + "\r\n" + ETX + "\r\n" + "\r\n".join(data) + "\r\n" + ETX + "\r\n")
    raw = body.encode("latin-1")
    if checksum == "auto":
        checksum = str(sum(raw) % 65535)
    if checksum is not None:
        raw += (checksum + "\r\n" + ETX + "\r\n").encode("latin-1")
    return raw


def profile_file(z_um, step_mm=0.0005, **kw) -> bytes:
    n = len(z_um)
    return smd(["ISO 5436 - 2000", "PRF", f"CX I {n} MM 1.0 D {step_mm}",
                f"CZ A {n} UM 1.0 D"], [f"{v:.6f}" for v in z_um], **kw)


def test_incremental_profile_is_read_in_full():
    z = np.round(np.sin(np.arange(401) * 0.05), 6)
    buf = profile_file(z)
    assert detect_format(buf, "soft.smd") == "smd"
    assert detect_format(buf, "soft.txt") == "smd"  # not misread as a one-point text matrix
    p = read_bytes(buf, name="soft.smd")
    assert p.n == 401 and p.is_uniform
    assert p.dx == pytest.approx(0.5e-6, rel=1e-12)
    np.testing.assert_allclose(p.z, z * 1e-6, rtol=1e-12)
    assert p.metadata["checksum"] == "ok"
    assert p.metadata["revision"] == "ISO 5436 - 2000"
    assert "CREATED-BY hand" in p.metadata["information"]


def test_nul_separated_fields_scale_factor_and_no_checksum():
    buf = smd(["ISO 5436 - 2000", "CX I 3 UM 2.0 D 0.5", "CZ A 3 NM 10.0 D"],
              ["1", "2", "-3"], checksum=None, sep="\0")
    p = read_bytes(buf, name="a.smd")
    assert p.dx == pytest.approx(1e-6)  # increment 0.5 x scale 2 µm
    np.testing.assert_allclose(p.z, [10e-9, 20e-9, -30e-9], rtol=1e-12)
    assert p.metadata["checksum"] == "absent"


def test_absolute_x_axis_keeps_positions():
    buf = smd(["ISO 5436 - 2000", "CX A 4 MM 1.0 D", "CZ A 4 UM 1.0 D"],
              ["0.0 1.0", "0.001 2.0", "0.003 3.0", "0.004 4.0"])
    p = read_bytes(buf, name="a.smd")
    assert not p.is_uniform
    np.testing.assert_allclose(p.x, [0, 1e-6, 3e-6, 4e-6], atol=1e-18)


def test_areal_file_x_fastest():
    buf = smd(["ISO 5436 - 2000", "SUR", "CX I 3 UM 1.0 D 2.0", "CY I 2 UM 1.0 D 4.0",
               "CZ A 6 NM 1.0 D"], [str(v) for v in range(6)])
    t = read_bytes(buf, name="a.smd")
    assert (t.nx, t.ny) == (3, 2) and t.dx == pytest.approx(2e-6) and t.dy == pytest.approx(4e-6)
    np.testing.assert_allclose(t.heights, np.arange(6).reshape(2, 3) * 1e-9)


def test_damage_fails_in_one_line():
    good = profile_file(np.zeros(10))
    cases = {
        "checksum": good.replace(b"0.000000\r\n\x03", b"0.000001\r\n\x03", 1),
        "ETX": good[:60],
        "announces": profile_file(np.zeros(10)).replace(b"CZ A 10", b"CZ A 11")
        .replace(b"CX I 10", b"CX I 11"),
        "CZ axis": good.replace(b"CZ A", b"CQ A"),
    }
    for why, bad in cases.items():
        with pytest.raises(SurfmetFormatError, match=why if why != "announces" else
                           "checksum|announces") as info:
            read_bytes(bad, name="a.smd", format="smd")
        assert "\n" not in str(info.value)
    p = read_bytes(cases["checksum"], name="a.smd", verify_checksum=False)
    assert p.metadata["checksum"] == "not checked"
