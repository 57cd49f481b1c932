"""Fuzzing every reader with mutated real files: damage must give SurfmetFormatError only.

Each real instrument file (every format with a real sample; the coordinate-text and the
ISO 5436-2 softgauge formats have none here, so synthetic ones stand in) is truncated at
random offsets, cut to its header, emptied, bit-flipped, has header fields overwritten
with huge / negative / zero / NaN values (binary fields or numbers in a text header),
regions zeroed, bytes inserted and garbage appended.
The seeds are fixed, so every run tests the same cases.

For every case the outcome must be either a valid scan (the registry has already checked
that it is a Topography or Profile with finite-or-NaN heights) or a
:class:`~surfmet._errors.SurfmetFormatError` whose cause is not a ``MemoryError``. Any other
exception type, a ``MemoryError`` behind the format error (a reader trying to allocate
what a header claims) or a case slower than a few seconds is a failure, reported with the
file, the mutation and the exception so it can be routed to the reader's owner.

Memory guard: the default run caps the process address space (``RLIMIT_AS``) at its
current size plus 3 GiB while the cases run, so an absurd allocation surfaces as a
``MemoryError`` instead of swapping the machine. The long campaign
(``pytest -m fuzz_long``) runs 10x more cases in a subprocess with a hard 4 GiB cap, which
also catches crashes.

Run the long campaign with ``pytest -m fuzz_long tests/test_io_fuzz.py``; it is skipped
unless ``fuzz_long`` is named in the ``-m`` expression.
"""

from __future__ import annotations

import io
import json
import os
import re
import struct
import subprocess
import sys
import zipfile
from contextlib import contextmanager
from pathlib import Path

import numpy as np
import pytest
from _refusal import refused_cheaply

from surfmet._errors import SurfmetFormatError
from surfmet._model import Profile, Topography
from surfmet.io import read_bytes

REALDATA = Path(os.environ.get("SURFMET_SHARED", Path(__file__).resolve().parents[2] / "shared")) \
    / "realdata"

# file -> (registry format, default-suite cases). Slow-to-decode files get fewer cases.
FILES = {
    "al3d-1.al3d": ("al3d", 400),
    "frt-2.frt": ("frt", 400),
    "sdf-1.sdf": ("sdf", 400),
    "test.gwy": ("gwy", 400),
    "opdx-3.opdx": ("opdx", 400),
    "nms-1.nms": ("nms", 320),
    "metropro-1.dat": ("metropro", 320),
    "sur-3.sur": ("sur", 320),
    "opd-1.opd": ("opd", 240),
    "plu-1.plu": ("plu", 240),
    "matrix-4.txt": ("asc", 160),
    "dektak-1.csv": ("dektak", 160),
    "hfm-1.hfm": ("hfm", 160),
    "x3p-2.x3p": ("x3p", 120),
    "KautschukInfiniteFocus.x3p": ("x3p", 100),
    "synthetic-grid.xyz": ("xyz", 300),
    "mitutoyo_2_mock.xlsx": ("mitutoyo", 40),
    "di-1.di": ("di", 200),
    "di-2.di": ("di", 120),
    "spot_1-1000nm.ibw": ("ibw", 120),
    "10x10-one_channel_without_name.ibw": ("ibw", 300),
    "nid-1.nid": ("nid", 160),
    "mi-1.mi": ("mi", 160),
    "bcrf-1.bcrf": ("bcr", 120),
    "tmd-1.tmd": ("tmd", 200),
    "stp-1.stp": ("wsxm", 160),
    "top-1.top": ("wsxm", 200),
    "nc-1.nc": ("nc", 300),
    "example_ps.tiff": ("park", 160),
    "synthetic-profile.smd": ("smd", 300),
    "mnt-1.mnt": ("mnt", 120),
    "jpk-afmreader-0.jpk": ("jpk", 120),
    "h5-multiple.h5": ("h5", 120),
    "zon-surfalize-1.zon": ("zon", 60),
    "container-2.zip": ("ce", 30),
}
TEXT_FORMATS = {"sdf", "asc", "dektak", "hfm", "xyz", "smd"}
_NUMBER_RE = re.compile(rb"[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?")
_FIELD_VALUES = [0, 1, 2**16 - 1, 2**31 - 1, 2**31, 2**32 - 1, 100_000, -1, -(2**31)]
_DOUBLE_VALUES = [0.0, -1.0, 1e300, -1e300, float("nan"), float("inf"), 1e-300]
_TEXT_VALUES = [b"0", b"-1", b"999999999", b"1e308", b"-1e308", b"nan", b"", b"x", b"1e-320"]


