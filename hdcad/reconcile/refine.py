"""Refinements of the named model once the effects are chosen: the joint's damping, the
temperature law's viscosity law and speed term, a low-load drag that grows with the oil's
viscosity, a play held by friction or changing along the record, and the gear's stiffness
beyond its spread. The transmission error's forms (:mod:`.te_forms`), the joint's spring on
the catalog curve (:mod:`.joint_fit`) and the loop's form (:mod:`.loops`) are chosen from
here too.

None changes which effects are named; each makes the reconciled model follow the data as
closely as the physics and the noise allow, and says what it chose in the notes.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from scipy.optimize import minimize_scalar

from . import efficiency_laws as laws
from .baseline import COMPLIANCE_SCALE_BOUNDS, STIFFNESS_SPREAD
from .fitting import Fit, Problem, best_setting, finish, fit_model, shapes_in_use
from .frames import refine_frames
from .gates import EXPLAINED_MIN, beyond, bic_best, effective_n
from .damping import refine_damping
from .joint_fit import refine_spring
from .loops import refine_creep, refine_hysteresis, refine_plays, refine_preisach
from .params import linear_of, play_along_record
from .readings import free_scale
from .rig import step_position
from .springs import refine_opening
from .stribeck import refine_hersey
from .te_forms import refine_te_order, refine_te_overtones, refine_te_sidebands
from .widening_loops import refine_duhem, refine_flank_friction

_SPEED_LOSS_BOUNDS = (-0.5, 0.9)  # as the viscous share a of the temperature law
# exponent k of a drag ∝ ν^k: 0 (no coupling) … 2 (Petroff's viscous torque is ∝ ν; a
# rolling bearing's no-load torque ∝ ν^(2/3), Palmgren)
_DRAG_VISCOSITY_BOUNDS = (0.0, 2.0)
_PLAY_HOLD_BOUNDS = (0.0, 0.3)  # holding torque of a play, as a share of the largest torque
_PLAY_BIAS_BOUNDS = (-0.15, 0.15)  # torque a play is crossed at, as a share of the largest
# ln p of a play's engagement exponent: p from 1/2 (a take-up that starts at once and ends
# slowly, like an arctangent's) to 3 (one that waits, then closes like a smoothed step)
_PLAY_SHAPE_BOUNDS = (math.log(0.5), math.log(3.0))
# highest Legendre order of a play's lost motion along the record: wear and warmth change a
# clearance smoothly one way over a test, a line or a parabola (higher orders took an
# unmodelled creep or a start-up transient for a clearance swinging up and down), and a
# step is a form of its own; the span of record positions a step is looked for in (the
# play crossed often enough on either side of it)
PLAY_DRIFT_MAX = 2
PLAY_STEP_SPAN = 0.8
# a band of temperature over which a loss changes: centres between the temperatures tested
# (at most this many), widths [K] from a step between two of them to a gradual change
_BAND_CENTRES = 8
_BAND_WIDTHS_K = (2.0, 6.0, 18.0)


def refine(problem: Problem, fit: Fit) -> Fit:
    """The named model's final form: the named errors' frames, then (vibration) the joint's
    damper on its twist or structural damping in the steady state where BIC prefers it, and
    unless the steady state is kept, the joint on the catalog curve (viscous, damped on the
    load) where the twist leaves its first segment and it fits better; otherwise the TE's
    overtones and modulation order, the viscosity law, the loop's Bouc–Wen form, a play
    held by friction and its lost motion along the record, then a Preisach relay sum in
    place of the Bouc–Wen loop, and a sum of friction elements in place of either, where
    BIC prefers them, then the play's engagement exponent; last, the gear's stiffness where
    the data put it beyond the catalog's spread."""
    fit = refine_frames(problem, fit)
    steady = refine_damping(problem, fit)
    if steady is fit or problem.relative_damping:  # a viscous joint: on the catalog curve?
        on_twist, problem.relative_damping = problem.relative_damping, False
        curved = refine_spring(problem, fit)
        if curved is not fit and curved.rss < steady.rss:
            return curved
        problem.relative_damping = on_twist
    fit = refine_te_sidebands(problem, refine_te_overtones(problem, steady))
    fit = refine_hysteresis(problem, refine_viscosity(problem, refine_low_load(
        problem, refine_te_order(problem, fit))))
    fit = refine_play_drift(problem, refine_play(problem, fit))
    fit = refine_plays(problem, refine_preisach(problem, fit))
    fit = refine_creep(problem, refine_duhem(problem, refine_flank_friction(problem, fit)))
    fit = refine_play_shape(problem, fit)
    return refine_stiffness(problem, refine_opening(problem, refine_hersey(problem, fit)))


