"""The named transmission errors' final forms, once the effects are chosen: the overtones of
their harmonic series, a periodic modulation (sidebands) and the Legendre order of their
slowly varying amplitude and phase.

None changes which effects are named; each makes the reconciled model follow the data as
closely as the physics and the noise allow, and says what it chose in the notes.

References
----------
Seed 000 p.021 (angular transmission error, two cycles per input revolution).
Schwarz, G. (1978) "Estimating the dimension of a model", Ann. Stat. 6: BIC.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import minimize_scalar

from .fitting import Fit, Problem, finish
from .gates import BIC_MIN, bic_best, bic_gain, effective_n
from .harmonics import TE_ORDER_MAX, te_order_of
from .model_columns import nonlinear
from .noise import correlation_time, noise_rms
from .regions import ripples


def refine_te_order(problem: Problem, fit: Fit) -> Fit:
    """The named transmission errors with the Legendre order of their slowly varying
    amplitude and phase chosen by BIC (effective sample size N/τ, τ from the most flexible
    fit's residual), from the naming order up to ``TE_ORDER_MAX``; leaves
    ``problem.te_order`` at it.

    Effects are named at a low order (a flexible TE would take what a second effect
    explains); once named, a modulated error (amplitude or phase varying over the record)
    is followed as closely as the data support.
    """
    if not any(e.startswith("te_") for e in fit.effects):
        return fit
    shapes = len(nonlinear(problem.kind, fit.effects))
    fits = {}
    # the widest first: the lower orders' columns are its first ones (cached)
    for order in [TE_ORDER_MAX, *range(problem.te_order, TE_ORDER_MAX)]:
        problem.te_order = order
        fits[order] = finish(problem, fit.effects, fit.theta, shapes)
    best = bic_best({o: (f.rss, f.n_params) for o, f in fits.items()},
                     effective_n(problem, fits[TE_ORDER_MAX].residual(problem)))
    problem.te_order = best
    return fits[best]


# pairs of sidebands k ± j·f_m a named error's periodic modulation may carry: a phase
# modulation of depth d puts J_j(d) of the error into the j-th pair (J_3(1.2) = 2 %)
SIDEBANDS_MAX = 2

# overtones a named error may carry [cycles per WG revolution]: the multiples of its order up
# to the twelfth. A profile with corners carries them far: a full-wave rectified 2× has every
# even order at 4/π(4k² − 1) of its own (8× at 4.8 %), a triangle or trapezoid wave every odd
# or even one at 1/k²; up to the sixth only, suite P's rectified 2× kept 1.13σ for 1.05σ
TE_OVERTONES = {"te_1x": tuple(range(3, 13)), "te_2x": (4, 6, 8, 10, 12)}


def refine_te_overtones(problem: Problem, fit: Fit) -> Fit:
    """The named transmission errors with the overtones of their harmonic series that the
    data support (forward selection, each kept while it lowers the BIC by more than
    ``BIC_MIN`` at N/τ, τ from the fit with every allowed overtone); leaves
    ``problem.te_overtones`` at them.

    A wave generator's ellipse is not a pure 2× profile: its series carries 4× and 6×
    beside the 2×, and a runout's 1× its multiples. They are the named error's own
    harmonics, not effects of their own. In a run-up (vibration) each overtone passes
    through the joint like the error itself and excites the resonance at its own speed
    (k·f_input = f_n). A joint on the catalog curve, whose nonlinearity makes
    superharmonics of its own, is tried first (:func:`.refine.refine_spring`); when it is
    kept, no overtones are chosen.
    """
    allowed = sorted({k for e in fit.effects for k in TE_OVERTONES.get(e, ())})
    if problem.kind not in ("transmission", "vibration") or not allowed:
        return fit
    shapes = len(nonlinear(problem.kind, fit.effects))

    def with_overtones(orders):
        problem.te_overtones = tuple(sorted(orders))
        return finish(problem, fit.effects, fit.theta, shapes)

    n_eff = effective_n(problem, with_overtones(allowed).residual(problem))
    chosen, best = (), fit
    while len(chosen) < len(allowed):
        trials = {k: with_overtones(chosen + (k,)) for k in allowed if k not in chosen}
        k = min(trials, key=lambda j: trials[j].rss)
        if bic_gain(best, trials[k], n_eff) <= BIC_MIN:
            break
        chosen, best = chosen + (k,), trials[k]
    problem.te_overtones = tuple(sorted(chosen))
    if chosen:
        problem.notes.append("transmission error: overtones of the named error's harmonic "
                             "series kept at " + ", ".join(f"{k}×" for k in sorted(chosen))
                             + " per WG revolution (BIC)")
    return best


def refine_te_sidebands(problem: Problem, fit: Fit) -> Fit:
    """Transmission: a named error modulated periodically, its sidebands k ± j·f_m beside it
    (:func:`.harmonics.sidebands`), f_m from a ripple the residual holds within half an
    order of k (:func:`.regions.ripples`), the first pair and then each next kept while it
    lowers the BIC by more than ``BIC_MIN`` (f_m counted as a parameter, up to
    ``SIDEBANDS_MAX`` pairs); leaves ``problem.te_sidebands`` at those kept. A member turning
    slower than the wave generator (the output, an Oldham coupling, a bearing's cage) whose
    runout or stiffness changes the error's amplitude or phase every 1/f_m WG revolutions
    gives such sidebands; the slow Legendre form follows a modulation over the record, not
    one that repeats within it. Vibration: the same sidebands through the joint, f_m
    searched (:func:`_vibration_sidebands`)."""
    named = {te_order_of(e) for e in fit.effects if e.startswith("te_")}
    if problem.kind == "vibration" and named:
        return _vibration_sidebands(problem, fit, named)
    if problem.kind != "transmission" or not named:
        return fit
    residual = problem.base.y - fit.prediction
    rows = residual[problem.rows]
    found = ripples(problem, residual, noise_rms(rows), correlation_time(rows),
                    named | set(problem.te_overtones))
    for order, _, whole in found:
        near = min(named, key=lambda k: abs(order - k))
        if whole or abs(order - near) >= 0.5 or near in problem.te_sidebands:
            continue
        f_m, kept = abs(order - near), 0
        for count in range(1, SIDEBANDS_MAX + 1):
            problem.te_sidebands[near] = (f_m, count)
            shapes = len(nonlinear(problem.kind, fit.effects)) + len(problem.te_sidebands)
            trial = finish(problem, fit.effects, fit.theta, shapes)
            if bic_gain(fit, trial, effective_n(problem, trial.residual(problem))) <= BIC_MIN:
                break
            fit, kept = trial, count
        if not kept:
            del problem.te_sidebands[near]
        else:
            problem.te_sidebands[near] = (f_m, kept)
            problem.notes.append(
                f"transmission error: the {near}× error's amplitude or phase varies every "
                f"{1 / f_m:.3g} WG revolutions; its sidebands at {near} ± "
                + ", ".join(f"{j * f_m:.3g}" for j in range(1, kept + 1))
                + " cycles per WG revolution kept (BIC)")
    return fit


# modulation rates f_m [cycles per WG revolution] a vibration test's sidebands are searched
# over: a member turning slower than the wave generator (a bearing's cage at about 0.4 of
# the WG's rate relative to its outer ring, an Oldham coupling, the output) within one
# order; the grid's step, then a bounded search about its best
SIDEBAND_RATES = (0.03, 0.9)
SIDEBAND_GRID_STEP = 0.02


def _vibration_sidebands(problem: Problem, fit: Fit, named: set[int]) -> Fit:
    """Vibration: a named error modulated periodically, its sidebands k ± f_m through the
    joint beside it. Each sideband order crosses the resonance at a run-up speed of its own
    (f_n/(k ± f_m)), where a steady error has none, so f_m is found by the fit: a grid over
    ``SIDEBAND_RATES``, then a bounded search about its best; one pair kept per error when it
    lowers the BIC by more than ``BIC_MIN`` (f_m counted as a parameter)."""
    for order in sorted(named):
        tried: dict[float, Fit] = {}

        def trial(f_m: float) -> Fit:
            """The fit with one sideband pair at ``f_m`` (left set on the problem)."""
            problem.te_sidebands[order] = (float(f_m), 1)
            if float(f_m) not in tried:
                shapes = len(nonlinear(problem.kind, fit.effects)) + len(problem.te_sidebands)
                tried[float(f_m)] = finish(problem, fit.effects, fit.theta, shapes)
            return tried[float(f_m)]

        grid = np.arange(SIDEBAND_RATES[0], SIDEBAND_RATES[1] + 1e-9, SIDEBAND_GRID_STEP)
        start = min(grid, key=lambda f: trial(f).rss)
        found = minimize_scalar(lambda f: trial(f).rss, method="bounded", bounds=(
            max(start - SIDEBAND_GRID_STEP, SIDEBAND_RATES[0]),
            min(start + SIDEBAND_GRID_STEP, SIDEBAND_RATES[1])), options={"xatol": 1e-4})
        best = trial(found.x)
        if bic_gain(fit, best, effective_n(problem, best.residual(problem))) <= BIC_MIN:
            del problem.te_sidebands[order]
            continue
        fit = best
        problem.notes.append(
            f"transmission error: the {order}× error's amplitude or phase varies every "
            f"{1 / found.x:.3g} WG revolutions (a member turning slower than the wave "
            f"generator: a bearing's cage, a coupling); its sidebands at {order} ± "
            f"{found.x:.3g} cycles per WG revolution cross the resonance at run-up speeds of "
            "their own, kept (BIC)")
    return fit
