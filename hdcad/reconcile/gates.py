"""The evidence an effect must show to be named: the gates and the loop test.

A model is accepted over a simpler one when it passes the gates:
ΔBIC = (N/τ)·ln(RSS_before/RSS_after) − Δk·ln(N/τ) > ``BIC_MIN`` with N/τ the effective
sample size (τ the noise's correlation time), the blocked 5-fold cross-validated error falls
by ``CV_GAIN_MIN`` (contiguous chunks: correlated neighbours are held out together), the
variance it explains is ≥ ``EXPLAINED_MIN`` of the noise variance; and an effect added to
another must explain ≥ ``SECOND_SHARE_MIN`` of the structure the other leaves (residual
variance above the noise): the shape mismatch of an effect's formula must not be named as a
second effect. Hysteresis also needs its signature: loading and unloading branches that
differ beyond the noise (a loop), not only a better fit (:func:`loop_evidence`). A linear
housing spring, alone or beside a backlash, may pass by its shape instead (ΔBIC and a
cross-validated error that falls: :func:`.springs.by_its_shape`).

References
----------
Schwarz, G. (1978) "Estimating the dimension of a model", Ann. Stat. 6: BIC.
Kass, R. E., Raftery, A. E. (1995) J. Am. Stat. Assoc. 90: ΔBIC > 10 is very strong evidence.
Roberts, D. R. et al. (2017) "Cross-validation strategies for data with temporal, spatial,
hierarchical, or phylogenetic structure", Ecography 40: blocked cross-validation.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .fitting import Fit, Problem
from .noise import ar1_time, noise_model, noise_rms
from .regions import directions

BIC_MIN = 10.0
CV_GAIN_MIN = 0.05
EXPLAINED_MIN = 0.1
SECOND_SHARE_MIN = 0.3
# An effect named on a second try (a loop tried once every effect has failed, a second
# decided only once the first has its final form) must explain at least the noise variance:
# a second try must not rest on a marginal gain (a wrong-units decoy passed at 0.13σ²).
SECOND_TRY_EXPLAINED_MIN = 1.0
# Loop evidence: branch separation χ² z-score and RMS (in noise RMS) over torque bins.
LOOP_Z = 5.0
LOOP_RMS_MIN = 0.5
LOOP_BINS = 10
GATE_NOTE = (f"an effect is named when ΔBIC > {BIC_MIN:g} (effective sample size N/τ), the "
             f"blocked 5-fold cross-validated error falls by ≥ {CV_GAIN_MIN:.0%}, it explains "
             f"≥ {EXPLAINED_MIN:g}× the noise variance and, added to another effect, "
             f"≥ {SECOND_SHARE_MIN:.0%} of what that one leaves; hysteresis needs a loop "
             "(loading and unloading branches apart beyond the noise); a linear housing "
             "spring, alone or beside a backlash, is named by its shape (ΔBIC > "
             f"{BIC_MIN:g} and a cross-validated error that falls: the same compliance at "
             "every torque, which the stiffness scale does not give)")


@dataclass
class Gate:
    """The evidence of ``fit`` over ``reference``."""

    delta_bic: float
    cv_gain: float
    explained: float        # explained variance / noise variance
    share: float            # share of the reference's structure above the noise explained

    def passes(self, second: bool = False) -> bool:
        ok = (self.delta_bic > BIC_MIN and self.cv_gain > CV_GAIN_MIN
              and self.explained > EXPLAINED_MIN)
        return ok and (not second or self.share >= SECOND_SHARE_MIN)


def gate(problem: Problem, reference: Fit, fit: Fit, sigma: float, tau: float) -> Gate:
    n = len(problem.rows)
    bic = bic_gain(reference, fit, n / tau)
    cv = ((reference.cv_mse - fit.cv_mse) / reference.cv_mse if reference.cv_mse > 0
          else 0.0)
    explained = (reference.rss - fit.rss) / n / sigma ** 2
    structure = reference.rss / n - sigma ** 2
    share = (reference.rss - fit.rss) / n / structure if structure > 0 else math.inf
    return Gate(bic, cv, explained, share)


def bic_gain(reference: Fit, fit: Fit, n_eff: float) -> float:
    """ΔBIC [-] of ``fit`` over ``reference`` at the effective sample size ``n_eff``:
    n_eff·ln(RSS_ref/RSS) − Δk·ln(n_eff) (positive: ``fit`` is preferred)."""
    return rss_bic_gain(reference.rss, fit.rss, fit.n_params - reference.n_params, n_eff)


def rss_bic_gain(rss_reference: float, rss: float, extra_params: int, n_eff: float) -> float:
    """ΔBIC [-] of a fit of residual sum of squares ``rss`` with ``extra_params`` more
    parameters over one of ``rss_reference`` (:func:`bic_gain`)."""
    return (n_eff * math.log(rss_reference / max(rss, 1e-300))
            - extra_params * math.log(n_eff))


def round_noise(problem: Problem, fits: list[Fit]) -> tuple[float, float]:
    """(σ, τ): noise RMS and correlation time [fitted rows] for one round of candidates.

    From the residual of all the round's candidates together (their columns at their own
    shapes, one least squares): the residual of one candidate still holds the effects it
    lacks, which would pass for noise (a transmission error sampled a dozen times per
    revolution is as rough as noise to the lagged differences) and deflate every candidate's
    evidence alike. τ = (1 + φ)/(1 − φ) of the AR(1) fit (:func:`.noise.noise_model`).
    """
    X = np.column_stack([f.columns for f in fits])
    beta = np.linalg.lstsq(X, problem.y, rcond=None)[0]
    sigma, phi = noise_model(problem.y - X @ beta)
    return sigma, ar1_time(phi)


def loop_evidence(problem: Problem, residual: np.ndarray, sigma: float, tau: float
                  ) -> tuple[float, float]:
    """(z, rms/σ) of the difference between loading and unloading branches of the residual.

    In each of ``LOOP_BINS`` torque bins the mean residual on loading rows minus that on
    unloading rows; χ² of these differences against their standard errors
    σ·√(τ·(1/n_up + 1/n_down)), as z = (χ² − m)/√(2m). A single-valued error of the curve
    (stiffness, shape, play) moves both branches alike; only a loop separates them.
    """
    torque = problem.base.inputs["torque_Nm"][problem.rows]
    up = directions(problem)[problem.rows] > 0
    edges = np.linspace(torque.min(), torque.max(), LOOP_BINS + 1)
    index = np.clip(np.searchsorted(edges, torque, side="right") - 1, 0, LOOP_BINS - 1)
    diffs, errs = [], []
    for b in range(LOOP_BINS):
        a, d = residual[(index == b) & up], residual[(index == b) & ~up]
        if len(a) >= 5 and len(d) >= 5:
            diffs.append(a.mean() - d.mean())
            errs.append(sigma * math.sqrt(tau * (1 / len(a) + 1 / len(d))))
    if not diffs:
        return 0.0, 0.0
    diffs, errs = np.array(diffs), np.array(errs)
    m = len(diffs)
    chi2 = float(np.sum((diffs / errs) ** 2))
    return (chi2 - m) / math.sqrt(2 * m), float(np.sqrt(np.mean(diffs ** 2))) / sigma


def has_evidence(problem: Problem, effect: str, without: Fit, sigma: float, tau: float
                 ) -> bool:
    """The effect's signature is in the residual of the model without it."""
    if effect != "hysteresis":
        return True
    z, rms = loop_evidence(problem, without.residual(problem), sigma, tau)
    return z > LOOP_Z and rms > LOOP_RMS_MIN