def refine_stiffness(problem: Problem, fit: Fit) -> Fit:
    """The named model with the gear's compliance scale let out of the catalog's spread,
    where the data put the gear beyond it: stiffer, or softer with no series spring named
    (a spring would take the rest). The scale is held within the spread while effects are
    named, so that a gear effect must explain more than the catalog's scatter; a gear
    outside it is reported as a nuisance outside its range, and the RMSE after is that of
    the gear as measured, not of the catalog's bound. Leaves ``problem.scale_free`` set when
    taken."""
    scale = free_scale(problem, fit)
    if not scale or scale <= 0:
        return fit
    stiffer = scale < COMPLIANCE_SCALE_BOUNDS[0]
    softer = scale > COMPLIANCE_SCALE_BOUNDS[1] and "housing_compliance" not in fit.effects
    if not (stiffer or softer):
        return fit
    problem.scale_free = True
    free = fit_model(problem, fit.effects, fit.theta)
    if free.rss >= fit.rss:
        problem.scale_free = False
        return fit
    scale = free_scale(problem, free) or scale
    problem.notes.append(
        f"the reconciled model keeps the gear {abs(1.0 / scale - 1.0):.1%} "
        f"{'stiffer' if stiffer else 'softer'} than the catalog, outside its assumed "
        f"±{STIFFNESS_SPREAD:.0%} spread, where the data put it (the RMSE after is with "
        "it): a gear out of its scatter, or a twist sensor's gain; check the sensor's "
        "calibration before the catalog value")
    return free


def refine_play(problem: Problem, fit: Fit) -> Fit:
    """A named backlash whose play friction holds at one side until the load passes a
    holding torque T_h in the new direction (a loop at zero torque of area b·2T_h), then one
    crossed at a torque T_c off zero (a steady torque preloads one flank), each one
    parameter more, kept when BIC prefers it (:func:`_one_more`). A held play's position
    before the load first passes T_h is where the last handling left it, anywhere within
    its clearance: fitted (one term more) where BIC prefers it to the flank the first
    branch's form would put it at."""
    if "backlash" not in fit.effects or problem.branches is None:
        return fit
    t0 = problem.scales["T0"]
    # the hold searched with the play's start position on the first branch's flank and free
    # (one linear term): the search is not convex, so each start is searched on its own
    tries = {}
    for start in (False, True):
        problem.play_start = start
        tries[start] = _searched(problem, fit, "play_hold", _PLAY_HOLD_BOUNDS)
    start = bic_best({s: (w.rss, int(s)) for s, (_, w) in tries.items()},
                     effective_n(problem, fit.residual(problem)))
    problem.play_start = start
    fit = _kept(problem, fit, "play_hold", *tries[start], lambda h: (
        f"backlash: the play is held by friction until the load passes {h * t0:.3g} N·m "
        "in the new direction"), terms=1 + int(start))
    problem.play_start = bool(start and problem.play_hold)
    if problem.play_start:
        b = linear_of(fit, "backlash")
        problem.notes.append(
            f"backlash: the record starts with the play at {b['start_position']:.3g} rad "
            f"(its lost motion {b['lost_motion']:.3g} rad), where the last handling left "
            "it, until the load first passes the holding torque")
    return _one_more(problem, fit, "play_bias", _PLAY_BIAS_BOUNDS, lambda c: (
        f"backlash: the play is crossed at {c * t0:.3g} N·m, not at zero torque (a steady "
        "torque preloads one flank: a slider's weight on a horizontal axis, a drag)"))


def refine_play_shape(problem: Problem, fit: Fit) -> Fit:
    """A named backlash whose take-up has an engagement exponent p other than tanh's 1
    (:func:`.effects.backlash_twist`), one parameter more, kept when BIC prefers it. Tried
    once the loop beside it has its final form: a play that closes slowly reads, over the
    torque, as part of a loop's backbone, and taken first it keeps what a sum of friction
    elements would follow better (suite R's Berg loop beside a Weibull take-up: 1.15σ with
    the loop refined first, 1.39σ with the exponent first)."""
    if "backlash" not in fit.effects:
        return fit
    return _one_more(problem, fit, "play_shape", _PLAY_SHAPE_BOUNDS, lambda s: (
        f"backlash: the play is taken up as tanh(|T/T_w|^p) with p = {math.exp(s):.2f} "
        + ("(it waits, then closes steeply: a slider held centred, lugs touching together)"
           if s > 0 else "(it starts at once and closes ever more slowly: contact spreading "
           "over lugs or a line)")))


