"""Prototype: a nonlinear FAS multigrid for the periodic normal contact (issue 37 item 7).

The production solve (:func:`contact.bem.solve_normal`: the constrained conjugate
gradient of Polonsky & Keer 1999, preconditioned by the masked stiffness |q|/2, from a
coarse-to-fine nested start) needs 25/31/44/61/82 fine iterations at 128^2-2048^2 on the
periodic self-affine case of ``benchmarks/core_scaling.py`` (H 0.8, rms slope 0.1, tol
1e-8). ``benchmarks/contact_set_preconditioners.py`` showed that linear remedies on the
final contact set keep the growth. Here the coarse levels carry the contact conditions
themselves: a full approximation scheme (Brandt 1977, Math. Comp. 31:333) for the
complementarity problem (Brandt & Cryer 1983, SIAM J. Sci. Stat. Comput. 4:655; the dry
contact of Venner & Lubrecht 2000, "Multilevel methods in lubrication", ch. 4-5):

- relaxation: a few projected steps of the same constrained, |q|/2-preconditioned
  conjugate gradient (steepest descent first: a fresh Krylov space every cycle), on
  p >= 0 with the load held by rescaling;
- restriction: the pressure by 2 x 2 block means (the load kept); the gap of the fine
  iterate, g = K p + h - delta, by a contact-aware restriction (the mean over the
  block's contact cells where it holds contact, else the block's least gap), so that the
  converged fine answer is a fixed point of the coarse problem;
- the coarse problem is itself a contact problem with the FAS gap
  h_H = R g + delta - K_H (R p): at P = R p its gap is R g, so it corrects the fine
  iterate only by what the fine grid cannot see;
- the coarse correction P - R p is spread evenly over each block's fine contact cells
  (the default, ``--prolong block``), or prolonged bilinearly (periodic) and added on
  the fine contact set (``--prolong bilinear``; everywhere with ``--correct all``);
  projected on p >= 0, the load restored; then post-relaxation;
- V(nu1, nu2) cycles down to 64^2 (solved there to 1e-10 by the same iteration), or
  W cycles (``--gamma 2``).

Work is counted in fine-grid FFT convolution pairs (forward + inverse of the grid's
size): a pair on a grid of a quarter of the cells counts a quarter. The production
solve is counted the same way from its per-level iterations (two pairs an iteration: the
step's convolution and the preconditioner; its re-syncs and sparse corrections are left
out, so it is counted slightly short).

Run::

    python3 benchmarks/contact_multigrid.py --sizes 128,256,512,1024

The figures and the verdict are in ``benchmarks/contact_multigrid.md``.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np
from scipy.fft import irfft2, rfft2

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from core_scaling import periodic_case  # noqa: E402

COARSEST = 64


class Level:
    """One grid: the periodic Love operator K, the preconditioner |q|/2, the work count."""

    def __init__(self, n: int, dx: float, counter: list[float], fine_cells: int):
        from contact.halfspace.convolution import convolution

        op = convolution(n, n, dx, dx, True)
        self.n, self.spec, self.stiff = n, op.spec64, op.stiffness(False)
        self.k0 = op.self_influence
        self.counter, self.weight = counter, n * n / fine_cells

    def conv(self, x: np.ndarray, multiplier: np.ndarray) -> np.ndarray:
        self.counter[0] += self.weight
        return irfft2(rfft2(x) * multiplier, s=x.shape)

    def k(self, p: np.ndarray) -> np.ndarray:
        return self.conv(p, self.spec)


def residual(level: Level, p: np.ndarray, g: np.ndarray) -> float:
    """The production solver's residual: rms gap error on the contact (plus violations
    off it) over the self-displacement of a cell at the mean contact pressure."""
    on = p > 0
    if not on.any():
        return math.inf
    err = np.sum(g[on] ** 2) + np.sum(np.minimum(g[~on], 0.0) ** 2)
    return math.sqrt(err / on.sum()) / (level.k0 * float(p[on].mean()))


def relax(level: Level, p: np.ndarray, h: np.ndarray, total: float, steps: int,
          tol: float = 0.0) -> tuple[np.ndarray, float, float, int]:
    """``steps`` constrained PCG steps (Polonsky-Keer, restarted from steepest descent
    when more than 1 % of the free cells enter); pressure, approach, residual, steps."""
    u = level.k(p)
    t = np.zeros_like(p)
    rho_old, restart = 1.0, True
    delta, res = 0.0, math.inf
    for k in range(steps):
        on = p > 0
        delta = float((u + h)[on].mean())
        g = u + h - delta
        res = residual(level, p, g)
        if res <= tol:
            return p, delta, res, k
        z = level.conv(g * on, level.stiff) * on
        z[on] -= z[on].mean()
        rho = float(np.vdot(g[on], z[on]))
        t = z + (0.0 if restart else rho / rho_old) * t * on
        rho_old = rho if rho > 0 else 1.0
        kt = level.k(t)
        kt_on = kt[on] - kt[on].mean()
        tau = float(np.vdot(g[on], t[on])) / float(np.vdot(t[on], kt_on))
        if not (tau > 0 and math.isfinite(tau)):
            restart = True
            continue
        p_new = p - tau * t
        enter = (~on) & (g < 0)
        p_new[enter] = -tau * g[enter]
        np.maximum(p_new, 0.0, out=p_new)
        scale = total / p_new.sum()
        p_new *= scale
        restart = enter.sum() > 0.01 * on.sum()
        changed = (p_new != scale * (p - tau * t))
        corr = np.where(changed, p_new - scale * (p - tau * t), 0.0)
        u = scale * (u - tau * kt)
        if changed.any():
            u += level.k(corr)
        p = p_new
    on = p > 0
    delta = float((u + h)[on].mean())
    return p, delta, residual(level, p, u + h - delta), steps


def coarsen(x: np.ndarray) -> np.ndarray:
    n = x.shape[0] // 2
    return x.reshape(n, 2, n, 2).mean(axis=(1, 3))


def restrict_gap(g: np.ndarray, p: np.ndarray) -> np.ndarray:
    """The contact-aware restriction: the mean gap over a block's contact cells where it
    holds contact, the block's least gap elsewhere."""
    n = g.shape[0] // 2
    on = (p > 0).reshape(n, 2, n, 2)
    gb = g.reshape(n, 2, n, 2)
    count = on.sum(axis=(1, 3))
    mean_on = np.where(on, gb, 0.0).sum(axis=(1, 3)) / np.maximum(count, 1)
    return np.where(count > 0, mean_on, gb.min(axis=(1, 3)))


