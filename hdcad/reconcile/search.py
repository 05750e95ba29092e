"""Which effects to name: gates, the measurement-chain stage and the joint search of pairs.

1. Measurement-chain effects (:mod:`.rig`) first, greedily, on top of the baseline with its
   nuisances; each is tested again at the end with the gear effects in place and dropped
   when no longer needed.
2. Gear effects: every single effect and every pair is fitted (pairs from the shapes of
   both singles: multi-start), so a pair is found even when neither member wins alone.
3. A model is accepted over a simpler one when it passes the gates:
   ΔBIC = (N/τ)·ln(RSS_before/RSS_after) − Δk·ln(N/τ) > ``BIC_MIN`` with N/τ the effective
   sample size (τ the noise's correlation time), the blocked 5-fold cross-validated error
   falls by ``CV_GAIN_MIN`` (contiguous chunks: correlated neighbours are held out
   together), the variance it explains is ≥ ``EXPLAINED_MIN`` of the noise variance; and an
   effect added to another must explain ≥ ``SECOND_SHARE_MIN`` of the structure the other
   leaves (residual variance above the noise): the shape mismatch of an effect's formula
   must not be named as a second effect.
4. Evidence of the effect's signature: hysteresis needs loading and unloading branches that
   differ beyond the noise (a loop), not only a better fit (:func:`loop_evidence`).
5. Readings: when another pair with the same first member comes within
   ``SECOND_AMBIGUITY`` of the best pair's ΔBIC, the second is not identified and only the
   first is named (:func:`ambiguous_second`); a hysteresis + housing spring pair whose
   spring is the loop's own slip compliance is named as one slip element in series, and
   reported with the pair as its other reading (:func:`series_slip`).

References
----------
Schwarz, G. (1978) "Estimating the dimension of a model", Ann. Stat. 6: BIC.
Kass, R. E., Raftery, A. E. (1995) J. Am. Stat. Assoc. 90: ΔBIC > 10 is very strong evidence.
Roberts, D. R. et al. (2017) "Cross-validation strategies for data with temporal, spatial,
hierarchical, or phylogenetic structure", Ecography 40: blocked cross-validation.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, replace

import numpy as np

from . import effects as fx
from . import rig
from .fitting import Fit, Problem, finish, fit_model, nonlinear
from .noise import ar1_time, noise_model
from .refine import refine_te_order
from .regions import directions

BIC_MIN = 10.0
CV_GAIN_MIN = 0.05
EXPLAINED_MIN = 0.1
SECOND_SHARE_MIN = 0.3
# Two pairs that share a member and whose ΔBIC differ by less than this share of the best:
# what the shared member leaves fits either other member about as well, so it is shape the
# shared member's formula misses, not an identified second effect.
SECOND_AMBIGUITY = 0.05
# Loop evidence: branch separation χ² z-score and RMS (in noise RMS) over torque bins.
LOOP_Z = 5.0
LOOP_RMS_MIN = 0.5
LOOP_BINS = 10
MAX_GEAR_EFFECTS = 2
GATE_NOTE = (f"an effect is named when ΔBIC > {BIC_MIN:g} (effective sample size N/τ), the "
             f"blocked 5-fold cross-validated error falls by ≥ {CV_GAIN_MIN:.0%}, it explains "
             f"≥ {EXPLAINED_MIN:g}× the noise variance and, added to another effect, "
             f"≥ {SECOND_SHARE_MIN:.0%} of what that one leaves; hysteresis needs a loop "
             "(loading and unloading branches apart beyond the noise)")


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
    n_eff = n / tau
    dk = fit.n_params - reference.n_params
    bic = n_eff * math.log(reference.rss / max(fit.rss, 1e-300)) - dk * math.log(n_eff)
    cv = ((reference.cv_mse - fit.cv_mse) / reference.cv_mse if reference.cv_mse > 0
          else 0.0)
    explained = (reference.rss - fit.rss) / n / sigma ** 2
    structure = reference.rss / n - sigma ** 2
    share = (reference.rss - fit.rss) / n / structure if structure > 0 else math.inf
    return Gate(bic, cv, explained, share)


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


def select_rig(problem: Problem, start: Fit) -> tuple[Fit, list[dict], dict[str, Fit] | None]:
    """Add measurement-chain effects greedily while one passes the gates and explains more
    than any single gear effect would (a drift with test time must not take a temperature
    effect of a test that warms steadily, nor the reverse). Also returns the single gear
    effects fitted on the final model of this stage (None when none were)."""
    current, table, singles = start, [], None
    names = list(rig.applicable(problem.kind))
    gear = fx.applicable(problem.kind)
    while names:
        fits = {}
        for name in names:
            if name == "angle_offset":
                problem.step_position = rig.step_position(
                    current.residual(problem),
                    problem.base.inputs["record_position"][problem.rows])
            fits[name] = fit_model(problem, current.effects + (name,), current.theta)
        singles = {n: fit_model(problem, current.effects + (n,), current.theta) for n in gear}
        rivals = list(singles.values())
        sigma, tau = round_noise(problem, list(fits.values()) + rivals)
        gates = {n: gate(problem, current, f, sigma, tau) for n, f in fits.items()}
        rival = max((gate(problem, current, f, sigma, tau).delta_bic for f in rivals),
                    default=-math.inf)
        table.append([{"effect": n, "delta_bic": g.delta_bic, "cv_gain": g.cv_gain,
                       "explained_var_over_noise": g.explained,
                       "passes": g.passes() and g.delta_bic > rival}
                      for n, g in gates.items()])
        passing = [n for n, g in gates.items() if g.passes() and g.delta_bic > rival]
        if not passing:
            break
        best = max(passing, key=lambda n: gates[n].delta_bic)
        current, singles = fits[best], None
        names.remove(best)
    return current, table, singles


def select_gear(problem: Problem, start: Fit, singles: dict[str, Fit] | None = None
                ) -> tuple[Candidate | None, list[Candidate]]:
    """The best passing model among every single gear effect and every pair; ``singles``
    are the single effects already fitted on ``start``."""
    names = fx.applicable(problem.kind)
    if singles is None:
        singles = {n: fit_model(problem, start.effects + (n,), start.theta) for n in names}
    pairs = {(a, b): _pair_fit(problem, start, singles[a], singles[b])
             for a, b in itertools.combinations(names, 2)} if MAX_GEAR_EFFECTS >= 2 else {}
    sigma, tau = round_noise(problem, [start] + list(singles.values()) + list(pairs.values()))
    out: list[Candidate] = []
    for n, fit in singles.items():
        g = gate(problem, start, fit, sigma, tau)
        evidence = has_evidence(problem, n, start, sigma, tau)
        out.append(Candidate((n,), fit, g, g.passes() and evidence,
                             "" if evidence else "no loop in the residual"))
    for (a, b), fit in pairs.items():
        out.append(_pair(problem, start, singles[a], singles[b], fit, sigma, tau))
    passing = [c for c in out if c.passes]
    best = max(passing, key=lambda c: c.gate.delta_bic) if passing else None
    best = _unless_ambiguous(best, passing)
    tied = series_slip(problem, start, best, sigma, tau) if best is not None else None
    if tied is not None:  # the simpler reading is named: one slip element in series
        problem.hysteresis_series = True
        best = Candidate(("hysteresis",), tied, gate(problem, start, tied, sigma, tau), True,
                         series_slip=True)
        out = [best if c.effects == best.effects else c for c in out]
    return best, out


def ambiguous_second(best: Candidate, passing: list[Candidate]
                     ) -> tuple[str, tuple[str, str]] | None:
    """(shared member, (second, rival)) when another passing pair shares a member with the
    ``best`` pair and comes within ``SECOND_AMBIGUITY`` of its ΔBIC; else None."""
    if len(best.effects) < 2:
        return None
    floor = (1.0 - SECOND_AMBIGUITY) * best.gate.delta_bic
    for shared in best.effects:
        second = next(e for e in best.effects if e != shared)
        for c in passing:
            if (len(c.effects) == 2 and shared in c.effects and second not in c.effects
                    and c.gate.delta_bic >= floor):
                rival = next(e for e in c.effects if e != shared)
                return shared, (second, rival)
    return None


def _unless_ambiguous(best: Candidate | None, passing: list[Candidate]) -> Candidate | None:
    """The best pair, or its shared member alone when its second is ambiguous
    (:func:`ambiguous_second`) and that member passes alone."""
    found = ambiguous_second(best, passing) if best else None
    if found is None:
        return best
    single = next((c for c in passing if c.effects == (found[0],)), None)
    return replace(single, undecided=found[1]) if single else best


def series_slip(problem: Problem, start: Fit, best: Candidate, sigma: float, tau: float
                ) -> Fit | None:
    """The fit of one slip element in series with the gear when a hysteresis +
    housing_compliance pair reads the same as it (its spring is the loop's own slip
    compliance); else None.

    Friction in parallel with the gear (Bouc–Wen, −z_sat·z) plus a spring of compliance
    z_sat/T_s is, term for term, a slip element in series (z_sat·(T/T_s − z): Iwan,
    Preisach, Masing–Ramberg–Osgood loops add their slip to the gear's twist). At the pair's
    own shape the compliance is tied to z_sat/T_s; when BIC does not prefer the free spring
    to the tie (ΔBIC ≤ 0) the data read the same both ways: the simpler reading, one
    hysteresis, is named and the report gives the other.
    """
    if set(best.effects) != {"hysteresis", "housing_compliance"}:
        return None
    effects = start.effects + ("hysteresis",)
    problem.hysteresis_series = True
    try:
        tied = finish(problem, effects, best.fit.theta, len(nonlinear(problem.kind, effects)))
    finally:
        problem.hysteresis_series = False
    return tied if gate(problem, tied, best.fit, sigma, tau).delta_bic <= 0.0 else None


def _pair_fit(problem: Problem, start: Fit, fa: Fit, fb: Fit) -> Fit:
    """A pair fitted from both singles' shapes (multi-start), the better of the two."""
    effects = start.effects + (fa.effects[-1], fb.effects[-1])
    fits = [fit_model(problem, effects, {**fb.theta, **fa.theta}),
            fit_model(problem, effects, {**fa.theta, **fb.theta})]
    return min(fits, key=lambda f: f.rss)


def _pair(problem: Problem, start: Fit, fa: Fit, fb: Fit, fit: Fit, sigma: float, tau: float
          ) -> Candidate:
    """A pair candidate; each member must earn its place over the other alone."""
    a, b = fa.effects[-1], fb.effects[-1]
    g = gate(problem, start, fit, sigma, tau)
    ok, reason = g.passes(), ""
    for member, other in ((a, fb), (b, fa)):
        over = gate(problem, other, fit, sigma, tau)
        if not (over.passes(second=True) or over.passes()
                and _beyond_modulation(problem, member, other, fit, sigma, tau)):
            ok, reason = False, f"{member} adds too little to {other.effects[-1]}"
        elif not has_evidence(problem, member, other, sigma, tau):
            ok, reason = False, f"no loop in the residual of {other.effects[-1]}"
    # the member that explains more alone is named first
    order = (a, b) if fa.rss <= fb.rss else (b, a)
    return Candidate(order, fit, g, ok, reason)


def _beyond_modulation(problem: Problem, member: str, other: Fit, fit: Fit, sigma: float,
                       tau: float) -> bool:
    """Whether the transmission error ``member`` still earns its place once the other
    error follows its own slow modulation (Legendre order chosen by BIC,
    :func:`.refine.refine_te_order`). What a modulated error leaves at the naming order is
    its own misfit, which the share rule would ask a second harmonic to explain; another
    harmonic's carrier cannot take that misfit, so the pair, its order chosen the same way,
    is tested against the modulated one by ΔBIC and explained variance (a blocked
    cross-validation would judge the Legendre columns' extrapolation into the held-out
    block, not the harmonic)."""
    if not (member.startswith("te_") and other.effects[-1].startswith("te_")):
        return False
    saved = problem.te_order
    try:
        modulated = refine_te_order(problem, other)
        problem.te_order = saved
        pair = refine_te_order(problem, fit)
    finally:
        problem.te_order = saved
    g = gate(problem, modulated, pair, sigma, tau)
    return g.delta_bic > BIC_MIN and g.explained > EXPLAINED_MIN


def recheck_rig(problem: Problem, final: Fit) -> Fit:
    """Drop measurement effects that the gear effects made unnecessary."""
    current = final
    for name in [e for e in final.effects if e in rig.RIG_EFFECTS]:
        reduced = tuple(e for e in current.effects if e != name)
        fit = fit_model(problem, reduced, current.theta)
        sigma, tau = round_noise(problem, [current])
        if not gate(problem, fit, current, sigma, tau).passes():
            current = fit
    return current