def refine_play_drift(problem: Problem, fit: Fit) -> Fit:
    """A named backlash whose lost motion changes along the record: b(u) = b0 + Σ b_k·P_k(u),
    u the record's position (−1 … 1), Legendre order 1 … ``PLAY_DRIFT_MAX``, or one step
    b0 + d·[u ≥ u_s] at the likeliest position within ±``PLAY_STEP_SPAN`` (:func:`.rig.
    step_position` of the residual along the play's column); of the forms whose lost motion
    stays ≥ 0 along the record, the one BIC prefers with the shapes held, kept when it
    passes :func:`.gates.beyond` (ΔBIC > ``BIC_MIN`` and ``EXPLAINED_MIN`` noise variances
    more), then the shapes polished with it. A clearance grows with wear and with the gear's
    temperature over a test (wear only where the play is crossed, so in steps when the
    crossings come in blocks); a play seen at the output depends on where the input was
    locked, which a test in two parts changes once. The amplitudes are linear, so each form
    costs one solve. Leaves ``problem.play_drift`` and ``problem.play_step`` at the form
    kept."""
    if problem.kind != "torsion" or "backlash" not in fit.effects:
        return fit
    trials = _drift_trials(problem, fit)
    if not trials:
        return fit
    n_eff = effective_n(problem, fit.residual(problem))
    form = bic_best({k: (f.rss, f.n_params) for k, f in trials.items()}, n_eff)
    if not beyond(problem, fit, trials[form], explained_min=EXPLAINED_MIN):
        return fit
    problem.play_drift, problem.play_step = form
    drifted = fit_model(problem, fit.effects, fit.theta)
    if drifted.rss < trials[form].rss and _a_clearance(problem, drifted):
        drifted = replace(drifted, n_params=trials[form].n_params)
    else:
        drifted = trials[form]
    start, end, low, high = play_along_record(problem, drifted)
    form_text = (f"one step at {(1.0 + problem.play_step) / 2.0:.0%} of the record"
                 if problem.play_step is not None else
                 f"Legendre order {problem.play_drift} in the record's position")
    problem.notes.append(
        f"backlash: the lost motion changes along the record, from {start:.3g} rad at its "
        f"start to {end:.3g} rad at its end (between {low:.3g} and {high:.3g}; {form_text}, "
        "BIC): a clearance that grows with wear or with the gear's temperature, or a play "
        "seen through an input locked at another angle")
    return drifted


def _drift_trials(problem: Problem, fit: Fit) -> dict[tuple[int, float | None], Fit]:
    """{(Legendre order, step position): fit with the shapes held} of a play's lost motion
    along the record, the forms whose lost motion stays ≥ 0 (a clearance); leaves the
    problem's form at none."""
    shapes = fit.shapes
    play = fit.columns[:, fit.labels.index(("backlash", "lost_motion"))]
    u = problem.base.inputs["record_position"][problem.rows]
    inner = np.abs(u) <= PLAY_STEP_SPAN
    step = step_position((fit.residual(problem) * play)[inner], u[inner])
    forms = [(order, None) for order in range(1, PLAY_DRIFT_MAX + 1)] + [(0, step)]
    trials = {}
    for form in forms:
        problem.play_drift, problem.play_step = form
        trial = finish(problem, fit.effects, fit.theta, shapes)
        if _a_clearance(problem, trial):
            position = 0 if form[1] is None else 1  # the step's position is a parameter
            trials[form] = replace(trial, n_params=trial.n_params + position)
    problem.play_drift, problem.play_step = 0, None
    return trials


def _a_clearance(problem: Problem, fit: Fit) -> bool:
    """The play's lost motion in ``fit`` stays ≥ 0 along the whole record."""
    return play_along_record(problem, fit)[2] >= 0.0


