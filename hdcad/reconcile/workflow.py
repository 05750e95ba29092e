"""Reconcile a catalog model with measured data.

1. Units: a channel in the wrong unit is converted and reported (:mod:`.units`).
2. Baseline: the catalog model with its scatter as nuisance parameters (compliance scale and
   corner width of the twist curve, efficiency level, offset), fitted first
   (:mod:`.baseline`); gross outliers (:mod:`.outliers`: > 6 noise RMS from their
   neighbours' median, where the residual around them is quiet) are left out of every fit
   and of the RMSE, and counted.
3. Noise from the data itself (:mod:`.noise`): its RMS from lagged fourth differences of the
   residual, its correlation time τ for the effective sample size.
4. Search (:mod:`.search`): measurement-chain effects, then every gear effect and pair,
   with the gates and the loop evidence.
5. Report: what disagreed where (:mod:`.regions`), the named gear effects (``missing_effects``),
   the rig's effects (``measurement_effects``), the nuisances against the catalog's spread
   (``nuisances``), readings the data cannot tell apart (``equivalent_readings``) and what
   is left unexplained.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from ..catalog import Catalog
from ..models import GearModel
from . import baseline as baselines
from . import frames, readings, refine, rig_alike, seconds
from . import regions as rg
from . import search
from . import units
from .data import check_revolutions, validate_data
from .fitting import Fit, Problem, copy_problem, fit_model, make_problem
from .gates import BIC_MIN, bic_gain, effective_n
from .noise import correlation_time, noise_rms
from .outliers import outliers_of_final, without_outliers
from .params import effect_form, effect_params
from .rig_entries import output_gain_entry, rig_entry, twist_zero_entry

GATE_NOTE = search.GATE_NOTE


@dataclass
class Step:
    """One named gear effect: its parameters in the final model, the ΔBIC and CV gain of the
    model that added it and the RMSE [unit of the data] after adding it."""

    effect: str
    params: dict[str, dict]
    criterion_gain: float
    cv_gain: float
    rmse: float
    form: str = ""  # the effect's formula as the final model has it


@dataclass
class Reconciliation:
    """Result of :func:`reconcile`; ``as_dict()`` is the JSON of ``hdcad reconcile``."""

    kind: str
    model: str
    disagreements: list[dict]
    missing_effects: list[str]
    rmse_before: float
    rmse_after: float
    steps: list[Step]
    unexplained: list[str]
    noise_rms: float = math.nan
    unit: str = "rad"
    baseline_params: dict[str, dict] = field(default_factory=dict)
    regions: list[dict] = field(default_factory=list)
    candidates: list[list[dict]] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    measurement_effects: list[dict] = field(default_factory=list)
    nuisances: list[dict] = field(default_factory=list)
    equivalent_readings: list[dict] = field(default_factory=list)
    outliers: int = 0
    series: dict[str, np.ndarray] = field(default_factory=dict, repr=False)

    def as_dict(self) -> dict:
        return {"kind": self.kind, "model": self.model, "disagreements": self.disagreements,
                "missing_effects": list(self.missing_effects),
                "rmse_before": self.rmse_before, "rmse_after": self.rmse_after,
                "steps": [{"effect": s.effect, "params": s.params,
                           "criterion_gain": s.criterion_gain, "rmse": s.rmse,
                           "form": s.form}
                          for s in self.steps],
                "unexplained": list(self.unexplained),
                "measurement_effects": self.measurement_effects,
                "nuisances": self.nuisances,
                "equivalent_readings": self.equivalent_readings,
                "noise_rms": self.noise_rms, "outliers": self.outliers, "notes": self.notes}


def _rmse(x: np.ndarray) -> float:
    return float(np.sqrt(np.mean(x * x))) if len(x) else math.nan


def _baseline(kind, data, model, catalog, load_inertia_kgm2):
    """The baseline of the data with their units fixed, and the fixes made."""
    rated = None
    if kind == "efficiency":
        rated = baselines.rated_torque(model)[0]
    twist = baselines.catalog_curve(model) if kind == "torsion" else None
    fixes = units.find_fix(kind, data, twist, float(model.ratio), rated)
    if kind == "torsion" and fixes:  # kN·m or mrad: keep the reading the catalog fits best
        fixes = [units.torsion_fix(data, fixes, twist)]
    data = units.apply(data, fixes)
    if kind == "transmission":
        check_revolutions(data)
    return baselines.build(kind, data, model, catalog, load_inertia_kgm2), fixes


def _start(problem: Problem) -> Fit:
    """The baseline fit, with gross outliers found on its residual and left out."""
    return without_outliers(problem, fit_model(problem, ()))


def reconcile(kind: str, data: dict, model: GearModel, catalog: Catalog,
              load_inertia_kgm2: float | None = None) -> Reconciliation:
    """Find, name and add the effects the catalog model misses."""
    data = validate_data(kind, data)
    base, fixes = _baseline(kind, data, model, catalog, load_inertia_kgm2)
    problem = make_problem(kind, base)
    start = _start(problem)
    in_frames = frames.choose_frames(problem, start)
    with_rig, rig_table, singles = search.select_rig(problem, start, in_frames)
    unselected = copy_problem(problem)  # the selection sets the named forms on the problem
    best, candidates = search.select_gear(problem, with_rig, singles)
    chosen = _gear_twin_instead(problem, unselected, with_rig, best, candidates,
                                _held_for_twin(kind, rig_table))
    # the rig search's last round was over the gear search's start unless a twin changed it
    near = rig_table[-1] if rig_table and chosen[0] is problem else []
    problem, with_rig, best, candidates, set_aside = chosen
    final = search.recheck_rig(problem, best.fit if best else with_rig)
    final = refine.refine(problem, without_outliers(problem, final))
    outliers_of_final(problem, final)
    keep = np.ones(len(base.y), bool)
    keep[problem.outliers] = False

    def sigma_of(fit: Fit) -> float:
        r = (base.y - fit.prediction)[keep]
        return noise_rms(r) or _rmse(r)

    # undecided seconds, each added to the named model in its final form (a loop refined to
    # a Preisach or friction-element sum keeps that form)
    rivals = best.undecided if best else ()
    beside_fits = {r: fit_model(problem, final.effects + (r,), final.theta) for r in rivals}
    decided = seconds.decided_after_refining(problem, final, beside_fits)
    added = None if decided else seconds.added_after_refining(problem, final, best)
    if decided or added:
        second, final, _ = decided or added
        beside_fits = {}
        best = replace(best, effects=best.effects + (second,), undecided=())
        problem.notes.append(_second_note(decided or added, undecided=bool(decided)))
    changed = (seconds.swapped_after_refining(problem, final, best, with_rig)
               or seconds.dropped_after_refining(problem, final, best, with_rig)
               or seconds.te_2x_as_overtone(problem, final, best, with_rig))
    if changed:  # the second weighed again beside the named model's final form
        problem, final, best = changed
        candidates = candidates + [best] * (best.effects not in {c.effects for c in candidates})
    rivals = tuple(beside_fits)
    alone = {c.effects[0]: c.gate.delta_bic for c in candidates if len(c.effects) == 1}
    named = _by_weight(best.effects, alone) if best else ()
    resid0 = (base.y - start.prediction)
    residual = base.y - final.prediction
    sigma = sigma_of(final)
    tau = correlation_time(residual[keep])
    steps = _steps(problem, named, candidates, final, keep)
    beside = {r: _rmse((base.y - f.prediction)[keep]) for r, f in beside_fits.items()}
    measurement = [f.as_dict() for f in fixes] + [
        rig_alike.mark(problem, rig_entry(problem, final, e),
                       rig_alike.rivals(problem, final, e, sigma, tau))
        for e in final.effects if e in search.rig.RIG_EFFECTS]
    if "sensor_gain" not in final.effects:
        measurement += output_gain_entry(problem, final, sigma, tau)
    measurement += twist_zero_entry(problem, final, sigma, tau)
    nuisances = readings.nuisances(problem, final)
    given = (readings.equivalent(problem, final, named, nuisances)
             + readings.undecided(named, rivals, beside, sigma, base.unit)
             + readings.series_slip(problem, final, bool(best and best.series_slip))
             + readings.loop_in_series(seconds.spring_beside_series_loop(problem, final))
             + readings.held_play(seconds.held_play_for_loop(problem, final))
             + readings.twin_set_aside(set_aside, named)
             + readings.progressive_spring(bool(best and best.progressive)))
    return _result(problem, model, start, final, resid0, residual, sigma, tau, keep, steps,
                   candidates, rig_table, measurement, nuisances,
                   given + readings.rig_near(near, named, alone, given))


def _second_note(found: tuple[str, Fit, dict[str, float]], undecided: bool) -> str:
    """The note of a second named once the loop took its final form: one left undecided
    between two beside the parametric loop, or one added to a loop named alone."""
    second, _, gains = found
    other = next(r for r in gains if r != second)
    how = (f"beside the parametric loop it and {other} fitted about equally (ΔBIC within "
           f"{search.SECOND_AMBIGUITY:.0%}); beside the final loop {second}" if undecided
           else f"beside it {second}")
    why = "" if undecided else (" (while effects were named, the loop's parametric form "
                                "took what it leaves)")
    return (f"{second} named once the loop took its final form: {how} adds ΔBIC "
            f"{gains[second]:.1f}, passes the gates for a second and explains at least the "
            f"noise variance; {other} adds {gains[other]:.1f} and does not{why}")


def _gear_twin_instead(problem: Problem, unselected: Problem, with_rig: Fit, best,
                       candidates, held: tuple[str, ...]):
    """The gear effects selected again (on ``unselected``, the problem as it was before the
    selection) without a measurement effect that a gear effect reads nearly as (a torque
    channel's gain takes the extra twist of a series spring), kept when they fit better:
    the measurement effect was preferred to each gear effect alone, and two gear effects
    together may explain what it took. The other way round for one ``held`` back because
    its gear twin alone read about the same (a warm-up's drift with time and the
    efficiency's temperature dependence): selected again with it, kept when that fits
    better by ``BIC_MIN`` (the twin may leave a part of the change the drift takes up).
    Returns (problem, rig fit, best, candidates) of the reading kept and the measurement
    effects set aside by less than ``BIC_MIN``, each with the ΔBIC the gear effects won by."""
    twins = [e for e in with_rig.effects if (problem.kind, e) in search.GEAR_TWIN]
    if twins:
        other = tuple(e for e in with_rig.effects if e not in twins)
    elif held:
        other = with_rig.effects + held
    else:
        return problem, with_rig, best, candidates, {}
    start = fit_model(unselected, other, with_rig.theta)
    alt_best, alt_candidates = search.select_gear(unselected, start)
    if alt_best is None and twins:
        return problem, with_rig, best, candidates, {}
    kept = best.fit if best else with_rig
    gain = bic_gain(kept, alt_best.fit if alt_best else start,
                    effective_n(problem, kept.residual(problem)))
    if gain <= (0.0 if twins else BIC_MIN):
        return problem, with_rig, best, candidates, {}
    unselected.notes.append(
        f"{' and '.join(twins)} set aside: without it, {' + '.join(alt_best.effects)} fit "
        f"better (ΔBIC {gain:.1f})" if twins else
        f"{' and '.join(held)} added after all: with it, the model fits better (ΔBIC "
        f"{gain:.1f}) than with the gear effects alone")
    return unselected, start, alt_best, alt_candidates, {
        t: gain for t in twins if gain <= BIC_MIN}


def _held_for_twin(kind: str, table: list[list[dict]]) -> tuple[str, ...]:
    """The measurement effects of the rig search's last round held back only for their gear
    twin (each passed, but did not beat the twin alone by ``BIC_MIN``) that are selected
    again beside the gear effects (:data:`.search.TWIN_RETRIED`)."""
    return tuple(row["effect"] for row in (table[-1] if table else ())
                 if row.get("held_for_twin") and (kind, row["effect"]) in search.TWIN_RETRIED)


def _by_weight(effects: tuple[str, ...], alone: dict[str, float]) -> tuple[str, ...]:
    """The named gear effects, the one that explains the most alone (ΔBIC, ``alone``) first:
    a pair's order otherwise follows the search (a play read again as a stiffening spring
    keeps the play's place)."""
    return tuple(sorted(effects, key=lambda e: -alone.get(e, math.inf)))


def _steps(problem, named, candidates, final, keep) -> list[Step]:
    by_effects = {c.effects: c for c in candidates}
    by_set = {frozenset(c.effects): c for c in candidates}
    out = []
    for i, effect in enumerate(named):
        cand = by_effects.get((effect,)) if i == 0 else by_set[frozenset(named)]
        fit = cand.fit if i < len(named) - 1 else final
        out.append(Step(effect, effect_params(problem, final, effect), cand.gate.delta_bic,
                        cand.gate.cv_gain, _rmse((problem.base.y - fit.prediction)[keep]),
                        effect_form(problem, effect)))
    return out


def _candidate_rows(candidates, rig_table, named, rig_kept) -> list[list[dict]]:
    """The rounds of the search as the report lists them: each round's measurement effects
    (the one the round added is ``set_aside`` when the final model does not keep it,
    ``rig_kept`` its measurement effects; one held back for its gear twin and added after
    the gear effects is accepted), then the gear candidates."""
    gear = [{"effect": "+".join(c.effects), "delta_bic": c.gate.delta_bic,
             "cv_gain": c.gate.cv_gain, "explained_var_over_noise": c.gate.explained,
             "accepted": c.effects == tuple(named), "passes": c.passes, "reason": c.reason}
            for c in candidates]
    last = len(rig_table) - 1  # only the last round's held effects are selected again
    rounds = [[dict(r, accepted=(r.get("added", False) or (k == last and r.get(
                    "held_for_twin", False))) and r["effect"] in rig_kept,
                    set_aside=r.get("added", False) and r["effect"] not in rig_kept)
               for r in round_] for k, round_ in enumerate(rig_table)]
    return rounds + [gear]


def _result(problem, model, start, final, resid0, residual, sigma, tau, keep, steps,
            candidates, rig_table, measurement, nuisances, equivalent) -> Reconciliation:
    base, kind = problem.base, problem.kind
    table = rg.region_table(problem, resid0, residual, sigma, tau)
    theta = {"damping_ratio": 0.05, **final.theta} if kind == "vibration" else final.theta
    harm0 = rg.harmonics(problem, resid0, sigma, tau, theta)
    harm1 = rg.harmonics(problem, residual, sigma, tau, theta)
    disagreements = [{"where": label, "rms": rms, "noise_rms": sigma}
                     for label, rms, _, sig in table if sig]
    disagreements += [{"where": f"{k} cycle(s) per WG revolution", "rms": rms,
                       "noise_rms": sigma} for k, rms, sig in harm0 if sig]
    after = {label: sig for label, _, _, sig in rg.region_table(problem, residual, residual,
                                                                sigma, tau)}
    regions = [{"where": label, "rms_before": b, "rms_after": a, "significant": s,
                "significant_after": after.get(label, False)} for label, b, a, s in table]
    regions += [{"where": f"{k} cycle(s) per WG revolution", "rms_before": r0,
                 "rms_after": r1, "significant": s0, "significant_after": s1}
                for (k, r0, s0), (_, r1, s1) in zip(harm0, harm1)]
    return Reconciliation(
        kind=kind, model=model.code, disagreements=disagreements,
        missing_effects=[s.effect for s in steps], rmse_before=_rmse(resid0[keep]),
        rmse_after=_rmse(residual[keep]), steps=steps,
        unexplained=rg.unexplained(problem, residual, sigma, tau, harm1, final),
        noise_rms=sigma, unit=base.unit,
        baseline_params={n: {"value": float(v), "unit": u} for n, v, u in
                         zip(base.free_names, final.beta, base.free_units)},
        regions=regions,
        candidates=_candidate_rows(candidates, rig_table, [s.effect for s in steps],
                                   {m["effect"] for m in measurement}),
        notes=problem.notes + [GATE_NOTE], measurement_effects=measurement,
        nuisances=nuisances, equivalent_readings=equivalent,
        outliers=int(problem.outliers.size),
        series={**{k: v for k, v in base.inputs.items() if np.ndim(v) == 1},
                "measured": base.y,
                "catalog": base.fixed if base.curve is None else base.free[:, 0],
                "baseline": start.prediction,
                "reconciled": final.prediction})
