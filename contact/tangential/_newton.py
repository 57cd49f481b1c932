"""One Newton step of the tangential problem for fixed adhesion and slip sets (GMRES).

Unknowns: the traction increments on the adhesion set H; in 3D the rotation d theta of
each slip traction q = g (cos theta, sin theta); and, when the total force F_x is
prescribed, the increment of the rigid slip (creepage or shift). Equations: s = 0 on H,
s x e = 0 (slip along the traction) on the slip set S, and sum(q_x) dA = F_x, linearised
about the present state (Kalker's Newton-Raphson for the slip directions, 1990 sec. 2.2).
In plane strain the slip directions are +-x and only H carries unknowns.

Scaling: traction unknowns are divided by G, equations by the slip scale (1 in rolling,
dx in a shift), slip rows by their own diagonal (elements at the rim, g -> 0, would
otherwise dwarf the rest). GMRES (Saad & Schultz 1986) is right-preconditioned by an
FFT approximation of the adhesion block's inverse (in the spirit of Vollebregt 2014,
J. Comput. Phys. 257:333): undo the upwind difference by summing from the leading edge,
then the influence by the inverse kernel spectrum.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from threadpoolctl import ThreadpoolController

from contact.halfspace.pair import HalfSpacePair
from contact.tangential._cropped import BoxProducts
from contact.tangential._kinematics import rolling_slip

PRECONDITIONER = "continuum"
# inner solves at or above this relative tolerance use float32 FFT products
SINGLE_ABOVE = 1e-6


def gmres(matvec, b: np.ndarray, precondition, rtol: float, restart: int = 100,
          max_cycles: int = 10) -> np.ndarray:
    """Right-preconditioned restarted GMRES (Saad & Schultz 1986) from x = 0.

    The Krylov basis is a matrix and each new vector is orthogonalised against it by two
    passes of classical Gram-Schmidt as matrix products (numerically as good as modified
    Gram-Schmidt, and free of the per-vector Python loops that dominate SciPy's version
    at tens of thousands of unknowns). Returns x (inexact if the cycles run out).

    BLAS runs on one thread here: its products are of vectors of 10^4-10^5 entries, where
    a second thread gains little on an idle machine and, spinning for a busy core, costs
    ten to a hundred times the product itself on a loaded one (measured, issue 19).
    """
    with _blas_controller().limit(limits=1, user_api="blas"):
        return _gmres(matvec, b, precondition, rtol, restart, max_cycles)


@lru_cache(maxsize=1)
def _blas_controller() -> ThreadpoolController:
    """One inspection of the loaded BLAS libraries (it reads files: a millisecond a call,
    a tenth of a small GMRES solve, measured, issue 19)."""
    return ThreadpoolController()


def _gmres(matvec, b, precondition, rtol, restart, max_cycles) -> np.ndarray:
    n = b.size
    x = np.zeros(n)
    bnorm = float(np.linalg.norm(b))
    if bnorm == 0.0:
        return x
    r = b.copy()
    for _ in range(max_cycles):
        beta = float(np.linalg.norm(r))
        if beta <= rtol * bnorm:
            break
        V = np.zeros((restart + 1, n))
        Z = np.zeros((restart, n))
        H = np.zeros((restart + 1, restart))
        V[0] = r / beta
        m, converged = restart, False
        for j in range(restart):
            Z[j] = precondition(V[j])
            w = matvec(Z[j])
            for _ in range(2):
                h = V[: j + 1] @ w
                w -= h @ V[: j + 1]
                H[: j + 1, j] += h
            H[j + 1, j] = np.linalg.norm(w)
            e1 = np.zeros(j + 2)
            e1[0] = beta
            y = np.linalg.lstsq(H[: j + 2, : j + 1], e1, rcond=None)[0]
            res = float(np.linalg.norm(H[: j + 2, : j + 1] @ y - e1))
            if H[j + 1, j] == 0.0 or res <= rtol * bnorm:
                m, converged = j + 1, True
                break
            V[j + 1] = w / H[j + 1, j]
        x += y @ Z[:m]
        if converged:
            # the least-squares residual is the residual (in exact arithmetic; the
            # products' float32 rounding is far below any rtol used here): a product
            # to confirm it would be a seventh of a Newton step's products
            break
        r = b - matvec(x)
    return x


def flat_indices(mask: np.ndarray, ncomp: int) -> np.ndarray:
    """Indices into a flattened (ncomp, *mask.shape) array of the masked elements of each
    component: with np.take and an assignment through a flat view these gather and
    scatter in a fraction of the time of boolean indexing, which recounts the mask on
    every call (measured, issue 19; the assignment is also about twice as fast as
    np.put, measured, issue 26)."""
    idx = np.flatnonzero(mask)
    return (idx[None, :] + mask.size * np.arange(ncomp)[:, None]).ravel()


def diagonal(op: HalfSpacePair, rolling: bool) -> tuple[float, float]:
    """The diagonal (x and y) of the slip operator: an element's slip per unit of its own
    traction (m/Pa in a shift, 1/Pa in rolling)."""
    kxx, kyy = op.real["xx"], op.real["yy"]
    if not rolling:
        return float(kxx[0, 0]), float(kyy[0, 0])
    return (float(kxx[0, 0] - kxx[0, 1]) / op.dx, float(kyy[0, 0] - kyy[0, 1]) / op.dx)


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """z component of a x b for stacked 2-vectors."""
    return a[0] * b[1] - a[1] * b[0]


@dataclass
class NewtonStep:
    """What a step changed: tractions, slip directions, largest rotation, rigid slip."""

    q: np.ndarray
    e: np.ndarray
    rotation: float
    dw: float


class NewtonSystem:
    """The linearised problem about (q0, e) for the sets H (adhesion) and S (slip)."""

    def __init__(self, op: HalfSpacePair, g, s0, q0, e_all, H, S, rolling: bool,
                 ncomp: int, dxx: float, force_residual: float | None):
        self.op, self.rolling, self.ncomp = op, rolling, ncomp
        self.H, self.S, self.q0, self.e_all = H, S, q0, e_all
        self.nh = int(H.sum())
        self.ns = int(S.sum()) if ncomp == 2 else 0
        self.aug = force_residual is not None and ncomp == 2
        self.G = op.c.G
        self.sref = 1.0 if rolling else op.dx
        self.e = e_all[:, S]
        self.t = np.stack([-self.e[1], self.e[0]])
        self.gs = g[S]
        # s . e < 0 on a settled slip element; one slipping the wrong way (about to
        # stick) is linearised as if its slip were zero, keeping the Jacobian regular
        self.se = np.minimum((s0[:, S] * self.e).sum(axis=0), 0.0)
        self.row = 1.0 / (1.0 + np.abs(self.se) / (self.gs * dxx)) if self.ns else None
        self.nc = max(int((g > 0).sum()), 1)
        b = [-s0[:ncomp, H].ravel()]
        if self.ns:
            b.append(-cross(s0[:, S], self.e) * self.row)
        if self.aug:
            b.append(np.array([force_residual / (self.G * self.nc)]))
        b = np.concatenate(b)
        # slip rows over the slip scale, the force row as it is (an array of the scales,
        # not a list of tens of thousands of floats: 3 ms a step at 256^2)
        scale = np.full(b.size, self.sref)
        if self.aug:
            scale[-1] = 1.0
        self.b = b / scale
        self.n = self.b.size
        # the products only ever see tractions on, and slips read on, loaded elements:
        # every product, difference and preconditioner runs on their box
        box = BoxProducts(op, g > 0)
        self._win = box.box or (slice(None), slice(None))
        self._inner = box.inner
        hb, sb = H[self._win], S[self._win]
        # the same elements are written on every call, so the rest stays zero
        self._dq = np.zeros((2, *hb.shape))
        self._ih = flat_indices(hb, ncomp)
        self._is = flat_indices(sb, 2)
        # the preconditioner stays the grid's: the box's own periodic symbol is a worse
        # one (the 64^2 and 128^2 solves took up to a fifth more products, measured)
        self._inverse = (op.tangential_stiffness if PRECONDITIONER == "continuum"
                         else op.tangential_inverse)
        self._full = np.zeros((2, *H.shape))
        self._window = self._full[(slice(None), *self._win)]
        self._u = np.zeros_like(self._dq)
        self.matvecs = 0
        self.single = False
        self._slip_diag = self._slip_diagonal(op, rolling) if self.ns else None

    def _slip_diagonal(self, op: HalfSpacePair, rolling: bool) -> np.ndarray:
        """The diagonal of the slip rows, as :meth:`matvec` forms them: the element's own
        slip across its traction per unit rotation of that traction (the self term of
        the slip operator along t), plus the linearised slip magnitude, row-scaled.
        Dividing by it (Jacobi) puts the slip rows' eigenvalues near 1 beside the
        adhesion rows' (whose FFT preconditioner does the same), instead of near a
        negative constant: two to six times fewer GMRES products (measured, issue 19)."""
        dxx, dyy = diagonal(op, rolling)
        own = self.G * (dxx * self.t[0] * self.e[1] - dyy * self.t[1] * self.e[0])
        return (own + self.se * self.G / self.gs) * self.row / self.sref

    def increments(self, x: np.ndarray) -> np.ndarray:
        """Traction increments (Pa) of the unknowns x, on the box."""
        k = self.ncomp * self.nh
        d = self._dq
        flat = d.reshape(-1)
        flat[self._ih] = x[:k] * self.G
        if self.ns:
            flat[self._is] = (self.G * x[k : k + self.ns] * self.t).ravel()
        return d

    def matvec(self, x: np.ndarray) -> np.ndarray:
        self.matvecs += 1
        k = self.ncomp * self.nh
        d = self.increments(x)
        u = self._inner.tangential(d[0], d[1] if self.ncomp == 2 else None, self.single)
        r = rolling_slip(u, self.op.dx) if self.rolling else u
        z = x[-1] * self.sref if self.aug else 0.0  # rigid slip increment along x
        rh = np.take(r, self._ih)
        rh[: self.nh] += z
        out = [rh / self.sref]
        if self.ns:
            xs = x[k : k + self.ns]
            rs = np.take(r, self._is).reshape(2, self.ns)
            rows = cross(rs, self.e) + z * self.e[1] + self.se * xs * self.G / self.gs
            out.append(rows * self.row / self.sref)
        if self.aug:
            out.append(np.array([d[0].sum() / (self.G * self.nc)]))
        return np.concatenate(out)

    def precondition(self, r: np.ndarray) -> np.ndarray:
        out = r.copy()
        k = self.ncomp * self.nh
        # the same elements are written on every call, so the rest of u stays zero; the
        # sums along x go straight into the grid's buffer (no temporaries: a fifth of
        # the preconditioner's time at 256^2)
        u = self._u
        u.reshape(-1)[self._ih] = r[:k] if self.sref == 1.0 else r[:k] * self.sref
        window = self._window
        if self.rolling:
            np.cumsum(u[..., ::-1], axis=-1, out=window[..., ::-1])
            window *= self.op.dx
            # the grid's preconditioner: the sums from the leading edge carry on,
            # constant, to the trailing edge of the grid (nothing is added outside the box)
            rows, cols = self._win
            if cols.start:
                self._full[:, rows, : cols.start] = window[..., :1]
        else:
            window[...] = u
        q = self._inverse(self._full[0], self._full[1])[(slice(None), *self._win)]
        out[:k] = np.take(q, self._ih) / self.G
        if self.ns:
            out[k : k + self.ns] = r[k : k + self.ns] / self._slip_diag
        return out

    def solve(self, rtol: float) -> NewtonStep:
        """Solve by GMRES (an inexact step is still a step: the caller judges)."""
        if self.n == 0 or not np.any(self.b):
            return NewtonStep(self.q0, self.e_all, 0.0, 0.0)
        pre = self.precondition if self.ncomp == 2 else (lambda v: v)
        # float32 products are exact enough for a loose step (their error, ~1e-7 of the
        # product, is far below its tolerance); the residual of every step is still
        # formed in float64 by the caller, so the answer keeps double precision
        self.single = rtol >= SINGLE_ABOVE
        x = gmres(self.matvec, self.b, pre, rtol)
        q = self.q0.copy()
        q[(slice(None), *self._win)] += self.increments(x)
        e_new = self.e_all.copy()
        rot = 0.0
        if self.ns:
            k = self.ncomp * self.nh
            dth = np.clip(x[k : k + self.ns] * self.G / self.gs, -np.pi / 3, np.pi / 3)
            en = self.e * np.cos(dth) + self.t * np.sin(dth)
            e_new[:, self.S] = en / np.hypot(en[0], en[1])
            q[:, self.S] = self.gs * e_new[:, self.S]
            rot = float(np.abs(dth).max())
        dw = float(x[-1] * self.sref) if self.aug else 0.0
        return NewtonStep(q, e_new, rot, dw)