@dataclass
class Candidate:
    effects: tuple[str, ...]      # the gear effects of the model, most important first
    fit: Fit
    gate: Gate
    passes: bool
    reason: str = ""
    undecided: tuple[str, ...] = ()   # second effects left unnamed as ambiguous
    series_slip: bool = False         # the pair reads the same as one series slip element
    progressive: bool = False         # a slow backlash read as a stiffening series spring
    by_shape: bool = False            # a housing spring that passes by its shape only


def effective_n(problem: Problem, residual: np.ndarray) -> float:
    """N/τ of the fitted rows, τ from the AR(1) noise of ``residual``."""
    return len(problem.rows) / ar1_time(noise_model(residual)[1])


def beyond(problem: Problem, *alternatives: Fit, explained_min: float) -> bool:
    """The last fit lowers the BIC by more than ``BIC_MIN`` against each of the others
    (N/τ, τ from its residual) and explains ``explained_min`` noise variances more than the
    last of them (the noise RMS from its residual): a refinement that the BIC alone would
    take at thousands of rows for a sliver of the misfit is not taken."""
    *others, trial = alternatives
    residual = trial.residual(problem)
    n_eff = effective_n(problem, residual)
    gained = (others[-1].rss - trial.rss) / len(problem.rows) / (noise_rms(residual) ** 2
                                                                 or 1e-300)
    return (min(bic_gain(f, trial, n_eff) for f in others) > BIC_MIN
            and gained >= explained_min)


def bic_choice(problem: Problem, fits: list) -> int:
    """Index of the fit in ``fits`` (forms of one model, nested or not) with the lowest BIC,
    N/τ from the closest one's residual: a form that contains another wins only when its
    extra parameters pay for themselves."""
    closest = min(fits, key=lambda f: f.rss)
    n_eff = effective_n(problem, closest.residual(problem))
    return bic_best({i: (f.rss, f.n_params) for i, f in enumerate(fits)}, n_eff)


def bic_best(fits: dict, n_eff: float):
    """The key of ``fits`` ({key: (rss, parameters)}) with the lowest BIC at n_eff."""
    return min(fits, key=lambda k: n_eff * math.log(max(fits[k][0], 1e-300))
               + fits[k][1] * math.log(n_eff))