def prolong(e: np.ndarray) -> np.ndarray:
    from contact._nesting import prolong as bilinear

    return bilinear(e, True)


def correction(e: np.ndarray, p: np.ndarray, args: argparse.Namespace) -> np.ndarray:
    """The fine correction of a coarse one ``e``: bilinear, on the fine contact (Brandt &
    Cryer) or everywhere; or ``block``: a block's change spread evenly over its contact
    cells, so that the block means of the correction are ``e`` exactly."""
    if args.prolong == "block":
        on = p > 0
        count = coarsen(on.astype(float)) * 4
        share = np.divide(4 * e, count, out=np.zeros_like(e), where=count > 0)
        return np.repeat(np.repeat(share, 2, 0), 2, 1) * on
    fine = prolong(e)
    return fine * (p > 0) if args.correct == "contact" else fine


def cycle(levels: list[Level], depth: int, p: np.ndarray, h: np.ndarray, total: float,
          args: argparse.Namespace) -> tuple[np.ndarray, float, float]:
    """One FAS cycle on ``levels[depth]``; pressure, approach, residual after it."""
    level = levels[depth]
    if depth == len(levels) - 1:
        p, delta, res, _ = relax(level, p, h, total, 400, 1e-10)
        return p, delta, res
    p, delta, _, _ = relax(level, p, h, total, args.nu1)
    g = level.k(p) + h - delta
    p_coarse = coarsen(p)
    coarse = levels[depth + 1]
    h_coarse = restrict_gap(g, p) + delta - coarse.k(p_coarse)
    q = p_coarse.copy()
    for _ in range(args.gamma):
        q, _, _ = cycle(levels, depth + 1, q, h_coarse, total / 4, args)
    p = p + correction(q - p_coarse, p, args)
    np.maximum(p, 0.0, out=p)
    p *= total / p.sum()
    p, delta, res, _ = relax(level, p, h, total, args.nu2)
    return p, delta, res


