"""Which effects to name: gates, the measurement-chain stage and the joint search of pairs.

1. Measurement-chain effects (:mod:`.rig`) first, greedily, on top of the baseline with its
   nuisances; each is tested again at the end with the gear effects in place and dropped
   when no longer needed.
2. Gear effects: every single effect and every pair is fitted (pairs from the shapes of
   both singles), so a pair is found even when neither member wins alone.
3. A model is accepted over a simpler one when it passes the gates of :mod:`.gates`
   (ΔBIC on the effective sample size, blocked cross-validation, explained variance, the
   share a second effect must explain; a loop for hysteresis).
4. Housing springs (:mod:`.springs`): one that stiffens, against a slow backlash or as a
   named effect's second; a linear one, alone or beside a backlash, by its shape.
5. Readings: when another pair with the same first member comes within
   ``SECOND_AMBIGUITY`` of the best pair's ΔBIC, the second is not identified and only the
   first is named (:func:`ambiguous_second`); a hysteresis + housing spring pair whose
   spring is the loop's own slip compliance is named as one slip element in series, and
   reported with the pair as its other reading (:func:`.loops.series_slip`), unless the
   pair with its loop through the gear's compliance fits clearly better
   (:func:`_through_gear`); otherwise a spring must also earn its place beside the loop
   through the gear's compliance, and a spring or a backlash beside the loop drawn about the
   catalog curve, or it is the loop's own shape and only the hysteresis is named
   (:func:`_spring_of_its_own`); and a spring that earns it may still be the compliance of
   friction elements in series with the gear past their slip torques
   (:func:`.loops.series_plays`).

References
----------
Schwarz, G. (1978) "Estimating the dimension of a model", Ann. Stat. 6: BIC.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import replace

from . import effects as fx
from . import drive, encoder_ripple, rig, rig_signatures, seconds, springs
from .fitting import Fit, Problem, fit_model, rss_at
from .gates import (BIC_MIN, GATE_NOTE, SECOND_TRY_EXPLAINED_MIN, Candidate, Gate, gate,
                    has_evidence, round_noise)
from .loops import THROUGH_GEAR, preisach_forms, series_plays, series_slip, use_preisach
from .te_forms import TE_OVERTONES

__all__ = ["BIC_MIN", "GATE_NOTE", "Candidate", "Gate", "gate", "round_noise", "select_gear",
           "select_rig", "recheck_rig"]

# Two pairs that share a member and whose ΔBIC differ by less than this share of the best:
# what the shared member leaves fits either other member about as well, so it is shape the
# shared member's formula misses, not an identified second effect.
SECOND_AMBIGUITY = 0.05
MAX_GEAR_EFFECTS = 2
# A measurement effect that a gear effect nearly reads as must beat it by BIC_MIN: a torque
# channel's gain takes a series spring's extra twist (a loop and a spring were read as a gain
# beside the loop, ΔBIC 342.5 against 340.6); a drift with time reads as a temperature law in
# a test that warms as it runs (0.2–3 BIC apart). The drift held back so is selected again
# beside the gear effects (a gain is not: beside two gear effects it could stand for a third)
GEAR_TWIN = {("torsion", "sensor_gain"): "housing_compliance",
             ("efficiency", "thermal_drift"): "temperature_dependence",
             ("efficiency", "sensor_gain"): "temperature_dependence"}
TWIN_RETRIED = {("efficiency", "thermal_drift")}


def select_rig(problem: Problem, start: Fit, known: dict[str, Fit] | None = None
               ) -> tuple[Fit, list[dict], dict[str, Fit] | None]:
    """Add measurement-chain effects greedily while one passes the gates and explains more
    than any single gear effect would (a drift with test time must not take a temperature
    effect of a test that warms steadily, nor the reverse). ``known`` holds single gear
    effects already fitted on ``start``. Also returns the single gear effects fitted on the
    final model of this stage (None when none were)."""
    current, table, singles, known = start, [], None, known or {}
    names = list(rig.applicable(problem.kind, problem.base.inputs))
    gear = fx.applicable(problem.kind)
    while names:
        fits = {}
        for name in names:
            if (name, problem.kind) in rig.STEPPED:
                problem.step_position = rig.step_position(
                    current.residual(problem),
                    problem.base.inputs["record_position"][problem.rows])
            if name == "drive_ripple":
                problem.drive_order = drive.best_order(problem, current.residual(problem))
                if not problem.drive_order:  # the run-up crosses no order's resonance
                    continue
            if name == "encoder_interpolation":
                problem.scales["angle_period"] = encoder_ripple.angle_period(
                    current.residual(problem),
                    problem.base.inputs["measured_rad"][problem.rows],
                    *rig_signatures.gear_orders_of(problem))
            fits[name] = fit_model(problem, current.effects + (name,), current.theta)
        singles = {n: known[n] if n in known
                   else fit_model(problem, current.effects + (n,), current.theta)
                   for n in gear}
        rivals = list(singles.values())
        own = {n: rig_signatures.own_signature(problem, n, current, f) for n, f in fits.items()}
        # a candidate without its own signature leaves the round's noise alone (its columns
        # would take the noise's correlation and raise every other candidate's evidence)
        sigma, tau = round_noise(problem, [f for n, f in fits.items() if own[n]] + rivals)
        gates = {n: gate(problem, current, f, sigma, tau) for n, f in fits.items()}
        alone = {n: gate(problem, current, f, sigma, tau).delta_bic for n, f in singles.items()}
        rival = max(alone.values(), default=-math.inf)
        # with its own signature, and beating every gear effect alone or coming within
        # BIC_MIN of the best (then reported beside it as a reading the data barely refuse)
        near = {n: g.passes() and g.delta_bic > rival - BIC_MIN for n, g in gates.items()}
        signed = {n: near[n] and own[n] for n in gates}
        beats = {n: signed[n] and gates[n].delta_bic > rival for n in gates}
        twin = {n: alone.get(GEAR_TWIN.get((problem.kind, n)), -math.inf) for n in gates}
        held = {n: beats[n] and g.delta_bic <= twin[n] + BIC_MIN for n, g in gates.items()}
        ok = {n: beats[n] and not held[n] for n in gates}
        table.append([{"effect": n, "delta_bic": g.delta_bic, "cv_gain": g.cv_gain,
                       "explained_var_over_noise": g.explained, "passes": ok[n],
                       "held_for_twin": held[n],
                       # a reading the data barely refuse: within BIC_MIN below the best
                       # gear effect, or above it where its signature may not show
                       "near_gear": near[n] and not beats[n]
                       and (signed[n] or (problem.kind, n) in rig_signatures.UNSEEN)}
                      for n, g in gates.items()])
        passing = [n for n in ok if ok[n]]
        if not passing:
            break
        best = max(passing, key=lambda n: gates[n].delta_bic)
        for row in table[-1]:
            row["added"] = row["effect"] == best
        current, singles, known = fits[best], None, {}
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
        shaped = not g.passes() and springs.by_its_shape(n, None, g)
        out.append(Candidate((n,), fit, g, (g.passes() or shaped) and evidence,
                             "" if evidence else "no loop in the residual", by_shape=shaped))
    for (a, b), fit in pairs.items():
        out.append(_pair(problem, start, singles[a], singles[b], fit, sigma, tau))
    passing = [c for c in out if c.passes]
    # a spring alone by its shape only when nothing else passes, a Preisach loop included
    strict = [c for c in passing if not (c.by_shape and len(c.effects) == 1)]
    best = max(strict, key=lambda c: c.gate.delta_bic) if strict else None
    best = _unless_ambiguous(best, passing)
    if best is None and "hysteresis" in singles and problem.base.curve is not None:
        best = _preisach_single(problem, start, singles, list(pairs.values()), out)
    if best is None and passing:
        best = max(passing, key=lambda c: c.gate.delta_bic)
    tied = series_slip(problem, start, best, sigma, tau) if best is not None else None
    through = _through_gear(problem, best, tied, sigma, tau) if tied is not None else None
    if through is not None:  # the pair stays, its loop through the gear's compliance
        best = replace(best, fit=through, gate=gate(problem, start, through, sigma, tau))
    elif tied is not None:  # one slip element in series
        problem.hysteresis_series = True
    else:
        best = _spring_of_its_own(problem, best, passing, sigma, tau)
        # a spring that earns its place beside the loop in parallel with the gear may still
        # be the loop's own compliance past its slip torques
        tied = series_plays(problem, start, best.fit, sigma, tau) if best else None
    if tied is not None and through is None:  # the simpler reading is named: a loop in series
        best = Candidate(("hysteresis",), tied, gate(problem, start, tied, sigma, tau), True,
                         series_slip=True)
    if tied is not None:
        out = [best if c.effects == best.effects else c for c in out]
    spring = springs.stiffening(problem, start, best, singles, sigma, tau) if best else None
    if spring is not None:
        out = [c for c in out if c.effects != spring.effects] + [spring]
        best = spring
    return best, out


def _preisach_single(problem: Problem, start: Fit, singles: dict[str, Fit], pairs: list[Fit],
                     out: list[Candidate]) -> Candidate | None:
    """When no effect passes: the hysteresis as a Preisach relay sum (in its best form),
    named when it passes the gates and the loop evidence, the noise estimated with it in
    the round. Under cycles of several amplitudes a Bouc–Wen loop, without the Preisach
    memory, can leave so much of a real loop that its residual reads as correlated noise;
    replaces the hysteresis candidate in ``out`` and sets the problem's loop when named."""
    fit, density, form = min(preisach_forms(problem, singles["hysteresis"]),
                             key=lambda t: t[0].rss)
    sigma, tau = round_noise(problem, [start, *singles.values(), *pairs, fit])
    g = gate(problem, start, fit, sigma, tau)
    if not (g.passes() and g.explained >= SECOND_TRY_EXPLAINED_MIN
            and has_evidence(problem, "hysteresis", start, sigma, tau)):
        return None
    use_preisach(problem, density, form)
    problem.notes.append("hysteresis named as a Preisach relay sum: the Bouc–Wen loop did "
                         "not pass the gates on these data")
    best = Candidate(("hysteresis",), fit, g, True)
    out[:] = [best if c.effects == best.effects else c for c in out]
    return best


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
    (:func:`ambiguous_second`) and that member passes alone (not a spring by its shape only)."""
    found = ambiguous_second(best, passing) if best else None
    if found is None:
        return best
    single = next((c for c in passing if c.effects == (found[0],) and not c.by_shape), None)
    return replace(single, undecided=found[1]) if single else best


def _through_gear(problem: Problem, best: Candidate, tied: Fit, sigma: float, tau: float
                  ) -> Fit | None:
    """The hysteresis + housing pair with the loop through the gear's compliance
    (:func:`.loops.refine_hysteresis`) when it passes the gates over the series slip
    element ``tied``; else None. A loop that narrows where the gear stiffens, beside a
    spring of its own, is not one slip element in series: the series reading is tested
    against both forms of the loop. Leaves the form set on ``problem`` when it is kept."""
    problem.hysteresis_through_gear = True
    pair = fit_model(problem, best.fit.effects, best.fit.theta)
    if gate(problem, tied, pair, sigma, tau).passes():
        problem.notes.append(f"{THROUGH_GEAR}, beside a housing spring of its own, fits "
                             "clearly better than one slip element in series")
        return pair
    problem.hysteresis_through_gear = False
    return None


def _pair_fit(problem: Problem, start: Fit, fa: Fit, fb: Fit) -> Fit:
    """A pair fitted from both singles' shapes; the shapes they share (the catalog curve's
    corner width, a measurement effect's) start from the single whose values leave the
    smaller residual (one polish: from both starts it named the same effects on every case
    of the truth suites' sample, at 12 % more time)."""
    effects = start.effects + (fa.effects[-1], fb.effects[-1])
    starts = [{**fb.theta, **fa.theta}, {**fa.theta, **fb.theta}]
    if starts[0] == starts[1]:
        return fit_model(problem, effects, starts[0])
    return fit_model(problem, effects, min(starts, key=lambda th: rss_at(problem, effects, th)))


def _pair(problem: Problem, start: Fit, fa: Fit, fb: Fit, fit: Fit, sigma: float, tau: float
          ) -> Candidate:
    """A pair candidate; each member must earn its place over the other alone
    (:func:`.seconds.earns_place`)."""
    a, b = fa.effects[-1], fb.effects[-1]
    g = gate(problem, start, fit, sigma, tau)
    ok, reason, shaped = g.passes(), "", False
    for member, other in ((a, fb), (b, fa)):
        earned, by_shape = seconds.earns_place(problem, member, other, fit, sigma, tau)
        shaped |= by_shape
        if not earned:
            ok, reason = False, f"{member} adds too little to {other.effects[-1]}"
        elif not has_evidence(problem, member, other, sigma, tau):
            ok, reason = False, f"no loop in the residual of {other.effects[-1]}"
        elif ok and not seconds.beyond_law(problem, member, other, fit, sigma, tau):
            ok, reason = False, (f"{member} adds too little to {other.effects[-1]} with its "
                                 "viscosity law fitted")
    # the member that explains more alone is named first
    order = (a, b) if fa.rss <= fb.rss else (b, a)
    return Candidate(order, fit, g, ok, reason, by_shape=shaped)


def _spring_of_its_own(problem: Problem, best: Candidate | None, passing: list[Candidate],
                       sigma: float, tau: float) -> Candidate | None:
    """The best candidate, or its hysteresis alone when the second beside it adds too little
    with the loop in another of its forms:

    - through the gear's compliance (:data:`.loops.THROUGH_GEAR`: it narrows where the gear
      stiffens), for a housing spring: beside a loop of constant width a linear spring can
      stand in for part of that narrowing;
    - about the catalog curve (:data:`.loops.CENTRED`: the loop's own centre line taken
      out), for a housing spring or a backlash, where that loop alone fits as well as the
      pair: beside a loop with its own backbone either can stand in for undoing it.

    A second of the gear's own is needed with every form of the loop."""
    single = next((c for c in passing if c.effects == ("hysteresis",)), None)
    if (best is None or single is None or len(best.effects) != 2
            or "hysteresis" not in best.effects):
        return best
    second = next(e for e in best.effects if e != "hysteresis")
    # (attribute, words, shape, only where the loop alone in that form fits as well as the pair)
    forms = [("hysteresis_centred", "about the catalog curve", "backbone", True)]
    if second == "housing_compliance" and problem.base.curve is not None:
        forms.insert(0, ("hysteresis_through_gear", "through the gear's compliance",
                         "narrowing", False))
    elif second != "backlash":
        return best
    for attribute, words, shape, if_better in forms:
        setattr(problem, attribute, True)
        try:
            alone = fit_model(problem, single.fit.effects, single.fit.theta)
            if if_better and alone.rss > best.fit.rss:
                continue  # the pair reads better than the loop about the curve alone
            pair = min((fit_model(problem, best.fit.effects, theta)
                        for theta in (best.fit.theta, {**best.fit.theta, **alone.theta})),
                       key=lambda f: f.rss)
        finally:
            setattr(problem, attribute, False)
        if not gate(problem, alone, pair, sigma, tau).passes(second=True):
            problem.notes.append(f"{second} beside the loop adds too little once the loop runs "
                                 f"{words}: read as the loop's own {shape}, not named")
            return single
    return best


def recheck_rig(problem: Problem, final: Fit) -> Fit:
    """Drop measurement effects that the gear effects made unnecessary, and a drive's
    ripple at an overtone order of a gear error named beside it (the error's overtones are
    chosen once it is named: :func:`.te_forms.refine_te_overtones`)."""
    current = final
    for name in [e for e in final.effects if e in rig.RIG_EFFECTS]:
        reduced = tuple(e for e in current.effects if e != name)
        fit = fit_model(problem, reduced, current.theta)
        sigma, tau = round_noise(problem, [current])
        if (not gate(problem, fit, current, sigma, tau).passes()
                or drive.at_a_named_overtone(problem, current.effects, TE_OVERTONES)):
            current = fit
    return current