def refine_low_load(problem: Problem, fit: Fit) -> Fit:
    """The named low-load factor in the better of its two shapes
    (:func:`.efficiency_laws.low_load_factor`): the load-independent loss's (Ke → 0 at no
    load, used to name it) or one flat at rated torque, finite at no load. The same
    parameters, so the smaller residual decides."""
    if "low_load_efficiency" not in fit.effects:
        return fit
    best, flat = best_setting(problem, fit, False, (True,),
                              lambda v: setattr(problem, "low_load_flat", v))
    if flat:
        problem.notes.append("low-load factor: Ke = 1 − c/(1 + c)·(1 − α)^q, flat at rated "
                             "torque, fits better than the load-independent loss's "
                             "(α·(1 + c)/(α + c))^q")
    return best


def refine_viscosity(problem: Problem, fit: Fit) -> Fit:
    """The viscosity–temperature law of a named temperature dependence: Reynolds'
    exponential (used to name it), Andrade's or Vogel–Cameron's, whichever fits best (the
    same parameters; the laws differ in how the viscosity curves over the temperatures)."""
    if "temperature_dependence" not in fit.effects:
        return fit
    best, law = fit_viscosity_law(problem, fit)
    problem.notes.append(f"viscosity law: {law} (C = {problem.viscosity_C:g} °C), the best "
                         f"of {', '.join(laws.VISCOSITY_LAWS_C)} on these data")
    return _viscous_drag(problem, _speed_loss(problem, _temperature_band(problem, best)))


def _temperature_band(problem: Problem, fit: Fit) -> Fit:
    """The temperature law as a loss that changes over a band of temperature
    (:func:`.efficiency_laws.band_ratio`, its centre and width two parameters more) in place
    of the viscosity law, kept when BIC with the effective sample size prefers it: an
    additive that activates or a grease that changes consistency steps the efficiency
    between two temperatures where a viscosity law bends it smoothly over all of them.
    Centres between the temperatures tested, a few widths; not tried when the residual's
    means over the test's temperatures and speeds hold too little to pay for the two
    parameters."""
    t = problem.base.inputs["temperature_C"][problem.rows]
    levels = np.unique(np.round(t, 1))
    if len(levels) < 3:
        return fit
    n_eff = effective_n(problem, fit.residual(problem))
    if _cell_share(problem, fit) < 1.0 - math.exp(-2.0 * math.log(n_eff) / n_eff):
        return fit
    if len(levels) > _BAND_CENTRES + 1:
        levels = np.quantile(t, np.linspace(0.0, 1.0, _BAND_CENTRES + 1))
    bands = [(float(centre), width) for centre in 0.5 * (levels[1:] + levels[:-1])
             for width in _BAND_WIDTHS_K]
    banded, band = best_setting(problem, fit, None, bands,
                                lambda b: setattr(problem, "temperature_band", b))
    if band is None:
        return fit
    n_eff = effective_n(problem, banded.residual(problem))
    if bic_best({False: (fit.rss, 0), True: (banded.rss, 2)}, n_eff) is False:
        problem.temperature_band = None
        return fit
    problem.notes.append(
        f"temperature law: the loss changes over a band of temperature about {band[0]:.3g} °C "
        f"(width {band[1]:g} K; an additive's activation, a grease's consistency) in place "
        "of the viscosity law (BIC)")
    return replace(banded, n_params=banded.n_params + 2)


def _cell_share(problem: Problem, fit: Fit) -> float:
    """Share of the residual sum of squares held by its means over the cells of the test's
    grid (temperature × input speed) beyond what white noise puts there: what a law in
    temperature and speed can take."""
    inputs = problem.base.inputs
    cells = np.column_stack([np.round(inputs[c][problem.rows], 1)
                             for c in ("temperature_C", "input_speed_rpm")])
    _, cell = np.unique(cells, axis=0, return_inverse=True)
    r = fit.residual(problem)
    sums, counts = np.bincount(cell.ravel(), r), np.bincount(cell.ravel())
    # white noise alone puts one row's worth of variance in each cell's mean
    return float(np.sum(sums ** 2 / counts) / max(r @ r, 1e-300)) - len(counts) / len(r)


def fit_viscosity_law(problem: Problem, fit: Fit) -> tuple[Fit, str]:
    """(fit, law name): ``fit`` (at Reynolds' exponential) or its refit under Andrade's or
    Vogel–Cameron's law, whichever leaves the least residual; ``problem.viscosity_C`` is
    left at that law."""
    return best_setting(problem, fit, "Reynolds", laws.VISCOSITY_LAWS_C, lambda law: setattr(
        problem, "viscosity_C", laws.VISCOSITY_LAWS_C[law]))


