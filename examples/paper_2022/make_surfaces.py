"""The bundled stand-in scans and how they are made
================================================

Synthetic stand-ins for the two scans of Alaci et al. (2022), built from the paper's
statistics and written with surfmet's own X3P writer.

Run:  python examples/paper_2022/make_surfaces.py [OUTDIR] [--gallery]

(default OUTDIR: ``surfmet/data``, where the package ships ``paper_plate.x3p`` and
``paper_ball.x3p``). The generator is seeded, so the files are reproducible; but what makes
them stand-ins for the paper is their statistics, which ``tests/test_paper_surfaces.py``
checks against the paper's numbers through surfmet's reader and roughness pipeline.

The output and figures on the documentation's page are ``make_surfaces.py OUTDIR
--gallery``, run while the documentation is built: the same two scans, made the same way
and written to a folder of the build (never over the shipped copies), with the closing
check of the statistics over every eighth row instead of every row, and the two height
maps drawn. The full run, ``python examples/paper_2022/make_surfaces.py``, rewrites
``surfmet/data`` and checks every row.

The aluminium plate (Table 2, Figs. 13-14)
------------------------------------------
- 1024 x 512 points at the paper's 5 µm pitch (5.12 mm x 2.56 mm; the paper scanned
  8.063 mm x 11.309 mm, which would be 3.6 M points, too large to ship).
- Isotropic Gaussian random field with a Gaussian autocorrelation of correlation length
  10 µm (the length that gives a Gaussian profile the paper's Rz/Rq = 5.15 and
  Rt/Rq = 6.2 over lc = 0.8 mm sampling lengths). The amplitude is set so that the median
  row Rq through surfmet's pipeline equals Table 2's mean Rq, 2.203 µm; Ra, Rz and Rt then
  follow from the shape of the spectrum, not from tuning (medians over all rows: 1.77 /
  11.4 / 13.8 µm against Table 2's means 1.735 / 11.354 / 13.720 µm).
- Pipeline settings (the ones the test uses, and those of ISO 4288 for Ra in 0.1-2 µm):
  ``surfmet roughness paper_plate.x3p --profile row:K --level plane --lc 0.8mm``
  (least-squares line, Gaussian filter λc = 0.8 mm, five sampling lengths, 4 mm).
- 60 spikes (single-pixel optical outliers, 20-150 µm, four in five upwards), the kind
  NanoFocus scans carry and that make Table 1's Sq/Sa reach 4.3. They are documented
  artefacts, not roughness: ``surfmet hertz-check`` and ``surfmet rolling`` remove them
  (``surfmet._spikes``) before the contact analysis.
- Heights rounded to float32 (the file stores ``F`` data; 2 MB).

The steel ball (Table 2, Figs. 15-16)
-------------------------------------
- 147 x 152 points at the paper's 50 µm pitch (7.35 mm x 7.60 mm, the paper's 7.327 x
  7.580 mm), a cap of a nominal 20 mm ball, apex near the middle of the scan.
- Roughness: white at the 50 µm pitch, heavy-tailed (Student t, 2.2 degrees of freedom)
  because Table 2's Rq/Ra = 0.316/0.210 = 1.50 is far above a Gaussian's 1.25; scaled so
  that the median row Rq equals Table 2's mean 0.316 µm (Ra then lands on 0.211 µm).
  About 0.5 % of its points are then isolated outliers that ``surfmet._spikes`` flags, as
  the outliers of a real 50 µm-pitch optical scan of a polished ball would be (a bearing
  ball's true Ra is nearer 0.02 µm: Table 2's 0.21 µm is mostly instrument noise).
  Settings: ``--profile row:K --level poly:2 --lc 0.8mm`` (the parabola takes the ball's
  curvature off each row).
- Form. The paper says the measured radius differs from the nominal one (Fig. 16) but
  prints neither. ASSUMPTION: the cap is toric, with radii of curvature 19.85 mm along x
  and 20.05 mm along y, i.e. a best-fit sphere of about 19.95 mm (0.25 % below nominal)
  and an astigmatic form deviation of about 3.4 µm peak-to-valley over the cap.
  ``surfmet fit --shape sphere`` recovers the radius and the form deviation; circle fits
  of a row and of a column (``profiles.fit_circle``) recover the two curvatures.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

# The script beside this one is called contact.py: keep this folder off the import path,
# or surfmet's own "import contact" (reached once the roughness pipeline runs) would
# import that script instead of the contact engine.
try:
    _HERE = Path(__file__).resolve().parent
except NameError:  # the documentation's gallery defines no __file__; it runs in this folder
    _HERE = Path.cwd()
sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != _HERE]

import numpy as np  # noqa: E402

from surfmet import Topography  # noqa: E402
from surfmet.io import encode  # noqa: E402
from surfmet.roughness import roughness  # noqa: E402

SEED = 20220325  # Materials 15(7):2518 was published in March 2022

PLATE_SHAPE = (512, 1024)  # (ny, nx)
PLATE_PITCH = 5e-6
PLATE_CORRELATION = 10e-6
PLATE_RQ = 2.203e-6  # mean of Table 2's three plate rows
PLATE_SPIKES = 60

BALL_SHAPE = (152, 147)
BALL_PITCH = 50e-6
BALL_RQ = 0.3163e-6  # mean of Table 2's three ball rows
BALL_T_DOF = 2.2
BALL_RADIUS_X = 19.85e-3
BALL_RADIUS_Y = 20.05e-3
BALL_APEX = (3.62e-3, 3.86e-3)  # scan coordinates of the apex (x, y)

LC = 8e-4  # λc = 0.8 mm (ISO 4288 for Ra in 0.1-2 µm)
PLATE_SETTINGS = {"level": "plane", "lc": LC}
BALL_SETTINGS = {"level": "poly:2", "lc": LC}


def gaussian_field(shape: tuple[int, int], pitch: float, correlation: float,
                   rng: np.random.Generator) -> np.ndarray:
    """Isotropic Gaussian random field of unit variance with autocorrelation
    exp(-r²/ξ²) (ξ = ``correlation``), by filtering white noise in Fourier space."""
    ny, nx = shape
    white = rng.standard_normal(shape)
    qy = 2 * np.pi * np.fft.fftfreq(ny, pitch)
    qx = 2 * np.pi * np.fft.rfftfreq(nx, pitch)
    q2 = qy[:, None] ** 2 + qx[None, :] ** 2
    # PSD of exp(-r²/ξ²) is ∝ exp(-q²ξ²/4); the amplitude filter is its square root
    z = np.fft.irfft2(np.fft.rfft2(white) * np.exp(-q2 * correlation**2 / 8), s=shape)
    return z / z.std()


def row_statistics(topo: Topography, settings: dict, rows: range) -> dict[str, np.ndarray]:
    """Ra, Rq, Rz, Rt (m) of the given rows through surfmet's profile pipeline."""
    out: dict[str, list[float]] = {k: [] for k in ("Ra", "Rq", "Rz", "Rt")}
    for k in rows:
        res = roughness(topo, profile=f"row:{k}", **settings)
        for key in out:
            out[key].append(res.value(key))
    return {k: np.asarray(v) for k, v in out.items()}