def fas_solve(gap: np.ndarray, pixel: float, load: float, args: argparse.Namespace,
              tol: float) -> dict:
    """FAS cycles from the production solver's nested start (the 64^2 answer prolonged
    level by level, each level one cycle) to ``tol``."""
    n = gap.shape[0]
    counter = [0.0]
    levels, m, dx = [], n, pixel
    coarsest = n // 2 if args.two_grid else COARSEST
    while m >= coarsest:
        levels.append(Level(m, dx, counter, n * n))
        m, dx = m // 2, dx * 2
    gaps = [gap]
    for _ in levels[1:]:
        gaps.append(coarsen(gaps[-1]))
    total = load / pixel ** 2
    p = np.full(levels[-1].n ** 2, total / n ** 2 * 4 ** (len(levels) - 1)).reshape(
        levels[-1].n, levels[-1].n)
    t0 = time.perf_counter()
    history = []
    for depth in range(len(levels) - 1, -1, -1):  # full multigrid start, one cycle a level
        cycles, res = 0, math.inf
        limit = args.max_cycles if depth == 0 else 1
        while cycles < limit and res > (tol if depth == 0 else 0.0):
            p, _, res = cycle(levels, depth, p, gaps[depth], total / 4 ** depth, args)
            cycles += 1
            if depth == 0:
                history.append(res)
        if depth:
            p = np.maximum(prolong(p), 0.0)
            p *= total / 4 ** (depth - 1) / p.sum()
    return {"pressure": p, "cycles": len(history), "pairs": counter[0],
            "seconds": time.perf_counter() - t0, "history": history}


def _pcg(a, m, center, b, x0, tol, maxit, flexible=False):
    """Preconditioned CG (Polak-Ribiere's beta where ``flexible``); iterate and steps."""
    x = x0.copy()
    r = center(b - a(x))
    r0 = np.linalg.norm(r)
    z = m(r)
    t, rho = z.copy(), float(np.vdot(r, z))
    for k in range(maxit):
        if np.linalg.norm(r) <= tol * r0 or rho == 0.0:
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


def ideal_two_grid(contact: np.ndarray, gap: np.ndarray, pixel: float) -> dict:
    """CG steps to a 1e-8 drop on the final contact set F (the linear problem of
    ``contact_set_preconditioners.py``): |q|/2 alone, and a two-grid cycle whose coarse
    operator is the exact Galerkin one, E^T C K C E (E: a 2 x 2 block's value on its
    contact cells, C: the load-neutral projection on F), solved to 1e-10 by an inner CG
    preconditioned by the coarse |q|/2 (each inner step a fine convolution: a yardstick
    of what a coarse level could do at best, not a cheap method)."""
    from contact_set_preconditioners import Level as SetLevel

    n, m = contact.shape[0], contact.shape[0] // 2
    fine = SetLevel(n, pixel, contact.astype(float))
    blocks = contact.reshape(m, 2, m, 2).any(axis=(1, 3))
    coarse = SetLevel(m, 2 * pixel, blocks.astype(float))

    def prolong_on(e: np.ndarray) -> np.ndarray:
        return fine.center(np.repeat(np.repeat(e, 2, 0), 2, 1) * contact)

    def restrict_on(r: np.ndarray) -> np.ndarray:
        return r.reshape(m, 2, m, 2).sum(axis=(1, 3)) * blocks

    def galerkin(e: np.ndarray) -> np.ndarray:
        return restrict_on(fine.center(fine.a(prolong_on(e))))

    inner: list[int] = []

    def cycle(r: np.ndarray) -> np.ndarray:
        z = fine.smooth(r)
        rc = restrict_on(fine.center(r - fine.a(z)))
        e, k = _pcg(galerkin, coarse.smooth, coarse.center, rc, np.zeros((m, m)), 1e-10, 500)
        inner.append(k)
        z = z + prolong_on(e)
        return z + fine.smooth(fine.center(r - fine.a(z)))

    b, x0 = -gap * contact, contact / contact.sum()
    plain = _pcg(fine.a, fine.smooth, fine.center, b, x0, 1e-8, 1000)[1]
    two = _pcg(fine.a, cycle, fine.center, b, x0, 1e-8, 200, flexible=True)[1]
    return {"stiffness": plain, "galerkin two-grid": two, "inner max": max(inner)}


