"""Weighted least-squares fits of the law-of-motion models on the times.

Every model but ``parabola`` is fitted on the *times*, the quantity that was measured,
weighted by the reading-noise model (:mod:`rotor._noise`). Each model's noise is its
maximum-likelihood estimate from leverage-corrected residuals ``r/sqrt(1 - h)``, so that a
model spending its parameters on the few slow rows does not also shrink ``sigma_a`` there.
The family is fitted in nesting order, every richer model from its parents' optima (the
unbalance models also from four phases), the constant-acceleration model also from the
start profile (:func:`rotor._starts.start_profile`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np
from scipy.optimize import least_squares

from contact._errors import ContactInputError
from rotor._arrays import on_rows, readonly
from rotor._diagnostics import (
    lag1_autocorrelation,
    minus_two_log_likelihood,
    runs_test_z,
)
from rotor._family import (
    CORE,
    MODELS,
    ORDER,
    ModelFit,
    ModelSpec,
    ancestors,
    with_derived_params,
)
from rotor._forward import PARAM_NAMES, batch_crossing_times, crossing_times, model_speeds
from rotor._noise import Noise, estimate_noise, quantisation_sigma
from rotor._paper import FPS, MARK_STEP
from rotor._parabola import fit_parabola
from rotor._starts import (
    from_rest_estimate,
    full_parameters,
    inside_bounds,
    parameter_bounds,
    start_profile,
)

__all__ = ["fit_all_models", "fit_model", "leverages_at", "loo_exact"]


def fit_model(
    times: np.ndarray,
    angles: np.ndarray,
    model: str,
    *,
    fps: float = FPS,
    step: float = MARK_STEP,
    used: np.ndarray | None = None,
    inits: Sequence[Mapping[str, float]] = (),
    noise: Noise | None = None,
    noise_start: Noise | None = None,
    loss: str = "linear",
    irls: int = 1,
    max_starts: int = 2,
    max_nfev: int | None = None,
) -> ModelFit:
    """Fit one model of the family on the times, weighted by the reading-noise model.

    Parameters
    ----------
    times, angles : ndarray
        Times (s, 0 at the first row) and angles (rad, 0 at the first row) of one test.
    model : str
        A key of :data:`MODELS`.
    fps, step : float
        Frame rate (quantisation floor) and mark step (bound on the start angle).
    used : ndarray of bool, optional
        Rows in the fit (default all); the others get prediction errors.
    inits : sequence of dict
        Starting points; the best fit over them is kept (missing parameters start at 0,
        ``eps0`` at the from-rest estimate).
    noise : Noise, optional
        Fixed reading noise. Default: estimated by maximum likelihood, alternating with the
        weighted fit ``irls`` times (iteratively reweighted least squares), from
        ``noise_start`` (default: quantisation only).
    loss : str
        ``least_squares`` loss on the standardised residuals (``soft_l1`` for robust fits).
    irls : int
        Reweighting rounds when the noise is estimated.
    max_starts : int
        The fit starts from this many of ``inits``, those that fit best as they are.
    max_nfev : int, optional
        Iteration budget of each least-squares run (default ``15 * n_params``): a model
        that cannot describe the data wanders for hundreds of iterations in a nearly flat
        valley without a better fit at the end.
    """
    if model not in MODELS:
        raise ContactInputError(f"unknown model {model!r}; known: {', '.join(MODELS)}")
    t = np.asarray(times, dtype=float)
    phi = np.asarray(angles, dtype=float)
    if t.shape != phi.shape or t.ndim != 1:
        raise ContactInputError("times and angles must be 1-D arrays of the same length")
    used = np.ones(t.shape, bool) if used is None else np.asarray(used, bool)
    n = int(used.sum())
    spec = MODELS[model]
    if n <= len(spec.free) + 2:
        raise ContactInputError(
            f"model {model!r} has {len(spec.free)} parameters; {n} rows are too few to fit it"
        )
    if model == "parabola":
        return fit_parabola(t, phi, used, fps, step)
    free = spec.free
    sq = quantisation_sigma(fps)
    tu, pu = t[used], phi[used]
    i0 = int(np.argmin(phi))
    fixed = {"t0": float(t[i0]), "phi0": float(phi[i0])} if model == "rest" else {}
    eps_rest = from_rest_estimate(tu, pu)
    bd = parameter_bounds(tu, pu, step, eps_rest)
    lo = np.array([bd[k][0] for k in free])
    hi = np.array([bd[k][1] for k in free])

    starts = []
    for start in list(inits) or [{}]:
        base = {"eps0": eps_rest, "t0": float(t[i0]), "phi0": float(phi[i0]) - 1e-6}
        base.update({k: v for k, v in start.items() if k in free})
        starts.append(np.array([inside_bounds(base.get(k, 0.0), lo[j], hi[j])
                                for j, k in enumerate(free)]))

    cur_noise = noise if noise is not None else (noise_start or Noise(sq, 0.0))
    if max_nfev is None:
        max_nfev = 15 * len(free)

    cols = [PARAM_NAMES.index(k) for k in free]
    base_row = np.array([full_parameters(free, np.zeros(len(free)), fixed)[k]
                         for k in PARAM_NAMES])

    def rows(xs: np.ndarray) -> np.ndarray:
        pr = np.repeat(base_row[None, :], xs.shape[0], axis=0)
        pr[:, cols] = xs
        return pr

    # weights from the best starting point's speeds
    def sigmas(x: np.ndarray, nz: Noise) -> np.ndarray:
        p = full_parameters(free, x, fixed)
        return nz.sigma(model_speeds(phi, p), p["eps0"], i0)

    def cost0(x0: np.ndarray) -> float:
        r = crossing_times(pu, **full_parameters(free, x0, fixed)) - tu
        return float(np.sum((r / sigmas(x0, cur_noise)[used]) ** 2))

    x0s = sorted(starts, key=cost0)[:max_starts]
    rounds = max(irls, 1) if noise is None else 1
    best = None
    sig = sigmas(x0s[0], cur_noise)
    for it in range(rounds + 1):
        best = _best_least_squares(pu, tu, rows, (lo, hi), [best.x] if best is not None
                                   else x0s, sig[used], loss, max_nfev)
        if it == rounds:
            break
        if noise is None:
            p = full_parameters(free, best.x, fixed)
            cur_noise = _noise_of_fit(best, p, pu, tu, np.flatnonzero(used) != i0, sq,
                                      cur_noise)
        new_sig = sigmas(best.x, cur_noise)
        # the weights depend on the fitted speeds; refit only if they moved
        if noise is not None and np.max(np.abs(new_sig / sig - 1.0)) < 0.02:
            break
        sig = new_sig
    return _finish_fit(model, t, phi, used, free, fixed, best, cur_noise, fps, sq)


def _best_least_squares(pu, tu, rows, bounds, x0s, sig_u, loss, max_nfev):
    """The best of bounded trust-region least-squares runs from ``x0s`` on the standardised
    time residuals; ``rows`` maps free-parameter vectors to full parameter rows."""
    lo, hi = bounds

    def fun(x: np.ndarray) -> np.ndarray:
        return (batch_crossing_times(pu, rows(x[None, :]))[0] - tu) / sig_u

    def jac(x: np.ndarray) -> np.ndarray:
        # forward differences, stepping inwards at an upper bound, in one batch
        hstep = 1e-7 * np.maximum(1.0, np.abs(x))
        hstep = np.where(x + hstep > hi, -hstep, hstep)
        xs = np.repeat(x[None, :], len(x) + 1, axis=0)
        xs[1:] += np.diag(hstep)
        tt = batch_crossing_times(pu, rows(xs))
        return ((tt[1:] - tt[0]) / hstep[:, None]).T / sig_u[:, None]

    best = None
    for x0 in x0s:
        # tolerances well below the noise: 1e-7 of the cost is ~1e-5 sigma in time
        r = least_squares(fun, x0, jac=jac, bounds=(lo, hi), x_scale="jac", loss=loss,
                          method="trf", max_nfev=max_nfev, ftol=1e-7, xtol=1e-7)
        if best is None or r.cost < best.cost:
            best = r
    return best


def _noise_of_fit(best, params, pu, tu, keep, sq, start: Noise) -> Noise:
    """The reading noise from a fit's leverage-corrected residuals ``r/sqrt(1 - h)`` on the
    rows ``keep``: a model that spends its parameters on the few slow early rows does not
    also shrink ``sigma_a`` there."""
    r = crossing_times(pu, **params) - tu
    jf = np.asarray(best.jac)[:, np.asarray(best.active_mask) == 0]
    lev = (np.einsum("ij,jk,ik->i", jf, np.linalg.pinv(jf.T @ jf), jf)
           if jf.shape[1] else np.zeros(r.size))
    rc = r / np.sqrt(np.maximum(1.0 - lev, 1e-6))
    return estimate_noise(rc[keep], model_speeds(pu, params)[keep], params["eps0"], sq, start)


def _finish_fit(model, t, phi, used, free, fixed, r, noise, fps, sq) -> ModelFit:
    params = full_parameters(free, r.x, fixed)
    res = crossing_times(phi, **params) - t
    sig = noise.sigma(model_speeds(phi, params), params["eps0"], int(np.argmin(phi)))
    ru = res[used]
    su = sig[used]
    n = int(used.sum())
    p = len(free)
    chi2 = float(np.sum((ru / su) ** 2))
    jac = np.asarray(r.jac, dtype=float)  # of the standardised residuals
    active = np.asarray(r.active_mask) != 0
    jf = jac[:, ~active]
    stderr = {k: math.nan for k in free}
    lev = np.zeros(n)
    if jf.shape[1]:
        jtj_inv = np.linalg.pinv(jf.T @ jf)
        cov = max(chi2 / max(n - p, 1), 1.0) * jtj_inv
        for j, k in enumerate(np.array(free)[~active]):
            stderr[str(k)] = float(math.sqrt(max(cov[j, j], 0.0)))
        lev = np.einsum("ij,jk,ik->i", jf, jtj_inv, jf)
    press = ru / np.maximum(1.0 - lev, 1e-6)
    # the first row is the time origin of every model: it is not predicted
    not_first = np.flatnonzero(used) != int(np.argmin(phi))
    rss = float(ru @ ru)
    return ModelFit(
        model=model,
        params=with_derived_params(params),
        stderr=stderr,
        residuals=readonly(res),
        sigma=readonly(sig),
        used=readonly(used),
        n=n,
        p=p,
        rss=rss,
        rms=math.sqrt(rss / n),
        chi2=chi2,
        noise=noise,
        bic=minus_two_log_likelihood(ru, su) + (p + 2) * math.log(n),
        loo_rms=float(np.sqrt(np.mean(press[not_first] ** 2))),
        chi2_quant=rss / (sq**2 * max(n - p, 1)),
        runs_z=runs_test_z(ru),
        lag1=lag1_autocorrelation(ru),
        success=bool(r.success),
        press=readonly(press),
        leverage=readonly(on_rows(lev, used)),
    )


def _parent_starts(fits: Mapping[str, ModelFit], spec: ModelSpec) -> list[dict[str, float]]:
    inits = []
    for parent in spec.parents:
        if parent in fits and fits[parent].success:
            pp = dict(fits[parent].params)
            if parent == "rest":
                pp["phi0"] = pp["phi0"] - 1e-6
            if "wave_c" in spec.free and "wave_c" not in MODELS[parent].free:
                # an unbalance is a plate wave of one turn's period
                pp.update(wave_c=pp["a_c"], wave_s=pp["a_s"], wave_period=2 * math.pi)
            inits.append({k: v for k, v in pp.items() if k in spec.free})
    return inits


def _parent_noise(fits: Mapping[str, ModelFit], spec: ModelSpec) -> Noise | None:
    cands = [fits[p] for p in spec.parents if p in fits]
    return min(cands, key=lambda f: f.bic).noise if cands else None


def fit_all_models(
    times: np.ndarray,
    angles: np.ndarray,
    *,
    fps: float = FPS,
    step: float = MARK_STEP,
    used: np.ndarray | None = None,
    models: Sequence[str] | None = None,
    noise: Noise | None = None,
    loss: str = "linear",
    starts: Mapping[str, Sequence[Mapping[str, float]]] | None = None,
    fitted: Mapping[str, ModelFit] | None = None,
    max_starts: Mapping[str, int] | None = None,
) -> dict[str, ModelFit]:
    """Fit models in nesting order, each started from its parents' optima (so a richer model
    does not end worse than a parent it contains). ``models`` defaults to the core family
    (:data:`rotor._family.CORE`); their ancestors are fitted too but only the
    requested ones are returned. ``starts`` adds starting points per model; ``fitted``
    holds fits already made on the same rows (reused, not refitted); ``max_starts``
    overrides, per model, how many starting points are run."""
    t = np.asarray(times, float)
    phi = np.asarray(angles, float)
    n_used = int(t.size if used is None else np.count_nonzero(used))
    # by default every model the rows can support (a short column leaves the richest out)
    wanted = list(models or [m for m in CORE if n_used > len(MODELS[m].free) + 2])
    todo = ancestors(wanted)
    fits: dict[str, ModelFit] = dict(fitted or {})
    for name in ORDER:
        if name not in todo or name in fits:
            continue
        spec = MODELS[name]
        extra = [dict(s) for s in (starts or {}).get(name, ())]
        # a wave model given starts (the periodogram's peaks) runs from them alone
        inits = extra if extra and "wave_c" in spec.free else _parent_starts(fits, spec) + extra
        if name == "const":
            u = np.ones(t.shape, bool) if used is None else np.asarray(used, bool)
            inits.extend(start_profile(t[u], phi[u], step))
        if name == "const" and "parabola" in fits:
            c2, c1, c0 = (fits["parabola"].params[k] for k in ("c2", "c1", "c0"))
            if c2 > 0:
                inits.append({"eps0": 2 * c2, "t0": -c1 / (2 * c2),
                              "phi0": c0 - c1 * c1 / (4 * c2)})
        n_starts = 2
        if "wave_c" in spec.free:
            n_starts = 1
        elif "a_c" in spec.free and inits:
            # the unbalance phase makes the cost multimodal: also start from four phases
            base = min(inits, key=lambda d: 0.0 if "a_c" in d else 1.0)
            amp = 0.25 * float(base.get("eps0", 1.0))
            for q in range(4):
                inits.append({**base, "a_c": amp * math.cos(q * math.pi / 2),
                              "a_s": amp * math.sin(q * math.pi / 2)})
            n_starts = 3
        n_starts = (max_starts or {}).get(name, n_starts)
        fits[name] = fit_model(t, phi, name, fps=fps, step=step, used=used, inits=inits,
                               noise=noise, noise_start=_parent_noise(fits, spec), loss=loss,
                               max_starts=n_starts)
    return {k: fits[k] for k in ORDER if k in wanted}


def loo_exact(times: np.ndarray, angles: np.ndarray, fit: ModelFit, *, fps: float = FPS,
              step: float = MARK_STEP) -> float:
    """Exact leave-one-point-out prediction rms (s): refit without each used row (from the
    full fit, with its noise model) and predict the row."""
    if fit.model == "parabola":
        return fit.loo_rms
    t = np.asarray(times, float)
    phi = np.asarray(angles, float)
    idx = np.flatnonzero(fit.used)
    init = {k: fit.params[k] for k in MODELS[fit.model].free}
    first = int(np.argmin(phi))
    errs = []
    for i in idx:
        if i == first:
            continue  # the first row is the time origin of every model
        keep = np.array(fit.used, copy=True)
        keep[i] = False
        f = fit_model(t, phi, fit.model, fps=fps, step=step, used=keep, inits=[init],
                      noise=fit.noise)
        errs.append(float(f.residuals[i]))
    return float(np.sqrt(np.mean(np.square(errs))))


def leverages_at(t: np.ndarray, phi: np.ndarray, fit: ModelFit, rows: np.ndarray,
                    fps: float) -> np.ndarray:
    """Leverages of ``rows`` (mask) at ``fit``'s parameters and noise, NaN elsewhere."""
    spec = MODELS[fit.model]
    first = int(np.argmin(phi))
    fixed = {"t0": float(t[first]), "phi0": float(phi[first])} if fit.model == "rest" else {}
    free = list(spec.free)
    x = np.array([fit.params[k] for k in free])
    sig = np.asarray(fit.sigma)[rows]
    base = crossing_times(phi[rows], **full_parameters(free, x, fixed))
    cols = []
    for j in range(len(free)):
        h = 1e-6 * max(1.0, abs(x[j]))
        xp = x.copy()
        xp[j] += h
        cols.append((crossing_times(phi[rows], **full_parameters(free, xp, fixed)) - base) / h)
    jac = np.array(cols).T / sig[:, None]
    lev = np.einsum("ij,jk,ik->i", jac, np.linalg.pinv(jac.T @ jac), jac)
    return on_rows(lev, rows)