def make_plate(seed: int = SEED) -> Topography:
    """The aluminium plate stand-in (see the module notes)."""
    rng = np.random.default_rng(seed)
    base = gaussian_field(PLATE_SHAPE, PLATE_PITCH, PLATE_CORRELATION, rng)
    rows = range(0, PLATE_SHAPE[0], 4)
    probe = Topography(base * 1e-6, PLATE_PITCH, PLATE_PITCH)
    rq = float(np.median(row_statistics(probe, PLATE_SETTINGS, rows)["Rq"]))
    z = base * 1e-6 * (PLATE_RQ / rq)
    # a slight tilt of the specimen under the profilometer (removed by any levelling)
    ny, nx = PLATE_SHAPE
    yy, xx = np.mgrid[:ny, :nx]
    z = z + 2e-4 * xx * PLATE_PITCH - 1e-4 * yy * PLATE_PITCH
    # optical spikes: single pixels, 20-150 µm, mostly upwards
    idx = rng.choice(z.size, PLATE_SPIKES, replace=False)
    heights = np.exp(rng.uniform(math.log(20e-6), math.log(150e-6), PLATE_SPIKES))
    signs = np.where(rng.random(PLATE_SPIKES) < 0.8, 1.0, -1.0)
    z.flat[idx] += signs * heights
    z = z.astype(np.float32).astype(np.float64)
    return Topography(z, PLATE_PITCH, PLATE_PITCH, metadata={
        "comment": "synthetic stand-in for the aluminium plate of Alaci et al. (2022), "
                   "Table 2 statistics; examples/paper_2022/make_surfaces.py",
        "creator": "surfmet",
        "instrument": "synthetic (surfmet examples/paper_2022/make_surfaces.py)",
    })