def error_structure(contact: np.ndarray, gap: np.ndarray, pixel: float,
                    steps: int = 15) -> dict:
    """Where the error of ``steps`` |q|/2-preconditioned CG steps on the final contact set
    lies: the share of its K-energy on edge cells (chessboard distance 1 to a free cell)
    beside their share of the contact cells, and the share a block-constant correction
    on the contact cells of 2 x 2, 4 x 4 and 8 x 8 blocks cannot represent."""
    from contact_set_preconditioners import Level as SetLevel
    from scipy import ndimage

    n = contact.shape[0]
    level = SetLevel(n, pixel, contact.astype(float))
    b, x0 = -gap * contact, contact / contact.sum()
    exact = _pcg(level.a, level.smooth, level.center, b, x0, 1e-14, 2000)[0]
    e = level.center(_pcg(level.a, level.smooth, level.center, b, x0, 0.0, steps)[0]
                     - exact)
    energy = e * level.a(e)
    total = energy.sum()
    edge = contact & (ndimage.distance_transform_cdt(contact, metric="chessboard") == 1)
    out = {"edge cells": round(float(edge.sum() / contact.sum()), 2),
           "edge energy": round(float(energy[edge].sum() / total), 2)}
    for s in (2, 4, 8):
        m = n // s
        count = contact.reshape(m, s, m, s).sum(axis=(1, 3))
        mean = e.reshape(m, s, m, s).sum(axis=(1, 3)) / np.maximum(count, 1)
        d = level.center(e - np.repeat(np.repeat(mean, s, 0), s, 1) * contact)
        out[f"not on {s}x{s}"] = round(float((d * level.a(d)).sum() / total), 2)
    return out


def production(gap: np.ndarray, pixel: float, load: float) -> dict:
    from contact._grid import gap_grid
    from contact.bem import SolveOptions, solve_normal
    from contact.bem._state import SolverStats

    n = gap.shape[0]
    solve_normal(gap_grid(gap[:64, :64], pixel, periodic=True), e_star=1.0,
                 load=load / (n / 64) ** 2, options=SolveOptions(tol=1e-4))
    stats = SolverStats()
    t0 = time.perf_counter()
    res = solve_normal(gap_grid(gap, pixel, periodic=True), e_star=1.0, load=load,
                       options=SolveOptions(tol=1e-8, stats=stats, workers=1,
                                            precision="double"))
    pairs = sum(2 * it * ny * nx for ny, nx, it in stats.levels) / n ** 2
    return {"pressure": np.asarray(res.pressure), "iterations": res.iterations,
            "pairs": pairs, "seconds": time.perf_counter() - t0, "levels": stats.levels}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="128,256,512")
    ap.add_argument("--nu1", type=int, default=4)
    ap.add_argument("--nu2", type=int, default=4)
    ap.add_argument("--gamma", type=int, default=1)
    ap.add_argument("--correct", choices=("contact", "all"), default="contact")
    ap.add_argument("--prolong", choices=("bilinear", "block"), default="block")
    ap.add_argument("--ideal", action="store_true",
                    help="the Galerkin two-grid yardstick on the final contact set instead")
    ap.add_argument("--errors", action="store_true",
                    help="where the CG error lies on the final contact set instead")
    ap.add_argument("--two-grid", action="store_true",
                    help="two levels, the coarse contact problem solved to 1e-10")
    ap.add_argument("--max-cycles", type=int, default=60)
    ap.add_argument("--tol", type=float, default=1e-8)
    args = ap.parse_args(argv)
    print("n  | production: fine it, pairs, s | FAS: cycles, pairs, s | "
          "|dp|/pmax, dA/A | residual history", flush=True)
    for n in (int(v) for v in args.sizes.split(",") if v):
        gap, pixel, load = periodic_case(n)
        ref = production(gap, pixel, load)
        if args.ideal or args.errors:
            study = error_structure if args.errors else ideal_two_grid
            print(f"{n:5d}^2", study(ref["pressure"] > 0, gap, pixel), flush=True)
            continue
        fas = fas_solve(gap, pixel, load, args, args.tol)
        p_ref, p = ref["pressure"], fas["pressure"]
        dp = float(np.abs(p - p_ref).max() / p_ref.max())
        da = abs(int((p > 0).sum()) - int((p_ref > 0).sum())) / int((p_ref > 0).sum())
        hist = " ".join(f"{r:.1e}" for r in fas["history"][:12])
        print(f"{n:5d}^2 | {ref['iterations']:3d} {ref['pairs']:6.1f} {ref['seconds']:6.2f} | "
              f"{fas['cycles']:3d} {fas['pairs']:6.1f} {fas['seconds']:6.2f} | "
              f"{dp:.1e} {da:.1e} | {hist}", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