def _speed_loss(problem: Problem, fit: Fit) -> Fit:
    """The temperature law with its viscous loss at t_ref growing with speed as well
    (``speed_loss`` u, one parameter more), kept when BIC with the effective sample size
    prefers it: the law then has one reference point (t_ref, n_ref) instead of t_ref at
    every speed."""
    if fit.theta.get("temperature_dependence.s", 0.0) == 0.0:
        return fit  # no speed in the law: u would have nothing to act on
    return _one_more(problem, fit, "speed_loss", _SPEED_LOSS_BOUNDS, lambda u: (
        f"temperature law: the viscous loss at {laws.REFERENCE_TEMPERATURE_C:g} °C grows with "
        f"speed too (u = {u:.3g} of the input power at {laws.KE_REFERENCE_SPEED_RPM:g} r/min, "
        "× (n/n_ref)^s − 1)"))


def _viscous_drag(problem: Problem, fit: Fit) -> Fit:
    """A named low-load factor whose drag grows with the oil's viscosity (× g^k, the
    temperature law's g; ``drag_viscosity_exponent`` k, one parameter more), kept when BIC
    prefers it. A drag torque is a viscous loss too (Palmgren: ∝ (ν·n)^(2/3)), so the
    efficiency at low load falls further in a cold gear: the two effects do not multiply
    independently."""
    if not {"low_load_efficiency", "temperature_dependence"} <= set(fit.effects):
        return fit
    return _one_more(problem, fit, "drag_viscosity_exponent", _DRAG_VISCOSITY_BOUNDS,
                     lambda k: "low-load factor: its drag grows with the oil's viscosity "
                               f"(no-load loss × (ν/ν(20 °C))^{k:.3g}; Palmgren)")


def _one_more(problem: Problem, fit: Fit, attribute: str, bounds: tuple[float, float],
              note) -> Fit:
    """``fit`` with one more term, the scalar ``problem.attribute`` searched within
    ``bounds`` with the shapes refitted, kept (and ``note(value)`` added) when BIC with the
    effective sample size prefers it; else ``fit`` with the attribute back at 0."""
    return _kept(problem, fit, attribute, *_searched(problem, fit, attribute, bounds), note)


def _searched(problem: Problem, fit: Fit, attribute: str, bounds: tuple[float, float]
              ) -> tuple[float, Fit]:
    """(value, fit) of the scalar ``problem.attribute`` searched within ``bounds`` with the
    shapes refitted (the attribute is left at the value)."""

    tried: dict[float, Fit] = {}

    def trial(value: float) -> Fit:
        """The shapes refitted at ``value``, from those of the nearest value tried (they
        move little between neighbours, and the polish then takes a few steps)."""
        value = float(value)
        if value not in tried:
            near = min(tried, key=lambda v: abs(v - value), default=None)
            setattr(problem, attribute, value)
            tried[value] = fit_model(problem, fit.effects,
                                     fit.theta if near is None else tried[near].theta)
        return tried[value]

    found = minimize_scalar(lambda v: trial(v).rss, bounds=bounds, method="bounded",
                            options={"xatol": 1e-3, "maxiter": 20})
    wider = trial(found.x)
    setattr(problem, attribute, float(found.x))
    return float(found.x), wider


def _kept(problem: Problem, fit: Fit, attribute: str, value: float, wider: Fit, note,
          terms: int = 1) -> Fit:
    """``wider`` (``problem.attribute`` at ``value``, ``terms`` more than ``fit``) when BIC
    with the effective sample size prefers it, with ``note(value)`` added; else ``fit`` with
    the attribute back at 0."""
    setattr(problem, attribute, value)
    n_eff = effective_n(problem, wider.residual(problem))
    if bic_best({False: (fit.rss, 0), True: (wider.rss, terms)}, n_eff) is False:
        setattr(problem, attribute, 0.0)
        return fit
    problem.notes.append(note(value))
    # the terms earlier refinements added to ``fit`` stay (the refit counts its shapes only)
    earlier = fit.shapes - shapes_in_use(problem, fit.effects, fit.theta)
    return replace(wider, n_params=wider.n_params + 1 + max(earlier, 0))