def make_ball(seed: int = SEED + 1) -> Topography:
    """The steel ball stand-in (see the module notes)."""
    rng = np.random.default_rng(seed)
    ny, nx = BALL_SHAPE
    x = np.arange(nx) * BALL_PITCH - BALL_APEX[0]
    y = np.arange(ny) * BALL_PITCH - BALL_APEX[1]
    X, Y = np.meshgrid(x, y)
    inv_m = 0.5 * (1 / BALL_RADIUS_X + 1 / BALL_RADIUS_Y)
    r_m = 1 / inv_m
    astig = 0.25 * (X**2 - Y**2) * (1 / BALL_RADIUS_X - 1 / BALL_RADIUS_Y)
    form = np.sqrt(r_m**2 - X**2 - Y**2) - r_m - astig
    rough = rng.standard_t(BALL_T_DOF, size=BALL_SHAPE)
    rows = range(ny)
    probe = Topography(form + rough * 1e-7, BALL_PITCH, BALL_PITCH)
    rq = float(np.median(row_statistics(probe, BALL_SETTINGS, rows)["Rq"]))
    z = form + rough * 1e-7 * (BALL_RQ / rq) + 0.4e-3  # heights above the stage
    return Topography(z, BALL_PITCH, BALL_PITCH, metadata={
        "comment": "synthetic stand-in for the 20 mm steel ball of Alaci et al. (2022), "
                   "Table 2 statistics, assumed toric form (Rx 19.85 mm, Ry 20.05 mm); "
                   "examples/paper_2022/make_surfaces.py",
        "creator": "surfmet",
        "instrument": "synthetic (surfmet examples/paper_2022/make_surfaces.py)",
    })


def main(argv: list[str]) -> int:
    import argparse

    root = _HERE.parents[1]
    parser = argparse.ArgumentParser(
        description="Make the bundled stand-ins of the paper's two scans.")
    parser.add_argument("outdir", nargs="?", default=str(root / "surfmet" / "data"),
                        help="where to write paper_plate.x3p and paper_ball.x3p "
                        "(default: surfmet/data, the shipped copies)")
    parser.add_argument("--gallery", action="store_true",
                        help="the documentation's run: check every eighth row, draw the maps")
    opts = parser.parse_args(argv)
    out = Path(opts.outdir)
    every = 8 if opts.gallery else 1
    out.mkdir(parents=True, exist_ok=True)
    plate, ball = make_plate(), make_ball()
    (out / "paper_plate.x3p").write_bytes(encode(plate, "x3p", dtype="F",
                                                 date="2022-03-25T00:00:00"))
    (out / "paper_ball.x3p").write_bytes(encode(ball, "x3p", date="2022-03-25T00:00:00"))
    for name, topo, settings, rows in (
        ("plate", plate, PLATE_SETTINGS, range(0, PLATE_SHAPE[0], every)),
        ("ball", ball, BALL_SETTINGS, range(0, BALL_SHAPE[0], every)),
    ):
        st = row_statistics(topo, settings, rows)
        text = ", ".join(f"{k} {np.median(v) * 1e6:.3f} µm" for k, v in st.items())
        size = (out / f"paper_{name}.x3p").stat().st_size
        print(f"{name}: median over {len(rows)} rows: {text}  ({size / 1e6:.2f} MB)")
        shipped = root / "surfmet" / "data" / f"paper_{name}.x3p"
        if shipped.exists() and shipped.resolve() != (out / shipped.name).resolve():
            same = shipped.read_bytes() == (out / shipped.name).read_bytes()
            print(f"  {shipped.name} is byte for byte the shipped copy: {same}")
    if opts.gallery:  # the gallery shows the figures left open
        from surfmet.plots.areal import height_map

        height_map(plate, title="plate stand-in (spikes included: the colour scale "
                   "clips them)")
        height_map(ball, title="ball stand-in (the cap of a 20 mm ball)")
    return 0


# %%
# The run
# -------
# The documentation's gallery runs this file as ``make_surfaces.py OUTDIR --gallery``
# (see the top); the output and the height maps below are that run's.

if __name__ == "__main__":
    # no SystemExit on success: the gallery runs this file inside the documentation build
    if status := main(sys.argv[1:]):
        sys.exit(status)
