"""FFT boundary-element solver for frictionless normal contact on a regular grid.

The package's public entry is :func:`solve_normal`; its rooms:

- :mod:`contact.bem._solver`: input checks, nesting, result assembly (``solve_normal``:
  a :class:`~contact._grid.Grid`, the load or approach, the
  :class:`~contact.bem._bounds.PressureBounds` and the
  :class:`~contact.bem._options.SolveOptions`);
- :mod:`contact.bem._options`: :class:`~contact.bem._options.SolveOptions`, how a solve runs;
- :mod:`contact.bem._loop`: the one iteration driver of the 3D normal solves (this one's
  and the adhesive solve's): residual test, step, budget, callback;
- :mod:`contact.bem._iteration`: the feasible start and the Polonsky-Keer method the
  driver runs;
- :mod:`contact.bem._steps`: the conjugate-gradient (Polonsky-Keer) step, the projected
  gradient step and the mixed-precision re-sync, each a function of the iteration state;
- :mod:`contact.bem._state`: the problem, the work arrays, the iteration state, the counters;
- :mod:`contact.bem._kernels`: the numba kernels of the steps;
- :mod:`contact._nesting`: grid transfer for the nested (coarse-to-fine) solve;
- :mod:`contact.bem._result`: :class:`~contact.bem._result.ContactResult` and its derived
  quantities;
- :mod:`contact.bem._memory`: the memory model (peak bytes per cell) and the grid check.

The elastic half-space itself (influence coefficients, FFT convolution) is
:mod:`contact.halfspace`.

Conventions
-----------
- Grid: row ``i`` at ``y = y0 + i dy``, column ``j`` at ``x = x0 + j dx`` (cell centres).
  Each cell carries a uniform pressure (Love's influence coefficients,
  :mod:`contact.halfspace.influence`).
- ``gap0`` (h) is the initial separation of the two undeformed surfaces, in metres,
  positive where they are apart (for a ball on a plate: x^2/2R minus the composite
  roughness). Only differences of h matter to a load-controlled solve.
- ``u`` is the combined normal elastic displacement of the two surfaces, positive *into*
  the bodies (it opens the gap), u = K * p / E*.
- ``approach`` (delta) is the rigid-body approach of the two bodies. The deformed gap is
  ``g = h + u - delta`` and the contact conditions are g >= 0, p >= 0, p g = 0 (and, with a
  hardness H, p <= H, where g < 0 is the plastic displacement).
- Load control prescribes sum(p) dx dy = W and returns delta; approach control prescribes
  delta and returns W.

Algorithm
---------
Polonsky & Keer (1999), Wear 231:206: constrained conjugate gradient on the contact set,
with the mean gap removed (the Lagrange multiplier of the load constraint) and points
re-entering the contact restarting the conjugacy. Free boundaries use DC-FFT (Liu, Wang &
Liu 2000, Wear 243:101); periodic ones the periodised Love kernel.

Elastic-perfectly-plastic contact
---------------------------------
The pressure is capped at the hardness H as in Almqvist, Sahlin, Larsson & Glavatskih
(2007), Wear 262:1321: the capped points are a second active set, with their own
complementarity (0 <= p <= H; g = 0 where 0 < p < H; g >= 0 where p = 0; g <= 0 where
p = H, -g being the plastic displacement). The solution minimises the elastic energy
q(p) = p.K p / 2 + (h - delta).p over the box 0 <= p <= H (and, in load control, the
hyperplane sum p = W / (dx dy)), a convex bound-constrained quadratic programme. The
plain Polonsky-Keer step alone is not enough there: when every loaded point is capped no
free point is left to step on, the load rescaling of a handful of free points amplifies
them wildly, and a step that moves many points on and off the cap can raise q and cycle.
Following the gradient-projection / conjugate-gradient scheme of More & Toraldo (1991,
SIAM J. Optim. 1:93) and the bound-constrained CG of Vollebregt ("The bound-constrained
conjugate gradient method for non-negative matrices", 2014, J. Optim. Theory Appl.
162:931), the iteration is made monotone in q:

- each Polonsky-Keer step (CG on the free points, projection onto [0, H], points entering
  the contact or leaving the cap, load rescaling) is checked against q. The step s and
  K s (= the change of u, known by superposition) give q along s exactly, for the cost of
  a dot product: a step that raises q is cut to its minimiser;
- when that step cannot be taken (no free point, no descent, a load the rescaling cannot
  restore, or a rescaling by more than a factor 2), or after a cut one, a projected
  gradient step is taken instead: p + theta (P(p - alpha g) - p), where P is the exact
  projection onto the feasible set (clip(x - mu, 0, H) with the shift mu that restores the
  load) and theta the exact minimiser of q on that segment (one convolution). It moves
  points into contact and on and off the cap all at once and lowers q unless p is
  optimal; alpha follows Barzilai & Borwein (1988, IMA J. Numer. Anal. 8:141).

q thus decreases at every step, which rules out the cycling; the iteration stops at the
tolerance, at ``max_iter``, or (not converged) when even an exact displacement leaves no
descent direction. The elastic path (no hardness) is untouched.

What makes it fast
------------------
- Preconditioning: the search direction is built from the gap residual filtered by the
  periodic stiffness |q|/2, the approximate inverse of the influence operator (in the
  spirit of Vollebregt 2014, J. Comput. Phys. 257:333). This costs one unpadded FFT pair
  per iteration and cuts the iterations several-fold (117 -> 25 for Hertz at 1024^2).
- One padded FFT convolution per iteration instead of two: the displacement is updated by
  superposition, u <- s (u - tau K*t) + K*c, where c holds the few cells that the
  projection onto p >= 0 (or the entry of new contact points) changed. A handful of such
  cells are added by direct summation, more by one extra FFT.
- Mixed precision: the search-direction convolution K*t runs in float32 (half the memory
  traffic), while u, p and every reduction stay in float64. The float32 error of each
  update scales with the update, which shrinks as the solver converges; u is recomputed
  exactly in float64 whenever the residual has dropped 100-fold since the last exact
  evaluation and before convergence is declared, so the final answer carries float64
  accuracy.
- Pruned transforms: only the rows that carry pressure are transformed forward, the padded
  half of the result is never transformed back.
- Nested grids: without a warm start, the problem is first solved on a grid twice as
  coarse (recursively), and its pressure, interpolated, starts the fine solve.
- Kernel spectra and convolution plans are cached by (grid, pitch, periodicity).
"""

from contact.bem._bounds import PressureBounds
from contact.bem._options import SolveOptions
from contact.bem._solver import solve_normal

__all__ = ["PressureBounds", "SolveOptions", "solve_normal"]
