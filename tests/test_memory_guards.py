"""Issue 25 item 13: estimate memory before allocating, in reading and in the areal
spatial parameters, as the solvers do."""

from __future__ import annotations

import numpy as np
import pytest
from test_io_fuzz import address_space_cap

import surfmet
from surfmet._model import Topography
from surfmet.cli import main


def test_a_device_is_refused_before_reading(capsys):
    """``info /dev/zero`` read until memory ran out; it is not a regular file."""
    with address_space_cap(256 * 2**20):  # on main: MemoryError instead of an endless read
        with pytest.raises(surfmet.SurfmetFormatError, match="not a regular file"):
            surfmet.read("/dev/zero")
    assert main(["info", "/dev/zero"]) == 1
    assert "not a regular file" in capsys.readouterr().err


def test_a_file_larger_than_the_memory_left_is_refused_before_reading(tmp_path,
                                                                        monkeypatch):
    import contact._sysmem as memory

    path = tmp_path / "scan.npy"
    np.save(path, np.zeros((512, 512)))  # 2 MB
    monkeypatch.setattr(memory, "available_bytes", lambda: 3 * 2**20)
    with pytest.raises(surfmet.SurfmetFormatError, match=r"needs at least .* MB of memory"):
        surfmet.read(path)
    monkeypatch.setattr(memory, "available_bytes", lambda: 64 * 2**20)
    assert surfmet.read(path).shape == (512, 512)


def test_the_address_space_limit_counts_as_available_memory():
    """A valid file under ``ulimit -v`` was called "corrupted"; the limit is now part of
    the memory the estimate plans with."""
    from contact._sysmem import available_bytes

    free = available_bytes()
    with address_space_cap(64 * 2**20):
        capped = available_bytes()
    assert capped is not None and capped <= 64 * 2**20
    assert free is None or capped < free


def test_a_valid_file_that_does_not_fit_is_not_called_corrupted(tmp_path, monkeypatch):
    """When memory runs out while decoding, the message says so, not "corrupted"."""
    import contact._sysmem as memory
    import surfmet.io.npy as npy

    path = tmp_path / "scan.npy"
    np.save(path, np.zeros((64, 64)))
    monkeypatch.setattr(memory, "available_bytes", lambda: None)

    def oom(buf, name):
        raise MemoryError("Unable to allocate 3 GiB")

    monkeypatch.setattr(npy, "_load_npy", oom)
    with pytest.raises(surfmet.SurfmetFormatError, match="not enough memory") as info:
        surfmet.read(path)
    assert "corrupted" not in str(info.value)


def test_spatial_parameters_do_not_grow_with_pixel_anisotropy():
    """A 10 x 10 map of 1 mm x 0.1 µm pixels took 7.5 s and 1.3 GB (rays sampled at half
    the smaller pixel). Under a 300 MB address-space cap it now runs, and Sal along the
    fine axis is the analytic decay length of a cosine's ACF."""
    from surfmet.areal._spatial import spatial_parameters

    ny, nx, dy, dx, lam = 200, 10, 0.1e-6, 1e-3, 4e-6
    y = np.arange(ny) * dy
    z = np.tile(np.cos(2 * np.pi * y / lam)[:, None], (1, nx)) * 1e-6
    with address_space_cap(300 * 2**20):
        values, _ = spatial_parameters(Topography(z, dx, dy))
    # ACF of a cosine: cos(2 pi tau / lam) = 0.2 first at tau = lam acos(0.2) / (2 pi)
    assert values["Sal"] == pytest.approx(lam * np.arccos(0.2) / (2 * np.pi), rel=0.03)
