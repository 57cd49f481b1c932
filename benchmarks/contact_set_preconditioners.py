"""Why the normal solver's iterations grow with the grid: preconditioners on a fixed contact set.

The second phase of the periodic self-affine solve of ``benchmarks/core_scaling.py``
(the contact set no longer moving) is a linear problem: find p on the contact set F,
sum p = W, with (K p)(x) = delta - h(x) on F. Here it is solved by conjugate gradients
(float64, from a uniform pressure on F, to a 1e-8 drop of the residual norm) on the
final contact set of the full solve, with several preconditioners, at growing grids:

- ``stiffness``: the solver's own, the periodic stiffness |q|/2 applied to the residual
  masked to F (Vollebregt 2014, J. Comput. Phys. 257:333);
- ``exact``: the exact inverse 1/K^ of the discrete periodic operator instead;
- ``jacobi``: the diagonal 1/K[0, 0] alone (the yardstick of an unpreconditioned CG);
- ``two-grid``: a symmetric multiplicative two-grid cycle on F (pre-smoothing with
  ``stiffness``, the coarse correction on the 2 x 2 blocks that hold contact with the
  Galerkin-like operator D K_2h D, D the blocks' contact fraction, solved to 1e-2 by an
  inner preconditioned CG, post-smoothing), in a flexible CG (Notay 2000, SIAM J. Sci.
  Comput. 22:1444);
- ``deflated``: deflation by one piecewise constant per contact island (Nicolaides 1987,
  SIAM J. Numer. Anal. 24:355; the deflated CG of Saad, Yeung, Erhel & Guyomarc'h 2000,
  SIAM J. Sci. Comput. 21:1909), its Galerkin matrix exact (one convolution an island:
  up to 512^2 only).

A disc contact of radius N/4 (a Hertz-like gap) is solved the same way for comparison.

Run::

    python3 benchmarks/contact_set_preconditioners.py --sizes 128,256,512

The figures are in ``benchmarks/core_scaling.md`` (section "Preconditioners on a fixed
contact set").
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np
from scipy import ndimage
from scipy.fft import irfft2, rfft2

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from core_scaling import periodic_case  # noqa: E402

Op = Callable[[np.ndarray], np.ndarray]


def _conv(x: np.ndarray, multiplier: np.ndarray) -> np.ndarray:
    return irfft2(rfft2(x) * multiplier, s=x.shape)


def pcg(a: Op, m: Op, center: Op, b: np.ndarray, x0: np.ndarray, tol: float,
        maxit: int, flexible: bool = False) -> tuple[np.ndarray, int]:
    """Preconditioned CG (Polak-Ribiere's beta where ``flexible``); the iterate and steps."""
    x = x0.copy()
    r = center(b - a(x))
    r0 = np.linalg.norm(r)
    z = m(r)
    t, rho = z.copy(), float(np.vdot(r, z))
    for k in range(maxit):
        if np.linalg.norm(r) <= tol * r0:
            return x, k
        at = a(t)
        step = rho / float(np.vdot(t, at))
        x += step * t
        r_new = center(r - step * at)
        z_new = m(r_new)
        rho_new = float(np.vdot(r_new, z_new))
        beta = (rho_new - float(np.vdot(z_new, r))) / rho if flexible else rho_new / rho
        r, rho = r_new, rho_new
        t = z_new + beta * t
    return x, maxit


class Level:
    """The operator D K D on the cells of one grid that hold contact (D their fraction)."""

    def __init__(self, n: int, dx: float, weight: np.ndarray):
        from contact.halfspace.convolution import convolution

        op = convolution(n, n, dx, dx, True)
        self.spec, self.stiff = op.spec64, op.stiffness(False)
        self.w, self.mask = weight, weight > 0

    def a(self, e: np.ndarray) -> np.ndarray:
        return self.w * _conv(self.w * e, self.spec)

    def center(self, z: np.ndarray) -> np.ndarray:
        z = z * self.mask
        return z - self.w * (np.sum(self.w * z) / np.sum(self.w * self.w))

    def smooth(self, r: np.ndarray) -> np.ndarray:
        return self.center(self.mask * _conv(self.mask * r, self.stiff))


def two_grid(fine: Level, coarse: Level) -> Op:
    """The symmetric two-grid cycle (pre-smooth, coarse correction, post-smooth)."""
    n = fine.w.shape[0] // 2

    def restrict(r: np.ndarray) -> np.ndarray:
        return coarse.center(r.reshape(n, 2, n, 2).sum(axis=(1, 3)) / 2)

    def prolong(e: np.ndarray) -> np.ndarray:
        return fine.center(fine.mask * np.repeat(np.repeat(e, 2, 0), 2, 1) / 2)

    def cycle(r: np.ndarray) -> np.ndarray:
        z = fine.smooth(r)
        e, _ = pcg(coarse.a, coarse.smooth, coarse.center,
                   restrict(fine.center(r - fine.a(z))), np.zeros((n, n)), 1e-2, 100)
        z = z + prolong(e)
        return z + fine.smooth(fine.center(r - fine.a(z)))

    return cycle


def deflated(level: Level, b: np.ndarray, x0: np.ndarray, tol: float,
             maxit: int) -> tuple[np.ndarray, int]:
    """CG deflated by one constant per island (8-connected; not merged across the wrap)."""
    n = b.shape[0]
    labels, m = ndimage.label(level.mask, structure=np.ones((3, 3)))
    idx = np.flatnonzero(level.mask.ravel())
    z_basis = np.zeros((idx.size, m))
    z_basis[np.arange(idx.size), labels.ravel()[idx] - 1] = 1.0
    z_basis -= z_basis.mean(axis=0)  # load-neutral

    def full(v: np.ndarray) -> np.ndarray:
        out = np.zeros(n * n)
        out[idx] = v
        return out.reshape(n, n)

    az = np.stack([level.center(level.a(full(z_basis[:, j]))).ravel()[idx]
                   for j in range(m)], axis=1)
    e_inv = np.linalg.pinv(z_basis.T @ az, rcond=1e-12)
    x = x0.copy()
    r = level.center(b - level.a(x))
    x += full(z_basis @ (e_inv @ (z_basis.T @ r.ravel()[idx])))
    r = level.center(b - level.a(x))
    r0 = np.linalg.norm(r)
    z = level.smooth(r)
    t = z - full(z_basis @ (e_inv @ (az.T @ z.ravel()[idx])))
    rho = float(np.vdot(r, z))
    for k in range(maxit):
        if np.linalg.norm(r) <= tol * r0:
            return x, k
        at = level.center(level.a(t))
        step = rho / float(np.vdot(t, at))
        x += step * t
        r = level.center(r - step * at)
        z = level.smooth(r)
        rho_new = float(np.vdot(r, z))
        t = z + (rho_new / rho) * t - full(z_basis @ (e_inv @ (az.T @ z.ravel()[idx])))
        rho = rho_new
    return x, maxit


def counts(contact: np.ndarray, gap: np.ndarray, pixel: float, islands: bool) -> dict:
    """CG steps to a 1e-8 drop on ``contact`` with each preconditioner."""
    n = contact.shape[0]
    fine = Level(n, pixel, contact.astype(float))
    coarse = Level(n // 2, 2 * pixel,
                   fine.w.reshape(n // 2, 2, n // 2, 2).sum(axis=(1, 3)) / 4)
    b = -gap * contact
    x0 = contact / contact.sum()
    inverse = np.divide(1.0, fine.spec, out=np.zeros_like(fine.spec), where=fine.spec > 0)
    diagonal = 1.0 / float(irfft2(fine.spec, s=(n, n))[0, 0])
    runs: dict[str, Op] = {
        "stiffness": fine.smooth,
        "exact": lambda r: fine.center(fine.mask * _conv(fine.mask * r, inverse)),
        "jacobi": lambda r: fine.center(diagonal * r),
    }
    out = {name: pcg(fine.a, m, fine.center, b, x0, 1e-8, 1000)[1]
           for name, m in runs.items()}
    out["two-grid"] = pcg(fine.a, two_grid(fine, coarse), fine.center, b, x0, 1e-8, 400,
                          flexible=True)[1]
    if islands:
        out["deflated"] = deflated(fine, b, x0, 1e-8, 400)[1]
        out["islands"] = int(ndimage.label(contact, structure=np.ones((3, 3)))[1])
    return out


def main(argv: list[str] | None = None) -> int:
    from contact._grid import gap_grid
    from contact.bem import SolveOptions, solve_normal

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="128,256,512")
    ap.add_argument("--deflate-up-to", type=int, default=512)
    args = ap.parse_args(argv)
    for n in (int(v) for v in args.sizes.split(",") if v):
        gap, pixel, load = periodic_case(n)
        res = solve_normal(gap_grid(gap, pixel, periodic=True), e_star=1.0, load=load,
                           options=SolveOptions(tol=1e-8))
        rough = counts(np.asarray(res.pressure) > 0, gap, pixel, n <= args.deflate_up_to)
        y, x = (np.mgrid[:n, :n] - n / 2 + 0.5) * pixel
        disc = counts(x * x + y * y < (n * pixel / 4) ** 2, (x * x + y * y) / 2e-3, pixel,
                      False)
        print(f"{n:5d}^2  self-affine {rough}  disc {disc}", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