def synthetic_xyz() -> bytes:
    rng = np.random.default_rng(2024)
    x, y = np.meshgrid(np.arange(12) * 0.5, np.arange(9) * 0.25)
    z = rng.normal(size=x.shape)
    rows = [f"{a:.4f}\t{b:.4f}\t{c:.6e}" for a, b, c in zip(x.ravel(), y.ravel(), z.ravel())]
    return ("x\ty\tz\n" + "\n".join(rows[:-3]) + "\n").encode()


def synthetic_smd() -> bytes:
    # No public softgauge file is in ../shared: one written from ISO 5436-2's four records.
    rng = np.random.default_rng(2025)
    z = "\r\n".join(f"{v:.5f}" for v in rng.normal(size=300))
    body = (f"ISO 5436 - 2000\r\nPRF\r\nCX I 300 MM 1.0 D 0.0005\r\nCZ A 300 UM 1.0 D\r\n"
            f"\x03\r\nDATE 2025-01-01\r\n\x03\r\n{z}\r\n\x03\r\n").encode()
    return body + f"{sum(body) % 65535}\r\n\x03\r\n".encode()


SYNTHETIC = {"synthetic-grid.xyz": synthetic_xyz, "synthetic-profile.smd": synthetic_smd}


def load(name: str) -> bytes:
    if name in SYNTHETIC:
        return SYNTHETIC[name]()
    return (REALDATA / name).read_bytes()


# --- mutations --------------------------------------------------------------------------


def mutate(buf: bytes, case: int, rng: np.random.Generator, text: bool) -> tuple[bytes, str]:
    """The ``case``-th mutation of ``buf`` and a description of it."""
    n = len(buf)
    head = max(1, min(n, 4096))
    kind = case % 10
    if kind == 0:
        cut = int(rng.integers(0, n)) if rng.random() < 0.6 else int(rng.integers(0, head))
        return buf[:cut], f"truncate at {cut}"
    if kind == 1:
        size = [0, 1, 4, 12, 17, 64, 100, 256, 512, 1024, 2048, 4096][case // 10 % 12]
        return buf[:size], f"header only ({size} bytes)"
    if kind in (2, 3):
        out = bytearray(buf)
        k = int(rng.integers(1, 9))
        where = rng.integers(0, head if kind == 2 else n, size=k)
        for p in where:
            out[p] ^= int(rng.integers(1, 256))
        return bytes(out), f"flip {k} bytes at {sorted(int(p) for p in where)[:8]}"
    if kind in (4, 5) and text:
        matches = list(_NUMBER_RE.finditer(buf[:head]))
        if matches:
            m = matches[int(rng.integers(0, len(matches)))]
            value = _TEXT_VALUES[int(rng.integers(0, len(_TEXT_VALUES)))]
            return (buf[: m.start()] + value + buf[m.end() :],
                    f"number {m.group().decode()!r} at {m.start()} -> {value.decode()!r}")
    if kind in (4, 5):
        out = bytearray(buf)
        p = int(rng.integers(0, max(1, min(n, 2048) - 8)))
        if kind == 4:
            width = [2, 4, 4, 8][int(rng.integers(0, 4))]
            value = _FIELD_VALUES[int(rng.integers(0, len(_FIELD_VALUES)))]
            order = "<>"[int(rng.integers(0, 2))]
            code = {2: "H", 4: "I", 8: "Q"}[width]
            packed = struct.pack(order + code, value % (1 << (8 * width)))
            desc = f"int{8 * width}{order} {value} at {p}"
        else:
            value = _DOUBLE_VALUES[int(rng.integers(0, len(_DOUBLE_VALUES)))]
            packed = struct.pack("<d", value)
            desc = f"float64 {value} at {p}"
        out[p : p + len(packed)] = packed
        return bytes(out[:n]), desc
    if kind == 6:
        start = int(rng.integers(0, n)) if n else 0
        length = int(rng.integers(1, max(2, min(4096, n // 10 + 2))))
        out = bytearray(buf)
        out[start : start + length] = bytes(len(out[start : start + length]))
        return bytes(out), f"zero {length} bytes at {start}"
    if kind == 7:
        extra = rng.integers(0, 256, int(rng.integers(1, 4096)), dtype=np.uint8).tobytes()
        return buf + extra, f"append {len(extra)} garbage bytes"
    if kind == 8:
        p = int(rng.integers(0, head))
        extra = rng.integers(0, 256, int(rng.integers(1, 16)), dtype=np.uint8).tobytes()
        return buf[:p] + extra + buf[p:], f"insert {len(extra)} bytes at {p}"
    return b"", "empty file"


def check_scan(scan: object) -> str | None:
    """Why a successful read is not a valid scan (None if it is)."""
    if isinstance(scan, Topography):
        h = scan.heights
        if h.ndim != 2 or h.size == 0:
            return f"bad heights shape {h.shape}"
        steps = (scan.dx, scan.dy)
    elif isinstance(scan, Profile):
        h = scan.z
        steps = (scan.dx,)
    else:
        return f"returned {type(scan).__name__}"
    if not all(np.isfinite(s) and s > 0 for s in steps):
        return f"bad steps {steps}"
    if np.isinf(h).any() or np.isnan(h).all():
        return "infinite or all-NaN heights"
    if "format" not in scan.metadata:
        return "no format in metadata"
    return None


def run_cases(name: str, fmt: str, buf: bytes, count: int, seed: int) -> tuple[list[dict], int]:
    """Run ``count`` mutations; return the failures and the number of successful reads."""
    failures: list[dict] = []
    ok = 0
    text = fmt in TEXT_FORMATS
    ext = Path(name).suffix
    for case in range(count):
        rng = np.random.default_rng([seed, case, len(buf)])
        data, desc = mutate(buf, case, rng, text)
        forced = fmt if case % 3 == 2 else None
        problem = None
        try:
            scan = read_bytes(data, format=forced, name=f"fuzz{ext}")
        except SurfmetFormatError as exc:
            if isinstance(exc.__cause__, MemoryError):
                problem = f"MemoryError behind the format error: {exc}"
        except Exception as exc:  # any other type is the finding
            problem = f"{type(exc).__name__}: {str(exc)[:200]}"
        else:
            ok += 1
            problem = check_scan(scan)
        if problem is not None:
            failures.append({"file": name, "case": case, "mutation": desc,
                             "format_forced": forced, "problem": problem})
    return failures, ok


def _vmsize() -> int | None:
    try:
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("VmSize:"):
                return int(line.split()[1]) * 1024
    except OSError:
        return None
    return None


@contextmanager
def address_space_cap(extra: int):
    """Cap the address space at its current size + ``extra`` bytes (Linux), then restore."""
    try:
        import resource
    except ImportError:  # pragma: no cover - not POSIX
        yield
        return
    now = _vmsize()
    if now is None:  # pragma: no cover
        yield
        return
    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    cap = now + extra
    if hard != resource.RLIM_INFINITY:
        cap = min(cap, hard)
    resource.setrlimit(resource.RLIMIT_AS, (cap, hard))
    try:
        yield
    finally:
        resource.setrlimit(resource.RLIMIT_AS, (soft, hard))


def _report(failures: list[dict]) -> str:
    lines = [f"{len(failures)} fuzz failures:"]
    for f in failures[:40]:
        forced = f" (format={f['format_forced']})" if f["format_forced"] else ""
        lines.append(f"  {f['file']} case {f['case']}{forced}: {f['mutation']} -> {f['problem']}")
    return "\n".join(lines)


@pytest.mark.realdata
@pytest.mark.parametrize("name", list(FILES))
def test_mutated_files_fail_cleanly(name, realdata):
    fmt, count = FILES[name]
    if name not in SYNTHETIC:
        realdata(name)  # skip (or fail under CI) if the shared file is missing
    buf = load(name)
    assert read_bytes(buf, name=name).metadata["format"] == fmt  # the seed file reads
    with address_space_cap(3 * 2**30):
        failures, ok = run_cases(name, fmt, buf, count, seed=1)
    assert not failures, _report(failures)
    # the mutations are not all trivially fatal: some damaged files still read
    if fmt not in ("x3p",):
        assert ok > 0


def test_default_suite_size():
    assert sum(c for _, c in FILES.values()) >= 2000


# --- tiny files whose header claims a 10^5 x 10^5 grid ------------------------------------


def _put(buf: bytearray, offset: int, fmt: str, expect: int, value: int) -> None:
    # Patch a header field, first checking that it holds the value we believe it holds.
    (old,) = struct.unpack_from(fmt, buf, offset)
    assert old == expect, f"field at {offset} holds {old}, expected {expect}"
    struct.pack_into(fmt, buf, offset, value)


def _huge_x3p(name: str) -> bytes:
    src = zipfile.ZipFile(io.BytesIO(load(name)))
    xml = src.read("main.xml").decode("utf-8")
    xml, nx = re.subn(r"<SizeX>\s*\d+\s*</SizeX>", "<SizeX>100000</SizeX>", xml)
    xml, ny = re.subn(r"<SizeY>\s*\d+\s*</SizeY>", "<SizeY>100000</SizeY>", xml)
    assert nx == ny == 1
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as zf:
        zf.writestr("main.xml", xml)
        for member in src.namelist():
            if member.endswith(".bin"):
                zf.writestr(member, bytes(1024))
    return out.getvalue()


def huge_claim(name: str) -> bytes:
    """A small file built from the real header, its grid fields set to 10^5 x 10^5 (or the
    largest value the field holds)."""
    if name.endswith(".x3p"):
        return _huge_x3p(name)
    if name == "sdf-binary":
        head = struct.pack("<8s10s12s12sHHddddBBB", b"bISO-1.0", b"X", b"0" * 12, b"0" * 12,
                           65535, 65535, 1e-6, 1e-6, 1e-6, -1.0, 0, 7, 0)
        return head + bytes(1024)
    buf = bytearray(load(name))
    if name == "al3d-1.al3d":
        text = bytes(buf[:1300])
        text = text.replace(b"Cols\0".ljust(20, b"\0") + b"200".ljust(30, b"\0"),
                            b"Cols\0".ljust(20, b"\0") + b"100000".ljust(30, b"\0"))
        text = text.replace(b"Rows\0".ljust(20, b"\0") + b"296".ljust(30, b"\0"),
                            b"Rows\0".ljust(20, b"\0") + b"100000".ljust(30, b"\0"))
        assert text.count(b"100000") == 2
        return text
    if name == "frt-2.frt":
        _put(buf, 54, "<I", 150, 100_000)
        _put(buf, 58, "<I", 300, 100_000)
        return bytes(buf[:1024])
    if name == "test.gwy":
        _put(buf, 147, "<i", 128, 100_000)
        _put(buf, 157, "<i", 128, 100_000)
        return bytes(buf[:1024])
    if name == "opdx-3.opdx":
        at = bytes(buf).index(b"NumPoints\x0b") + 10
        _put(buf, at, "<Q", 3001, 10**10)
        return bytes(buf)  # the point count sits after the arrays: keep them
    if name == "sur-3.sur":
        _put(buf, 108, "<i", 512, 100_000)
        _put(buf, 112, "<i", 512, 100_000)
        struct.pack_into("<i", buf, 116, 2**31 - 1)
        return bytes(buf[:1024])
    if name == "plu-1.plu":
        for off in (443, 452):
            _put(buf, off, "<I", 768, 100_000)
        for off in (448, 456):
            _put(buf, off, "<I", 576, 100_000)
        return bytes(buf[:1024])
    if name == "nms-1.nms":
        _put(buf, 1368, "<I", 512, 100_000)
        _put(buf, 1372, "<I", 512, 100_000)
        return bytes(buf[:2048])
    if name == "metropro-1.dat":
        for off, expect in ((52, 640), (54, 480), (68, 640), (70, 480), (234, 640), (236, 480)):
            _put(buf, off, ">H", expect, 65535)
        return bytes(buf[:1024])
    if name == "opd-1.opd":
        # The block directory comes first; the grid is the first field of the data block.
        _put(buf, 24020, "<H", 640, 65535)
        _put(buf, 24022, "<H", 480, 65535)
        return bytes(buf[: 24024 + 1024])
    raise AssertionError(name)


HUGE = ["al3d-1.al3d", "frt-2.frt", "test.gwy", "opdx-3.opdx", "sdf-binary", "sur-3.sur",
        "plu-1.plu", "nms-1.nms", "metropro-1.dat", "opd-1.opd", "x3p-2.x3p",
        "KautschukInfiniteFocus.x3p"]


@pytest.mark.realdata
@pytest.mark.parametrize("name", HUGE)
def test_tiny_file_claiming_huge_grid_fails_fast(name, realdata):
    if name != "sdf-binary":
        realdata(name)
    data = huge_claim(name)
    info = refused_cheaply(data, f"huge{Path(name).suffix or '.sdf'}", limit=64 * 2**20)
    assert not isinstance(info.value.__cause__, MemoryError), info.value
    assert len(data) <= 26_000 or name == "opdx-3.opdx"


# --- the long campaign (opt-in) -------------------------------------------------------------


@pytest.mark.fuzz_long
@pytest.mark.realdata
def test_long_campaign_in_capped_subprocess(realdata):
    # Deselected by default through pyproject's addopts (-m "not fuzz_long");
    # run it with: pytest -m fuzz_long
    realdata("al3d-1.al3d")
    env = dict(os.environ, SURFMET_SHARED=str(REALDATA.parent))
    proc = subprocess.run([sys.executable, __file__, "--campaign", "10", "7"],
                          capture_output=True, text=True, env=env, timeout=3600)
    assert proc.returncode == 0, f"campaign crashed ({proc.returncode}): {proc.stderr[-3000:]}"
    result = json.loads(proc.stdout.strip().splitlines()[-1])
    assert result["cases"] >= 40_000
    assert not result["failures"], _report(result["failures"])


def campaign(multiplier: int, seed: int) -> dict:
    """Run ``multiplier`` times the default number of cases per file, other seeds."""
    import resource

    resource.setrlimit(resource.RLIMIT_AS, (4 * 2**30, resource.getrlimit(resource.RLIMIT_AS)[1]))
    failures: list[dict] = []
    cases = 0
    for name, (fmt, count) in FILES.items():
        buf = load(name)
        fails, _ = run_cases(name, fmt, buf, count * multiplier, seed)
        failures += fails
        cases += count * multiplier
    return {"cases": cases, "failures": failures}


if __name__ == "__main__" and len(sys.argv) == 4 and sys.argv[1] == "--campaign":
    print(json.dumps(campaign(int(sys.argv[2]), int(sys.argv[3]))))


# --- the readers added for issue 18, forced onto every other sample (wrong magic) -------------

NEW_FORMATS = ["di", "ibw", "mi", "nid", "tmd", "mnt", "wsxm", "nc", "park", "bcr", "mitutoyo",
               "smd"]
FOREIGN = ["x3p-2.x3p", "sur-3.sur", "frt-2.frt", "di-2.di", "nid-1.nid", "top-1.top",
           "bcrf-1.bcrf", "mitutoyo_2_mock.xlsx", "synthetic-profile.smd", "nc-1.nc"]


@pytest.mark.realdata
@pytest.mark.parametrize("fmt", NEW_FORMATS)
def test_new_readers_refuse_other_formats_in_one_line(fmt, realdata):
    for name in FOREIGN:
        if name not in SYNTHETIC:
            realdata(name)
        if FILES.get(name, (None,))[0] == fmt:
            continue
        with pytest.raises(SurfmetFormatError) as info:
            read_bytes(load(name), format=fmt, name=name)
        message = str(info.value)
        assert "\n" not in message and name in message, message
        assert not isinstance(info.value.__cause__, MemoryError)
